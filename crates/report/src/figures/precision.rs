//! The work-precision figure of the speed/accuracy study: for each integration method, the
//! largest relative error over the benchmark run against the right-hand-side evaluations it
//! cost, with the reference's own uncertainty as a floor.

use super::FigureError;
use crate::figures::chart::Chart;
use crate::figures::{Drawing, Figure, Series, Style};
use studies::precision::{reference, Study};

/// The figure, from a finished study (computed once by the report's pipeline; no integration
/// here).
pub fn figure(study: &Study) -> Result<Figure, FigureError> {
    let mut series = Vec::new();
    for s in &study.series {
        let pts: Vec<(f64, f64)> = s
            .points
            .iter()
            .filter(|p| p.ending.is_complete() && p.trajectory_error > 0.0)
            .map(|p| (p.evaluations as f64, p.trajectory_error))
            .collect();
        series.push(Series::new(s.method.to_string(), pts, Style::Line));
    }
    let floor = study.reference.uncertainty;
    let (x0, x1) = (3e2, 3e5);
    series.push(Series::new(
        format!("reference uncertainty {floor:.1e}"),
        vec![(x0, floor), (x1, floor)],
        Style::Dashed,
    ));
    let chart = Chart {
        title: "Work against precision, benchmark scene (10 s)".into(),
        x_label: "right-hand-side evaluations (count)".into(),
        y_label: "largest relative error over the run (dimensionless)".into(),
        x_log: true,
        y_log: true,
        series,
    };
    Ok(Figure {
        name: "work-precision",
        title: "Speed against accuracy".into(),
        caption: super::captions::caption(
            "work-precision",
            &serde_json::json!({
                "settings": format!("{}", reference::label(&study.reference.trace.settings)),
            }),
        )?,
        drawing: Drawing::Chart(chart),
    })
}
