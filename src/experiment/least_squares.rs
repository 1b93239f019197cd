//! Generalised nonlinear least squares with banded, correlated errors, minimised by the
//! `levenberg-marquardt` crate (MINPACK's algorithm on nalgebra 0.34).
//!
//! A [`Problem`] gives the data $y_i$, the model $f_i(\mathbf p)$ with its gradient, and the rows of
//! $B$ (how each residual depends on the peak times, see [`band`](crate::experiment::band)). The
//! residuals $f - y$ and the Jacobian's columns are whitened by the banded Cholesky factor $L$ of
//! $\Sigma = B W B^{\mathsf T}$ evaluated at the current parameters; as $\Sigma$ depends (weakly) on
//! $\mathbf p$, the minimisation is repeated three times with $L$ refreshed at the last minimum
//! (iteratively reweighted).
//!
//! **Uncertainties.** The covariance is the scaled one,
//! $$\mathrm{Cov}(\hat{\mathbf p}) = s^2\,(J_w^{\mathsf T} J_w)^{-1}, \qquad
//!   s^2 = \frac{|r_w|^2}{n - p},$$
//! so that an error model that is too optimistic (noise larger than the peak-time variances say,
//! or a law that departs from the data) widens the intervals by $\sqrt{s^2}$ instead of
//! overstating the precision. With [`Scale::Floored`] (prior variances that are estimates of
//! the noise, the peak times') they are never narrowed: $\max(s^2, 1)$ is used, as the Particle
//! Data Group does with its scale factor; with [`Scale::Unknown`] (no prior variances, unit
//! weights) $s^2$ is the variance itself.
//!
//!
//! Residuals that are still correlated after whitening (a slow error the peak-time model does
//! not know: envelope-level or interpolation errors shared by neighbouring peaks, or the law's
//! own departure) carry less information than their number says. Taking them as AR(1) with the
//! whitened residuals' lag-one autocorrelation $\rho$ (clamped to [0, 0.9]), the covariance is
//! further multiplied by $(1 + \rho)/(1 - \rho)$, the variance inflation of a mean of AR(1)
//! errors. Uncorrelated residuals ($\rho \le 0$) leave it unchanged.
//!
//! The crate replaced a hand-written Levenberg-Marquardt loop; both reach the same minimum on the
//! tests' traces (the fits' results are compared to the truth in `tests/experiment.rs`).

use crate::experiment::band::{BandCholesky, Row};
use levenberg_marquardt::{LeastSquaresProblem, LevenbergMarquardt};
use nalgebra::storage::Owned;
use nalgebra::{Const, DMatrix, Dyn, OMatrix, OVector, SMatrix, SVector};

/// A least-squares problem in `P` parameters.
pub trait Problem<const P: usize> {
    /// The data.
    fn y(&self) -> &[f64];
    /// The model at datum `i` and its gradient in the parameters.
    fn model(&self, p: &SVector<f64, P>, i: usize) -> (f64, SVector<f64, P>);
    /// The model at datum `i` alone (the residuals need no gradient); a problem whose gradient
    /// costs more than its value (by differences) computes the value only.
    fn value(&self, p: &SVector<f64, P>, i: usize) -> f64 {
        self.model(p, i).0
    }
    /// The rows of $B$: the residuals' dependence on the (independent) peak-time errors.
    fn rows(&self, p: &SVector<f64, P>) -> Vec<Row>;
    /// Whether the parameters are inside the law's domain.
    fn admissible(&self, p: &SVector<f64, P>) -> bool;
}

/// A solved problem.
#[derive(Debug, Clone)]
pub struct Solved<const P: usize> {
    /// The parameters.
    pub p: SVector<f64, P>,
    /// Their scaled covariance $s^2 (J_w^T J_w)^{-1}$.
    pub cov: SMatrix<f64, P, P>,
    /// The reduced $\chi^2$, $s^2$.
    pub s2: f64,
    /// $\chi^2 = |r_w|^2$ (whitened, unscaled).
    pub chi2: f64,
    /// $y - f$.
    pub residual: Vec<f64>,
    /// The whitened residuals $L^{-1}(y - f)$.
    pub whitened: Vec<f64>,
    /// The model values.
    pub model: Vec<f64>,
    /// $\ln\det\Sigma$ of the errors' covariance at the solution (for likelihoods).
    pub ln_det_sigma: f64,
}

