//! Steady motion, sections 4-5 of the paper (eqs 27-40).
//!
//! The references here never use the paper's steady-motion formulas (nor `model::steady`, which
//! implements eqs 28-30 and is therefore a claim): a steady motion is found by solving the
//! model's equation of motion (eq 24, `model::rolling::rates`) for $\ddot\alpha = 0$ with
//! Newton's method (exact derivatives by dual numbers), at a tilt $\alpha_0$ and a ratio
//! $\rho = \omega_{10}/\Omega_0$; the radius $b$ of the centre of mass's circle and the radius
//! $r$ of the contact point's circle are then MEASURED on an integration of the rolling model
//! that carries the heading and the centre of mass in the plane (the circle's centre is the mean
//! of the path sampled evenly over one precession period).
//!
//! Section 5's vector relations (eqs 33-37) are checked against the independent lab-frame
//! Newton-Euler model (`model::lab_frame`): the $b = 0$ steady state found as above is started in
//! the lab model, integrated over one precession period (its steadiness measured there), and
//! $\mathbf L$, $d\mathbf L/dt$, the contact torque, $\boldsymbol\omega$, the precession and
//! relative-spin rates are all computed or measured in the lab.
//!
//! The helpers here are shared with `slippage.rs` and `oscillation.rs`.

use super::{
    add_threshold, printed_relations, printed_threshold, solve_printed, solve_printed_with, Bench,
    Equation,
};
use crate::disk::Disk;
use crate::finding::{Finding, Method, Tolerance, Worst};
use crate::model::lab_frame::{Contact, LabFrame, Snapshot};
use crate::model::rolling::{contact_force, rates, Rolling};
use crate::model::{Extras, Model, Motion};
use crate::numerics::linearize::jacobian;
use crate::numerics::oscillation::bisect;
use crate::paper::Bindings;
use crate::solve::{solve, Problem, State};
use nalgebra::{SMatrix, Vector3};
use num_dual::{Dual64, DualNum};
use std::f64::consts::PI;

/// The checks of this part of the paper.
pub const EQUATIONS: &[Equation] = &[
    Equation {
        number: 27,
        label: "e21",
        check: eq27,
    },
    Equation {
        number: 28,
        label: "e22",
        check: eq28,
    },
    Equation {
        number: 29,
        label: "e23",
        check: eq29,
    },
    Equation {
        number: 30,
        label: "e23a",
        check: eq30,
    },
    Equation {
        number: 31,
        label: "e24",
        check: eq31,
    },
    Equation {
        number: 32,
        label: "e25",
        check: eq32,
    },
    Equation {
        number: 33,
        label: "e26",
        check: eq33,
    },
    Equation {
        number: 34,
        label: "e27",
        check: eq34,
    },
    Equation {
        number: 35,
        label: "e28",
        check: eq35,
    },
    Equation {
        number: 36,
        label: "e29",
        check: eq36,
    },
    Equation {
        number: 37,
        label: "e30",
        check: eq37,
    },
    Equation {
        number: 38,
        label: "e31",
        check: eq38,
    },
    Equation {
        number: 39,
        label: "e32",
        check: eq39,
    },
    Equation {
        number: 40,
        label: "e33",
        check: eq40,
    },
];

// ------------------------------------------------------------------------------------------
// Shared helpers (also used by slippage.rs and oscillation.rs)
// ------------------------------------------------------------------------------------------

/// The inertia factors swept: a thin ring-like spread from 0.1 to 0.9, with the uniform disk
/// (1/4) and the hoop (1/2).
pub(super) const KS: [f64; 4] = [0.1, 0.25, 0.5, 0.9];

/// A disk of the Euler's Disk toy's size (a = 37.5 mm) with inertia factor `k`.
pub(super) fn disk(k: f64) -> Disk {
    Disk::new(0.0375, k, 0.4, 9.81).expect("a valid disk")
}

/// The model's accelerations (eqs 23-25 as implemented in `model::rolling`, no torque) as a
/// function of the state $(\alpha, \dot\alpha, \Omega, \omega_1)$, generic over dual numbers.
pub(super) fn rhs<T: DualNum<f64> + Copy>(d: &Disk, y: &[T; 4]) -> [T; 4] {
    let m = Motion {
        alpha: y[0],
        alpha_dot: y[1],
        precession: y[2],
        spin: y[3],
    };
    let r = rates(d, &m, [T::zero(); 3]);
    [y[1], r.alpha_ddot, r.precession_dot, r.spin_dot]
}

/// The exact Jacobian of the rolling model at state `y`.
pub(super) fn jac(d: &Disk, y: &[f64; 4]) -> SMatrix<f64, 4, 4> {
    jacobian(|x: &[Dual64; 4]| rhs(d, x), y)
}

