//! The report's JSON document (`report.json`): every equation and claim with its outcome, the
//! figures, the corrections and each part's record, with numbers as numbers.

use super::json::{self, outcome_for, Document};
use super::{FigureView, RunSettings};
use checks::check::{Checked, Subject};
use checks::equations::{Bench, UNCHECKABLE_CLAIMS, UNCHECKABLE_EQUATIONS};
use checks::mutation::StoredScores;

/// The paper, as the report names it.
pub const PAPER: &str =
    "A. J. McDonald and K. T. McDonald, The Rolling Motion of a Disk on a Horizontal Plane (2001)";

/// The records of the studies the document carries as they are.
pub struct Records {
    /// The corrected forms' records.
    pub corrections: Vec<json::CorrectionRecord>,
    /// The parts' records.
    pub parts: crate::parts::record::PartRecords,
}

/// The checked equation `n`, if it was checked.
pub fn equation_checked(checked: &[Checked], n: u32) -> Option<&Checked> {
    checked
        .iter()
        .find(|c| matches!(c.subject, Subject::Equation { number, .. } if number == n))
}

/// The JSON document of a report on `bench`'s paper.
pub fn document(
    bench: &Bench,
    checked: &[Checked],
    stored: Option<&StoredScores>,
    settings: &RunSettings,
    figure_views: &[FigureView],
    records: Records,
) -> Document {
    Document {
        header: json::Header::new(
            json::SCHEMA_ID,
            PAPER,
            bench.paper,
            json::Settings {
                method: settings.method.clone(),
                rtol: settings.rtol,
                command: settings.command.clone(),
            },
            checked,
        ),
        equations: bench
            .paper
            .equations
            .iter()
            .map(|e| &e.entry)
            .map(|e| json::EquationRecord {
                number: e.number,
                section: e.section,
                latex: e.latex.clone(),
                kind: e.kind.clone(),
                premises: e.premises.clone(),
                outcome: outcome_for(
                    checked,
                    |s| matches!(s, Subject::Equation { number, .. } if *number == e.number),
                    UNCHECKABLE_EQUATIONS
                        .iter()
                        .find(|(n, _)| *n == e.number)
                        .map(|(_, why)| *why),
                ),
                derivation: equation_checked(checked, e.number).and_then(json::derivation_outcome),
                cause: equation_checked(checked, e.number).and_then(|c| c.cause.clone()),
                cause_text: equation_checked(checked, e.number)
                    .and_then(|c| c.cause.as_ref().map(checks::cause::Cause::describe)),
                mutants: stored.and_then(|st| st.of(e.number)).cloned(),
            })
            .collect(),
        claims: bench
            .paper
            .claims
            .iter()
            .map(|c| json::ClaimRecord {
                id: c.id.clone(),
                section: c.section,
                near_equation: c.near_equation,
                also_at: c
                    .also_at
                    .iter()
                    .map(|l| json::Place {
                        section: l.section,
                        near_equation: l.near_equation,
                    })
                    .collect(),
                printed_value: c.claimed_value,
                rule: c
                    .rule
                    .as_ref()
                    .map(|r| r.describe(c.claimed_value, &c.unit)),
                unit: c.unit.clone(),
                outcome: outcome_for(
                    checked,
                    |s| matches!(s, Subject::Claim { id } if *id == c.id),
                    UNCHECKABLE_CLAIMS
                        .iter()
                        .find(|(id, _)| *id == c.id)
                        .map(|(_, why)| *why),
                ),
            })
            .collect(),
        figures: figure_views
            .iter()
            .map(|f| json::FigureRecord {
                name: f.name.clone(),
                title: f.title.clone(),
                file: f.file.clone(),
            })
            .collect(),
        corrections: records.corrections,
        parts: records.parts,
    }
}
