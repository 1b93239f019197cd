//! The steady motion solved from the model itself: the shared reference of the checks of
//! eqs 27-40 (`steady/`), 41-43 (`slippage.rs`) and 44-58 (`oscillation.rs`). A steady motion
//! is found by Newton's method on the model's eq 24 (exact derivatives by dual numbers) at a tilt
//! $\alpha_0$ and a ratio $\rho = \omega_{10}/\Omega_0$, never from the paper's steady-motion
//! formulas; its radii are measured on integrations. Not a check: no check file imports another.

use crate::harness::disk_constants;
use crate::harness::Bench;
use num_dual::Dual64;
use numerics::oscillation::bisect;
use paper::Bindings;
use physics::disk::Disk;
use physics::model::rolling::{field, Rolling};
use physics::model::{Extras, Model, Motion};
use physics::solve::{solve, Problem, State};
use std::f64::consts::PI;

// ------------------------------------------------------------------------------------------
// Shared helpers (also used by slippage.rs and oscillation.rs)
// ------------------------------------------------------------------------------------------

/// The inertia factors swept: a thin ring-like spread from 0.1 to 0.9, with the uniform disk
/// (1/4) and the hoop (1/2).
pub(crate) const KS: [f64; 4] = [0.1, 0.25, 0.5, 0.9];

/// A steady motion found from the model alone: at tilt `alpha0` with $\omega_{10} = \rho\,\Omega_0$,
/// Newton's method on $\ddot\alpha(\Omega) = 0$ (eq 24 of the model), exact derivative by a dual
/// number. $\Omega_0$ has the sign of $\rho$ (or is positive for $\rho = 0$) so that
/// $\omega_{10} \ge 0$. `None` when no real root exists (the model's $\ddot\alpha$ does not
/// change sign along $\Omega$).
pub(crate) fn steady_ref(d: &Disk, alpha0: f64, rho: f64) -> Option<Motion> {
    let sign = if rho < 0.0 { -1.0 } else { 1.0 };
    let f = |om: Dual64| {
        let y = [Dual64::from(alpha0), Dual64::from(0.0), om, om * rho];
        field(d, &y)[1]
    };
    let mut om = sign * d.g_over_a().sqrt();
    // Walk outwards until alpha_ddot > 0 (the convex branch to the right of the root).
    let mut tries = 0;
    while f(Dual64::from(om)).re <= 0.0 {
        om *= 2.0;
        tries += 1;
        if tries > 60 {
            return None;
        }
    }
    for _ in 0..200 {
        let v = f(Dual64::new(om, 1.0));
        let step = v.re / v.eps;
        om -= step;
        if step.abs() <= 4.0 * f64::EPSILON * om.abs() {
            break;
        }
    }
    // A final clean-up step.
    let v = f(Dual64::new(om, 1.0));
    om -= v.re / v.eps;
    om.is_finite().then_some(Motion {
        alpha: alpha0,
        alpha_dot: 0.0,
        precession: om,
        spin: rho * om,
    })
}

/// The model's state vector of a motion.
pub(crate) fn state(m: &Motion) -> [f64; 4] {
    [m.alpha, m.alpha_dot, m.precession, m.spin]
}

