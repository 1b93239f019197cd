//! Figures: the paper's (regenerated from the models) and new ones, each a PURE function of the
//! studies' results ([`Results`], computed once by [`crate::pipeline`]) that returns a
//! [`Figure`] as data. No figure integrates anything: tests/architecture.rs forbids this module
//! to reach the solver, the scene runner, the simulations or the checks. The report renders the
//! figures as inline SVG (HTML) or PNG (LaTeX). Each caption is a text template,
//! `templates/figures/NAME.txt.tera` ([`captions`]), rendered from the figure's numbers.
//!
//! | name | what | file |
//! |---|---|---|
//! | `fig1` | the geometry, from the triad and a steady motion (eqs 1-9, 28-29) | `geometry/` |
//! | `tek04`, `tek01`, `tek02` | the synthetic light signal: 10 s, last 0.25 s, last 0.06 s | `experiment.rs` |
//! | `Omega` | $\Omega_i$ against $t$ | `experiment.rs` |
//! | `tek726`, `tek728` | $1/\Omega$ against $t_0 - t$ for two $t_0$, lines of eq 84 | `experiment.rs` |
//! | `Odot` | $d\Omega/dt$ against $\Omega$, lines of eq 85 | `experiment.rs` |
//! | `residuals` | the residuals of the fits of eqs 84 and 85 | `experiment.rs` |
//! | `sound-spectrogram`, `sound-residuals` | the phone's sound: its spectrogram with the fitted pitch, the residuals of the phase's fit | `sound.rs` |
//! | `coverage` | the coverage of the experiment's stated uncertainties (stored studies) | `coverage.rs` |
//! | `stability-map` | where eq 54 gives $\varpi^2 < 0$, against the paper's boundary | `stability.rs` |
//! | `frequency` | measured against predicted $\varpi/\Omega_0$ (eqs 54, 55, 71) | `frequency.rs` |
//! | `energy-drift` | energy drift of each method on the benchmark scene | `energy.rs` |
//! | `path` | the centre of mass in the plane | `path.rs` |
//! | `spin-down-alpha` | $\alpha$ against $t_0 - t$, eq 78 with 2/5 and with 2/3 | `spin_down.rs` |
//! | `lab-frame-difference` | eqs 23-25 against the lab-frame model | `lab_frame.rs` |
//! | `work-precision` | error against work of each method (the speed/accuracy study) | `precision.rs` |
//! | `slip-stick`, `slip-stick-path` | the sliding model's slip-stick scene: slip, normal force, energy; paths | `sliding.rs` |
//! | `mechanisms` | the power of each dissipation mechanism against $\Omega$, and what the record needs | `sliding.rs` |
//! | `peer-tilt`, `peer-difference` | the toy's tilt and its difference, this tool against the peer program | `toy.rs` |
//! | `premises` | which equation follows from which, coloured by verdict (drawn by the report from the checks) | `premises.rs` |
//!
//! What a figure draws and how it is rendered (SVG, PNG) is `drawing.rs`, the PNG encoder
//! `png.rs`; a test holds this table to [`FAMILIES`].
//!
//! Everything is deterministic: the same build gives the same bytes.

pub mod canvas;
pub mod captions;
pub mod chart;
pub mod coverage;
mod drawing;
pub mod energy;
pub mod error;
pub mod experiment;
pub mod font;
pub mod frequency;
pub mod geometry;
pub mod lab_frame;
pub mod legend;
mod mark_label;
pub mod paper_scale;
pub mod path;
mod png;
pub mod precision;
pub mod premises;
pub mod ranges;
mod series_drawing;
pub mod sliding;
pub mod sound;
pub mod spin_down;
pub mod stability;
pub mod ticks;
pub mod toy;

pub use chart::{Axis, Chart, Legend, Mark, Note, Options, Plot, Series, Style};
pub use drawing::{Drawing, Panels};
pub use error::{Drawn, FigureError};
pub use geometry::Geometry;
pub use legend::Layout;

use crate::results::Results;
use crate::study::{self, Run, Study};
use serde::Serialize;

/// A figure of the report.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Figure {
    /// Its name: the paper's label for the paper's figures (`fig1`, `tek04`, ...), a short
    /// slug for new ones. Also the file name of its PNG.
    pub name: &'static str,
    /// A short title.
    pub title: String,
    /// What it shows and what to look for.
    pub caption: String,
    /// What to draw.
    pub drawing: Drawing,
}

