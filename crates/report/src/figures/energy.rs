//! Energy drift of each integration method on the benchmark scene: $|E(t) - E_0|/E_0$ with
//! $E$ from eq 26, which the rolling model conserves exactly.

use crate::figures::chart::{Legend, Plot, Series, Style};
use crate::figures::FigureError;
use crate::figures::{max_per_bin, Drawing, Figure};
use crate::study::energy_drift::{DriftCurve, Stepping};

/// How a run's curve is drawn: fixed steps and DOP853 solid, DOPRI5 dashed, DOP853 projected
/// onto the energy dotted.
fn style(run: &DriftCurve) -> Style {
    match run.stepping {
        Stepping::Dopri5 => Style::Dashed,
        Stepping::Dop853Projected => Style::Dotted,
        Stepping::FixedStep | Stepping::Dop853 => Style::Line,
    }
}

/// The figure, from the study's runs (no integration here).
pub fn figure(runs: &[DriftCurve]) -> Result<Figure, FigureError> {
    let mut plot = Plot::new(
        "Energy drift on the benchmark scene",
        "time t (s)",
        "|E(t) − E₀| / E₀ (relative)",
    )
    .log(false, true)
    .legend_at(Legend::UpperRight);
    let mut lowest = f64::INFINITY;
    let mut summary = Vec::new();
    for run in runs {
        let last = run.drift.last().map_or(0.0, |p| p.1);
        summary.push(format!(
            "{}: {last:.1e} at 10 s, {} evaluations",
            run.label, run.evaluations
        ));
        let shown = max_per_bin(&run.drift, 300);
        lowest = shown.iter().map(|p| p.1).fold(lowest, f64::min);
        plot = plot.with(Series::new(run.label.clone(), shown, style(run)));
    }
    // Room above the curves for the legend.
    let plot = plot.y_range(lowest.max(1e-18) / 2.0, 1e-3);
    Ok(Figure {
        name: "energy-drift",
        title: "Energy drift of each method".into(),
        caption: super::captions::caption(
            "energy-drift",
            &serde_json::json!({
                "methods": format!("{}", summary.join("; ")),
            }),
        )?,
        drawing: Drawing::Plot(plot),
    })
}
