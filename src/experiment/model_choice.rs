//! How often the model choice ([`compare_laws`](crate::experiment::models::compare_laws)) takes
//! a record of ONE mechanism for two: a Monte Carlo over records whose disk is spun down by a
//! single mechanism, each analysed as any recording is ([`analyze`]).
//!
//! The records: eq 79 exactly ($\beta$ = 1, 2, 3, 4; $\Omega$ = 100 rad/s seven seconds before
//! $t_0$), the dissipative model with eq 75's law (the built-in `spin-down` scene, the
//! report's own record), and the rolling model with each of the six mechanisms of
//! [`crate::model::mechanism`] alone ([`mechanism_record`](crate::experiment::mechanism_record)),
//! calibrated as the friction section calibrates them (each supplies the power the paper's
//! fit, $\beta = 2$ and $C^{-1/4}$ = 5.5 ms, needs where its 10 s record starts). Each is seen
//! through the default light model and scope with its own noise seed. The statistic is
//! $$\Delta\mathrm{BIC}_2 = \mathrm{BIC}(\text{best single law}) -
//!   \mathrm{BIC}(\text{two mechanisms}),$$
//! positive where the two-mechanism law is preferred.

use crate::disk::Disk;
use crate::experiment::analysis::{analyze, AnalysisSettings};
use crate::experiment::error::ExperimentError;
use crate::experiment::law::{law_trace, Law};
use crate::experiment::light::LightModel;
use crate::experiment::mechanism_record::mechanism_motion;
use crate::experiment::models::Comparison;
use crate::experiment::simulate::{simulate_motion, trace_of_motion, Motion};
use crate::friction::mechanisms::{calibrated, RECORD};
use crate::model::mechanism::Mechanism;
use crate::scene::Scene;
use crate::solve::Settings;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

/// The name of the two-mechanism candidate in a [`Comparison`].
pub const TWO_MECHANISMS: &str = "two mechanisms";

/// One single-mechanism record's outcome.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RecordOutcome {
    /// What spun the disk down.
    pub source: String,
    /// The scope's noise seed.
    pub seed: u64,
    /// Why the analysis refused the record, if it did (no model choice then).
    pub refused: Option<String>,
    /// $\Delta\mathrm{BIC}_2$ (module doc), when the two-mechanism law converged.
    pub two_over_single: Option<f64>,
    /// $\beta_2 - \beta_1$ of the two-mechanism law, when it converged.
    pub beta_change: Option<f64>,
    /// Whether the later half's refit says eq 79 drifts over the window.
    pub drifts: bool,
}

/// $\Delta\mathrm{BIC}_2$ of a comparison: the best single law's BIC minus the two-mechanism
/// law's; `None` when either is missing.
pub fn two_over_single(c: &Comparison) -> Option<f64> {
    let two = c.candidates.iter().find(|x| x.name == TWO_MECHANISMS)?.bic;
    let single = c
        .candidates
        .iter()
        .filter(|x| x.name != TWO_MECHANISMS)
        .map(|x| x.bic)
        .fold(f64::INFINITY, f64::min);
    single.is_finite().then_some(single - two)
}

/// A source of single-mechanism records: a law to record exactly, or a simulated motion.
enum Source {
    Law(Law),
    Motion(Motion),
}

/// The sources of the study, by name (their motions integrated once, the noise drawn per seed).
fn sources() -> Result<Vec<(String, Source)>, ExperimentError> {
    let mut out = Vec::new();
    for beta in [1.0, 2.0, 3.0, 4.0] {
        let law = Law {
            beta,
            c: 100f64.powf(beta + 2.0) * 7.0,
        };
        out.push((format!("eq 79 exactly, beta = {beta}"), Source::Law(law)));
    }
    let light = LightModel::default();
    let scope = &light.scope;
    let scene = Scene::load("spin-down").map_err(|e| ExperimentError::Setting(e.to_string()))?;
    let m = simulate_motion(&scene, scope.end_at, scope.sample_rate, scope.samples)?;
    out.push((
        "dissipative model, eq 75 with beta = 2 (scene spin-down)".to_string(),
        Source::Motion(m),
    ));
    let disk = crate::friction::toy_disk();
    let paper = Law::from_fit(2.0, 0.0055);
    let omega_cal = (paper.c / RECORD).powf(1.0 / (paper.beta + 2.0));
    let mechs: Vec<Mechanism> = Mechanism::all_unit()
        .iter()
        .map(|m| calibrated(&disk, &paper, m, omega_cal))
        .collect();
    let motions: Vec<_> = mechs
        .par_iter()
        .map(|m| (m, mechanism_motion(&disk, m, scope, &Settings::default())))
        .collect();
    for (m, r) in motions {
        match r {
            Ok(motion) => out.push((m.name().to_string(), Source::Motion(motion))),
            Err(e) => eprintln!("{}: {e}", m.name()),
        }
    }
    Ok(out)
}

/// Analyses `seeds` records of every source, seeds `seed0..seed0 + seeds`.
pub fn study(seeds: u64, seed0: u64) -> Result<Vec<RecordOutcome>, ExperimentError> {
    let sources = sources()?;
    let disk = Disk::uniform(0.0375);
    let jobs: Vec<(usize, u64)> = (0..sources.len())
        .flat_map(|i| (seed0..seed0 + seeds).map(move |s| (i, s)))
        .collect();
    jobs.par_iter()
        .map(|&(i, seed)| {
            let (name, source) = &sources[i];
            let mut light = LightModel::default();
            light.scope.seed = seed;
            let trace = match source {
                Source::Law(law) => law_trace(law, &disk, &light)?,
                Source::Motion(m) => trace_of_motion(m, &light, name),
            };
            Ok(match analyze(&trace, &AnalysisSettings::default()) {
                Ok(a) => RecordOutcome {
                    source: name.clone(),
                    seed,
                    refused: None,
                    two_over_single: two_over_single(&a.models),
                    beta_change: a.crossover.as_ref().map(|x| x.beta_above - x.beta_below),
                    drifts: a.law_stability.as_ref().is_some_and(|l| l.drifts),
                },
                Err(e) => RecordOutcome {
                    source: name.clone(),
                    seed,
                    refused: Some(e.to_string()),
                    two_over_single: None,
                    beta_change: None,
                    drifts: false,
                },
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    #[ignore = "slow"]
    fn measure() {
        let r = study(3, 1).unwrap();
        for o in &r {
            println!(
                "{:<60} {:>3} dBIC2 {:>10.1?} dbeta {:>8.3?} drifts {} {}",
                o.source,
                o.seed,
                o.two_over_single,
                o.beta_change,
                o.drifts,
                o.refused.as_deref().unwrap_or("")
            );
        }
    }
}