/// The lag-one autocorrelation of `r`, clamped to [0, 0.9].
fn lag_one(r: &[f64]) -> f64 {
    let n = r.len();
    if n < 3 {
        return 0.0;
    }
    let m = r.iter().sum::<f64>() / n as f64;
    let c0: f64 = r.iter().map(|x| (x - m).powi(2)).sum();
    let c1: f64 = r.windows(2).map(|w| (w[0] - m) * (w[1] - m)).sum();
    if c0 > 0.0 {
        (c1 / c0).clamp(0.0, 0.9)
    } else {
        0.0
    }
}

/// How the covariance is scaled by the reduced $\chi^2$ $s^2$.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scale {
    /// By $\max(s^2, 1)$: the prior variances estimate the noise and are widened, never narrowed.
    Floored,
    /// By $s^2$: the prior variances are only relative weights.
    Unknown,
}

/// Cost assigned to parameters outside the law's domain: the crate's step is then rejected and
/// shortened, as for any step that raises the cost.
const OUTSIDE: f64 = 1e100;

/// The adapter between a [`Problem`] and the crate's trait, with a fixed whitening.
struct Whitened<'a, const P: usize, Q: Problem<P>> {
    problem: &'a Q,
    whitening: &'a BandCholesky,
    p: SVector<f64, P>,
}

impl<const P: usize, Q: Problem<P>> LeastSquaresProblem<f64, Dyn, Const<P>> for Whitened<'_, P, Q> {
    type ResidualStorage = Owned<f64, Dyn>;
    type JacobianStorage = Owned<f64, Dyn, Const<P>>;
    type ParameterStorage = Owned<f64, Const<P>>;

    fn set_params(&mut self, x: &SVector<f64, P>) {
        self.p = *x;
    }

    fn params(&self) -> SVector<f64, P> {
        self.p
    }

    fn residuals(&self) -> Option<OVector<f64, Dyn>> {
        let n = self.problem.y().len();
        if !self.problem.admissible(&self.p) {
            return Some(OVector::<f64, Dyn>::from_element(n, OUTSIDE));
        }
        let y = self.problem.y();
        let mut r: Vec<f64> = (0..n)
            .map(|i| self.problem.value(&self.p, i) - y[i])
            .collect();
        self.whitening.whiten(&mut r);
        r.iter()
            .all(|x| x.is_finite())
            .then(|| OVector::<f64, Dyn>::from_vec(r))
    }

    fn jacobian(&self) -> Option<OMatrix<f64, Dyn, Const<P>>> {
        let n = self.problem.y().len();
        if !self.problem.admissible(&self.p) {
            return Some(OMatrix::<f64, Dyn, Const<P>>::zeros(n));
        }
        let mut cols = vec![Vec::with_capacity(n); P];
        for i in 0..n {
            let (_, g) = self.problem.model(&self.p, i);
            for (k, c) in cols.iter_mut().enumerate() {
                c.push(g[k]);
            }
        }
        for c in cols.iter_mut() {
            self.whitening.whiten(c);
        }
        let j = OMatrix::<f64, Dyn, Const<P>>::from_fn(n, |i, k| cols[k][i]);
        j.iter().all(|x| x.is_finite()).then_some(j)
    }
}

