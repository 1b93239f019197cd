//! How often the model choice ([`compare_laws`](experiment::fit::law_choice::compare_laws)) takes
//! a record of ONE mechanism for two: a Monte Carlo over records whose disk is spun down by a
//! single mechanism, each analysed as any recording is ([`analyze`]).
//!
//! The records: eq 79 exactly ($\beta$ = 1, 2, 3, 4; $\Omega$ = 100 rad/s seven seconds before
//! $t_0$), the dissipative model with eq 75's law (the built-in `spin-down` scene, the
//! report's own record), and the rolling model with each of the six mechanisms of
//! [`physics::model::mechanism`] alone ([`mechanism_record`](experiment::synthetic::mechanism_record)),
//! calibrated as the friction section calibrates them (each supplies the power the paper's
//! fit, $\beta = 2$ and $C^{-1/4}$ = 5.5 ms, needs where its 10 s record starts). Each is seen
//! through the default light model and scope with its own noise seed. The statistic is
//! $$\Delta\mathrm{BIC}_2 = \mathrm{BIC}(\text{best single law}) -
//!   \mathrm{BIC}(\text{two mechanisms}),$$
//! positive where the two-mechanism law is preferred.
//!
//! **What the records show** (stored in `snapshots/model_choice.json`; [`stored`](experiment::fit::law_choice_record::stored) says which
//! command made it and when). On eq 79 exactly the two-mechanism law is never preferred
//! ($\Delta\mathrm{BIC}_2 \approx -11$ to $-14$: its two extra parameters buy nothing). On every
//! simulated spin-down it is, by hundreds, whatever the mechanism: the model is not eq 79
//! exactly (the centre drifts off $b = 0$ as the tilt falls, by eq 23), so the exponent eq 84
//! sees drifts along the record, and a law with two exponents follows that drift. No threshold
//! on $\Delta\mathrm{BIC}_2$ separates this from two mechanisms: the drift is systematic, so
//! $\Delta\mathrm{BIC}_2$ grows without bound as the noise falls or the record lengthens, and a
//! threshold set above the simulated records would hold only at their noise.
//!
//! **The rule: account for the drift.** What the drift does not give is a large change of
//! exponent: one mechanism's records change it by a few tenths at most (stored: at most the
//! largest $|\beta_2 - \beta_1|$ of [`stored`](experiment::fit::law_choice_record::stored), about 0.2), while two mechanisms differ by at
//! least [`MIN_EXPONENT_CHANGE`](experiment::fit::law_choice::MIN_EXPONENT_CHANGE). The two-mechanism law is admitted only when its exponents
//! differ by that much and by three of their combined standard uncertainties
//! ([`admits_two`](experiment::fit::law_choice::admits_two)); otherwise, where it has the least BIC, the comparison reads it as one law
//! that drifts over the window ([`Comparison::drift`](experiment::fit::law_choice::Comparison))
//! and chooses the best single law. The false-alarm rate, the records of one mechanism on
//! which two mechanisms are still called, is counted from the stored study ([`FalseAlarms`](experiment::fit::law_choice_record::FalseAlarms))
//! and stated with every comparison.

use experiment::error::ExperimentError;
use experiment::fit::law_choice::{Comparison, TWO_MECHANISMS};
use experiment::fit::law_choice_record::RecordOutcome;
use experiment::light_analysis::analysis::{analyze, AnalysisSettings};
use experiment::synthetic::law::{law_trace, Law};
use experiment::synthetic::light::LightModel;
use experiment::synthetic::mechanism_record::mechanism_motion;
use experiment::synthetic::mechanisms::{calibrated, RECORD};
use experiment::synthetic::simulate::{simulate_motion, trace_of_motion};
use experiment::trace::Motion;
use physics::disk::Disk;
use physics::model::mechanism::Mechanism;
use physics::scene::Scene;
use physics::solve::Settings;
use rayon::prelude::*;

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

/// How many sources the study has: eq 79 at four exponents, eq 75's model, six mechanisms.
pub const SOURCES: usize = 11;