/// A steady motion found from the model alone: at tilt `alpha0` with $\omega_{10} = \rho\,\Omega_0$,
/// Newton's method on $\ddot\alpha(\Omega) = 0$ (eq 24 of the model), exact derivative by a dual
/// number. $\Omega_0$ has the sign of $\rho$ (or is positive for $\rho = 0$) so that
/// $\omega_{10} \ge 0$. `None` when no real root exists (the model's $\ddot\alpha$ does not
/// change sign along $\Omega$).
pub(super) fn steady_ref(d: &Disk, alpha0: f64, rho: f64) -> Option<Motion> {
    let sign = if rho < 0.0 { -1.0 } else { 1.0 };
    let f = |om: Dual64| {
        let y = [Dual64::from(alpha0), Dual64::from(0.0), om, om * rho];
        rhs(d, &y)[1]
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
pub(super) fn state(m: &Motion) -> [f64; 4] {
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
pub(super) fn measure_b_r(bench: &Bench, d: &Disk, m: &Motion) -> (f64, f64) {
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
pub(super) fn steady_drift(bench: &Bench, d: &Disk, m: &Motion, periods: f64) -> f64 {
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
const ALPHAS: [f64; 4] = [0.1, 0.5, 1.0, 1.4];

/// Ratios $\rho = \omega_{10}/\Omega_0$ swept, as fractions of the most negative one allowed by
/// the model (found numerically): -0.5 of it, 0, and the positive values 0.2 and 1.5.
fn rhos(d: &Disk, alpha0: f64) -> [f64; 4] {
    let edge = rho_edge(d, alpha0, 1e-12);
    [0.5 * edge, 0.0, 0.2, 1.5]
}

/// The most negative $\rho = \omega_{10}/\Omega_0$ with a steady motion at `alpha0`, by bisection
/// on whether the model's $\ddot\alpha(\Omega)$ at $\omega_1 = \rho\Omega$ can vanish: it is
/// $A\Omega^2 - C$ with $C > 0$ (the weight) for $\alpha_0 < \pi/2$, so a root exists iff the
/// growth $A = \ddot\alpha(1) - \ddot\alpha(0) > 0$.
pub(super) fn rho_edge(d: &Disk, alpha0: f64, width: f64) -> f64 {
    let (lo, hi) = bisect(-2.0, 2.0, width, |rho| steady_exists(d, alpha0, rho));
    0.5 * (lo + hi)
}

/// The disk's constants and the steady tilt, bound to the paper's symbols.
fn steady_bindings(d: &Disk, alpha0: f64) -> Bindings<f64> {
    Bindings::new()
        .scalar("a", d.a)
        .scalar("k", d.k)
        .scalar("g", d.g)
        .scalar("m", d.m)
        .scalar("alpha_0", alpha0)
}

/// Whether the model has a steady motion at `alpha0` with $\omega_{10} = \rho\Omega_0$.
pub(super) fn steady_exists(d: &Disk, alpha0: f64, rho: f64) -> bool {
    let f = |om: f64| rhs(d, &[alpha0, 0.0, om, rho * om])[1];
    f(1.0) - f(0.0) > 0.0
}

fn at(k: f64, alpha0: f64, rho: f64) -> String {
    format!("k = {k}, alpha0 = {alpha0}, b/a = {rho:.4}")
}

// ------------------------------------------------------------------------------------------
// Section 4
// ------------------------------------------------------------------------------------------

/// Eq 27, the steady balance
/// $k\Omega_0^2\sin\alpha_0\cos\alpha_0 + (2k+1)\omega_{10}\Omega_0\sin\alpha_0 = \frac{g}{a}\cos\alpha_0$.
///
/// Integration: at each tilt and ratio $\omega_{10}/\Omega_0$, the $\Omega_0$ that eq 27 gives
/// is the start of an integration of the rolling model over two precession periods; the claim
/// holds if $\alpha$, $\Omega$ and $\omega_1$ stay constant to the solver's accuracy (a wrong
/// $\Omega_0$ makes the disk nutate with an amplitude proportional to the error).
fn eq27(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for k in KS {
        let d = disk(k);
        for alpha0 in [0.1, 0.5, 1.0] {
            for rho in rhos(&d, alpha0) {
                // Eq 27 as printed, solved for Omega_0 with omega_10 = rho Omega_0.
                let sign = if rho < 0.0 { -1.0 } else { 1.0 };
                let unit = d.g_over_a().sqrt();
                let eq = b.paper.equation(27);
                let bind_at = |x: f64| {
                    steady_bindings(&d, alpha0)
                        .scalar("Omega_0", x)
                        .scalar("omega_10", rho * x)
                };
                let om = eq
                    .relations()
                    .first()
                    .and_then(|rel| {
                        solve_printed_with(eq, rel, &bind_at, sign * 1e-3 * unit, sign * 1e3 * unit)
                    })
                    .map_or(f64::NAN, |x| b.claim(x));
                let m = Motion {
                    alpha: alpha0,
                    alpha_dot: 0.0,
                    precession: om,
                    spin: rho * om,
                };
                let drift = steady_drift(b, &d, &m, 2.0);
                w.add(drift, 0.0, 1.0, || {
                    format!(
                        "{}; largest relative drift of (alpha, Omega, omega_1) over 2 precession periods",
                        at(k, alpha0, rho)
                    )
                });
            }
        }
    }
    Finding::from_worst(
        Method::Integration,
        "drift of alpha, Omega, omega_1 started at eq 27's steady state",
        w,
        Tolerance::solver(b.rtol),
        false,
    )
}

/// Eq 28, $\omega_{10} = \frac{b}{a}\Omega_0 = \Omega_0\left(\frac{r}{a} - \cos\alpha_0\right)$.
///
/// Integration: steady motions solved from the model (Newton on eq 24); $b$ and $r$ measured on
/// the integrated path of the centre of mass; both forms of the claim are compared with the
/// state's $\omega_{10}$ (relative to $|\Omega_0|$, since $\omega_{10}$ vanishes at $b = 0$).
fn eq28(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for k in KS {
        let d = disk(k);
        for alpha0 in ALPHAS {
            for rho in rhos(&d, alpha0) {
                let Some(m) = steady_ref(&d, alpha0, rho) else {
                    continue;
                };
                let (bb, r) = measure_b_r(b, &d, &m);
                let bind = steady_bindings(&d, alpha0)
                    .scalar("b", bb)
                    .scalar("r", r)
                    .scalar("Omega_0", m.precession)
                    .scalar("omega_10", m.spin);
                printed_relations(b, 28, &bind, m.precession.abs(), &mut w, &|| {
                    format!("{}; b and r measured on the path", at(k, alpha0, rho))
                });
            }
        }
    }
    Finding::from_worst(
        Method::Integration,
        "both printed relations of eq 28 at the model's steady spin and the measured b, r, relative to |Omega_0|",
        w,
        Tolerance::solver(b.rtol),
        false,
    )
}

/// Eq 29, $\Omega_0^2 = \dfrac{g\cot\alpha_0}{k a\cos\alpha_0 + (2k+1)b}
/// = \dfrac{g\cot\alpha_0}{(2k+1)r - (k+1)a\cos\alpha_0}$.
///
/// Integration and derivation: the steady motion is solved from the model (Newton on eq 24 at a
/// ratio $\omega_{10}/\Omega_0$), $b$ and $r$ are measured on its integrated path, and both
/// forms of eq 29 at the measured $b$, $r$ are compared with the solved $\Omega_0^2$. Tilts
/// 0.1-1.4, $b$ negative (half way to eq 30's edge found numerically), zero and positive.
fn eq29(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for k in KS {
        let d = disk(k);
        for alpha0 in ALPHAS {
            for rho in rhos(&d, alpha0) {
                let Some(m) = steady_ref(&d, alpha0, rho) else {
                    continue;
                };
                let (bb, r) = measure_b_r(b, &d, &m);
                let bind = steady_bindings(&d, alpha0)
                    .scalar("b", bb)
                    .scalar("r", r)
                    .scalar("Omega_0", m.precession);
                let om2 = m.precession * m.precession;
                printed_relations(b, 29, &bind, om2, &mut w, &|| at(k, alpha0, rho));
            }
        }
    }
    Finding::from_worst(
        Method::Integration,
        "both printed forms of eq 29 at the measured b and r against the model's steady Omega_0^2",
        w,
        Tolerance::solver(b.rtol),
        false,
    )
}

/// Eq 30, $b > -\dfrac{a k\cos\alpha_0}{2k+1}$.
///
/// Threshold: the most negative ratio $\rho = \omega_{10}/\Omega_0$ at which the model's eq 24
/// still has a real steady $\Omega_0$ is located by bisection (the coefficient of $\Omega^2$ in
/// $\ddot\alpha$ changes sign there and $\Omega_0^2$ diverges); $b = \rho a$ by the kinematics
/// verified in eq 28's check. Compared with the edge the printed inequality gives (solved for
/// $b$), and its direction with the model's at $b$ 0.1 % either side of the edge.
fn eq30(b: &Bench) -> Finding {
    let width = 1e-10;
    let mut w = Worst::default();
    for k in KS {
        let d = disk(k);
        for alpha0 in [0.1, 0.5, 1.0, 1.4, 1.55] {
            let edge = rho_edge(&d, alpha0, width) * d.a;
            let probes = [edge - 1e-3 * edge.abs(), edge + 1e-3 * edge.abs()];
            let bind = Bindings::new()
                .scalar("a", d.a)
                .scalar("k", k)
                .scalar("alpha_0", alpha0);
            let printed = printed_threshold(b, 30, "b", &bind, (-d.a, d.a), probes);
            let allowed = probes.map(|x| steady_exists(&d, alpha0, x / d.a));
            add_threshold(b, &mut w, &printed, edge, allowed, &|| {
                format!("k = {k}, alpha0 = {alpha0}")
            });
        }
    }
    Finding::from_worst(
        Method::Threshold,
        "lower bound on b for a steady motion: the printed edge and direction against the model's edge found by bisection",
        w,
        Tolerance::bisection(width),
        false,
    )
}

/// Eq 31, $\Omega_0^2 = \dfrac{g}{a k\sin\alpha_0}$ for $b = 0$.
///
/// Integration: the centre of mass at rest means $\dot\alpha = 0$ and $\omega_1 = 0$ (eq 13's
/// velocity vanishes); the rolling model is started with eq 31's $\Omega_0$ and integrated
/// over two precession periods; $\alpha$, $\Omega$, $\omega_1$ must stay constant to the solver's
/// accuracy. Tilts 0.05-1.5.
fn eq31(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for k in KS {
        let d = disk(k);
        for alpha0 in [0.05, 0.3, 0.8, 1.2, 1.5] {
            let eq = b.paper.equation(31);
            let unit = d.g_over_a().sqrt();
            let bind = steady_bindings(&d, alpha0);
            let om = eq
                .relations()
                .first()
                .and_then(|rel| solve_printed(eq, rel, "Omega_0", &bind, 1e-3 * unit, 1e3 * unit))
                .map_or(f64::NAN, |x| b.claim(x));
            let m = Motion {
                alpha: alpha0,
                alpha_dot: 0.0,
                precession: om,
                spin: 0.0,
            };
            let drift = steady_drift(b, &d, &m, 2.0);
            w.add(drift, 0.0, 1.0, || {
                format!("k = {k}, alpha0 = {alpha0}; relative drift over 2 precession periods")
            });
        }
    }
    Finding::from_worst(
        Method::Integration,
        "drift of alpha, Omega, omega_1 started at eq 31's steady state (b = 0)",
        w,
        Tolerance::solver(b.rtol),
        false,
    )
}

/// The rate of the face angle (the disk's spin relative to the triad) measured on an
/// integration of `m` over one precession period: the face state's advance divided by the time.
/// The model advances the face angle at $\omega_1 + \Omega\cos\alpha$ (eq 11, checked with the
/// kinematics).
fn measured_rel_spin(bench: &Bench, d: &Disk, m: &Motion) -> f64 {
    let extras = Extras {
        heading: false,
        path: false,
        face: true,
    };
    let model = Rolling::<5>::new(*d, extras, None);
    let t = 2.0 * PI / m.precession.abs();
    let sol = solve(
        Problem::new(&model, 0.0, model.state(m), t),
        &bench.settings(),
    )
    .expect("valid settings");
    let (t1, y1) = sol.last();
    y1[4] / t1
}

/// Shared by eqs 32 and 39: $\omega_{rel} = \Omega_0\cos\alpha_0$ at $b = 0$, against the face
/// angle's rate measured on an integration of the model's $b = 0$ steady motion.
fn rel_spin_check(b: &Bench, n: u32) -> Finding {
    let mut w = Worst::default();
    for k in KS {
        let d = disk(k);
        for alpha0 in ALPHAS {
            let Some(m) = steady_ref(&d, alpha0, 0.0) else {
                continue;
            };
            let measured = measured_rel_spin(b, &d, &m);
            let bind = steady_bindings(&d, alpha0)
                .scalar("Omega_0", m.precession)
                .scalar("omega_rel", measured);
            printed_relations(b, n, &bind, m.precession.abs(), &mut w, &|| {
                format!("k = {k}, alpha0 = {alpha0}, b = 0")
            });
        }
    }
    Finding::from_worst(
        Method::Integration,
        "omega_rel = Omega_0 cos(alpha_0) against the face angle's measured rate at b = 0, relative to |Omega_0|",
        w,
        Tolerance::solver(b.rtol),
        false,
    )
}

/// Eq 32, $\omega_{rel} = \Omega_0\cos\alpha_0$ for $b = 0$.
///
/// Integration: the model's $b = 0$ steady motion (Newton on eq 24 at $\omega_{10} = 0$) is
/// integrated with the face angle over one precession period; its rate is the relative spin.
fn eq32(b: &Bench) -> Finding {
    rel_spin_check(b, 32)
}

/// Eq 39, $\omega_{rel} = \Omega_0\cos\alpha_0$ (section 5's rederivation of eq 32).
///
/// Integration, as for eq 32.
fn eq39(b: &Bench) -> Finding {
    rel_spin_check(b, 39)
}

/// Eq 38, $\omega = -\Omega_0\sin\alpha_0$: at $b = 0$ the disk turns about axis
/// $\hat{\mathbf 3}$ at rate $\omega$.
///
/// Derivation from the contact force: with the angular velocity $\omega\hat{\mathbf 3}$ the
/// angular momentum about the centre is $k m a^2\omega\hat{\mathbf 3}$ (eq 18's moments); the
/// torque of the model's contact force (`contact_force`, eq 20 through the model's
/// accelerations) about the centre, $a\hat{\mathbf 3}\times\mathbf F$, must turn it at the
/// precession: $\frac{d}{dt}(k m a^2\omega\hat{\mathbf 3}) = k m a^2\omega\Omega_0\cos\alpha_0
/// \hat{\mathbf 2}$ (eq 7 at $\dot\alpha = 0$), while $\mathbf N\cdot\hat{\mathbf 2} =
/// a\mathbf F\cdot\hat{\mathbf 1}$. So $\omega = a F_1/(k m a^2\Omega_0\cos\alpha_0)$ from the
/// model's force, the reference (and $F_2 = 0$, since $d\mathbf L/dt$ has no axis-1 part).
fn eq38(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for k in KS {
        let d = disk(k);
        for alpha0 in [0.1, 0.5, 1.0, 1.4] {
            let Some(m) = steady_ref(&d, alpha0, 0.0) else {
                continue;
            };
            let r = rates(&d, &m, [0.0; 3]);
            let [fz, fr, f2] = contact_force(&d, &m, &r);
            // F along axis 1: z = -c 1 - s 3, r = -s 1 + c 3.
            let (s, c) = alpha0.sin_cos();
            let f1 = -c * fz - s * fr;
            // N = a 3 x F has axis-2 component a F.1; dL/dt = k m a^2 omega d3/dt has axis-2
            // component k m a^2 omega Omega cos(alpha) (eq 7, alpha_dot = 0). The axis-1 parts
            // (a F.2 against 0) are compared too.
            let omega_ref = d.a * f1 / (d.i22() * m.precession * c);
            w.add(f2, 0.0, d.m * d.g, || {
                format!("k = {k}, alpha0 = {alpha0}: F along axis 2 / mg")
            });
            let bind = steady_bindings(&d, alpha0)
                .scalar("Omega_0", m.precession)
                .scalar("omega_3", omega_ref);
            printed_relations(b, 38, &bind, omega_ref.abs(), &mut w, &|| {
                format!("k = {k}, alpha0 = {alpha0}, b = 0")
            });
        }
    }
    Finding::from_worst(
        Method::Derivation,
        "rate about axis 3 at b = 0: claimed against the rate the model's contact torque sustains",
        w,
        Tolerance::roundoff(),
        false,
    )
}

/// Eq 40, $\Omega_0^2 = \dfrac{g}{a k\sin\alpha_0}$ (section 5's rederivation of eq 31).
///
/// Derivation: compared with the $\Omega_0^2$ of the model's steady motion at $\omega_{10} = 0$
/// (Newton on eq 24), tilts 0.05-1.5.
fn eq40(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for k in KS {
        let d = disk(k);
        for alpha0 in [0.05, 0.3, 0.8, 1.2, 1.5] {
            let Some(m) = steady_ref(&d, alpha0, 0.0) else {
                continue;
            };
            let om2 = m.precession * m.precession;
            let bind = steady_bindings(&d, alpha0).scalar("Omega_0", m.precession);
            printed_relations(b, 40, &bind, om2, &mut w, &|| {
                format!("k = {k}, alpha0 = {alpha0}")
            });
        }
    }
    Finding::from_worst(
        Method::Derivation,
        "Omega_0^2 at b = 0 against the model's steady state solved by Newton",
        w,
        Tolerance::roundoff(),
        false,
    )
}

// ------------------------------------------------------------------------------------------
// Section 5, against the lab-frame model
// ------------------------------------------------------------------------------------------

/// Tilts of the section 5 checks.
const LAB_ALPHAS: [f64; 3] = [0.1, 0.8, 1.4];

/// Samples per precession period of a lab run: $\Omega_0 h = 2\pi/320 \approx 0.02$, so the
/// seven-point derivative's truncation, $(\Omega_0 h)^6/140 \approx 4\times10^{-13}$ of
/// $|\dot{\mathbf L}|$ ($\mathbf L$ turns uniformly at $\Omega_0$), and its round-off,
/// about $2\epsilon/(\Omega_0 h\cos\alpha_0) \approx 10^{-13}$ at $\alpha_0 = 1.4$, both stay far
/// below [`Tolerance::solver`] at the default rtol (measured: 5e-13 worst).
const LAB_SAMPLES: usize = 320;

/// Every how many samples a lab run's state is compared with a claim (32 points per run).
const LAB_STRIDE: usize = 10;

/// A $b = 0$ steady motion integrated by the lab-frame Newton-Euler model over one precession
/// period, with what is measured on it.
struct LabSteady {
    k: f64,
    alpha0: f64,
    disk: Disk,
    lab: LabFrame,
    /// Sample times (uniform).
    t: Vec<f64>,
    /// The lab states sampled.
    y: Vec<State<13>>,
    /// The geometry of each sample.
    snaps: Vec<Snapshot>,
    /// The angular momentum about the centre of mass, $R\,I\boldsymbol\omega_b$ (lab components).
    l: Vec<Vector3<f64>>,
    /// The precession rate: the heading's (unwrapped) advance over the run divided by its time.
    precession: f64,
    /// The relative spin: the face angle's (unwrapped) advance over the run divided by its time.
    rel_spin: f64,
    /// The largest departure from a steady $b = 0$ motion along the run: $|\alpha - \alpha_0|/\alpha_0$
    /// and the centre's speed over $a|\Omega_0|$.
    unsteadiness: f64,
}

/// The advance per unit time of an angle sampled in $(-\pi, \pi]$, unwrapped sample to sample.
fn angle_rate(t: &[f64], angles: &[f64]) -> f64 {
    let advance: f64 = angles
        .windows(2)
        .map(|w| (w[1] - w[0] + PI).rem_euclid(2.0 * PI) - PI)
        .sum();
    advance / (t[t.len() - 1] - t[0])
}

impl LabSteady {
    /// The $b = 0$ steady motion of the rolling model (Newton on eq 24 at $\omega_{10} = 0$, not
    /// the paper's eq 31), precessing with the sign `sign`, started in the lab model (heading
    /// 0.3, centre at (0.01, -0.02) m, face angle 0.7: nothing special) and integrated over one
    /// precession period. Its steadiness is measured on the lab run itself.
    fn run(bench: &Bench, k: f64, alpha0: f64, sign: f64) -> Option<Self> {
        let d = disk(k);
        let mut m = steady_ref(&d, alpha0, 0.0)?;
        m.precession *= sign;
        let lab = LabFrame::new(d, Contact::Rolling);
        let y0 = lab.state_from(&m, 0.3, [0.01, -0.02], 0.7);
        let period = 2.0 * PI / m.precession.abs();
        let sol = solve(
            Problem::new(&lab, 0.0, y0, period).sampled(period / LAB_SAMPLES as f64),
            &bench.settings(),
        )
        .ok()?;
        if !sol.ending.is_complete() {
            return None;
        }
        let snaps: Vec<Snapshot> = sol.y.iter().map(|y| lab.snapshot(y)).collect();
        let inertia = Vector3::new(d.i11(), d.i22(), d.i22());
        let l = snaps
            .iter()
            .map(|s| s.rotation * inertia.component_mul(&s.omega_body))
            .collect();
        let headings: Vec<f64> = snaps.iter().map(Snapshot::heading).collect();
        let faces: Vec<f64> = snaps.iter().map(Snapshot::face).collect();
        let unsteadiness = snaps
            .iter()
            .map(|s| {
                ((s.alpha() - alpha0).abs() / alpha0)
                    .max(s.velocity.norm() / (d.a * m.precession.abs()))
            })
            .fold(0.0, f64::max);
        Some(Self {
            k,
            alpha0,
            disk: d,
            precession: angle_rate(&sol.t, &headings),
            rel_spin: angle_rate(&sol.t, &faces),
            t: sol.t,
            y: sol.y,
            lab,
            snaps,
            l,
            unsteadiness,
        })
    }

    /// Every lab run of the section 5 checks: the inertia factors [`KS`], tilts
    /// [`LAB_ALPHAS`], both senses of precession.
    fn all(bench: &Bench) -> Vec<Self> {
        let mut out = Vec::new();
        for k in KS {
            for alpha0 in LAB_ALPHAS {
                for sign in [1.0, -1.0] {
                    if let Some(run) = Self::run(bench, k, alpha0, sign) {
                        out.push(run);
                    }
                }
            }
        }
        out
    }

    /// The indices compared: every [`LAB_STRIDE`]-th sample, three in from either end (room
    /// for the seven-point derivative).
    fn points(&self) -> impl Iterator<Item = usize> {
        (3..self.t.len() - 3).step_by(LAB_STRIDE)
    }

    /// $d\mathbf L/dt$ at sample `i`, by the seven-point central difference (error
    /// $h^6 L^{(7)}/140$) of the sampled angular momentum.
    fn l_dot(&self, i: usize) -> Vector3<f64> {
        let h = (self.t[i + 3] - self.t[i - 3]) / 6.0;
        let l = &self.l;
        (45.0 * (l[i + 1] - l[i - 1]) - 9.0 * (l[i + 2] - l[i - 2]) + (l[i + 3] - l[i - 3]))
            / (60.0 * h)
    }

    /// The rate $\omega$ about axis 3 measured at sample `i`: $|\boldsymbol\omega|$ with the sign
    /// of $\boldsymbol\omega\cdot\hat{\mathbf 3}$.
    fn omega3(&self, i: usize) -> f64 {
        let s = &self.snaps[i];
        s.omega.norm().copysign(s.omega.dot(&s.e3))
    }

    /// Where, in words.
    fn at(&self, i: usize, what: &str) -> String {
        format!(
            "k = {}, alpha0 = {}, Omega_0 = {:.4} rad/s (b = 0, lab frame), t = {:.5} s: {what}",
            self.k, self.alpha0, self.precession, self.t[i]
        )
    }

    /// Records the run's departure from steadiness (the premise of every section 5 claim).
    fn add_steadiness(&self, w: &mut Worst) {
        w.add(self.unsteadiness, 0.0, 1.0, || {
            self.at(
                self.t.len() - 1,
                "largest departure of the lab run from steady b = 0 motion (premise)",
            )
        });
    }
}

/// What a sample of a lab run gives the paper's symbols of sec. 5 ($b = 0$), all measured on the
/// lab-frame Newton-Euler run: the triad, $\alpha_0$, the precession and relative spin rates
/// (heading and face angle over the run), $\omega$ about axis 3, $\mathbf L = RI\boldsymbol\omega_b$,
/// its rate (seven-point difference), the contact torque $\boldsymbol\rho\times\mathbf F$, the
/// moment $I_{33}$ from the lab's inertia tensor, and the precession vector (vertical part the
/// heading's rate, horizontal part $\dot\alpha\hat{\mathbf 2}$).
fn lab_bindings(run: &LabSteady, i: usize) -> Bindings<f64> {
    let d = &run.disk;
    let s = &run.snaps[i];
    let inertia = Vector3::new(d.i11(), d.i22(), d.i22());
    let e3_body = s.rotation.inverse() * s.e3;
    let i33 = e3_body.dot(&inertia.component_mul(&e3_body));
    Bindings::new()
        .scalar("m", d.m)
        .scalar("g", d.g)
        .scalar("a", d.a)
        .scalar("k", d.k)
        .scalar("alpha_0", s.alpha())
        .scalar("Omega_0", run.precession)
        .scalar("omega_rel", run.rel_spin)
        .scalar("omega_3", run.omega3(i))
        .scalar("I_33", i33)
        .vector("e1", s.e1)
        .vector("e2", s.e2)
        .vector("e3", s.e3)
        .vector("z_hat", Vector3::z())
        .vector("omega_vec", s.omega)
        .vector("L", run.l[i])
        .vector("L_rate", run.l_dot(i))
        .vector("N", s.rho.cross(&run.lab.contact_force(&run.y[i])))
        .vector(
            "Omega_0_vec",
            s.motion().alpha_dot * s.e2 + run.precession * Vector3::z(),
        )
}

/// Eqs 33-37 share this: every printed relation of eq `n` at 32 samples of each lab run,
/// relative to `scale(run, i)`.
fn lab_relations(b: &Bench, n: u32, scale: impl Fn(&LabSteady, usize) -> f64, what: &str) -> Worst {
    let mut w = Worst::default();
    for run in LabSteady::all(b) {
        run.add_steadiness(&mut w);
        for i in run.points() {
            printed_relations(
                b,
                n,
                &lab_bindings(&run, i),
                scale(&run, i),
                &mut w,
                &|| run.at(i, what),
            );
        }
    }
    w
}

/// Eq 33, $\mathbf L = I_{33}\omega\hat{\mathbf 3} = k m a^2\omega\hat{\mathbf 3}$ at $b = 0$.
///
/// Independent model: the $b = 0$ steady motion (solved by Newton on the rolling model, its
/// steadiness measured on the lab run) integrated by the lab-frame Newton-Euler model over one
/// precession period; at 32 samples the angular momentum computed in the lab,
/// $R\,I\boldsymbol\omega_b$, against both printed forms, with $\omega$ measured
/// ($|\boldsymbol\omega|$ with the sign of $\boldsymbol\omega\cdot\hat{\mathbf 3}$),
/// $\hat{\mathbf 3}$ the lab's direction to the lowest rim point, and $I_{33} =
/// \hat{\mathbf 3}\cdot R I R^T\hat{\mathbf 3}$ from the lab's inertia tensor.
fn eq33(b: &Bench) -> Finding {
    let w = lab_relations(b, 33, |run, i| run.l[i].norm(), "L, relative to |L|");
    Finding::from_worst(
        Method::IndependentModel,
        "the printed forms of L against R I omega_b along lab-frame b = 0 steady runs, relative to |L|",
        w,
        Tolerance::solver(b.rtol),
        false,
    )
}

/// Eq 34, $\mathbf N = a\hat{\mathbf 3}\times m g\hat{\mathbf z} = \dfrac{d\mathbf L}{dt}$ at $b = 0$.
///
/// Independent model: along the lab runs of eq 33's check, $\mathbf N$ is the torque about the
/// centre of the contact force the lab model solves from the rolling condition,
/// $\boldsymbol\rho\times\mathbf F$, and $d\mathbf L/dt$ the rate of the lab's angular momentum
/// (seven-point central difference of the sampled $\mathbf L(t)$); relative to $|\mathbf N|$.
fn eq34(b: &Bench) -> Finding {
    let w = lab_relations(
        b,
        34,
        |run, i| {
            lab_bindings(run, i)
                .get("N")
                .and_then(|v| v.vector().ok())
                .map_or(1.0, |v| v.norm())
        },
        "N, relative to its norm",
    );
    Finding::from_worst(
        Method::IndependentModel,
        "the printed torque against the lab's contact torque rho x F and the lab run's dL/dt (seven-point difference), relative to |N|",
        w,
        Tolerance::solver(b.rtol),
        false,
    )
}

/// Eq 35, $\dfrac{d\mathbf L}{dt} = \vec\Omega_0\times\mathbf L$ at $b = 0$.
///
/// Independent model: along the lab runs of eq 33's check, with $\vec\Omega_0$ the precession
/// vector MEASURED on the lab run, against the lab run's $d\mathbf L/dt$ (seven-point central
/// difference), relative to its norm.
fn eq35(b: &Bench) -> Finding {
    let w = lab_relations(
        b,
        35,
        |run, i| run.l_dot(i).norm(),
        "dL/dt, relative to |dL/dt|",
    );
    Finding::from_worst(
        Method::IndependentModel,
        "Omega_0 x L (the lab run's measured precession) against the lab run's dL/dt, relative to |dL/dt|",
        w,
        Tolerance::solver(b.rtol),
        false,
    )
}

/// Eq 36, $\vec\Omega_0 = -\dfrac{g}{a k\omega}\hat{\mathbf z}$ at $b = 0$.
///
/// Independent model: along the lab runs of eq 33's check, with $\omega$ measured in the lab
/// ($|\boldsymbol\omega|$ with the sign of $\boldsymbol\omega\cdot\hat{\mathbf 3}$) at each sample,
/// against the precession vector measured on the run (vertical part the heading's advance over
/// one period divided by its time, horizontal part $\dot\alpha\hat{\mathbf 2}$ read from the lab
/// state); relative to the measured $|\Omega_0|$. Both senses of precession.
fn eq36(b: &Bench) -> Finding {
    let w = lab_relations(
        b,
        36,
        |run, _| run.precession.abs(),
        "Omega_0, relative to |Omega_0|",
    );
    Finding::from_worst(
        Method::IndependentModel,
        "the printed precession vector (omega measured in the lab) against the lab run's measured precession vector, relative to |Omega_0|",
        w,
        Tolerance::solver(b.rtol),
        false,
    )
}

/// Eq 37, $\vec\omega = (-\Omega_0\cos\alpha_0 + \omega_{rel})\hat{\mathbf 1} -
/// \Omega_0\sin\alpha_0\hat{\mathbf 3} = \omega\hat{\mathbf 3}$ at $b = 0$.
///
/// Independent model: along the lab runs of eq 33's check, the lab's angular velocity
/// $R\boldsymbol\omega_b$ against both printed forms, with $\Omega_0$ the run's measured
/// precession rate (heading), $\omega_{rel}$ its measured face-angle rate, $\alpha_0$ and
/// $\hat{\mathbf 1}, \hat{\mathbf 3}$ read from the lab state at the sample, and $\omega$ measured;
/// relative to $|\boldsymbol\omega|$.
fn eq37(b: &Bench) -> Finding {
    let w = lab_relations(
        b,
        37,
        |run, i| run.snaps[i].omega.norm(),
        "omega, relative to |omega|",
    );
    Finding::from_worst(
        Method::IndependentModel,
        "the printed forms of the angular velocity (Omega_0, omega_rel measured) against the lab's R omega_b, relative to |omega|",
        w,
        Tolerance::solver(b.rtol),
        false,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::finding::Verdict;

    fn run(number: u32) -> (Finding, Finding) {
        let e = EQUATIONS.iter().find(|e| e.number == number).unwrap();
        (
            (e.check)(&Bench::default()),
            (e.check)(&Bench::perturbed(1e-3)),
        )
    }

    #[test]
    fn every_check_holds_and_fails_when_perturbed() {
        for e in EQUATIONS {
            let (ok, bad) = run(e.number);
            eprintln!(
                "eq {}: {} err {:.3e} tol {:.1e} at {}; perturbed {} err {:.3e}",
                e.number, ok.verdict, ok.error, ok.tolerance.value, ok.at, bad.verdict, bad.error
            );
            assert_eq!(ok.verdict, Verdict::Holds, "eq {}: {ok:?}", e.number);
            assert_eq!(bad.verdict, Verdict::Fails, "eq {} perturbed", e.number);
        }
    }

    /// Eqs 33-37 against the lab-frame model: hold, and fail under either sign of perturbation.
    #[test]
    fn section_5_holds_in_the_lab_frame_and_fails_when_perturbed() {
        for number in 33..=37 {
            let e = EQUATIONS.iter().find(|e| e.number == number).unwrap();
            let ok = (e.check)(&Bench::default());
            eprintln!(
                "eq {number}: {} err {:.3e} tol {:.1e} at {}",
                ok.verdict, ok.error, ok.tolerance.value, ok.at
            );
            assert_eq!(ok.verdict, Verdict::Holds, "eq {number}: {ok:?}");
            for p in [1e-3, -1e-3] {
                let bad = (e.check)(&Bench::perturbed(p));
                eprintln!(
                    "eq {number} under {p}: {} err {:.3e}",
                    bad.verdict, bad.error
                );
                assert_eq!(bad.verdict, Verdict::Fails, "eq {number} under {p}");
            }
        }
    }

    /// The lab runs really are steady b = 0 motions of both senses, with the rates measured.
    #[test]
    fn lab_runs_are_steady() {
        let runs = LabSteady::all(&Bench::default());
        assert_eq!(runs.len(), KS.len() * LAB_ALPHAS.len() * 2);
        for run in &runs {
            assert!(run.unsteadiness < 1e-9, "{}", run.unsteadiness);
            let m = steady_ref(&run.disk, run.alpha0, 0.0).unwrap();
            assert!((run.precession.abs() - m.precession).abs() < 1e-9 * m.precession);
        }
    }
}