/// Why a fit of the experiment could not be made: each sentence is shown to the user (wrapped
/// by the analysis with the law that was being fitted).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FitError {
    /// Not enough data for the law.
    #[error("{got} {what} in the window, at least {need} are needed{why}")]
    TooFew {
        /// What was counted (points, cycles, accelerations).
        what: &'static str,
        /// How many there are.
        got: usize,
        /// How many the fit needs.
        need: usize,
        /// Why that many, or nothing.
        why: &'static str,
    },
    /// No more points than parameters.
    #[error("{points} points for {params} parameters")]
    Underdetermined {
        /// Points.
        points: usize,
        /// Parameters.
        params: usize,
    },
    /// The start or the result lies outside the law's domain.
    #[error("{0}")]
    Domain(&'static str),
    /// The data do not have the shape the law needs (no end time ahead, Omega not rising).
    #[error("{0}")]
    Shape(&'static str),
    /// The minimiser or the linear algebra failed (not positive definite, singular, not
    /// finite, stopped).
    #[error("{0}")]
    Numerics(String),
}

/// Minimises the whitened residuals of `problem` from `p0`, with peak-time variances `w`.
pub fn solve<const P: usize>(
    problem: &impl Problem<P>,
    w: &[f64],
    p0: SVector<f64, P>,
    scale: Scale,
) -> Result<Solved<P>, FitError> {
    let n = problem.y().len();
    if n <= P {
        return Err(FitError::Underdetermined {
            points: n,
            params: P,
        });
    }
    if !problem.admissible(&p0) {
        return Err(FitError::Domain(
            "the starting point is outside the law's domain",
        ));
    }
    let lm = LevenbergMarquardt::new()
        .with_ftol(1e-14)
        .with_xtol(1e-14)
        .with_patience(400);
    let mut p = p0;
    let mut whitening = None;
    for _round in 0..3 {
        let ch = BandCholesky::from_rows(&problem.rows(&p), w).ok_or_else(|| {
            FitError::Numerics("the residuals' covariance is not positive definite".into())
        })?;
        let (done, report) = lm.minimize(Whitened {
            problem,
            whitening: &ch,
            p,
        });
        if !(report.termination.was_successful()
            || matches!(
                report.termination,
                levenberg_marquardt::TerminationReason::NoImprovementPossible(_)
                    | levenberg_marquardt::TerminationReason::LostPatience
            ))
        {
            return Err(FitError::Numerics(format!(
                "the minimiser stopped: {:?}",
                report.termination
            )));
        }
        if !problem.admissible(&done.p) {
            return Err(FitError::Domain("the fit left the law's domain"));
        }
        p = done.p;
        whitening = Some(ch);
    }
    let ch = whitening.ok_or_else(|| FitError::Numerics("no iteration".into()))?;
    let adapter = Whitened {
        problem,
        whitening: &ch,
        p,
    };
    let r = adapter
        .residuals()
        .ok_or_else(|| FitError::Numerics("the residuals are not finite at the minimum".into()))?;
    let j = adapter
        .jacobian()
        .ok_or_else(|| FitError::Numerics("the Jacobian is not finite at the minimum".into()))?;
    let chi2 = r.norm_squared();
    let jtj = j.transpose() * &j;
    let inv = DMatrix::from_fn(P, P, |a, b| jtj[(a, b)])
        .try_inverse()
        .ok_or_else(|| {
            FitError::Numerics(
                "the parameters are not determined by the data (singular normal matrix)".into(),
            )
        })?;
    let s2 = chi2 / (n - P) as f64;
    let rho = lag_one(r.as_slice());
    let ar1 = ((1.0 + rho) / (1.0 - rho)).max(1.0);
    let scale = match scale {
        Scale::Floored => s2.max(1.0) * ar1,
        Scale::Unknown => s2 * ar1,
    };
    let cov = SMatrix::<f64, P, P>::from_fn(|a, b| inv[(a, b)] * scale);
    let model: Vec<f64> = (0..n).map(|i| problem.value(&p, i)).collect();
    let residual = (0..n).map(|i| problem.y()[i] - model[i]).collect();
    Ok(Solved {
        p,
        cov,
        s2,
        chi2,
        residual,
        whitened: r.iter().map(|x| -x).collect(),
        model,
        ln_det_sigma: ch.ln_det(),
    })
}
