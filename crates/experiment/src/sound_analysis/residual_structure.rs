//! Whether the phase fit's residuals show structure: eq 79's heading does not hold over the
//! record as the fit states it.
//!
//! The blocks' whitened residuals $e_k = r_k/\sigma_k$ of a law that holds are independent noise
//! about zero; a nuisance that moves the heading smoothly (a bump, clipping, reverb, the law's
//! own failure near $t_0$) leaves them correlated from block to block. Two tests read it, each
//! one-sided (structure makes neighbours alike, never less alike than noise):
//!
//! - the lag-one autocorrelation
//!   $$\hat\rho = \frac{\sum_{k=1}^{n-1} (e_k - \bar e)(e_{k+1} - \bar e)}{\sum_{k=1}^{n} (e_k - \bar e)^2},$$
//!   which for independent noise is $-1/n$ with standard deviation $1/\sqrt n$, read as
//!   $z_\rho = (\hat\rho + 1/n)\sqrt n$;
//! - the runs of sign (Wald-Wolfowitz): with $n_+$ residuals $\ge 0$ and $n_-$ below, the number
//!   of runs $R$ of independent noise has mean $\mu = 2n_+n_-/n + 1$ and variance
//!   $2n_+n_-(2n_+n_- - n)/(n^2(n-1))$, read as $z_R = (R - \mu)/\sigma_R$.
//!
//! The residuals show structure where $z_\rho > $ [`STRUCTURE_SIGMAS`] or
//! $z_R < -$[`STRUCTURE_SIGMAS`]; below [`MIN_BLOCKS`] blocks neither is read.

use serde::Serialize;
use std::fmt;

/// How far (in standard deviations of independent noise) a test must stand for the residuals to
/// show structure: 3, so that a law that holds is called in doubt by either test on about
/// 0.27 % of records.
pub const STRUCTURE_SIGMAS: f64 = 3.0;

/// Fewest blocks for the tests to be read (their normal approximations need about ten).
pub const MIN_BLOCKS: usize = 10;

/// The two tests of a fit's whitened residuals.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Structure {
    /// The residuals tested.
    pub n: usize,
    /// $\hat\rho$, the lag-one autocorrelation.
    pub lag_one: f64,
    /// $z_\rho$.
    pub lag_one_z: f64,
    /// $R$, the runs of sign.
    pub runs: usize,
    /// $\mu$, the runs independent noise gives.
    pub runs_expected: f64,
    /// $z_R$.
    pub runs_z: f64,
}

impl Structure {
    /// The tests of residuals `r` with standard uncertainties `sigma`; `None` below
    /// [`MIN_BLOCKS`] or where a residual or sigma is not finite or a sigma is not positive.
    pub fn of(r: &[f64], sigma: &[f64]) -> Option<Self> {
        let n = r.len();
        if n < MIN_BLOCKS || sigma.len() != n {
            return None;
        }
        let e: Vec<f64> = r.iter().zip(sigma).map(|(r, s)| r / s).collect();
        if e.iter().any(|x| !x.is_finite()) || sigma.iter().any(|s| *s <= 0.0) {
            return None;
        }
        let nf = n as f64;
        let lag_one = numerics::autocorrelation::lag_one(&e);
        let plus = e.iter().filter(|x| **x >= 0.0).count() as f64;
        let minus = nf - plus;
        let runs = 1 + e
            .windows(2)
            .filter(|w| (w[0] >= 0.0) != (w[1] >= 0.0))
            .count();
        let pm = 2.0 * plus * minus;
        let runs_expected = pm / nf + 1.0;
        let var = pm * (pm - nf) / (nf * nf * (nf - 1.0));
        let runs_z = if var > 0.0 {
            (runs as f64 - runs_expected) / var.sqrt()
        } else {
            // All of one sign: one run, as far from noise as the record can show.
            -nf.sqrt()
        };
        Some(Structure {
            n,
            lag_one,
            lag_one_z: (lag_one + 1.0 / nf) * nf.sqrt(),
            runs,
            runs_expected,
            runs_z,
        })
    }

    /// Whether either test stands beyond [`STRUCTURE_SIGMAS`].
    pub fn shown(&self) -> bool {
        self.lag_one_z > STRUCTURE_SIGMAS || self.runs_z < -STRUCTURE_SIGMAS
    }
}

impl fmt::Display for Structure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "lag-one autocorrelation {:.2} ({:+.1} sigma), {} runs of sign where noise gives {:.1} ({:+.1} sigma), of {} residuals",
            self.lag_one, self.lag_one_z, self.runs, self.runs_expected, self.runs_z, self.n
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Independent noise shows no structure; a smooth drift under the same noise does, by both
    /// tests; an alternating sequence (anti-correlated) is not structure.
    #[test]
    fn noise_passes_and_a_drift_is_structure() {
        let mut state: u64 = 0x2545_F491_4F6C_DD1D;
        let mut noise = || {
            // Sum of 12 uniforms: near-normal, unit variance.
            (0..12)
                .map(|_| {
                    state ^= state << 13;
                    state ^= state >> 7;
                    state ^= state << 17;
                    (state >> 11) as f64 / (1u64 << 53) as f64
                })
                .sum::<f64>()
                - 6.0
        };
        let n = 80;
        let white: Vec<f64> = (0..n).map(|_| noise()).collect();
        let sigma = vec![1.0; n];
        let s = Structure::of(&white, &sigma).unwrap();
        assert!(!s.shown(), "{s}");
        let drift: Vec<f64> = white
            .iter()
            .enumerate()
            .map(|(k, e)| e + 3.0 * (k as f64 / n as f64 * std::f64::consts::TAU).sin())
            .collect();
        let d = Structure::of(&drift, &sigma).unwrap();
        assert!(d.lag_one_z > STRUCTURE_SIGMAS, "{d}");
        assert!(d.runs_z < -STRUCTURE_SIGMAS, "{d}");
        assert!(d.shown());
        let alternating: Vec<f64> = (0..n)
            .map(|k| if k % 2 == 0 { 1.0 } else { -1.0 })
            .collect();
        let a = Structure::of(&alternating, &sigma).unwrap();
        assert!(!a.shown(), "{a}");
        assert_eq!(a.runs, n);
        assert!(Structure::of(&white[..MIN_BLOCKS - 1], &sigma[..MIN_BLOCKS - 1]).is_none());
    }
}
