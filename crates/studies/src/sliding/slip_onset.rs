//! Eq 42 against integration: the friction steady motion with $b > 0$ needs, and where the
//! sliding model actually starts to slip.
//!
//! Eq 42 (small $b$): the friction needed is $\mu \approx b/(a k\sin\alpha_0)$, so a table with
//! coefficient $\mu$ holds steady motions up to $b_{42} = \mu\,a k\sin\alpha_0$. The exact
//! steady force is $-mb\Omega_0^2\hat{\mathbf r}$ with $mg$ vertical (see
//! `equations/slippage.rs`), so the exact limit solves $b\,\Omega_0^2(b) = \mu g$ with
//! $\Omega_0^2$ from eq 29. The study finds the limit by integration instead: the largest $b$ for
//! which the sliding model started in that steady roll keeps rolling for [`super::WATCH`]
//! seconds, by bisection to $10^{-9}a$.

use super::slips;
use numerics::oscillation::bisect_to_width;
use physics::disk::Disk;
use serde::Serialize;

/// The slip limit at one tilt and one $\mu$.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, schemars::JsonSchema)]
pub struct SlipOnset {
    /// Coulomb's coefficient.
    pub mu: f64,
    /// The steady tilt (rad).
    pub alpha0: f64,
    /// Eq 42's largest $b$, $\mu a k\sin\alpha_0$ (m).
    pub b_eq42: f64,
    /// The largest $b$ that rolls without slipping in the sliding model (m).
    pub b_integrated: f64,
    /// $(b_{42} - b_{\rm integrated})/b_{\rm integrated}$.
    pub relative_error: f64,
}

/// The slip limit of disk `d` at tilt `alpha0` on a table with coefficient `mu`; `None` when
/// the bracket cannot be built (no steady motion slips below $10\,b_{42}$).
pub fn slip_onset(d: &Disk, alpha0: f64, mu: f64) -> Option<SlipOnset> {
    let b_eq42 = mu * d.a * d.k * alpha0.sin();
    let hi = 10.0 * b_eq42;
    if !slips(d, alpha0, hi, mu)? {
        return None;
    }
    let b_integrated = bisect_to_width(0.0, hi, 1e-9 * d.a, |b| slips(d, alpha0, b, mu))?;
    Some(SlipOnset {
        mu,
        alpha0,
        b_eq42,
        b_integrated,
        relative_error: (b_eq42 - b_integrated) / b_integrated,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use physics::model::steady::precession_squared;

    #[test]
    fn the_integrated_limit_is_the_exact_steady_one_and_eq42_is_its_small_b_form() {
        let d = physics::disk::toy_disk();
        for (alpha0, mu) in [(0.3, 0.05), (0.3, 0.3), (1.0, 0.3)] {
            let s = slip_onset(&d, alpha0, mu).unwrap();
            // At the integrated limit the exact steady friction ratio b Omega0^2 / g is mu.
            let needed = s.b_integrated * precession_squared(&d, alpha0, s.b_integrated) / d.g;
            assert!(
                (needed - mu).abs() < 1e-6 * mu,
                "alpha0 {alpha0} mu {mu}: needed {needed} at b {}",
                s.b_integrated
            );
        }
        // Eq 42 is the small-b form: its error is of order 1 in b/a, so it shrinks in
        // proportion to the limit itself.
        let small = slip_onset(&d, 0.3, 0.01).unwrap();
        let large = slip_onset(&d, 0.3, 0.05).unwrap();
        let ratio = large.relative_error / small.relative_error;
        let b_ratio = large.b_integrated / small.b_integrated;
        assert!(
            (ratio / b_ratio - 1.0).abs() < 0.1,
            "error ratio {ratio} for a b ratio {b_ratio}: {small:?} {large:?}"
        );
    }
}
