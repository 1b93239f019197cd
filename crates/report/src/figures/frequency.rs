//! Measured against predicted frequency of small oscillations about steady motion, across the
//! tilt: $\varpi/\Omega_0$ measured on integrations of the rolling model (b = 0 and b = a/2) and
//! of the frictionless model (b = 0), with the curves of eqs 54, 55 and 71.

use crate::figures::chart::{Legend, Plot, Series, Style};
use crate::figures::stability::{eq54, onset};
use crate::figures::FigureError;
use crate::figures::{Drawing, Figure};
use numerics::oscillation::try_bisect;
use paper::printed::printed_ratio;
use paper::{Bindings, Paper};
use std::f64::consts::FRAC_PI_2;
use studies::frequency::Measured;

/// $\varpi/\Omega_0$ by the printed eq `n` (55 or 71) at tilt `alpha0`, read from the paper.
fn ratio(paper: &Paper, n: u32, k: f64, alpha0: f64) -> Option<f64> {
    printed_ratio(
        paper,
        n,
        &Bindings::new().scalar("k", k).scalar("alpha_0", alpha0),
    )
}

/// Eq 54 at b = a/2 solved for $\varpi/\Omega_0$, where it has a real root.
fn eq54_half(paper: &Paper, k: f64, alpha0: f64) -> Option<f64> {
    let bind = Bindings::new()
        .scalar("k", k)
        .scalar("alpha_0", alpha0)
        .scalar("a", 1.0)
        .scalar("b", 0.5);
    printed_ratio(paper, 54, &bind)
}

/// The largest relative difference of measured points from their curve, and its tilt (deg).
fn worst(points: &[(f64, f64)], curve: &dyn Fn(f64) -> Option<f64>) -> (f64, f64) {
    points
        .iter()
        .fold((0.0, 0.0), |w, &(deg, r)| match curve(deg.to_radians()) {
            Some(p) if (r / p - 1.0).abs() > w.0 => ((r / p - 1.0).abs(), deg),
            _ => w,
        })
}

/// The figure, from the measured frequencies and the paper's eqs 54-56 and 71 (no integration
/// here).
pub fn figure(m: &Measured, paper: &Paper) -> Result<Figure, FigureError> {
    let k = m.k;
    let worst = [
        worst(&m.rolled0, &|a| ratio(paper, 55, k, a)),
        worst(&m.rolled_half, &|a| eq54_half(paper, k, a)),
        worst(&m.slid0, &|a| ratio(paper, 71, k, a)),
    ];
    let (rolled0, rolled_half, slid0) = (m.rolled0.clone(), m.rolled_half.clone(), m.slid0.clone());
    // Where b = a/2 turns unstable: eq 54 at b = a/2 changes sign (bisection).
    let (lo, hi) = (onset(paper, k)?.0, FRAC_PI_2 - 1e-9);
    let negative = |al: f64| eq54(paper, k, al, 0.5).ok().map(|q| q < 0.0);
    let (_, hi) = try_bisect(lo, hi, |_, _| false, negative)
        .ok_or("the frequency figure: eq 54 cannot be evaluated at b = a/2")?;
    let unstable_from = (eq54(paper, k, hi, 0.5)? < 0.0).then(|| hi.to_degrees());
    let curve = |f: &dyn Fn(f64) -> Option<f64>| -> Vec<(f64, f64)> {
        (1..=179)
            .filter_map(|i| {
                let deg = i as f64 * 0.5;
                f(deg.to_radians()).map(|r| (deg, r))
            })
            .collect()
    };
    let c55 = curve(&|a| ratio(paper, 55, k, a));
    let c54 = curve(&|a| eq54_half(paper, k, a));
    let c71 = curve(&|a| ratio(paper, 71, k, a));
    let (blue, vermilion, green) = ([0, 114, 178], [213, 94, 0], [0, 158, 115]);
    let limit = paper
        .right_side(56, &Bindings::new().scalar("k", k))
        .map_err(|e| FigureError::Data(format!("the frequency figure reads eq 56: {e}")))?;
    let plot = Plot::new(
        "Frequency of small oscillations about steady motion (k = 1/4)",
        "tilt α₀ (degrees)",
        "ϖ / Ω₀ (dimensionless)",
    )
    .x_range(0.0, 90.0)
    .with_colored(
        Series::new("eq 55 (rolling, b = 0)", c55, Style::Line),
        blue,
    )
    .with_colored(
        Series::new("measured, rolling, b = 0", rolled0, Style::Points),
        blue,
    )
    .with_colored(
        Series::new("eq 54 (rolling, b = a/2)", c54, Style::Dashed),
        vermilion,
    )
    .with_colored(
        Series::new("measured, rolling, b = a/2", rolled_half, Style::Squares),
        vermilion,
    )
    .with_colored(
        Series::new("eq 71 (no friction, b = 0)", c71, Style::Dotted),
        green,
    )
    .with_colored(
        Series::new("measured, no friction, b = 0", slid0, Style::Triangles),
        green,
    )
    .mark(crate::figures::Axis::Y, limit, format!("eq 56: {limit:.3}"))
    .legend_at(Legend::LowerLeft);
    Ok(Figure {
        name: "frequency",
        title: "Measured against predicted oscillation frequency".into(),
        caption: super::captions::caption(
            "frequency",
            &serde_json::json!({
                "limit": format!("{:.3}", limit),
                "rolling_worst": format!("{:.1e}", worst[0].0),
                "rolling_at": format!("{:.0}", worst[0].1),
                "offset_worst": format!("{:.1e}", worst[1].0),
                "offset_at": format!("{:.0}", worst[1].1),
                "free_worst": format!("{:.1e}", worst[2].0),
                "free_at": format!("{:.0}", worst[2].1),
                "near_vertical": format!("{}", unstable_from.map_or(String::new(), |d| format!(
                "The steady motion with b = a/2 is unstable above {d:.1} deg (see the \
                 stability map), so it has no frequency there. "
            ))),
            }),
        )?,
        drawing: Drawing::Plot(plot),
    })
}
