//! The path of the centre of mass in the plane, for a few of the paper's situations.
//!
//! Rolling without slipping has no radial slippage, so the inward spiral of section 6 (which
//! needs the contact to slip) cannot appear here: the figure shows what the models do.

use crate::figures::chart::{Legend, Plot, Series, Style};
use crate::figures::FigureError;
use crate::figures::{Drawing, Figure, Panels};
use studies::runs::{PathRun, SCENES};

/// A unit for lengths of size `extent` (m): its name and the factor from metres.
fn unit(extent: f64) -> (&'static str, f64) {
    if extent >= 1e-3 {
        ("mm", 1e3)
    } else if extent >= 1e-6 {
        ("µm", 1e6)
    } else {
        ("nm", 1e9)
    }
}

/// The samples from `start` through one turn of the direction of motion (the heading of the
/// path's tangent sweeps 2 pi), or to the end of the run.
fn one_loop(pts: &[(f64, f64)], start: usize) -> &[(f64, f64)] {
    let mut swept = 0.0;
    let mut last: Option<f64> = None;
    for i in start + 1..pts.len() {
        let (dx, dy) = (pts[i].0 - pts[i - 1].0, pts[i].1 - pts[i - 1].1);
        if dx == 0.0 && dy == 0.0 {
            continue;
        }
        let a = dy.atan2(dx);
        if let Some(b) = last {
            let mut d = a - b;
            while d > std::f64::consts::PI {
                d -= std::f64::consts::TAU;
            }
            while d < -std::f64::consts::PI {
                d += std::f64::consts::TAU;
            }
            swept += d;
        }
        last = Some(a);
        if swept.abs() >= std::f64::consts::TAU {
            return &pts[start..=i];
        }
    }
    &pts[start..]
}

/// The figure: three panels side by side, one per run of [`SCENES`] in that order (no
/// integration here).
pub fn figure(runs: &[PathRun]) -> Result<Figure, FigureError> {
    if runs.len() != SCENES.len()
        || runs
            .iter()
            .zip(SCENES)
            .any(|(r, (name, _))| r.scene != name)
    {
        return Err(format!(
            "the path figure needs the runs of {:?}, in that order",
            SCENES.map(|s| s.0)
        )
        .into());
    }
    let mut plots = Vec::new();
    let mut notes = Vec::new();
    let mut loops = String::new();
    for (run, (name, what)) in runs.iter().zip(SCENES) {
        let (t, pts, ending) = (&run.t, &run.xy, &run.ending);
        let (sx, sy) = pts[0];
        let rel: Vec<(f64, f64)> = pts.iter().map(|(x, y)| (x - sx, y - sy)).collect();
        let dist: Vec<f64> = rel.iter().map(|p| p.0.hypot(p.1)).collect();
        let extent = dist.iter().copied().fold(0.0, f64::max);
        let (u, f) = unit(extent);
        let scaled: Vec<(f64, f64)> = rel.iter().map(|(x, y)| (x * f, y * f)).collect();
        let t_end = t.last().copied().unwrap_or(0.0);
        // The farthest the centre gets from its start in the first and the last tenth of the run.
        let far = |from: f64, to: f64| {
            t.iter()
                .zip(&dist)
                .filter(|(t, _)| **t >= from && **t <= to)
                .map(|(_, d)| *d)
                .fold(0.0, f64::max)
        };
        let (early, late) = (far(0.0, 0.1 * t_end), far(0.9 * t_end, t_end));
        notes.push(format!(
            "{what}: {t_end:.2} s ({ending}); farthest from the start {:.3} {u} in the first \
             tenth of the run, {:.3} {u} in the last",
            early * f,
            late * f
        ));
        let mut plot =
            Plot::new(what, format!("x − x₀ ({u})"), format!("y − y₀ ({u})")).equal_aspect();
        if name == "spin-down" {
            // Hundreds of loops of slowly growing radius fill a disc: one loop at each of a
            // few times shows the growth instead.
            // The panel is too narrow for a legend: the caption names the loops' times and
            // colours.
            let mut which = Vec::new();
            for (frac, colour) in [
                (0.05, "blue"),
                (0.5, "orange"),
                (0.9, "green"),
                (0.99, "pink"),
            ] {
                let i = t
                    .partition_point(|x| *x < frac * t_end)
                    .min(scaled.len() - 1);
                which.push(format!("{colour} from t = {:.2} s", t[i]));
                plot = plot.with(Series::new(
                    format!("loop at t = {:.2} s", t[i]),
                    one_loop(&scaled, i).to_vec(),
                    Style::Line,
                ));
            }
            loops = which.join(", ");
            plot = plot.legend_at(Legend::Hidden);
        } else {
            plot = plot
                .with(Series::new(
                    format!("t = 0 to {t_end:.1} s"),
                    scaled.clone(),
                    Style::Line,
                ))
                .with(Series::new("start", vec![scaled[0]], Style::Points))
                .legend_at(Legend::Hidden);
        }
        plots.push(plot);
    }
    Ok(Figure {
        name: "path",
        title: "The path of the centre of mass".into(),
        caption: super::captions::caption(
            "path",
            &serde_json::json!({
                "scenes": format!("{}", notes.join("; ")),
                "loops": loops.to_string(),
            }),
        )?,
        drawing: Drawing::Panels(Panels {
            title: "Path of the centre of mass (rolling without slipping)".into(),
            plots,
        }),
    })
}
