//! The two-mechanism law: the spin-down obeys eq 79 with one exponent $\beta_1$ while
//! $\Omega < \Omega_c$ and with another, $\beta_2$, once $\Omega > \Omega_c$ (sec. 11's mechanisms
//! taking over from each other as the disk speeds up), fitted to the same cycles as eq 84 so that
//! it can be ranked against the single laws by AIC/BIC ([`models`](crate::fit::law_choice)).
//!
//! In terms of the time left, eq 84 reads $t_0 - t = C\,\Omega^{-(\beta+2)}$, so
//! $\dot\Omega = \Omega^{\beta+3}/((\beta+2)C)$ (eq 85's form). The crossover law is
//! $$t_0 - t = C_2\,\Omega^{-(\beta_2+2)} \quad (\Omega \ge \Omega_c), \qquad
//!   t_0' - t = C_1\,\Omega^{-(\beta_1+2)} \quad (\Omega < \Omega_c),$$
//! joined at $t_c = t_0 - C_2\Omega_c^{-(\beta_2+2)}$ with $\Omega$ and $\dot\Omega$ both
//! continuous there, which fixes
//! $$C_1 = C_2\,\frac{\beta_2+2}{\beta_1+2}\,\Omega_c^{\beta_1-\beta_2}, \qquad
//!   t_0' = t_c + C_1\,\Omega_c^{-(\beta_1+2)}.$$
//! Five parameters $(\beta_1, \beta_2, t_0, \ln C_2, \ln\Omega_c)$. Each branch is eq 79 with its
//! own constants, so the heading $\Phi$ is the closed form of [`fit`](crate::fit::eq84_85) on
//! each side, offset to be continuous at $t_c$, and the datum of a cycle is compared with the law's
//! own cycle mean $(t_b - t_a)/(\Phi(t_b) - \Phi(t_a))$, as for eq 84.
//!
//! The gradient is taken by central differences (the branch point moves with the parameters,
//! which makes the analytic one long and error-prone); the errors' covariance is eq 84's.

use crate::fit::band::Row;
use crate::fit::eq84_85::{cycle_row, phase, Eq84Fit};
use crate::fit::least_squares::{solve, FitError, Problem, Scale};
use nalgebra::SVector;
use serde::Serialize;
use std::f64::consts::PI;

/// The fitted crossover law.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CrossoverFit {
    /// $\beta_1$, below $\Omega_c$.
    pub beta_below: f64,
    /// Its standard uncertainty.
    pub beta_below_sigma: f64,
    /// $\beta_2$, above $\Omega_c$.
    pub beta_above: f64,
    /// Its standard uncertainty.
    pub beta_above_sigma: f64,
    /// $\Omega_c$ (rad/s).
    pub omega_c: f64,
    /// Its standard uncertainty (rad/s).
    pub omega_c_sigma: f64,
    /// $t_0$ (s), where the law above $\Omega_c$ ends.
    pub t0: f64,
    /// Its standard uncertainty (s).
    pub t0_sigma: f64,
    /// Whitened $\chi^2$ (unscaled).
    pub chi2: f64,
    /// $\ln\det\Sigma$ at the solution.
    pub ln_det_sigma: f64,
    /// Points fitted.
    pub n: usize,
    /// $\sum_i (y_i - \hat y_i)^2$ of $y_i = 1/\Omega_i$ at the solution (s^2), unweighted as
    /// the plausibility checks' $R^2$ takes it.
    pub residual_ss: f64,
}

/// The law on cycles $[t_a, t_b]$, times counted from the record's first fitted peak (so that
/// an absolute clock, such as epoch seconds, costs no precision).
struct Crossover<'a> {
    ta: &'a [f64],
    tb: &'a [f64],
    y: &'a [f64],
    start: &'a [usize],
    /// The span of the fitted times, $t_b^{last} - t_a^{first}$: the scale of $t_0$'s
    /// difference step, so that the gradient does not depend on the unit of time.
    span: f64,
    /// The range of the data's rates: $\Omega_c$ must fall inside it.
    omega_range: (f64, f64),
}

