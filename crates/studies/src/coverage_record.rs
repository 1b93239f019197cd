//! The coverage studies as the report shows them: run once by a command in the repository,
//! stored in `snapshots/coverage.json`, and proved current by a test.
//!
//! A study of hundreds of recordings takes minutes, far beyond the report's one second, so the
//! report does not run it: it draws the stored result ([`stored`]) and says which command made
//! it and when. Each recording is seeded by its index, so the stored pulls can be checked one
//! by one: the suite re-runs the first recordings of each study and asserts the same pulls to
//! the last bit (`tests/coverage_record.rs`). A stored file made by other code, or edited by
//! hand, fails that test; a change to the analysis that moves any pull makes it fail until the
//! studies are run again:
//! `ROLLING_DISK_BLESS=1 cargo test --release --test integration coverage_record:: -- --ignored`.

use crate::coverage::{coverage, Coverage};
use crate::sound_coverage::sound_coverage;
use experiment::error::ExperimentError;
use serde::{Deserialize, Serialize};

/// One stored coverage study.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
pub struct StoredCoverage {
    /// Which recordings: "clean" (the scope's noise and quantisation) or "artifact-laden".
    pub recordings: String,
    /// The seed of the first recording; recording `k` has seed `seed0 + k`.
    pub seed0: u64,
    /// Whether each recording carries realistic artifacts.
    pub artifacts: bool,
    /// Whether the recordings are sound ([`sound_coverage`]; else the light signal).
    #[serde(default)]
    pub sound: bool,
    /// The command that ran it.
    pub command: String,
    /// When (ISO date).
    pub date: String,
    /// The result.
    pub coverage: Coverage,
}

/// The studies the report draws, as `snapshots/coverage.json` holds them.
pub fn stored() -> Result<Vec<StoredCoverage>, ExperimentError> {
    serde_json::from_str(include_str!("../../../snapshots/coverage.json")).map_err(|e| {
        ExperimentError::Setting(format!(
            "snapshots/coverage.json does not hold the coverage studies ({e}): run \
             ROLLING_DISK_BLESS=1 cargo test --release --test integration coverage_record:: -- --ignored"
        ))
    })
}

/// The study of `runs` recordings from `seed0`: of sound when `sound` (phone recordings with
/// hum, whatever `artifacts` says), else of the light signal, with artifacts when `artifacts`.
pub fn study(
    runs: usize,
    seed0: u64,
    artifacts: bool,
    sound: bool,
) -> Result<Coverage, ExperimentError> {
    if sound {
        sound_coverage(runs, seed0)
    } else {
        coverage(runs, seed0, artifacts)
    }
}

/// Runs a study of `runs` recordings from `seed0` (see [`study`]) and records how it was made.
pub fn run(
    recordings: &str,
    (runs, seed0): (usize, u64),
    (artifacts, sound): (bool, bool),
    command: &str,
    date: &str,
) -> Result<StoredCoverage, ExperimentError> {
    Ok(StoredCoverage {
        recordings: recordings.to_string(),
        seed0,
        artifacts,
        sound,
        command: command.to_string(),
        date: date.to_string(),
        coverage: study(runs, seed0, artifacts, sound)?,
    })
}

impl StoredCoverage {
    /// One line: which recordings, the summary, and where it came from.
    pub fn line(&self) -> String {
        format!(
            "{} (seeds {}-{}): {} [{}, {}]",
            self.recordings,
            self.seed0,
            self.seed0 + self.coverage.runs as u64 - 1,
            self.coverage.summary(),
            self.command,
            self.date
        )
    }
}
