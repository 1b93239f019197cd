//! The order of an approximation: a printed formula of the paper that approximates a quantity of
//! the catalogue at small tilt, and the power $n$ in $|\text{eq } N - Q| \propto \alpha_0^n$ at
//! which its error vanishes, fitted over $\alpha_0$ from $10^{-1}$ to $10^{-3}$ rad
//! ([`crate::finding::Finding::from_order`] judges it, as for the equations' own orders).

use super::{Computed, Kind, Parameter, Quantity, Value, Values, B_OVER_A, K};
use crate::finding::{Method, Tolerance};
use crate::harness::Bench;

/// The tilts $\alpha_0$ at which the error is measured, rad.
const TILTS: [f64; 5] = [1e-1, 3e-2, 1e-2, 3e-3, 1e-3];

/// The quantities an approximation can be compared with: those computed at a tilt $\alpha_0$
/// and a radius $b$.
const EXACT: &[&str] = &[
    "steady-precession-rate",
    "friction-needed",
    "nutation-frequency",
    "nutation-ratio",
];

/// `approximation-order`.
pub(super) const APPROXIMATION_ORDER: Quantity = Quantity {
    name: "approximation-order",
    means: "the order n at which the error of a printed approximation, eq N's right side \
            against a quantity of the catalogue (exact), vanishes as the tilt alpha_0 goes to \
            0: |eq N - exact| proportional to alpha_0^n",
    unit: "order",
    method: Method::Asymptotic,
    tolerance: order,
    how: "eq N's right side as printed, at k, alpha_0 and b = (b/a) a for the disk a = g = m = 1 \
          (Omega_0, where it appears, bound to steady-precession-rate), against the exact \
          quantity from the models at alpha_0 = 1e-1, 3e-2, 1e-2, 3e-3 and 1e-3 rad; n the \
          slope of log |error| against log alpha_0 (least squares)",
    parameters: &[
        Parameter {
            name: "equation",
            means: "the number of the printed approximation (its right side is evaluated)",
            kind: Kind::Number {
                unit: "equation",
                above: 0.0,
                below: 86.0,
                whole: true,
            },
            default: None,
        },
        Parameter {
            name: "exact",
            means: "the quantity of the catalogue that eq N approximates, at the same k, alpha_0 \
                    and b/a",
            kind: Kind::Choice(EXACT),
            default: None,
        },
        K,
        B_OVER_A,
    ],
    compute: fitted_order,
};

/// [`APPROXIMATION_ORDER`]: the errors at [`TILTS`] and their fitted order.
fn fitted_order(v: &Values, b: &Bench) -> Computed {
    let n = v.number("equation") as u32;
    let exact = v.word("exact");
    let Some(q) = super::find(exact) else {
        return super::threshold::not_located(format!("`{exact}` is not in the catalogue"));
    };
    let (k, b_over_a) = (v.number("k"), v.number("b_over_a"));
    let at = |alpha0: f64| {
        Values(vec![
            ("k", Value::Number(k)),
            ("alpha0", Value::Number(alpha0)),
            ("b_over_a", Value::Number(b_over_a)),
        ])
    };
    let mut errors = Vec::with_capacity(TILTS.len());
    for alpha0 in TILTS {
        let reference = (q.compute)(&at(alpha0), b).value;
        let omega0 = (super::steady::STEADY_PRECESSION_RATE.compute)(&at(alpha0), b).value;
        let bind = paper::Bindings::new()
            .scalar("k", k)
            .scalar("alpha_0", alpha0)
            .scalar("b", b_over_a)
            .scalar("a", 1.0)
            .scalar("g", 1.0)
            .scalar("m", 1.0)
            .scalar("Omega_0", omega0);
        let printed = match b.paper.right_side(n, &bind) {
            Ok(x) => x,
            Err(e) => {
                return super::threshold::not_located(format!(
                    "eq {n}'s right side cannot be evaluated at k, $\\alpha_0$, b, $a = g = m = 1$ and \
                     $\\Omega_0$: {e}"
                ))
            }
        };
        if !reference.is_finite() {
            return super::threshold::not_located(format!(
                "{exact} at $\\alpha_0 = {alpha0}$ rad could not be computed"
            ));
        }
        errors.push((printed - reference).abs());
    }
    let order = numerics::fit::log_log_slope(&TILTS, &errors);
    Computed {
        value: order,
        at: format!(
            "eq {n} against {exact} at $k = {k}$, $b/a = {b_over_a}$: |error| {:.3e} at $\\alpha_0 =$ \
             0.1 rad, {:.3e} at 1e-3 rad",
            errors[0], errors[4]
        ),
        series: Some((TILTS.to_vec(), errors)),
    }
}

/// The tolerance of a fitted order.
fn order(_: &Bench) -> Tolerance {
    Tolerance::order()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn values(n: f64, exact: &'static str) -> Values {
        Values(vec![
            ("equation", Value::Number(n)),
            ("exact", Value::Word(exact)),
            ("k", Value::Number(0.25)),
            ("b_over_a", Value::Number(0.0)),
        ])
    }

    /// Eq 56's limit sqrt(3k/(k+1)) is approached at second order in alpha_0 (the claim
    /// `limits-eq55-eq71` says so and its check finds it); eq 55, exact at b = 0 for every tilt,
    /// has no order: its error is round-off.
    #[test]
    fn eq56_is_second_order_and_eq55_is_exact_at_b_0() {
        let c = fitted_order(&values(56.0, "nutation-ratio"), &Bench::default());
        assert!((c.value - 2.0).abs() < 0.1, "{c:?}");
        let c = fitted_order(&values(55.0, "nutation-ratio"), &Bench::default());
        let (_, errors) = c.series.expect("a series");
        assert!(errors.iter().all(|e| *e < 1e-8), "{errors:?}");
    }
}