/// Figures drawn together from the same results (the experiment's eight share one analysis):
/// their names, in the report's order, the studies they read, and how they are drawn. Adding
/// a figure is its file and its row here.
pub struct Family {
    /// The figures' names.
    pub names: &'static [&'static str],
    /// The studies they are drawn from (none for the stability map, drawn from the paper's
    /// printed eq 54, nor for the coverage studies, which are stored:
    /// `studies::coverage_record`).
    pub needs: &'static [&'static dyn Run],
    /// Draws them from the results.
    pub build: fn(&Results) -> Result<Vec<Figure>, FigureError>,
}

/// Every family, in the report's order.
pub const FAMILIES: &[Family] = &[
    Family {
        names: &["fig1"],
        needs: &[&study::SteadyMotion],
        build: |r| Ok(vec![geometry_figure(need(r, &study::SteadyMotion)?)?]),
    },
    Family {
        names: &[
            "tek04",
            "tek01",
            "tek02",
            "Omega",
            "tek726",
            "tek728",
            "Odot",
            "residuals",
        ],
        needs: &[&study::Experiment],
        build: |r| experiment::figures(need(r, &study::Experiment)?),
    },
    Family {
        names: &["sound-spectrogram", "sound-residuals"],
        needs: &[&study::Sound],
        build: |r| sound::figures(need(r, &study::Sound)?),
    },
    Family {
        names: &["coverage"],
        needs: &[],
        build: |_| {
            let stored = ::studies::coverage_record::stored().map_err(|e| e.to_string())?;
            Ok(vec![coverage::studies(&stored)?])
        },
    },
    Family {
        names: &["stability-map"],
        needs: &[],
        build: |r| Ok(vec![stability::figure(paper(r)?)?]),
    },
    Family {
        names: &["frequency"],
        needs: &[&study::Frequency],
        build: |r| {
            Ok(vec![frequency::figure(
                need(r, &study::Frequency)?,
                paper(r)?,
            )?])
        },
    },
    Family {
        names: &["energy-drift"],
        needs: &[&study::EnergyDrift],
        build: |r| Ok(vec![energy::figure(need(r, &study::EnergyDrift)?)?]),
    },
    Family {
        names: &["path"],
        needs: &[&study::Paths, &study::SpinDown],
        build: |r| {
            let mut runs = need(r, &study::Paths)?.clone();
            runs.push(need(r, &study::SpinDown)?.path.clone());
            Ok(vec![path::figure(&runs)?])
        },
    },
    Family {
        names: &["spin-down-alpha"],
        needs: &[&study::SpinDown],
        build: |r| Ok(vec![spin_down::figure(need(r, &study::SpinDown)?)?]),
    },
    Family {
        names: &["lab-frame-difference"],
        needs: &[&study::LabFrame],
        build: |r| Ok(vec![lab_frame::figure(need(r, &study::LabFrame)?)?]),
    },
    Family {
        names: &["work-precision"],
        needs: &[&study::Precision],
        build: |r| Ok(vec![precision::figure(need(r, &study::Precision)?)?]),
    },
    Family {
        names: &["slip-stick", "slip-stick-path", "mechanisms"],
        needs: &[&study::Friction],
        build: |r| {
            let f = need(r, &study::Friction)?;
            Ok(vec![
                sliding::slip_stick(f)?,
                sliding::paths(f)?,
                sliding::mechanisms(f)?,
            ])
        },
    },
    Family {
        names: &["peer-tilt", "peer-difference"],
        needs: &[&study::Toy],
        build: |r| {
            let t = need(r, &study::Toy)?;
            Ok(vec![toy::tilt(t)?, toy::difference(t)?])
        },
    },
];

/// Every figure's name, in the report's order.
pub fn names() -> Vec<&'static str> {
    FAMILIES
        .iter()
        .flat_map(|f| f.names.iter().copied())
        .collect()
}

fn family(name: &str) -> Result<&'static Family, String> {
    FAMILIES
        .iter()
        .find(|f| f.names.contains(&name))
        .ok_or_else(|| {
            format!(
                "no figure named {name:?}; the figures are: {}",
                names().join(", ")
            )
        })
}

/// The studies a figure is drawn from; an unknown name is an error that lists the figures.
pub fn needs(name: &str) -> Result<&'static [&'static dyn Run], FigureError> {
    Ok(family(name)?.needs)
}

