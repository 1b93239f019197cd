//! The section "Coverage of the stated uncertainties": whether the experiment's intervals
//! mean what they say, from the stored Monte Carlo studies ([`studies::coverage_record`]), as a
//! paragraph, a table of the fractions inside ±1σ and ±1.96σ with their binomial
//! uncertainties, and the stored studies' own lines for the disclosure and the appendix.

use crate::error::ReportError;
use crate::number::{error, measured, prose};
use crate::parts::prose::{paragraph, table};
use crate::study_table::{cite, StudySection, StudyTable};
use studies::coverage::Coverage;
use studies::coverage_record::StoredCoverage;

/// The fraction of `c`'s recordings with `pulls` inside ±`z`, in percent, with its binomial
/// standard uncertainty $\sqrt{p(1-p)/N}$.
fn inside(c: &Coverage, pulls: &[f64], z: f64) -> String {
    let p = c.fraction(pulls, z);
    let n = c.runs.max(1) as f64;
    measured(100.0 * p, 100.0 * (p * (1.0 - p) / n).sqrt())
}

/// The mean and the standard deviation of `pulls`, each with its standard uncertainty
/// ($s/\sqrt{n}$ and $s/\sqrt{2(n-1)}$ for a normal sample).
fn moments(pulls: &[f64]) -> (String, String) {
    let (m, s) = Coverage::moments(pulls);
    let n = pulls.len().max(2) as f64;
    (
        measured(m, s / n.sqrt()),
        measured(s, s / (2.0 * (n - 1.0)).sqrt()),
    )
}

/// The table: for each stored study, β and t₀.
pub fn tables(stored: &[StoredCoverage]) -> Result<Vec<StudyTable>, ReportError> {
    let mut t = table(
        &super::ABOUT.templates,
        "table-coverage",
        &serde_json::json!({}),
        &[
            "recordings",
            "fitted",
            "inside ±1σ (%)",
            "inside ±1.96σ (%)",
            "pulls: mean",
            "pulls: sd",
            "worst error",
        ],
    )?;
    for s in stored {
        let c = &s.coverage;
        let law = if s.sound {
            "eq 79 on the phase"
        } else {
            "eq 84"
        };
        let rows = [
            (
                format!("β, {law}"),
                &c.beta_pulls,
                error(c.worst_beta_error),
            ),
            (
                format!("t₀, {law}"),
                &c.t0_pulls,
                error(1e3 * c.worst_t0_error),
            ),
        ];
        for (what, pulls, worst) in rows {
            let (mean, sd) = moments(pulls);
            t.row(vec![
                format!("{} ({})", s.recordings, c.runs),
                what,
                inside(c, pulls, 1.0),
                inside(c, pulls, 1.96),
                mean,
                sd,
                worst,
            ]);
        }
    }
    Ok(vec![t])
}

/// The section, its tables numbered already; `figure` is the coverage figure's number. Its
/// paragraph is `templates/parts/coverage/summary.txt.tera`.
pub fn section(
    stored: &[StoredCoverage],
    tables: Vec<StudyTable>,
    figure: Option<usize>,
) -> Result<StudySection, ReportError> {
    let found: Vec<serde_json::Value> = stored
        .iter()
        .map(|s| {
            let c = &s.coverage;
            serde_json::json!({
                "recordings": s.recordings,
                "beta_1": inside(c, &c.beta_pulls, 1.0),
                "beta_2": inside(c, &c.beta_pulls, 1.96),
                "t0_1": inside(c, &c.t0_pulls, 1.0),
                "t0_2": inside(c, &c.t0_pulls, 1.96),
            })
        })
        .collect();
    let runs: Vec<String> = stored
        .iter()
        .map(|s| format!("{} {}", s.coverage.runs, s.recordings))
        .collect();
    let refused: usize = stored.iter().map(|s| s.coverage.refused).sum();
    let mut made: Vec<String> = stored.iter().map(|s| s.date.clone()).collect();
    made.dedup();
    let values = serde_json::json!({
        "runs": runs,
        "refused": refused,
        "found": found,
        "tables": cite(&tables),
        "figure": figure,
        "made": made,
    });
    let summary = paragraph(&super::ABOUT.templates, "summary", &values)?;
    Ok(StudySection {
        title: "Coverage of the stated uncertainties".into(),
        summary,
        tables,
        output: prose(
            &stored
                .iter()
                .map(StoredCoverage::line)
                .collect::<Vec<_>>()
                .join("\n"),
        ),
        output_title: "The stored studies as they record themselves: seeds, summary, command"
            .into(),
    })
}
