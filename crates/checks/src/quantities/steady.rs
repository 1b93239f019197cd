//! Steady motion: the precession rate at a tilt, found from the equations of motion, and the
//! friction coefficient it needs to roll without slipping.

use super::threshold::{bisection, not_located};
use super::{Computed, Quantity, Values, ALPHA0, B_OVER_A, K};
use crate::finding::{Method, Tolerance};
use crate::harness::Bench;
use numerics::oscillation::bisect;
use physics::disk::Disk;
use physics::model::rolling;
use physics::model::Motion;

/// Bisections narrow their bracket to this relative width.
const WIDTH: f64 = 1e-12;

/// `steady-precession-rate`.
pub(super) const STEADY_PRECESSION_RATE: Quantity = Quantity {
    name: "steady-precession-rate",
    means: "the precession rate Omega_0 of the steady rolling motion at tilt alpha_0 with the \
            centre of mass on a circle of radius b (negative with b < 0, the paper's convention \
            omega_1 >= 0)",
    unit: "sqrt(g/a)",
    method: Method::Derivation,
    tolerance: bisection,
    how: "the rate at which the rolling model's eqs 23-25 give alpha_ddot = 0 at alpha = \
          alpha_0, alpha_dot = 0, omega_1 = (b/a) Omega, by bisection over |Omega| in [1e-4, \
          1e4]; never eq 29's closed form",
    parameters: &[K, ALPHA0, B_OVER_A],
    compute: precession_rate,
};

/// `friction-needed`.
pub(super) const FRICTION_NEEDED: Quantity = Quantity {
    name: "friction-needed",
    means: "the friction coefficient |F_horizontal| / F_z that the steady rolling motion at tilt \
            alpha_0 and radius b needs to roll without slipping",
    unit: "1",
    method: Method::Derivation,
    tolerance: derived_tolerance,
    how: "the contact force of the rolling model (eq 20's premises: the centre of mass's \
          acceleration and gravity) at the steady motion of steady-precession-rate; never eq \
          41's or eq 43's closed form",
    parameters: &[K, ALPHA0, B_OVER_A],
    compute: friction_needed,
};

/// The steady rolling motion at `alpha0` and `b/a` of the disk $a = g = m = 1$ with inertia
/// factor `k`: the rate $\Omega$ at which $\ddot\alpha = 0$ with $\dot\alpha = 0$ and
/// $\omega_1 = (b/a)\Omega$, by bisection; an error saying why where there is none.
pub(super) fn steady_state(v: &Values) -> Result<(Disk, Motion, String), String> {
    let (k, alpha0, b) = (v.number("k"), v.number("alpha0"), v.number("b_over_a"));
    let disk = Disk::new(1.0, k, 1.0, 1.0).map_err(|e| format!("no disk with $k = {k}$: {e}"))?;
    let sign = if b < 0.0 { -1.0 } else { 1.0 };
    let motion = |om: f64| Motion {
        alpha: alpha0,
        alpha_dot: 0.0,
        precession: sign * om,
        spin: b * sign * om,
    };
    let alpha_ddot = |om: f64| rolling::rates(&disk, &motion(om), [0.0; 3]).alpha_ddot;
    let (lo, hi) = bisect(1e-4, 1e4, WIDTH, |om| alpha_ddot(om) > 0.0);
    if !(lo.is_finite() && hi.is_finite()) {
        return Err(format!(
            "no steady rolling motion at $\\alpha_0 = {alpha0}$ rad, $b/a = {b}$, $k = {k}$: \
             $\\ddot\\alpha$ keeps one sign for $|\\Omega|$ from 1e-4 to $1e4 \\sqrt{{g/a}}$"
        ));
    }
    let om = 0.5 * (lo + hi);
    let at = format!(
        "$k = {k}$, $\\alpha_0 = {alpha0}$ rad, $b/a = {b}$: $\\ddot\\alpha = 0$ of eqs 23-25 at $|\\Omega|$ in \
         [{lo:.12e}, {hi:.12e}] $\\sqrt{{g/a}}$ (bisection)"
    );
    Ok((disk, motion(om), at))
}

/// [`STEADY_PRECESSION_RATE`] in $\sqrt{g/a}$.
fn precession_rate(v: &Values, _: &Bench) -> Computed {
    match steady_state(v) {
        Ok((_, m, at)) => Computed {
            value: m.precession,
            at,
            series: None,
        },
        Err(why) => not_located(why),
    }
}

/// [`FRICTION_NEEDED`]: $|F_h|/F_z$ from the rolling model's exact contact force.
fn friction_needed(v: &Values, _: &Bench) -> Computed {
    match steady_state(v) {
        Ok((disk, m, at)) => {
            let r = rolling::rates(&disk, &m, [0.0; 3]);
            let [fz, fr, f2] = rolling::contact_force(&disk, &m, &r);
            Computed {
                value: fr.hypot(f2) / fz,
                at: format!("{at}; $F_z = {fz:.9} m g$"),
                series: None,
            }
        }
        Err(why) => not_located(why),
    }
}

/// The tolerance of a quantity computed in closed form from a steady rate located to relative
/// width `WIDTH`: a force or a frequency goes with at most the square of the rate, so its
/// relative error is at most about twice the rate's, with round-off.
pub(super) fn derived_tolerance(_: &Bench) -> Tolerance {
    Tolerance {
        value: 1e-10,
        rule: format!(
            "a steady rate bracketed by bisection to relative width {WIDTH:e}; what is computed \
             from it, quadratic at most in the rate, within 1e-10 relative (twice the rate's \
             bracket, with round-off)"
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::quantities::Value;

    fn values(k: f64, alpha0: f64, b: f64) -> Values {
        Values(vec![
            ("k", Value::Number(k)),
            ("alpha0", Value::Number(alpha0)),
            ("b_over_a", Value::Number(b)),
        ])
    }

    /// Eq 29 (compared here, never used by the quantity): Omega_0^2 = g cot(alpha_0) / (k a
    /// cos(alpha_0) + (2k+1) b).
    #[test]
    fn the_steady_rate_is_eq29s() {
        for (k, alpha0, b) in [(0.25, 0.3, 0.0), (0.5, 1.0, 0.2), (0.25, 0.8, -0.05)] {
            let om = precession_rate(&values(k, alpha0, b), &Bench::default()).value;
            let eq29 = (1.0 / alpha0.tan() / (k * alpha0.cos() + (2.0 * k + 1.0) * b)).sqrt();
            assert!((om.abs() - eq29).abs() < 1e-10 * eq29, "{om} {eq29}");
            assert_eq!(om < 0.0, b < 0.0);
        }
    }

    /// With b = 0 the centre of mass is at rest: no horizontal force is needed.
    #[test]
    fn no_friction_is_needed_with_the_centre_of_mass_at_rest() {
        assert!(friction_needed(&values(0.25, 0.3, 0.0), &Bench::default()).value < 1e-12);
        assert!(friction_needed(&values(0.25, 0.3, 0.1), &Bench::default()).value > 0.01);
    }

    #[test]
    fn beyond_eq30s_edge_there_is_no_steady_motion() {
        let c = precession_rate(&values(0.25, 0.3, -0.9), &Bench::default());
        assert!(c.value.is_nan());
        assert!(c.at.contains("no steady rolling motion"), "{}", c.at);
    }
}