/// Source `i` of the study (`i < SOURCES`), by name; `Err` names a source that gives no
/// record (a spin-down that does not end, which eq 79 cannot describe).
fn source(i: usize) -> Result<(String, Source), ExperimentError> {
    let scope = LightModel::default().scope;
    if i < 4 {
        let beta = (i + 1) as f64;
        let law = Law {
            beta,
            c: 100f64.powf(beta + 2.0) * 7.0,
        };
        return Ok((format!("eq 79 exactly, beta = {beta}"), Source::Law(law)));
    }
    if i == 4 {
        let scene =
            Scene::load("spin-down").map_err(|e| ExperimentError::Setting(e.to_string()))?;
        let m = simulate_motion(&scene, scope.end_at, scope.sample_rate, scope.samples)?;
        return Ok((
            "dissipative model, eq 75 with beta = 2 (scene spin-down)".to_string(),
            Source::Motion(m),
        ));
    }
    let disk = physics::disk::toy_disk();
    let paper = Law::from_fit(2.0, 0.0055);
    let omega_cal = (paper.c / RECORD).powf(1.0 / (paper.beta + 2.0));
    let mech = Mechanism::all_unit()
        .get(i - 5)
        .map(|m| calibrated(&disk, &paper, m, omega_cal))
        .ok_or_else(|| ExperimentError::Setting(format!("no source {i}")))?;
    let m = mechanism_motion(&disk, &mech, &scope, &Settings::default())?;
    Ok((mech.name().to_string(), Source::Motion(m)))
}

/// Analyses the record of `source` with noise seed `seed`.
fn record((name, source): &(String, Source), seed: u64) -> Result<RecordOutcome, ExperimentError> {
    let disk = Disk::uniform(0.0375);
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
            called_two: a.models.calls_two(),
            drifts: a.law_stability.as_ref().is_some_and(|l| l.drifts),
        },
        Err(e) => RecordOutcome {
            source: name.clone(),
            seed,
            refused: Some(e.to_string()),
            two_over_single: None,
            beta_change: None,
            called_two: false,
            drifts: false,
        },
    })
}

/// Analyses the records of sources `which` with noise seeds `seed0..seed0 + seeds`; returns
/// the outcomes (by source, then seed) and the sources that gave no record, with the reason.
pub fn study(
    which: &[usize],
    seeds: u64,
    seed0: u64,
) -> Result<(Vec<RecordOutcome>, Vec<String>), ExperimentError> {
    let built: Vec<_> = which.par_iter().map(|&i| source(i)).collect();
    let mut sources = Vec::new();
    let mut unrecorded = Vec::new();
    for b in built {
        match b {
            Ok(s) => sources.push(s),
            Err(e) => unrecorded.push(e.to_string()),
        }
    }
    let jobs: Vec<(usize, u64)> = (0..sources.len())
        .flat_map(|i| (seed0..seed0 + seeds).map(move |s| (i, s)))
        .collect();
    let outcomes: Result<Vec<_>, _> = jobs
        .par_iter()
        .map(|&(i, seed)| record(&sources[i], seed))
        .collect();
    Ok((outcomes?, unrecorded))
}

/// The command that regenerates the stored study.
#[cfg(test)]
const REGENERATE: &str =
    "ROLLING_DISK_BLESS=1 cargo test --release -p studies --lib law_choice_study -- --ignored";

#[cfg(test)]
mod tests {
    use super::*;
    use experiment::fit::law_choice::MIN_EXPONENT_CHANGE;
    use experiment::fit::law_choice_record::{
        calibration_sentence, stored, FalseAlarms, StoredStudy,
    };

    /// Noise seeds per source in the stored study, and the first.
    const SEEDS: u64 = 20;
    const SEED0: u64 = 1;

