//! The threshold of spinning about a vertical diameter: the least rate at which a disk upright
//! on its edge turns stably, rolling without slipping (the paper's eq 53) or without friction
//! (eq 65).

use super::{Computed, Kind, Parameter, Quantity, Values, K};
use crate::finding::{Method, Tolerance};
use crate::harness::Bench;
use numerics::oscillation::bisect;
use physics::disk::Disk;
use physics::model::frictionless as fl;
use physics::model::rolling;
use physics::model::steady::vertical_spin;
use std::f64::consts::FRAC_PI_2;

/// Bisections narrow their bracket to this relative width.
const WIDTH: f64 = 1e-12;

/// `vertical-spin-threshold`.
pub(super) const VERTICAL_SPIN_THRESHOLD: Quantity = Quantity {
    name: "vertical-spin-threshold",
    means: "the least rate Omega at which a disk upright on its edge (alpha = pi/2) spinning \
            about its vertical diameter is stable, rolling without slipping or without friction",
    unit: "sqrt(g/a)",
    method: Method::Linearization,
    tolerance: bisection,
    how: "bisection on the sign of varpi^2 = -tr(J^2)/2, J the exact Jacobian (dual numbers) of \
          the rolling model's eqs 23-25 (contact: rolling) or of the frictionless model's eqs \
          61-62 (contact: frictionless) at alpha = pi/2, omega_1 = 0; never eq 53's or eq 65's \
          closed form",
    parameters: &[
        K,
        Parameter {
            name: "contact",
            means: "the contact: rolling without slipping, or without friction",
            kind: Kind::Choice(&["rolling", "frictionless"]),
            default: None,
        },
    ],
    compute: vertical_spin_threshold,
};

/// The threshold of [`VERTICAL_SPIN_THRESHOLD`] in $\sqrt{g/a}$: the edge between an unstable
/// ($\varpi^2 < 0$) and a stable upright spin, by bisection over $[10^{-4}, 10^4]$.
fn vertical_spin_threshold(v: &Values, _: &Bench) -> Computed {
    let k = v.number("k");
    let contact = v.word("contact");
    let Ok(disk) = Disk::new(1.0, k, 1.0, 1.0) else {
        return not_located(format!("no disk with $k = {k}$"));
    };
    let varpi2 = |om: f64| -> f64 {
        if contact == "frictionless" {
            let j = fl::spinless_jacobian(&disk, &[FRAC_PI_2, 0.0, om]);
            -(j * j).trace() / 2.0
        } else {
            let m = vertical_spin(om);
            let j = rolling::jacobian(&disk, &[m.alpha, m.alpha_dot, m.precession, m.spin]);
            -(j * j).trace() / 2.0
        }
    };
    let (lo, hi) = bisect(1e-4, 1e4, WIDTH, |om| varpi2(om) > 0.0);
    Computed {
        value: 0.5 * (lo + hi),
        at: format!(
            "{contact} contact, $k = {k}$: bisection on $\\varpi^{{2}}$ of the linearized equations at \
             $\\alpha = \\pi/2$, bracket [{lo:.12e}, {hi:.12e}] $\\sqrt{{g/a}}$"
        ),
        series: None,
    }
}

/// A value that could not be computed, and why.
pub(super) fn not_located(why: String) -> Computed {
    Computed {
        value: f64::NAN,
        at: why,
        series: None,
    }
}

/// The tolerance of a value bracketed by bisection to relative width `WIDTH`.
pub(super) fn bisection(_: &Bench) -> Tolerance {
    Tolerance::bisection(WIDTH)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::quantities::Value;

    fn at(k: f64, contact: &'static str) -> f64 {
        vertical_spin_threshold(
            &Values(vec![
                ("k", Value::Number(k)),
                ("contact", Value::Word(contact)),
            ]),
            &Bench::default(),
        )
        .value
    }

    /// Eqs 53 and 65's closed forms, sqrt(1/(k+1)) and sqrt(1/k), are what the linearization
    /// finds (they are compared here, never used by the quantity).
    #[test]
    fn the_thresholds_are_eq53s_and_eq65s() {
        for k in [0.25, 0.5, 0.1] {
            assert!((at(k, "rolling") - (1.0 / (k + 1.0)).sqrt()).abs() < 1e-10);
            assert!((at(k, "frictionless") - (1.0 / k).sqrt()).abs() < 1e-10);
        }
    }
}