fn need<'r, S: Study>(r: &'r Results, study: &S) -> Result<&'r S::Output, FigureError> {
    Ok(r.required(study, "the figures")?)
}

fn paper(r: &Results) -> Result<&paper::Paper, FigureError> {
    r.paper
        .as_ref()
        .ok_or_else(|| "the figures need the paper the results were computed from".into())
}

/// Figure 1: the geometry of the disk in the steady motion `steady` (the toy's a = 37.5 mm at
/// alpha0 = 1 rad with b = 0.6 a: [`study::SteadyMotion`]).
pub fn geometry_figure(steady: &study::steady_motion::SteadyDisk) -> Result<Figure, FigureError> {
    let view = geometry::View {
        azimuth: -0.95,
        elevation: 0.45,
    };
    let g = Geometry::steady(steady, std::f64::consts::FRAC_PI_2, view);
    Ok(Figure {
        name: "fig1",
        title: "The disk, its triad and its lengths".into(),
        caption: captions::caption(
            "fig1",
            &serde_json::json!({
                "a_mm": format!("{:.1}", g.a * 1e3),
                "alpha": format!("{:.2}", g.alpha),
                "b_over_a": format!("{:.2}", g.b / g.a),
                "precession": format!("{:.2}", g.precession),
                "spin": format!("{:.2}", g.spin),
                "r_over_a": format!("{:.2}", g.r / g.a),
            }),
        )?,
        drawing: Drawing::Geometry(g),
    })
}

/// The figures named (each once, in the order given), drawn from `results`; an unknown name is
/// an error that lists the known ones, and so is a figure whose study was not computed.
/// Families are built on rayon's threads; the result does not depend on that.
pub fn some(names: &[&str], results: &Results) -> Result<Vec<Figure>, FigureError> {
    use rayon::prelude::*;
    let mut families: Vec<&'static Family> = Vec::new();
    for n in names {
        let f = family(n)?;
        if !families.iter().any(|g| std::ptr::eq(*g, f)) {
            families.push(f);
        }
    }
    let built: Vec<Result<Vec<Figure>, FigureError>> =
        families.par_iter().map(|f| (f.build)(results)).collect();
    let mut pool = Vec::new();
    for b in built {
        pool.extend(b?);
    }
    let mut out = Vec::new();
    for n in names {
        if out.iter().any(|f: &Figure| f.name == *n) {
            continue;
        }
        if let Some(i) = pool.iter().position(|f| f.name == *n) {
            out.push(pool.swap_remove(i));
        }
    }
    Ok(out)
}

/// Every figure, in the report's order, drawn from `results`.
pub fn all(results: &Results) -> Result<Vec<Figure>, FigureError> {
    some(&names(), results)
}

/// Keeps at most about `bins` points of a long series for drawing, honestly: the samples are
/// cut into `bins` runs of consecutive points and each run contributes its minimum and its
/// maximum (in time order), so that the drawn envelope is the data's.
pub fn min_max_decimate(points: &[(f64, f64)], bins: usize) -> Vec<(f64, f64)> {
    if points.len() <= 2 * bins || bins == 0 {
        return points.to_vec();
    }
    let per = points.len().div_ceil(bins);
    let mut out = Vec::with_capacity(2 * bins);
    for run in points.chunks(per) {
        let (mut lo, mut hi) = (0, 0);
        for (i, p) in run.iter().enumerate() {
            if p.1 < run[lo].1 {
                lo = i;
            }
            if p.1 > run[hi].1 {
                hi = i;
            }
        }
        let (a, b) = if lo <= hi { (lo, hi) } else { (hi, lo) };
        out.push(run[a]);
        if b != a {
            out.push(run[b]);
        }
    }
    out
}

/// The largest value of each of `bins` runs of consecutive points, at the run's middle time:
/// the upper envelope of a drift, drawable on a log axis (exact zeros have no logarithm).
pub fn max_per_bin(points: &[(f64, f64)], bins: usize) -> Vec<(f64, f64)> {
    if points.is_empty() || bins == 0 {
        return Vec::new();
    }
    let per = points.len().div_ceil(bins);
    points
        .chunks(per)
        .filter_map(|run| {
            let y = run.iter().map(|p| p.1).fold(0.0, f64::max);
            let t = 0.5 * (run[0].0 + run[run.len() - 1].0);
            (y > 0.0).then_some((t, y))
        })
        .collect()
}

