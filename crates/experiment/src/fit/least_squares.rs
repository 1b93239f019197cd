//! Generalised nonlinear least squares with banded, correlated errors, minimised by the
//! `levenberg-marquardt` crate (MINPACK's algorithm on nalgebra 0.34).
//!
//! A [`Problem`] gives the data $y_i$, the model $f_i(\mathbf p)$ with its gradient, and the rows of
//! $B$ (how each residual depends on the peak times, see [`band`](crate::fit::band)). The
//! residuals $f - y$ and the Jacobian's columns are whitened by the banded Cholesky factor $L$ of
//! $\Sigma = B W B^{\mathsf T}$ evaluated at the current parameters; as $\Sigma$ depends (weakly) on
//! $\mathbf p$, the minimisation is repeated three times with $L$ refreshed at the last minimum
//! (iteratively reweighted).
//!
//! **Uncertainties.** Two estimates, chosen by [`Scale`]:
//!
//! - [`Scale::Stationary`], for the fits to peak times (eqs 84, 85, the fixed-beta and the
//!   two-mechanism fits): the sandwich with the whitened residuals' own stationary covariance.
//!   If the whitened errors $\varepsilon$ have covariance $\Sigma_\varepsilon$ instead of $I$, the
//!   estimate's is $A\,J^{\mathsf T}\Sigma_\varepsilon J\,A$ with $A = (J^{\mathsf T}J)^{-1}$ and $J$ the
//!   whitened Jacobian. $\Sigma_\varepsilon$ is taken as stationary, estimated from the residuals'
//!   autocovariances $\hat\gamma_l = \sum_i r_i r_{i-l}/(n - p)$ tapered by Bartlett's weights
//!   (which keep it positive semi-definite):
//!   $$\mathrm{Cov}(\hat{\mathbf p}) = A \Bigl(\sum_{|l| \le L} \Bigl(1 - \frac{|l|}{L + 1}\Bigr)
//!   \hat\gamma_{|l|} \sum_i J_i J_{i-l}^{\mathsf T}\Bigr) A,$$
//!   with Newey and West's (1994) bandwidth $L = \lfloor 4 (n/100)^{2/9} \rfloor$ (4 at 150 cycles).
//!   Without correlation this is $s^2 (J^{\mathsf T}J)^{-1}$, $s^2 = |r|^2/(n - p)$: the covariance
//!   scaled by $\chi^2$/dof both ways, the peak-time variances being relative weights whose common
//!   size (the noise estimate's) the residuals measure. The errors are therefore **the
//!   covariance scaled by the residuals**, $\chi^2$/dof and the residuals' correlation, not a
//!   bootstrap. Not $\max(s^2, 1)\,(J^{\mathsf T}J)^{-1}$ times an AR(1) factor with the
//!   correlation clamped to $\ge 0$: on the coverage study's traces the whitened residuals of
//!   eq 84 are anti-correlated (about -0.045 at lags one and two), so the errors of smooth
//!   combinations (beta) are smaller than $\chi^2$/dof says; the floor and the clamp can only
//!   widen, and with the peak-time variances of
//!   [`peak_search`](crate::light_analysis::peak_search) they give pulls whose sd is 0.83 (beta)
//!   and 0.77 (t0) on 40 traces. Not the heteroscedastic Newey-West sandwich ($r_i r_k$ in place of
//!   $\hat\gamma_{|i-k|}$): $t_0$ is decided by the last few cycles, so its variance then rests
//!   on a few squared residuals; on 120 clean traces its pulls' sd is then 1.21 and only 85 % fall
//!   within 1.96 sigma. Pooled over all $n$ residuals, $\hat\gamma_l$ is steady; what it cannot
//!   see (a misstated variance in one part of the record) the peak-time variances must get right.
//! - [`Scale::Unknown`], with no prior variances (unit weights, the sound track's fit):
//!   $s^2 (J^{\mathsf T}J)^{-1}$ with $s^2 = |r|^2/(n - p)$, further multiplied by the AR(1) variance
//!   inflation $(1 + \rho)/(1 - \rho)$, $\rho$ the residuals' lag-one autocorrelation clamped to
//!   [0, 0.9] (too few points for a sandwich).
//!
//! The crate replaced a hand-written Levenberg-Marquardt loop; both reach the same minimum on the
//! tests' traces (the fits' results are compared to the truth in `tests/experiment.rs`).

use crate::fit::band::{BandCholesky, Row};
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
    /// Their covariance (see [`Scale`]).
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
    numerics::autocorrelation::lag_one(r).clamp(0.0, 0.9)
}

/// How the covariance is estimated (see the module's documentation).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scale {
    /// The sandwich with the whitened residuals' stationary covariance: the prior variances
    /// weight, the residuals give the errors' common size and their correlation.
    Stationary,
    /// $s^2 (J^T J)^{-1}$ times the AR(1) inflation: the prior variances are relative weights.
    Unknown,
}

/// The sandwich $A\,J^{\mathsf T}\hat\Sigma J\,A$ of the whitened residuals `r` and Jacobian `j`,
/// $A = (J^T J)^{-1}$ given as `inv`, with $\hat\Sigma$ the residuals' stationary covariance
/// $\hat\Sigma_{ik} = w_{|i-k|}\hat\gamma_{|i-k|}$ (see the module's documentation).
fn stationary_sandwich<const P: usize>(
    r: &OVector<f64, Dyn>,
    j: &OMatrix<f64, Dyn, Const<P>>,
    inv: &DMatrix<f64>,
) -> DMatrix<f64> {
    let n = r.len();
    let lags = ((4.0 * (n as f64 / 100.0).powf(2.0 / 9.0)).floor() as usize).min(n - 1);
    let dof = (n - P) as f64;
    let row = |i: usize| SVector::<f64, P>::from_fn(|k, _| j[(i, k)]);
    let mut s = SMatrix::<f64, P, P>::zeros();
    for l in 0..=lags {
        let gamma = (l..n).map(|i| r[i] * r[i - l]).sum::<f64>() / dof;
        let w = 1.0 - l as f64 / (lags + 1) as f64;
        let mut c = SMatrix::<f64, P, P>::zeros();
        for i in l..n {
            c += row(i) * row(i - l).transpose();
        }
        s += if l == 0 { c } else { c + c.transpose() } * (w * gamma);
    }
    let s = DMatrix::from_fn(P, P, |a, b| s[(a, b)]);
    inv * s * inv
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

impl FitError {
    /// [`FitError::TooFew`] unless there are at least `need` of `what` (`got` of them); `why`
    /// says why that many, or is empty.
    pub fn at_least(
        what: &'static str,
        got: usize,
        need: usize,
        why: &'static str,
    ) -> Result<(), FitError> {
        if got < need {
            return Err(FitError::TooFew {
                what,
                got,
                need,
                why,
            });
        }
        Ok(())
    }
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
    let cov = match scale {
        Scale::Stationary => {
            let c = stationary_sandwich(&r, &j, &inv);
            SMatrix::<f64, P, P>::from_fn(|a, b| c[(a, b)])
        }
        Scale::Unknown => {
            let rho = lag_one(r.as_slice());
            let ar1 = ((1.0 + rho) / (1.0 - rho)).max(1.0);
            SMatrix::<f64, P, P>::from_fn(|a, b| inv[(a, b)] * s2 * ar1)
        }
    };
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
