//! The corrected forms of paper/corrections.yaml, checked on the paper with all of them
//! substituted (`checks::corrections`).

use super::{Observer, Study};
use crate::error::ReportError;
use checks::check::Checked;
use checks::corrections::{self, Downstream};
use checks::equations::Bench;
use paper::Correction;
use physics::scene::Scene;

/// The corrections study: the corrected forms, their checks on the paper with all of them
/// substituted, and the dissipation strength the paper's fit means before and after.
#[derive(Debug, Clone)]
pub struct CorrectionsStudy {
    /// paper/corrections.yaml.
    pub corrections: Vec<Correction>,
    /// The corrected equations' checks.
    pub corrected: Vec<Checked>,
    /// $\epsilon$ from the paper's fit, printed and corrected eq 79, for the built-in
    /// spin-down disk.
    pub downstream: Option<Downstream>,
    /// Why the corrections could not be checked on this paper (a `--paper DIR` whose symbols
    /// or equations no longer fit them): the report says so instead of failing.
    pub error: Option<String>,
}

/// The corrections and their checks on the corrected paper.
pub struct Corrections;

impl Study for Corrections {
    type Output = CorrectionsStudy;
    const NAME: &'static str = "corrections";

    fn compute(&self, bench: &Bench, _: &Observer) -> Result<CorrectionsStudy, ReportError> {
        Ok(checked(bench).unwrap_or_else(|e| CorrectionsStudy {
            corrections: Vec::new(),
            corrected: Vec::new(),
            downstream: None,
            error: Some(e.to_string()),
        }))
    }
}

fn checked(bench: &Bench) -> Result<CorrectionsStudy, ReportError> {
    let corrections = bench.paper.corrections.clone();
    let threads = rayon::current_num_threads().max(1);
    let corrected = corrections::check_corrected(bench, &corrections, threads)?;
    let fixed = corrections::apply(bench.paper, &corrections)?;
    let disk = Scene::load("spin-down")?.disk;
    let downstream = corrections::downstream(bench.paper, &fixed, (disk.a, disk.k, disk.g));
    Ok(CorrectionsStudy {
        corrections,
        corrected,
        downstream,
        error: None,
    })
}