/// Keeps about `n` points spread evenly in log x (for log-log plots of long runs): the first
/// point of each logarithmic bin of x > 0.
pub fn log_thin(points: &[(f64, f64)], n: usize) -> Vec<(f64, f64)> {
    let xs: Vec<f64> = points
        .iter()
        .map(|p| p.0)
        .filter(|x| *x > 0.0 && x.is_finite())
        .collect();
    if xs.len() <= n || n == 0 {
        return points.to_vec();
    }
    let lo = xs.iter().copied().fold(f64::INFINITY, f64::min).ln();
    let hi = xs.iter().copied().fold(f64::NEG_INFINITY, f64::max).ln();
    let width = (hi - lo) / n as f64;
    let mut last_bin = None;
    let mut out = Vec::new();
    for p in points {
        if !(p.0 > 0.0 && p.0.is_finite()) {
            continue;
        }
        let bin = (((p.0.ln() - lo) / width).floor() as i64).min(n as i64 - 1);
        if last_bin != Some(bin) {
            out.push(*p);
            last_bin = Some(bin);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The table of the module's documentation names every figure, and the file it names is
    /// there.
    #[test]
    fn the_doc_table_names_every_figure_and_its_file() {
        let doc = include_str!("mod.rs");
        let table: Vec<&str> = doc.lines().filter(|l| l.starts_with("//! | `")).collect();
        for name in names().into_iter().chain(["premises"]) {
            let row = table.iter().find(|l| {
                l.split(" | ")
                    .nth(1)
                    .is_some_and(|c| c.contains(&format!("`{name}`")))
            });
            let row = row.unwrap_or_else(|| panic!("{name} is not in the table"));
            let file = row
                .trim_end_matches(" |")
                .rsplit('`')
                .nth(1)
                .unwrap_or_default();
            let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src/figures");
            assert!(dir.join(file).exists(), "{name}: {file} does not exist");
        }
    }

    #[test]
    fn decimation_keeps_the_envelope() {
        let pts: Vec<(f64, f64)> = (0..10_000)
            .map(|i| (i as f64, ((i * 7919) % 1000) as f64))
            .collect();
        let d = min_max_decimate(&pts, 100);
        assert!(d.len() <= 200);
        let max = d.iter().map(|p| p.1).fold(f64::MIN, f64::max);
        let min = d.iter().map(|p| p.1).fold(f64::MAX, f64::min);
        assert_eq!((min, max), (0.0, 999.0));
        assert!(d.windows(2).all(|w| w[1].0 > w[0].0));
    }

    #[test]
    fn unknown_names_are_errors_that_list_the_figures() {
        let e = some(&["nope"], &Results::default())
            .unwrap_err()
            .to_string();
        assert!(e.contains("fig1") && e.contains("work-precision"), "{e}");
        assert!(needs("nope").is_err());
    }

    #[test]
    fn a_figure_without_its_study_is_an_error_not_a_computation() {
        let e = some(&["spin-down-alpha"], &Results::default())
            .unwrap_err()
            .to_string();
        assert!(e.contains("spin-down"), "{e}");
        let e = some(&["fig1"], &Results::default())
            .unwrap_err()
            .to_string();
        assert!(e.contains("steady-motion"), "{e}");
        // The stability map needs no study, only the paper.
        let with_paper = Results::of(Some(paper::Paper::built_in().unwrap()));
        let f = some(&["stability-map"], &with_paper).unwrap();
        assert_eq!(f.len(), 1);
    }

    #[test]
    fn labels_of_close_reference_lines_do_not_overlap() {
        use chart::{Axis, Plot, Series, Style};
        let plot = Plot::new("t", "x", "y")
            .with(Series::new("s", vec![(0.0, 0.0), (1.0, 1.0)], Style::Line))
            .mark(Axis::X, 0.80, "first label")
            .mark(Axis::X, 0.81, "second label");
        chart::register_font();
        let svg = Drawing::Plot(plot).to_svg(900, 600).unwrap();
        // The y of the <text> holding each label.
        let y_of = |label: &str| -> f64 {
            let end = svg.find(label).unwrap();
            let start = svg[..end].rfind("<text").unwrap();
            let tag = &svg[start..end];
            let y = tag.find(" y=\"").unwrap() + 4;
            tag[y..y + tag[y..].find('"').unwrap()].parse().unwrap()
        };
        let (a, b) = (y_of("first label"), y_of("second label"));
        assert!((a - b).abs() >= 10.0, "labels at y = {a} and {b}");
    }
}
