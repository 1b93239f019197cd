//! Fits with uncertainties where the paper drew lines.
//!
//! **Eq 84.** $1/\Omega = \left((t_0 - t)/C\right)^{1/(\beta+2)}$, fitted for
//! $(\beta, t_0, \ln C)$ jointly by Levenberg-Marquardt on the whitened residuals (see
//! [`band`](crate::fit::band)). $\Omega_i = 2\pi/(t_{i+1} - t_i)$ is a mean over a cycle,
//! so the datum $1/\Omega_i$ is compared with the law's mean over the same cycle,
//! $(t_{i+1} - t_i)/(\Phi(t_{i+1}) - \Phi(t_i))$ with $\Phi = \int\Omega\,dt$ of eq 79; when the
//! cycles are short against $t_0 - t$ this is eq 84 at the cycle's middle. The residual
//! $r_i = \Delta_i/2\pi - \Delta_i/\Delta\Phi_i$ depends on $t_i$ and $t_{i+1}$, and its
//! covariance is propagated from theirs.
//!
//! **Eq 85.** $d\Omega/dt = K\,\Omega^{s}$ with $s = \beta + 3$, the slope of
//! $\log(d\Omega/dt)$ against $\log\Omega$. Fitted in linear space (the logarithm of a noisy
//! $d\Omega_i/dt$ is biased, and undefined where noise makes it negative), with the covariance
//! of the rows, which share peaks, propagated from $t_i, t_{i+1}, t_{i+2}$ in the same way.
//!
//! Both are minimised by [`least_squares::solve`](crate::fit::least_squares::solve),
//! whose covariance is the sandwich with the whitened residuals' stationary covariance (see
//! there): the peak-time variances weight and whiten, the residuals give the errors' common size
//! ($\chi^2$/dof) and their correlation.

use crate::fit::band::Row;
use crate::fit::law_fit::LawFit;
use crate::fit::least_squares::{solve, FitError, Problem, Scale, Solved};
use nalgebra::SVector;
use serde::Serialize;
use std::f64::consts::PI;

/// A point of a fit, kept for plotting.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FitPoint {
    /// The abscissa: $\bar t_i$ (s) for eq 84, $\Omega$ (rad/s) for eq 85.
    pub x: f64,
    /// The datum: $1/\Omega_i$ (s) for eq 84, $d\Omega_i/dt$ (rad/s^2) for eq 85.
    pub y: f64,
    /// The fitted curve there.
    pub model: f64,
    /// $y$ - model.
    pub residual: f64,
    /// The whitened residual (unit variance when the noise model holds).
    pub normalized: f64,
}

/// The fit of eq 84.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Eq84Fit {
    /// Eq 79's $\beta$, $t_0$ and $\ln C$ with their uncertainties, read as this fit's own
    /// fields.
    #[serde(flatten)]
    pub parameters: LawFit,
    /// $C^{-1/(\beta+2)}$ = $1/\Omega$ one second before $t_0$ (s): the paper's $C^{-1/4} = 0.0055$.
    pub inv_omega_1s: f64,
    /// Its standard uncertainty (s).
    pub inv_omega_1s_sigma: f64,
    /// Covariance of $(\beta, t_0, \ln C)$.
    pub covariance: [[f64; 3]; 3],
    /// Reduced $\chi^2$ = $s^2$.
    pub reduced_chi2: f64,
    /// Whitened $\chi^2$ (unscaled).
    pub chi2: f64,
    /// $\ln\det\Sigma$ at the solution.
    pub ln_det_sigma: f64,
    /// Points fitted.
    pub n: usize,
    /// Data, curve and residuals.
    pub points: Vec<FitPoint>,
}

/// The fit of eq 85.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Eq85Fit {
    /// The slope $s = \beta + 3$.
    pub slope: f64,
    /// Its standard uncertainty.
    pub slope_sigma: f64,
    /// $\beta = s - 3$.
    pub beta: f64,
    /// Its standard uncertainty (that of $s$).
    pub beta_sigma: f64,
    /// $\ln K$ at the reference rate `omega_ref`: $d\Omega/dt = e^{\ln K}(\Omega/\Omega_{ref})^s$.
    pub ln_k: f64,
    /// The reference rate (rad/s), the geometric mean of the data's.
    pub omega_ref: f64,
    /// Reduced $\chi^2$.
    pub reduced_chi2: f64,
    /// Points fitted.
    pub n: usize,
    /// Data, curve and residuals.
    pub points: Vec<FitPoint>,
}

