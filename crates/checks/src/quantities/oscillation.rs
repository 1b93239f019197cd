//! Small oscillations about steady rolling: the nutation frequency $\varpi$, in $\sqrt{g/a}$
//! and over the precession rate.

use super::steady::{derived_tolerance, steady_state};
use super::threshold::not_located;
use super::{Computed, Quantity, Values, ALPHA0, B_OVER_A, K};
use crate::finding::Method;
use crate::harness::Bench;
use physics::model::rolling;

/// `nutation-frequency`.
pub(super) const NUTATION_FREQUENCY: Quantity = Quantity {
    name: "nutation-frequency",
    means: "the angular frequency varpi of small oscillations about the steady rolling motion \
            at tilt alpha_0 and radius b",
    unit: "sqrt(g/a)",
    method: Method::Linearization,
    tolerance: derived_tolerance,
    how: "varpi^2 = -tr(J^2)/2, J the exact Jacobian (dual numbers) of the rolling model's eqs \
          23-25 at the steady motion of steady-precession-rate (its eigenvalues: 0, 0 and \
          +-i varpi); never eq 54's closed form",
    parameters: &[K, ALPHA0, B_OVER_A],
    compute: frequency,
};

/// `nutation-ratio`.
pub(super) const NUTATION_RATIO: Quantity = Quantity {
    name: "nutation-ratio",
    means: "varpi / |Omega_0|, the nutation frequency over the precession rate of the steady \
            rolling motion at tilt alpha_0 and radius b",
    unit: "1",
    method: Method::Linearization,
    tolerance: derived_tolerance,
    how: "nutation-frequency over |steady-precession-rate|, both from the rolling model's eqs \
          23-25; never eqs 54-58's closed forms",
    parameters: &[K, ALPHA0, B_OVER_A],
    compute: ratio,
};

/// $\varpi$ and $\Omega_0$ at the steady motion, or why there is no oscillation.
fn varpi(v: &Values) -> Result<(f64, f64, String), String> {
    let (disk, m, at) = steady_state(v)?;
    let j = rolling::jacobian(&disk, &[m.alpha, m.alpha_dot, m.precession, m.spin]);
    let varpi2 = -(j * j).trace() / 2.0;
    if varpi2 <= 0.0 {
        return Err(format!(
            "{at}; the steady motion is unstable there $(\\varpi^{{2}} = {varpi2:.6e} \\leq  0)$: it has no \
             oscillation frequency"
        ));
    }
    Ok((varpi2.sqrt(), m.precession, at))
}

/// [`NUTATION_FREQUENCY`].
fn frequency(v: &Values, _: &Bench) -> Computed {
    match varpi(v) {
        Ok((w, _, at)) => Computed {
            value: w,
            at: format!("{at}; $\\varpi$ from the exact Jacobian"),
            series: None,
        },
        Err(why) => not_located(why),
    }
}

/// [`NUTATION_RATIO`].
fn ratio(v: &Values, _: &Bench) -> Computed {
    match varpi(v) {
        Ok((w, om, at)) => Computed {
            value: w / om.abs(),
            at: format!("{at}; $\\varpi = {w:.9} \\sqrt{{g/a}}$ from the exact Jacobian"),
            series: None,
        },
        Err(why) => not_located(why),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::quantities::Value;

    /// Eq 56's small-tilt limit sqrt(3k/(k+1)) (compared here, never used) is approached.
    #[test]
    fn the_ratio_tends_to_eq56s_limit() {
        let k = 0.25;
        let r = ratio(
            &Values(vec![
                ("k", Value::Number(k)),
                ("alpha0", Value::Number(1e-3)),
                ("b_over_a", Value::Number(0.0)),
            ]),
            &Bench::default(),
        )
        .value;
        assert!((r - (3.0 * k / (k + 1.0)).sqrt()).abs() < 1e-3, "{r}");
    }
}