    /// Runs the whole study (11 sources, 20 seeds each; 3.5 minutes on two shared cores) and
    /// compares it with the stored one, or stores it with `ROLLING_DISK_BLESS=1`.
    #[test]
    #[ignore = "slow: 200 records of 10 sources (pivoting friction gives none), about four minutes"]
    fn the_stored_study_is_current() {
        let all: Vec<usize> = (0..SOURCES).collect();
        let (outcomes, unrecorded) = study(&all, SEEDS, SEED0).unwrap();
        for o in &outcomes {
            println!(
                "{:<58} {:>3} dBIC2 {:>8.1?} dbeta {:>7.3?} two {} drifts {}",
                o.source, o.seed, o.two_over_single, o.beta_change, o.called_two, o.drifts
            );
        }
        let f = FalseAlarms::of(&outcomes);
        println!("{f:?}\nunrecorded: {unrecorded:?}");
        let path = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../snapshots/model_choice.json"
        );
        if std::env::var_os("ROLLING_DISK_BLESS").is_some() {
            let s = StoredStudy {
                command: REGENERATE.into(),
                date: std::env::var("ROLLING_DISK_DATE").unwrap_or_else(|_| "unknown".into()),
                seed0: SEED0,
                seeds: SEEDS,
                unrecorded,
                outcomes,
            };
            let text = serde_json::to_string_pretty(&s).unwrap() + "\n";
            std::fs::write(path, text).unwrap();
            return;
        }
        let s = stored().unwrap();
        assert_eq!((s.seed0, s.seeds), (SEED0, SEEDS));
        assert_eq!(s.unrecorded, unrecorded);
        assert_eq!(s.outcomes.len(), outcomes.len());
        for (a, b) in s.outcomes.iter().zip(&outcomes) {
            same(a, b);
        }
    }

    /// Two outcomes agree: the same record, verdicts, and numbers to 1e-6 (relative).
    fn same(stored: &RecordOutcome, now: &RecordOutcome) {
        let close = |a: Option<f64>, b: Option<f64>| match (a, b) {
            (Some(a), Some(b)) => (a - b).abs() <= 1e-6 * a.abs().max(1.0),
            (a, b) => a.is_none() && b.is_none(),
        };
        assert_eq!(
            (&stored.source, stored.seed, stored.refused.is_some()),
            (&now.source, now.seed, now.refused.is_some())
        );
        assert_eq!(
            (stored.called_two, stored.drifts),
            (now.called_two, now.drifts)
        );
        assert!(
            close(stored.two_over_single, now.two_over_single),
            "{stored:?} {now:?}"
        );
        assert!(
            close(stored.beta_change, now.beta_change),
            "{stored:?} {now:?}"
        );
    }

    /// A few records of the stored study re-run (eq 79 exactly at beta = 2, eq 75's model,
    /// viscous rolling friction; seed 1) give the stored outcomes: the stored study is this
    /// code's.
    #[test]
    fn a_few_stored_records_are_reproduced() {
        let (outcomes, unrecorded) = study(&[1, 4, 6], 1, SEED0).unwrap();
        assert!(unrecorded.is_empty(), "{unrecorded:?}");
        let s = stored().unwrap();
        for now in &outcomes {
            let st = s
                .outcomes
                .iter()
                .find(|o| o.source == now.source && o.seed == now.seed)
                .unwrap_or_else(|| panic!("{now:?} not stored"));
            same(st, now);
        }
    }

    /// The stored study: no record of one mechanism is called two mechanisms, though BIC
    /// prefers the two-mechanism law decisively on every simulated spin-down; eq 79 exactly
    /// never prefers it.
    #[test]
    fn single_mechanism_records_are_not_called_two() {
        let s = stored().unwrap();
        let f = FalseAlarms::of(&s.outcomes);
        println!("{f:?}\n{}", calibration_sentence());
        assert_eq!(f.records, SEEDS as usize * (SOURCES - s.unrecorded.len()));
        assert_eq!(f.called_two, 0, "{f:?}");
        assert!(f.max_beta_change < MIN_EXPONENT_CHANGE, "{f:?}");
        for o in &s.outcomes {
            if o.source.starts_with("eq 79") {
                assert!(o.two_over_single.is_some_and(|x| x < 0.0), "{o:?}");
            }
        }
        assert!(f.decisive_by_bic > 0, "{f:?}");
    }
}