/// The steady state's geometry measured on an integration: $(b, r)$, the signed horizontal
/// distance from the axis of the circular motion to the centre of mass, along $\hat{\mathbf r}$,
/// and the same for the contact point. The axis is the mean of the centre of mass's path sampled
/// at 64 even times over one precession period (exact for a uniform circle); $\hat{\mathbf r}$ is
/// $\hat{\mathbf 2}\times\hat{\mathbf z}$ with $\hat{\mathbf 2}$ along the heading; the contact
/// point lies at $a\cos\alpha_0$ beyond the centre of mass along $\hat{\mathbf r}$ (the disk's
/// geometry: the radius to the contact point is in the disk's vertical plane, at angle
/// $\alpha_0$ to the table).
pub(crate) fn measure_b_r(bench: &Bench, d: &Disk, m: &Motion) -> (f64, f64) {
    let extras = Extras {
        heading: true,
        path: true,
        face: false,
    };
    let model = Rolling::<7>::new(*d, extras, None);
    let n = 64;
    let period = 2.0 * PI / m.precession.abs();
    let sol = solve(
        Problem::new(&model, 0.0, model.state(m), period).sampled(period / n as f64),
        &bench.settings(),
    )
    .expect("valid settings");
    let (mut cx, mut cy) = (0.0, 0.0);
    for y in sol.y.iter().take(n) {
        cx += y[5] / n as f64;
        cy += y[6] / n as f64;
    }
    let y0 = &sol.y[0];
    let psi = y0[4];
    let (rx, ry) = (psi.sin(), -psi.cos());
    let b = (y0[5] - cx) * rx + (y0[6] - cy) * ry;
    (b, b + d.a * m.alpha.cos())
}

/// The largest deviations of $\alpha$, $\Omega$ and $\omega_1$ from their start values along an
/// integration of `periods` precession periods, relative to $\alpha_0$, $|\Omega_0|$ and
/// $|\Omega_0|$ (the spin's natural scale, as $\omega_{10}$ may vanish).
pub(crate) fn steady_drift(bench: &Bench, d: &Disk, m: &Motion, periods: f64) -> f64 {
    let model = Rolling::<4>::new(*d, Extras::default(), None);
    let t_end = periods * 2.0 * PI / m.precession.abs();
    // A start that is not a number (a printed relation with no root, say) cannot be steady.
    let Ok(sol) = solve(
        Problem::new(&model, 0.0, model.state(m), t_end).sampled(t_end / 200.0),
        &bench.settings(),
    ) else {
        return f64::INFINITY;
    };
    if !sol.ending.is_complete() {
        return f64::INFINITY;
    }
    let om = m.precession.abs();
    sol.y
        .iter()
        .map(|y: &State<4>| {
            ((y[0] - m.alpha).abs() / m.alpha)
                .max((y[2] - m.precession).abs() / om)
                .max((y[3] - m.spin).abs() / om)
        })
        .fold(0.0, f64::max)
}

/// Tilts swept for steady motion.
pub(crate) const ALPHAS: [f64; 4] = [0.1, 0.5, 1.0, 1.4];

/// Ratios $\rho = \omega_{10}/\Omega_0$ swept, as fractions of the most negative one allowed by
/// the model (found numerically): -0.5 of it, 0, and the positive values 0.2 and 1.5.
pub(crate) fn rhos(d: &Disk, alpha0: f64) -> [f64; 4] {
    let edge = rho_edge(d, alpha0, 1e-12);
    [0.5 * edge, 0.0, 0.2, 1.5]
}

/// The most negative $\rho = \omega_{10}/\Omega_0$ with a steady motion at `alpha0`, by bisection
/// on whether the model's $\ddot\alpha(\Omega)$ at $\omega_1 = \rho\Omega$ can vanish: it is
/// $A\Omega^2 - C$ with $C > 0$ (the weight) for $\alpha_0 < \pi/2$, so a root exists iff the
/// growth $A = \ddot\alpha(1) - \ddot\alpha(0) > 0$.
pub(crate) fn rho_edge(d: &Disk, alpha0: f64, width: f64) -> f64 {
    let (lo, hi) = bisect(-2.0, 2.0, width, |rho| steady_exists(d, alpha0, rho));
    0.5 * (lo + hi)
}

/// The disk's constants and the steady tilt, bound to the paper's symbols.
pub(crate) fn steady_bindings(d: &Disk, alpha0: f64) -> Bindings<f64> {
    disk_constants(d).scalar("alpha_0", alpha0)
}

/// Whether the model has a steady motion at `alpha0` with $\omega_{10} = \rho\Omega_0$.
pub(crate) fn steady_exists(d: &Disk, alpha0: f64, rho: f64) -> bool {
    let f = |om: f64| field(d, &[alpha0, 0.0, om, rho * om])[1];
    f(1.0) - f(0.0) > 0.0
}