/// Eq 84 on cycles $[t_a, t_b]$: data $1/\Omega_i = (t_b - t_a)/2\pi$, compared with the law's
/// own cycle average $(t_b - t_a)/(\Phi(t_b) - \Phi(t_a))$, $\Phi$ the heading of eq 79
/// integrated (see [`law`](crate::synthetic::law)), so that placing a mean rate at a point costs
/// no bias however fast $\Omega$ changes.
struct Law84<'a> {
    ta: &'a [f64],
    tb: &'a [f64],
    y: &'a [f64],
    start: &'a [usize],
}

/// $\Phi(t) = -C^{q}(t_0 - t)^{1-q}/(1-q)$ ($q = 1/(\beta+2)$), $\Omega(t)$, and the gradient of
/// $\Phi$ in $(\beta, t_0, \ln C)$.
pub(crate) fn phase(p: &SVector<f64, 3>, t: f64) -> (f64, f64, SVector<f64, 3>) {
    let q = 1.0 / (p[0] + 2.0);
    let ln_tau = (p[1] - t).ln();
    let e = (q * p[2] + (1.0 - q) * ln_tau).exp();
    let phi = -e / (1.0 - q);
    let omega = (q * (p[2] - ln_tau)).exp();
    let d_q = phi * (p[2] - ln_tau) + phi / (1.0 - q);
    (
        phi,
        omega,
        SVector::<f64, 3>::new(-q * q * d_q, -omega, q * phi),
    )
}

impl Law84<'_> {
    /// The law's cycle average of $1/\Omega$ over cycle `i`, its gradient, $\Delta\Phi$ and the
    /// rates at both ends.
    fn mean(&self, p: &SVector<f64, 3>, i: usize) -> (f64, SVector<f64, 3>, f64, f64, f64) {
        let (pa, oa, ga) = phase(p, self.ta[i]);
        let (pb, ob, gb) = phase(p, self.tb[i]);
        let (d, dphi) = (self.tb[i] - self.ta[i], pb - pa);
        let m = d / dphi;
        (m, (gb - ga) * (-m / dphi), dphi, oa, ob)
    }
}

impl Problem<3> for Law84<'_> {
    fn y(&self) -> &[f64] {
        self.y
    }
    fn model(&self, p: &SVector<f64, 3>, i: usize) -> (f64, SVector<f64, 3>) {
        let (m, g, ..) = self.mean(p, i);
        (m, g)
    }
    fn rows(&self, p: &SVector<f64, 3>) -> Vec<Row> {
        (0..self.y.len())
            .map(|i| {
                // r = d/2pi - d/dphi, d = tb - ta, dphi = Phi(tb) - Phi(ta), dPhi/dt = Omega.
                let (_, _, dphi, oa, ob) = self.mean(p, i);
                cycle_row(self.start[i], self.tb[i] - self.ta[i], dphi, oa, ob)
            })
            .collect()
    }
    fn admissible(&self, p: &SVector<f64, 3>) -> bool {
        let tmax = self.tb.iter().copied().fold(f64::MIN, f64::max);
        p.iter().all(|v| v.is_finite()) && p[0] > -0.9 && p[0] < 50.0 && p[1] > tmax
    }
}

/// The row of $B$ for a cycle of length `d` from peak `start`: the residual
/// $r = d/2\pi - d/\Delta\Phi$ differentiated in the cycle's two peak times, with
/// $\partial\Delta\Phi/\partial t_{a,b} = \mp\Omega(t_{a,b})$ (rates `oa`, `ob`).
pub(crate) fn cycle_row(start: usize, d: f64, dphi: f64, oa: f64, ob: f64) -> Row {
    let k = 0.5 / PI - 1.0 / dphi;
    Row {
        start,
        coef: vec![-k - d * oa / (dphi * dphi), k + d * ob / (dphi * dphi)],
    }
}

