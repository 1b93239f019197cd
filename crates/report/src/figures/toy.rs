//! The peer program's stored runs against this tool (`studies::peer::stored`): the tilt over
//! time of both, and the tilt difference over time on a log scale, with the peer's slip
//! regularization as in its source and set far below it.

use crate::figures::chart::{Axis, Legend, Plot, Series, Style};
use crate::figures::FigureError;
use crate::figures::{Drawing, Figure, Panels};
use studies::peer::stored::{Differences, StoredComparison};
use studies::toy::Toy;

/// Points of a series: (x, y).
type Points = Vec<(f64, f64)>;

/// Differences below this are drawn at it (the log axis's floor): equal printed digits differ
/// by exactly 0.
const FLOOR: f64 = 1e-10;

/// The runs the tilt figure shows.
const SHOWN: [&str; 2] = ["thick-slip-stick", "thick-long-spin-down"];

fn run<'t>(t: &'t Toy, name: &str) -> Result<&'t StoredComparison, FigureError> {
    t.peer
        .iter()
        .find(|c| c.name == name)
        .ok_or_else(|| format!("the peer figures need the stored run {name}").into())
}

/// The tilt (deg) of this tool and of the peer, from the print times of `d`.
fn tilts(d: &Differences) -> (Points, Points) {
    d.tilts
        .iter()
        .map(|r| ((r[0], r[1].to_degrees()), (r[0], r[2].to_degrees())))
        .unzip()
}

/// The tilt over time, this tool against the peer, for the runs of [`SHOWN`].
pub fn tilt(t: &Toy) -> Result<Figure, FigureError> {
    let mut plots = Vec::new();
    let mut words = Vec::new();
    for (i, name) in SHOWN.iter().enumerate() {
        let c = run(t, name)?;
        let Some(sharp) = &c.sharp else {
            return Err(format!("the stored run {name} has no eps-1e-7 run").into());
        };
        let (mine, peer) = tilts(&c.regularized);
        let (_, peer_sharp) = tilts(sharp);
        plots.push(
            Plot::new(*name, "time t (s)", "tilt α (°)")
                .with(Series::new("this tool", mine, Style::Points))
                .with(Series::new("peer, ε = 1e-3 m/s", peer, Style::Squares))
                .with(Series::new(
                    "peer, ε = 1e-7 m/s",
                    peer_sharp,
                    Style::Crosses,
                ))
                .legend_at(if i == 0 { Legend::Auto } else { Legend::Hidden }),
        );
        words.push(format!(
            "{} ({}): largest difference {:.1e} rad, {:.1e} rad with ε = 1e-7 m/s",
            name, c.words, c.regularized.tilt, sharp.tilt
        ));
    }
    Ok(Figure {
        name: "peer-tilt",
        title: "The toy's tilt: this tool against M. Batista's program".into(),
        caption: super::captions::caption(
            "peer-tilt",
            &serde_json::json!({
                "left": format!("{}", words[0]),
                "right": format!("{}", words[1]),
            }),
        )?,
        drawing: Drawing::Panels(Panels {
            title: "Tilt of the toy over time".into(),
            plots,
        }),
    })
}

/// The largest tilt difference against the peer with $\varepsilon = 10^{-7}$ m/s, of the runs
/// whose peer record restarted its clock if `restarted`, else of all.
fn sharpest(runs: &[&StoredComparison], restarted: bool) -> f64 {
    runs.iter()
        .filter(|c| c.restarted || !restarted)
        .filter_map(|c| c.sharp.as_ref().map(|d| d.tilt))
        .fold(0.0, f64::max)
}

/// The tilt difference over time of every stored run with both regularizations.
pub fn difference(t: &Toy) -> Result<Figure, FigureError> {
    let both: Vec<&StoredComparison> = t.peer.iter().filter(|c| c.sharp.is_some()).collect();
    let others: Vec<&str> = t
        .peer
        .iter()
        .filter(|c| c.sharp.is_none())
        .map(|c| c.name.as_str())
        .collect();
    let floored = |d: &Differences| -> Vec<(f64, f64)> {
        d.tilt_gap.iter().map(|&(t, x)| (t, x.max(FLOOR))).collect()
    };
    let top = both
        .iter()
        .map(|c| c.regularized.tilt)
        .fold(FLOOR, f64::max);
    let panel = |title: &str, pick: &dyn Fn(&StoredComparison) -> Option<Points>, legend| {
        let mut p = Plot::new(title, "time t (s)", "|Δα| (rad)")
            .log(false, true)
            .y_range(FLOOR / 2.0, top * 1e5)
            .mark(Axis::Y, 5e-8, "the peer's printed digits")
            .legend_at(legend);
        for (i, c) in both.iter().enumerate() {
            // Past the palette's colours, the same colours dashed.
            let style = if i < crate::figures::chart::PALETTE.len() {
                Style::Line
            } else {
                Style::Dashed
            };
            if let Some(points) = pick(c) {
                p = p.with(Series::new(c.name.clone(), points, style));
            }
        }
        p
    };
    let left = panel(
        "ε = 1e-3 m/s (the peer's source)",
        &|c| Some(floored(&c.regularized)),
        Legend::Hidden,
    );
    let right = panel(
        "ε = 1e-7 m/s",
        &|c| c.sharp.as_ref().map(floored),
        Legend::UpperRight,
    );
    Ok(Figure {
        name: "peer-difference",
        title: "How far this tool and M. Batista's program differ in tilt".into(),
        caption: super::captions::caption(
            "peer-difference",
            &serde_json::json!({
                "scenes": format!("{}", both.len()),
                "FLOOR": format!("{:.0e}", FLOOR),
                "source_max": format!("{}", crate::number::scientific(top, 2)),
                "regularized_max": format!("{}", crate::number::scientific(sharpest(&both, false), 2)),
                "fine_max": format!("{}", crate::number::scientific(sharpest(&both, true), 2)),
                "undrawn": format!("{}", others.join(", ")),
            }),
        )?,
        drawing: Drawing::Panels(Panels {
            title: "Tilt difference, this tool against the peer".into(),
            plots: vec![left, right],
        }),
    })
}
