//! The stored calibration of the model choice (`snapshots/model_choice.json`, made by
//! [`crate::model_choice`]): each single-mechanism record's outcome, the false alarms they
//! count, and the sentence every comparison states.

use crate::error::ExperimentError;
use serde::{Deserialize, Serialize};

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
    /// Whether the comparison called two mechanisms (their law first, admitted by
    /// [`admits_two`]).
    pub called_two: bool,
    /// Whether the later half's refit says eq 79 drifts over the window.
    pub drifts: bool,
}

/// A stored study: its records' outcomes and where they came from.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StoredStudy {
    /// The command that ran it.
    pub command: String,
    /// When (ISO date).
    pub date: String,
    /// Noise seeds per source: `seed0 .. seed0 + seeds`.
    pub seed0: u64,
    /// How many seeds per source.
    pub seeds: u64,
    /// Sources that gave no record, with the reason.
    pub unrecorded: Vec<String>,
    /// Each record's outcome.
    pub outcomes: Vec<RecordOutcome>,
}

/// The stored study (`snapshots/model_choice.json`).
pub fn stored() -> Result<StoredStudy, ExperimentError> {
    serde_json::from_str(include_str!("../../../../snapshots/model_choice.json")).map_err(|e| {
        ExperimentError::Setting(format!(
            "snapshots/model_choice.json does not hold the model-choice calibration ({e}): run \
             ROLLING_DISK_BLESS=1 cargo test --release -p studies --lib law_choice_study -- --ignored"
        ))
    })
}

/// What a study says of the model choice on records of one mechanism.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FalseAlarms {
    /// Records analysed (refused ones included).
    pub records: usize,
    /// Records the analysis refused (no model choice).
    pub refused: usize,
    /// Records whose least BIC was the two-mechanism law's.
    pub preferred_by_bic: usize,
    /// Of those, by more than 10 (Kass & Raftery's "decisive").
    pub decisive_by_bic: usize,
    /// Records on which two mechanisms were called ([`admits_two`]): the false alarms.
    pub called_two: usize,
    /// The largest $|\beta_2 - \beta_1|$ among the records whose BIC prefers two mechanisms.
    pub max_beta_change: f64,
    /// The range of $\Delta\mathrm{BIC}_2$ among the records.
    pub two_over_single: (f64, f64),
}

impl FalseAlarms {
    /// Counts the outcomes.
    pub fn of(outcomes: &[RecordOutcome]) -> Self {
        let fitted: Vec<&RecordOutcome> = outcomes.iter().filter(|o| o.refused.is_none()).collect();
        let d: Vec<f64> = fitted.iter().filter_map(|o| o.two_over_single).collect();
        Self {
            records: outcomes.len(),
            refused: outcomes.len() - fitted.len(),
            preferred_by_bic: d.iter().filter(|&&x| x > 0.0).count(),
            decisive_by_bic: d.iter().filter(|&&x| x > 10.0).count(),
            called_two: fitted.iter().filter(|o| o.called_two).count(),
            max_beta_change: fitted
                .iter()
                .filter(|o| o.two_over_single.is_some_and(|x| x > 0.0))
                .filter_map(|o| o.beta_change)
                .map(f64::abs)
                .fold(0.0, f64::max),
            two_over_single: d
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
                    (a.min(x), b.max(x))
                }),
        }
    }
}

/// One sentence on the stored calibration: how often two mechanisms are called on records of
/// one mechanism, and with which seeds.
pub fn calibration_sentence() -> &'static str {
    static SENTENCE: std::sync::OnceLock<String> = std::sync::OnceLock::new();
    SENTENCE.get_or_init(|| match stored() {
        Ok(s) => {
            let f = FalseAlarms::of(&s.outcomes);
            format!(
                "calibrated on {} simulated records of one mechanism (eq 79 exactly, eq 75's \
                 model, six mechanisms alone; noise seeds {}-{}; snapshots/model_choice.json, \
                 {}): BIC prefers two mechanisms on {} of the {} analysed ({} decisively, by up \
                 to {:.0}) with exponent changes of at most {:.2}; two mechanisms called on {} \
                 of {} ({:.1} %)",
                f.records,
                s.seed0,
                s.seed0 + s.seeds - 1,
                s.date,
                f.preferred_by_bic,
                f.records - f.refused,
                f.decisive_by_bic,
                f.two_over_single.1,
                f.max_beta_change,
                f.called_two,
                f.records - f.refused,
                100.0 * f.called_two as f64 / (f.records - f.refused).max(1) as f64
            )
        }
        Err(e) => e.to_string(),
    })
}