/// A start for eq 84's fits: over trial end times $t_0$ after `xmax`, the straight line
/// $\ln y = q(\ln(t_0 - x) - \ln C)$ fitted to the data $y = 1/\Omega$ at times `x`; the trial with
/// the least relative squared error gives $(\beta, t_0, \ln C)$.
pub(crate) fn start84(x: &[f64], y: &[f64], xmax: f64) -> Option<SVector<f64, 3>> {
    let n = x.len();
    if n < 3 {
        return None;
    }
    let xmin = x.iter().copied().fold(f64::MAX, f64::min);
    let span = (xmax - xmin).max(1e-9);
    let last_period = 2.0 * PI * y[n - 1];
    let mut best: Option<(f64, SVector<f64, 3>)> = None;
    for k in 0..80 {
        let d = 1e-2 * last_period * (1e3 * span / (1e-2 * last_period)).powf(k as f64 / 79.0);
        let t0 = xmax + d;
        let lx: Vec<f64> = x.iter().map(|x| (t0 - x).ln()).collect();
        let ly: Vec<f64> = y.iter().map(|y| y.ln()).collect();
        let (mx, my) = (mean(&lx), mean(&ly));
        let sxx: f64 = lx.iter().map(|a| (a - mx).powi(2)).sum();
        let sxy: f64 = lx.iter().zip(&ly).map(|(a, b)| (a - mx) * (b - my)).sum();
        let q = sxy / sxx;
        if !(q > 0.0 && q < 1.0 / 1.1) {
            continue;
        }
        let ln_c = mx - my / q;
        let ssr: f64 = lx
            .iter()
            .zip(y)
            .map(|(a, b)| (b - (q * (a - ln_c)).exp()).powi(2) / (b * b))
            .sum();
        if best.as_ref().is_none_or(|b| ssr < b.0) {
            best = Some((ssr, SVector::<f64, 3>::new(1.0 / q - 2.0, t0, ln_c)));
        }
    }
    best.map(|b| b.1)
}

/// Fits eq 84 to the cycles between peaks `ta[i]` and `tb[i]` (first peak `start[i]`), given
/// the peak-time variances `w` (indexed by peak).
pub fn fit_eq84(ta: &[f64], tb: &[f64], start: &[usize], w: &[f64]) -> Result<Eq84Fit, FitError> {
    let n = ta.len();
    FitError::at_least("cycles", n, 5, "")?;
    let x: Vec<f64> = ta.iter().zip(tb).map(|(a, b)| 0.5 * (a + b)).collect();
    let y: Vec<f64> = ta
        .iter()
        .zip(tb)
        .map(|(a, b)| (b - a) / (2.0 * PI))
        .collect();
    let xmax = tb.iter().copied().fold(f64::MIN, f64::max);
    let p0 = start84(&x, &y, xmax).ok_or(FitError::Shape(
        "1/Omega does not fall toward an end time: no start for the fit",
    ))?;
    let pr = Law84 {
        ta,
        tb,
        y: &y,
        start,
    };
    let s = solve(&pr, w, p0, Scale::Stationary)?;
    let (beta, ln_c) = (s.p[0], s.p[2]);
    let q = 1.0 / (beta + 2.0);
    let inv = (-q * ln_c).exp();
    // d inv / d(beta, t0, lnC) = inv * (lnC q^2, 0, -q)
    let g = SVector::<f64, 3>::new(inv * ln_c * q * q, 0.0, -inv * q);
    let var_inv = (g.transpose() * s.cov * g)[(0, 0)];
    Ok(Eq84Fit {
        parameters: LawFit::of(&s),
        inv_omega_1s: inv,
        inv_omega_1s_sigma: var_inv.sqrt(),
        covariance: std::array::from_fn(|i| std::array::from_fn(|j| s.cov[(i, j)])),
        reduced_chi2: s.s2,
        chi2: s.chi2,
        ln_det_sigma: s.ln_det_sigma,
        n,
        points: points(&x, &y, &s),
    })
}

/// Eq 85 on accelerations: rates `x` = $4\pi/(t_{i+2} - t_i)$, data `y` = $d\Omega_i/dt$, first
/// peaks `start`, all peak times `t`, peak-time variances `w`.
struct Law85<'a> {
    y: &'a [f64],
    x: &'a [f64],
    lx: Vec<f64>,
    start: &'a [usize],
    t: &'a [f64],
}