/// $\Phi(t)$ and $\Omega(t)$ of the crossover law with parameters
/// `p` = $(\beta_1, \beta_2, t_0, \ln C_2, \ln\Omega_c)$.
pub fn heading(p: &SVector<f64, 5>, t: f64) -> (f64, f64) {
    let (b1, b2, t0, ln_c2, ln_wc) = (p[0], p[1], p[2], p[3], p[4]);
    let tc = t0 - (ln_c2 - (b2 + 2.0) * ln_wc).exp();
    let above = SVector::<f64, 3>::new(b2, t0, ln_c2);
    if t >= tc {
        let (phi, omega, _) = phase(&above, t);
        return (phi, omega);
    }
    let ln_c1 = ln_c2 + ((b2 + 2.0) / (b1 + 2.0)).ln() + (b1 - b2) * ln_wc;
    let t0_below = tc + (ln_c1 - (b1 + 2.0) * ln_wc).exp();
    let below = SVector::<f64, 3>::new(b1, t0_below, ln_c1);
    let offset = phase(&above, tc).0 - phase(&below, tc).0;
    let (phi, omega, _) = phase(&below, t);
    (phi + offset, omega)
}

impl Crossover<'_> {
    fn mean(&self, p: &SVector<f64, 5>, i: usize) -> (f64, f64, f64, f64) {
        let (pa, oa) = heading(p, self.ta[i]);
        let (pb, ob) = heading(p, self.tb[i]);
        let dphi = pb - pa;
        ((self.tb[i] - self.ta[i]) / dphi, dphi, oa, ob)
    }
}

impl Problem<5> for Crossover<'_> {
    fn y(&self) -> &[f64] {
        self.y
    }
    fn model(&self, p: &SVector<f64, 5>, i: usize) -> (f64, SVector<f64, 5>) {
        let m = self.mean(p, i).0;
        let mut g = SVector::<f64, 5>::zeros();
        for k in 0..5 {
            let h = if k == 2 {
                1e-6 * self.span
            } else {
                1e-6 * p[k].abs().max(1.0)
            };
            let (mut up, mut down) = (*p, *p);
            up[k] += h;
            down[k] -= h;
            g[k] = (self.mean(&up, i).0 - self.mean(&down, i).0) / (2.0 * h);
        }
        (m, g)
    }
    fn value(&self, p: &SVector<f64, 5>, i: usize) -> f64 {
        self.mean(p, i).0
    }
    fn rows(&self, p: &SVector<f64, 5>) -> Vec<Row> {
        (0..self.y.len())
            .map(|i| {
                let (_, dphi, oa, ob) = self.mean(p, i);
                cycle_row(self.start[i], self.tb[i] - self.ta[i], dphi, oa, ob)
            })
            .collect()
    }
    fn admissible(&self, p: &SVector<f64, 5>) -> bool {
        let tmax = self.tb.iter().copied().fold(f64::MIN, f64::max);
        let wc = p[4].exp();
        p.iter().all(|v| v.is_finite())
            && (-0.9..50.0).contains(&p[0])
            && (-0.9..50.0).contains(&p[1])
            && p[2] > tmax
            && wc > self.omega_range.0
            && wc < self.omega_range.1
    }
}

