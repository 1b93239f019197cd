//! The section "Speed against accuracy": the benchmark scene integrated by each method over a
//! range of steps or tolerances, as a paragraph, a table of what each method costs for an
//! accuracy, and every run's numbers for the disclosure and the appendix (and `report.json`).

use crate::error::ReportError;
use crate::number::{error, places, scientific};
use crate::parts::prose::{paragraph, table};
use crate::study_table::{cite, StudySection, StudyTable};
use physics::solve::Method;
use schemars::JsonSchema;
use serde::Serialize;
use studies::precision::{reference, Series, Study};

/// The accuracy the table prices: the largest relative error over the run.
const TARGET: f64 = 1e-8;

/// The cheapest complete run of `s` whose largest error over the run is within [`TARGET`].
fn cheapest(s: &Series) -> Option<u64> {
    s.points
        .iter()
        .filter(|p| p.ending.is_complete() && p.trajectory_error <= TARGET)
        .map(|p| p.evaluations)
        .min()
}

/// The most accurate complete run of `s`: (largest error over the run, evaluations).
fn best(s: &Series) -> Option<(f64, u64)> {
    s.points
        .iter()
        .filter(|p| p.ending.is_complete())
        .map(|p| (p.trajectory_error, p.evaluations))
        .min_by(|a, b| a.0.total_cmp(&b.0))
}

/// The table: one row per method.
pub fn tables(study: &Study) -> Result<Vec<StudyTable>, ReportError> {
    let values = serde_json::json!({
        "target": error(TARGET),
        "reference": error(study.reference.uncertainty),
    });
    let mut t = table(
        &super::ABOUT.templates,
        "table-cost",
        &values,
        &[
            "method",
            "order, nominal",
            "order, observed",
            &format!("evaluations for {}", error(TARGET)),
            "least error",
            "its evaluations",
        ],
    )?;
    for s in &study.series {
        let best = best(s);
        t.row(vec![
            s.method.to_string(),
            s.nominal_order.to_string(),
            s.observed_order.map_or("–".into(), |o| places(o, 2)),
            cheapest(s).map_or("not reached".into(), |n| n.to_string()),
            best.map_or("–".into(), |b| error(b.0)),
            best.map_or("–".into(), |b| b.1.to_string()),
        ]);
    }
    Ok(vec![t])
}

/// Every run, one per line, for the disclosure and the appendix.
fn output(study: &Study) -> String {
    let mut lines = vec![format!(
        "{:<20} {:>11} {:>16} {:>16}",
        "run", "evaluations", "error at the end", "largest error"
    )];
    for p in study.series.iter().flat_map(|s| &s.points) {
        lines.push(format!(
            "{:<20} {:>11} {:>16} {:>16}",
            p.label,
            p.evaluations,
            error(p.final_error),
            error(p.trajectory_error)
        ));
    }
    lines.join("\n")
}

/// One run of the speed/accuracy study.
#[derive(Debug, Clone, PartialEq, Serialize, JsonSchema)]
pub struct PrecisionRecord {
    /// Method and tolerance.
    pub label: String,
    /// Right-hand-side evaluations.
    pub evaluations: u64,
    /// Relative error at the final time.
    pub final_error: f64,
    /// Largest relative error over the run.
    pub trajectory_error: f64,
}

/// Every run's numbers, for `report.json`.
pub fn records(study: &Study) -> Vec<PrecisionRecord> {
    study
        .series
        .iter()
        .flat_map(|s| &s.points)
        .map(|p| PrecisionRecord {
            label: p.label.clone(),
            evaluations: p.evaluations,
            final_error: p.final_error,
            trajectory_error: p.trajectory_error,
        })
        .collect()
}

/// The section, its tables numbered already; `figure` is the work-precision figure's number.
/// Its paragraph is `templates/parts/precision/summary.txt.tera`.
pub fn section(
    study: &Study,
    tables: Vec<StudyTable>,
    figure: Option<usize>,
) -> Result<StudySection, ReportError> {
    let costs: Vec<String> = study
        .series
        .iter()
        .map(|s| match cheapest(s) {
            Some(n) => format!("{} needs {n}", s.method),
            None => format!("{} does not reach it", s.method),
        })
        .collect();
    let runs: usize = study.series.iter().map(|s| s.points.len()).sum();
    let rtols = study
        .series
        .iter()
        .flat_map(|s| &s.points)
        .filter(|p| p.method != Method::Rk4)
        .map(|p| p.settings.rtol);
    let (tightest, loosest) = rtols.fold((f64::INFINITY, 0.0_f64), |(lo, hi), r| {
        (lo.min(r), hi.max(r))
    });
    let values = serde_json::json!({
        "runs": runs,
        "loosest": scientific(loosest, 1),
        "tightest": scientific(tightest, 1),
        "reference": reference::label(&study.reference.trace.settings),
        "reference_error": error(study.reference.uncertainty),
        "target": error(TARGET),
        "costs": costs,
        "figure": figure,
        "tables": cite(&tables),
    });
    let summary = paragraph(&super::ABOUT.templates, "summary", &values)?;
    Ok(StudySection {
        title: "Speed against accuracy".into(),
        summary,
        tables,
        output: output(study),
        output_title: "Every run: its evaluations and errors".into(),
    })
}
