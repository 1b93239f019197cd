//! Eq 43 with a realistic $\mu$: does steady motion with $b < 0$ survive?
//!
//! Eq 30 allows $b$ down to $b_{\rm edge} = -a k\cos\alpha_0/(2k+1)$; eq 43 says
//! $\mu \ge \cot\alpha_0/(2k+1)$ suffices for all of them. Exactly (see `equations/slippage.rs`,
//! eq 43) the friction needed at $b = \beta b_{\rm edge}$ is
//! $\mu_* = \frac{\beta}{1-\beta}\frac{\cot\alpha_0}{2k+1}$, so a table with coefficient $\mu$
//! holds only $\beta \le \beta_{\max} = \mu / (\mu + \cot\alpha_0/(2k+1))$. The study finds
//! $\beta_{\max}$ by integration: the largest fraction of the edge at which the sliding model
//! started in that steady roll keeps rolling for [`super::WATCH`] seconds (bisection to 1e-9).

use super::slips;
use numerics::oscillation::bisect_to_width;
use physics::disk::Disk;
use serde::Serialize;

/// How much of the negative-$b$ range survives one $\mu$ at one tilt.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, schemars::JsonSchema)]
pub struct NegativeB {
    /// Coulomb's coefficient.
    pub mu: f64,
    /// The steady tilt (rad).
    pub alpha0: f64,
    /// Eq 30's edge $b_{\rm edge}$ (m).
    pub b_edge: f64,
    /// Eq 43's bound $\cot\alpha_0/(2k+1)$.
    pub mu_eq43: f64,
    /// The largest $b/b_{\rm edge}$ that rolls without slipping, by integration.
    pub beta_integrated: f64,
    /// The same from the exact steady force, $\mu/(\mu + \cot\alpha_0/(2k+1))$.
    pub beta_exact: f64,
}

/// The surviving fraction of negative $b$ for disk `d` at `alpha0` with coefficient `mu`.
pub fn negative_b(d: &Disk, alpha0: f64, mu: f64) -> Option<NegativeB> {
    let k = d.k;
    let b_edge = physics::model::steady::b_bound(d, alpha0);
    // The friction the exact steady force needs at half the edge, which eq 43 happens to print
    // (derived from the model's contact force: mu >= beta cot(alpha0) / ((2k+1)(1 - beta)) at
    // b = beta b_edge).
    let mu_eq43 = 1.0 / alpha0.tan() / (2.0 * k + 1.0);
    let beta_integrated = bisect_to_width(0.0, 0.999_999, 1e-9, |beta| {
        slips(d, alpha0, beta * b_edge, mu)
    })?;
    Some(NegativeB {
        mu,
        alpha0,
        b_edge,
        mu_eq43,
        beta_integrated,
        beta_exact: mu / (mu + mu_eq43),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_realistic_table_holds_only_a_small_part_of_the_negative_b_range() {
        let d = physics::disk::toy_disk();
        for (alpha0, mu) in [(0.3, 0.3), (0.3, 1.0), (1.0, 0.3)] {
            let n = negative_b(&d, alpha0, mu).unwrap();
            assert!((n.beta_integrated - n.beta_exact).abs() < 1e-6, "{n:?}");
        }
        // At alpha0 = 0.3, mu = 0.3 (a realistic table) only about 12 % of the range survives.
        let n = negative_b(&d, 0.3, 0.3).unwrap();
        assert!(n.beta_integrated < 0.15 && n.mu < n.mu_eq43, "{n:?}");
    }
}