/// Fits the crossover law to eq 84's cycles, started from the free fit `free` with
/// $\Omega_c$ at a third and two thirds of the data's (logarithmic) range of rates and the two
/// exponents 0.5 apart either way; the start with the least $\chi^2$ wins.
pub fn fit_crossover(
    ta: &[f64],
    tb: &[f64],
    start: &[usize],
    w: &[f64],
    free: &Eq84Fit,
) -> Result<CrossoverFit, FitError> {
    let n = ta.len();
    FitError::at_least("cycles", n, 10, " for five parameters")?;
    // Times from the first fitted peak: the fit is the same whatever the clock's origin.
    let origin = ta[0];
    let ta: Vec<f64> = ta.iter().map(|t| t - origin).collect();
    let tb: Vec<f64> = tb.iter().map(|t| t - origin).collect();
    let (ta, tb) = (&ta[..], &tb[..]);
    let y: Vec<f64> = ta
        .iter()
        .zip(tb)
        .map(|(a, b)| (b - a) / (2.0 * PI))
        .collect();
    let rates: Vec<f64> = y.iter().map(|v| 1.0 / v).collect();
    let lo = rates.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = rates.iter().copied().fold(0.0, f64::max);
    let pr = Crossover {
        ta,
        tb,
        y: &y,
        start,
        omega_range: (lo, hi),
        span: tb[n - 1] - ta[0],
    };
    let mut best: Option<crate::fit::least_squares::Solved<5>> = None;
    let mut last_err = FitError::Shape("no start");
    for frac in [1.0 / 3.0, 2.0 / 3.0] {
        let ln_wc = lo.ln() + frac * (hi / lo).ln();
        // The free law's time left at Omega_c, continued by the branch above.
        let ln_tau_c = free.ln_c - (free.beta + 2.0) * ln_wc;
        for d in [-0.25, 0.25] {
            let (b1, b2) = (free.beta - d, free.beta + d);
            let p0 = SVector::<f64, 5>::from_column_slice(&[
                b1,
                b2,
                free.t0 - origin,
                ln_tau_c + (b2 + 2.0) * ln_wc,
                ln_wc,
            ]);
            match solve(&pr, w, p0, Scale::Stationary) {
                Ok(s) if best.as_ref().is_none_or(|b| s.chi2 < b.chi2) => best = Some(s),
                Ok(_) => {}
                Err(e) => last_err = e,
            }
        }
    }
    let s = best.ok_or(last_err)?;
    let wc = s.p[4].exp();
    let residual_ss = (0..n).map(|i| (y[i] - pr.mean(&s.p, i).0).powi(2)).sum();
    Ok(CrossoverFit {
        beta_below: s.p[0],
        beta_below_sigma: s.cov[(0, 0)].sqrt(),
        beta_above: s.p[1],
        beta_above_sigma: s.cov[(1, 1)].sqrt(),
        omega_c: wc,
        omega_c_sigma: wc * s.cov[(4, 4)].sqrt(),
        t0: s.p[2] + origin,
        t0_sigma: s.cov[(2, 2)].sqrt(),
        chi2: s.chi2,
        ln_det_sigma: s.ln_det_sigma,
        n,
        residual_ss,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// With equal exponents the crossover law is eq 79 itself, wherever $\Omega_c$ is.
    #[test]
    fn equal_exponents_give_back_eq_79() {
        let (beta, t0, ln_c) = (2.0, 10.0, (7e8f64).ln());
        let single = SVector::<f64, 3>::new(beta, t0, ln_c);
        let p = SVector::<f64, 5>::from_column_slice(&[beta, beta, t0, ln_c, 200f64.ln()]);
        for t in [3.0, 6.0, 9.0, 9.9] {
            let (a, b) = (heading(&p, t), phase(&single, t));
            assert!((a.0 - b.0).abs() < 1e-9 * b.0.abs(), "{t}: {a:?} {b:?}");
            assert!((a.1 - b.1).abs() < 1e-9 * b.1, "{t}");
        }
    }

    /// $\Omega$ and $\dot\Omega$ are continuous at the crossover, and each side follows its own
    /// exponent: $d\ln\dot\Omega/d\ln\Omega = \beta + 3$.
    #[test]
    fn the_rate_and_its_derivative_are_continuous_at_omega_c() {
        // C2 = 1e12, Omega_c = 100: t_c = t0 - 1 s; below, C1 = 2e6 and t0' = t_c + 2 s.
        let (b1, b2, t0, ln_c2, wc) = (1.0, 4.0, 10.0, (1e12f64).ln(), 100.0);
        let p = SVector::<f64, 5>::from_column_slice(&[b1, b2, t0, ln_c2, f64::ln(wc)]);
        let tc = t0 - 1.0;
        let w = |t: f64| heading(&p, t).1;
        assert!((w(tc - 1e-9) / wc - 1.0).abs() < 1e-6 && (w(tc + 1e-9) / wc - 1.0).abs() < 1e-6);
        let rate = |t: f64| (w(t + 1e-5) - w(t - 1e-5)) / 2e-5;
        let (rb, ra) = (rate(tc - 1e-3), rate(tc + 1e-3));
        assert!((rb / ra - 1.0).abs() < 0.01, "{rb} {ra}");
        let slope = |t1: f64, t2: f64| (rate(t2) / rate(t1)).ln() / (w(t2) / w(t1)).ln();
        let (below, above) = (slope(tc - 3.0, tc - 0.5), slope(tc + 0.1, tc + 0.6));
        assert!((below - (b1 + 3.0)).abs() < 1e-3, "{below}");
        assert!((above - (b2 + 3.0)).abs() < 1e-3, "{above}");
    }
}
