//! The paper's reduced equations of motion (eqs 23-25) against the independent lab-frame
//! Newton-Euler model, over time: how far apart the two integrations drift.

use crate::figures::chart::{Legend, Plot, Series, Style};
use crate::figures::FigureError;
use crate::figures::{max_per_bin, Drawing, Figure, Panels};
use physics::model::Motion;
use studies::lab_frame::{Compared, SCENES};

/// One panel and the largest differences (alpha, Omega, omega1).
/// Differences below this are drawn at it (the log axis's floor); exact agreement has no
/// logarithm.
const FLOOR: f64 = 1e-17;

fn panel(c: &Compared, title: &str, legend: Legend) -> (Plot, [f64; 4]) {
    let (t, a, b) = (&c.t, &c.reduced, &c.lab);
    let diff = |f: &dyn Fn(&Motion) -> f64| -> Vec<(f64, f64)> {
        t.iter()
            .zip(a.iter().zip(b))
            .map(|(t, (x, y))| (*t, (f(x) - f(y)).abs()))
            .collect()
    };
    let da = diff(&|m| m.alpha);
    let dad = diff(&|m| m.alpha_dot);
    let dp = diff(&|m| m.precession);
    let ds = diff(&|m| m.spin);
    let max = |v: &[(f64, f64)]| v.iter().map(|p| p.1).fold(0.0, f64::max);
    let worst = [max(&da), max(&dad), max(&dp), max(&ds)];
    let top = worst.iter().copied().fold(FLOOR, f64::max);
    // The upper envelope over 120 time bins, floored.
    let env = |v: &[(f64, f64)]| -> Vec<(f64, f64)> {
        max_per_bin(
            &v.iter()
                .map(|&(t, d)| (t, d.max(FLOOR)))
                .collect::<Vec<_>>(),
            120,
        )
    };
    let plot = Plot::new(title, "time t (s)", "|reduced - lab frame| (rad, rad/s)")
        .log(false, true)
        .y_range(FLOOR / 2.0, top * 1e4)
        .with(Series::new("α (rad)", env(&da), Style::Line))
        .with(Series::new("dα/dt (rad/s)", env(&dad), Style::Dashed))
        .with(Series::new("Ω (rad/s)", env(&dp), Style::Line))
        .with(Series::new("ω₁ (rad/s)", env(&ds), Style::Dotted))
        .legend_at(legend);
    (plot, worst)
}

/// The figure: the nutating coin and the wheel rolling straight, side by side, from the runs
/// of [`SCENES`] in that order (no integration here).
pub fn figure(runs: &[Compared]) -> Result<Figure, FigureError> {
    let [c, w] = runs else {
        return Err("the lab-frame figure needs two compared runs".into());
    };
    if c.scene != SCENES[0].0 || w.scene != SCENES[1].0 {
        return Err(format!(
            "the lab-frame figure needs the runs of {} and {}, in that order",
            SCENES[0].0, SCENES[1].0
        )
        .into());
    }
    let (coin, wc) = panel(c, "nutating coin", Legend::Hidden);
    let (wheel, ww) = panel(w, "wheel rolling straight", Legend::UpperRight);
    Ok(Figure {
        name: "lab-frame-difference",
        title: "The paper's equations of motion against a lab-frame model".into(),
        caption: super::captions::caption(
            "lab-frame-difference",
            &serde_json::json!({
                "coin_alpha": format!("{:.1e}", wc[0]),
                "coin_alpha_dot": format!("{:.1e}", wc[1]),
                "coin_precession": format!("{:.1e}", wc[2]),
                "coin_spin": format!("{:.1e}", wc[3]),
                "wheel_alpha": format!("{:.1e}", ww[0]),
                "wheel_alpha_dot": format!("{:.1e}", ww[1]),
                "wheel_precession": format!("{:.1e}", ww[2]),
                "wheel_spin": format!("{:.1e}", ww[3]),
            }),
        )?,
        drawing: Drawing::Panels(Panels {
            title: "Reduced model (eqs 23-25) against the lab-frame model".into(),
            plots: vec![coin, wheel],
        }),
    })
}