impl Law85<'_> {
    fn g(&self, p: &SVector<f64, 2>, i: usize) -> f64 {
        (p[1] + p[0] * self.lx[i]).exp()
    }

    /// The expected value of the finite-difference estimate under $\dot\Omega = K\Omega^s$:
    /// expanding the peak times in the phase to third order gives
    /// $Y = K X^s\left(1 + \tfrac{s}{12}\rho^2\right)$ (checked against exact power-law peak
    /// times in the tests), with
    /// $\rho = 2\pi\dot\Omega/\Omega^2$ the relative change of $\Omega$ over one cycle. Without it
    /// the last, fastest cycles bias the slope by about $s\rho^2/12$.
    fn expected(&self, p: &SVector<f64, 2>, i: usize) -> (f64, SVector<f64, 2>) {
        let g = self.g(p, i);
        let x = self.x[i];
        let r2 = (2.0 * PI * g / (x * x)).powi(2);
        let c = p[0] / 12.0;
        let dc = 1.0 / 12.0;
        let y = g * (1.0 + c * r2);
        let dg = SVector::<f64, 2>::new(g * self.lx[i], g);
        // d(g r2)/dp = 3 r2 dg (r2 is proportional to g^2).
        let grad = dg * (1.0 + 3.0 * c * r2) + SVector::<f64, 2>::new(dc * r2 * g, 0.0);
        (y, grad)
    }
}

impl Problem<2> for Law85<'_> {
    fn y(&self) -> &[f64] {
        self.y
    }
    fn model(&self, p: &SVector<f64, 2>, i: usize) -> (f64, SVector<f64, 2>) {
        self.expected(p, i)
    }
    fn rows(&self, p: &SVector<f64, 2>) -> Vec<Row> {
        (0..self.y.len())
            .map(|r| {
                let i = self.start[r];
                let (d1, d2) = (self.t[i + 1] - self.t[i], self.t[i + 2] - self.t[i + 1]);
                let tt = d1 + d2;
                let y = 4.0 * PI * (d1 - d2) / (d1 * d2 * tt);
                let x = 4.0 * PI / tt;
                let gx = p[0] * self.g(p, r) / x;
                // dY/dt and dX/dt for t_i, t_{i+1}, t_{i+2}.
                let dy = [
                    -4.0 * PI / (d1 * d1 * tt) + y / tt,
                    4.0 * PI * (1.0 / (d1 * d1) + 1.0 / (d2 * d2)) / tt,
                    -4.0 * PI / (d2 * d2 * tt) - y / tt,
                ];
                let dx = [x / tt, 0.0, -x / tt];
                Row {
                    start: i,
                    coef: (0..3).map(|k| dy[k] - gx * dx[k]).collect(),
                }
            })
            .collect()
    }
    fn admissible(&self, p: &SVector<f64, 2>) -> bool {
        p.iter().all(|v| v.is_finite()) && p[0].abs() < 100.0
    }
}

/// Fits eq 85 to accelerations with first peaks `start`, given all peak times `t` and their
/// variances `w`.
pub fn fit_eq85(t: &[f64], start: &[usize], w: &[f64]) -> Result<Eq85Fit, FitError> {
    let n = start.len();
    FitError::at_least("accelerations", n, 4, "")?;
    let x: Vec<f64> = start
        .iter()
        .map(|&i| 4.0 * PI / (t[i + 2] - t[i]))
        .collect();
    let y: Vec<f64> = start
        .iter()
        .map(|&i| {
            let (o1, o2) = (
                2.0 * PI / (t[i + 1] - t[i]),
                2.0 * PI / (t[i + 2] - t[i + 1]),
            );
            2.0 * (o2 - o1) / (t[i + 2] - t[i])
        })
        .collect();
    let omega_ref = mean(&x.iter().map(|v| v.ln()).collect::<Vec<_>>()).exp();
    let lx: Vec<f64> = x.iter().map(|v| (v / omega_ref).ln()).collect();
    // Start: least squares on the logs of the positive rows.
    let pos: Vec<(f64, f64)> = lx
        .iter()
        .zip(&y)
        .filter(|(_, y)| **y > 0.0)
        .map(|(a, b)| (*a, b.ln()))
        .collect();
    if pos.len() < 2 {
        return Err(FitError::Shape(
            "dOmega/dt is not positive: Omega does not rise",
        ));
    }
    let (mx, my) = (
        mean(&pos.iter().map(|p| p.0).collect::<Vec<_>>()),
        mean(&pos.iter().map(|p| p.1).collect::<Vec<_>>()),
    );
    let sxx: f64 = pos.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let sxy: f64 = pos.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let s0 = if sxx > 0.0 { sxy / sxx } else { 5.0 };
    let p0 = SVector::<f64, 2>::new(s0, my - s0 * mx);
    let pr = Law85 {
        y: &y,
        x: &x,
        lx,
        start,
        t,
    };
    let s = solve(&pr, w, p0, Scale::Stationary)?;
    let sigma = s.cov[(0, 0)].sqrt();
    Ok(Eq85Fit {
        slope: s.p[0],
        slope_sigma: sigma,
        beta: s.p[0] - 3.0,
        beta_sigma: sigma,
        ln_k: s.p[1],
        omega_ref,
        reduced_chi2: s.s2,
        n,
        points: points(&x, &y, &s),
    })
}

