//! Do the stated intervals mean what they say? A Monte Carlo over synthetic recordings with a
//! known truth: each is analysed, and the pulls $(\hat\beta - \beta)/\sigma_\beta$ and
//! $(\hat t_0 - t_0)/\sigma_{t_0}$ are counted inside $\pm1$ (68.3 % claimed) and $\pm1.96$ (95 %).
//!
//! The recordings follow eq 79 exactly, so that the truth is exact: $\beta = 2$, $\Omega$ = 100
//! rad/s seven seconds before $t_0$, seen through the default light model and scope (5 mV of
//! noise, 8 bits), each with its own noise seed and, optionally, a realistic set of
//! [`Artifacts`] (drift, 50 Hz hum, clipping, glitches, 1 % of samples dropped) of its own seed.

use experiment::error::ExperimentError;
use experiment::light_analysis::analysis::{analyze, AnalysisSettings};
use experiment::synthetic::artifacts::Artifacts;
use experiment::synthetic::law::{law_trace, Law};
use experiment::synthetic::light::LightModel;
use physics::disk::Disk;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

/// The outcome of a coverage study.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
pub struct Coverage {
    /// Recordings analysed.
    pub runs: usize,
    /// Recordings refused (counted as misses).
    pub refused: usize,
    /// Pulls of beta (eq 84), in the stated uncertainty (the fit's, and the law's where it drifts).
    pub beta_pulls: Vec<f64>,
    /// Pulls of t0, likewise.
    pub t0_pulls: Vec<f64>,
    /// Recordings on which eq 79 was found to drift over the window, so that the law's
    /// systematic uncertainty was added ([`LawStability`](experiment::fit::law_stability)):
    /// none expected on recordings that follow eq 79 (absent from studies stored before it
    /// was counted).
    #[serde(default)]
    pub law_drifts: usize,
    /// Largest |beta - truth|.
    pub worst_beta_error: f64,
    /// Largest |t0 - truth| (s).
    pub worst_t0_error: f64,
}

impl Coverage {
    /// The fraction of `pulls` within `z` (refusals count as outside).
    pub fn fraction(&self, pulls: &[f64], z: f64) -> f64 {
        pulls.iter().filter(|p| p.abs() <= z).count() as f64 / self.runs.max(1) as f64
    }

    /// The mean and standard deviation of `pulls` (0 and 1 when the intervals are right).
    pub fn moments(pulls: &[f64]) -> (f64, f64) {
        let n = pulls.len().max(1) as f64;
        let m = pulls.iter().sum::<f64>() / n;
        let v = pulls.iter().map(|p| (p - m).powi(2)).sum::<f64>() / (n - 1.0).max(1.0);
        (m, v.sqrt())
    }

    /// A summary line.
    pub fn summary(&self) -> String {
        format!(
            "{} recordings ({} refused): beta inside 1 sigma {:.1} %, 1.96 sigma {:.1} %; \
             t0 inside 1 sigma {:.1} %, 1.96 sigma {:.1} % (claimed 68.3 % and 95 %); \
             pulls (mean, sd): beta ({:.2}, {:.2}), t0 ({:.2}, {:.2}); \
             worst errors: beta {:.4}, t0 {:.3} ms; law drift flagged on {}",
            self.runs,
            self.refused,
            100.0 * self.fraction(&self.beta_pulls, 1.0),
            100.0 * self.fraction(&self.beta_pulls, 1.96),
            100.0 * self.fraction(&self.t0_pulls, 1.0),
            100.0 * self.fraction(&self.t0_pulls, 1.96),
            Self::moments(&self.beta_pulls).0,
            Self::moments(&self.beta_pulls).1,
            Self::moments(&self.t0_pulls).0,
            Self::moments(&self.t0_pulls).1,
            self.worst_beta_error,
            1e3 * self.worst_t0_error,
            self.law_drifts
        )
    }
}

/// One recording's analysis against its truth.
struct Outcome {
    beta_error: f64,
    t0_error: f64,
    beta_sigma: f64,
    t0_sigma: f64,
    drifts: bool,
}

/// Runs `runs` recordings with seeds `seed0`, `seed0 + 1`, ..., with realistic artifacts when
/// `artifacts` is true (else the scope's noise and quantisation only).
pub fn coverage(runs: usize, seed0: u64, artifacts: bool) -> Result<Coverage, ExperimentError> {
    let disk = Disk::uniform(0.0375);
    let law = Law {
        beta: 2.0,
        c: 100f64.powi(4) * 7.0,
    };
    let mut c = Coverage {
        runs,
        refused: 0,
        beta_pulls: Vec::with_capacity(runs),
        t0_pulls: Vec::with_capacity(runs),
        worst_beta_error: 0.0,
        worst_t0_error: 0.0,
        law_drifts: 0,
    };
    let settings = AnalysisSettings::default();
    // Each recording is independent and seeded by its index: analysed in parallel, gathered in
    // order, so the result does not depend on the number of threads.
    let one = |k: u64| -> Result<Option<Outcome>, ExperimentError> {
        let mut light = LightModel::default();
        light.scope.seed = seed0 + k;
        let mut trace = law_trace(&law, &disk, &light)?;
        if artifacts {
            trace =
                trace.with_artifacts(&Artifacts::realistic(light.gain, seed0 + k + 1_000_000))?;
        }
        match analyze(&trace, &settings) {
            Ok(a) => {
                let (beta_sigma, t0_sigma) = a.stated_sigmas();
                Ok(Some(Outcome {
                    beta_error: a.eq84.beta - law.beta,
                    t0_error: a.eq84.t0 - light.scope.end_at,
                    beta_sigma,
                    t0_sigma,
                    drifts: a.law_stability.as_ref().is_some_and(|l| l.drifts),
                }))
            }
            Err(ExperimentError::Refused { .. }) => Ok(None),
            Err(e) => Err(e),
        }
    };
    let results: Vec<_> = (0..runs as u64).into_par_iter().map(one).collect();
    for r in results {
        match r? {
            Some(o) => {
                c.law_drifts += usize::from(o.drifts);
                c.beta_pulls.push(o.beta_error / o.beta_sigma);
                c.t0_pulls.push(o.t0_error / o.t0_sigma);
                c.worst_beta_error = c.worst_beta_error.max(o.beta_error.abs());
                c.worst_t0_error = c.worst_t0_error.max(o.t0_error.abs());
            }
            None => c.refused += 1,
        }
    }
    Ok(c)
}