fn points<const P: usize>(x: &[f64], y: &[f64], s: &Solved<P>) -> Vec<FitPoint> {
    (0..x.len())
        .map(|i| FitPoint {
            x: x[i],
            y: y[i],
            model: s.model[i],
            residual: s.residual[i],
            normalized: s.whitened[i],
        })
        .collect()
}

fn mean(v: &[f64]) -> f64 {
    v.iter().sum::<f64>() / v.len().max(1) as f64
}

/// A law of eq 84's family with $\beta$ fixed: parameters $(t_0, \ln C)$.
pub(crate) struct FixedBeta<Q> {
    /// The law with $(\beta, t_0, \ln C)$.
    pub law: Q,
    /// The fixed $\beta$.
    pub beta: f64,
}

impl<Q: Problem<3>> FixedBeta<Q> {
    fn full(&self, p: &SVector<f64, 2>) -> SVector<f64, 3> {
        SVector::<f64, 3>::new(self.beta, p[0], p[1])
    }
}

impl<Q: Problem<3>> Problem<2> for FixedBeta<Q> {
    fn y(&self) -> &[f64] {
        self.law.y()
    }
    fn model(&self, p: &SVector<f64, 2>, i: usize) -> (f64, SVector<f64, 2>) {
        let (m, g) = self.law.model(&self.full(p), i);
        (m, SVector::<f64, 2>::new(g[1], g[2]))
    }
    fn rows(&self, p: &SVector<f64, 2>) -> Vec<Row> {
        self.law.rows(&self.full(p))
    }
    fn admissible(&self, p: &SVector<f64, 2>) -> bool {
        self.law.admissible(&self.full(p))
    }
}

/// A fit of eq 84 with $\beta$ fixed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FixedFit {
    /// The fixed $\beta$.
    pub beta: f64,
    /// $t_0$ (s) and its standard uncertainty.
    pub t0: f64,
    /// (s)
    pub t0_sigma: f64,
    /// $\ln C$.
    pub ln_c: f64,
    /// Whitened $\chi^2$ (unscaled).
    pub chi2: f64,
    /// $\ln\det\Sigma$ at the solution.
    pub ln_det_sigma: f64,
    /// Points fitted.
    pub n: usize,
}

/// Fits eq 84 with $\beta$ fixed to the cycles of [`fit_eq84`], started from the free fit `free`.
pub fn fit_eq84_fixed(
    ta: &[f64],
    tb: &[f64],
    start: &[usize],
    w: &[f64],
    beta: f64,
    free: &Eq84Fit,
) -> Result<FixedFit, FitError> {
    let n = ta.len();
    let y: Vec<f64> = ta
        .iter()
        .zip(tb)
        .map(|(a, b)| (b - a) / (2.0 * PI))
        .collect();
    // ln C so that the law meets the datum at the window's middle.
    let m = n / 2;
    let tm = 0.5 * (ta[m] + tb[m]);
    let ln_c = -(beta + 2.0) * y[m].ln() + (free.t0 - tm).ln();
    let pr = FixedBeta {
        law: Law84 {
            ta,
            tb,
            y: &y,
            start,
        },
        beta,
    };
    let s = solve(
        &pr,
        w,
        SVector::<f64, 2>::new(free.t0, ln_c),
        Scale::Stationary,
    )?;
    Ok(FixedFit {
        beta,
        t0: s.p[0],
        t0_sigma: s.cov[(0, 0)].sqrt(),
        ln_c: s.p[1],
        chi2: s.chi2,
        ln_det_sigma: s.ln_det_sigma,
        n,
    })
}

crate::fit::law_fit::reads_law_fit!(Eq84Fit);
