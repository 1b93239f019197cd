//! The report's figures: each builds, has data, draws to SVG without NaN, and is the same bytes
//! on every build.

use rolling_disk::figures::{self, Drawing, Figure};

fn series_counts(f: &Figure) -> Vec<usize> {
    match &f.drawing {
        Drawing::Chart(c) => c.series.iter().map(|s| s.points.len()).collect(),
        Drawing::Plot(p) => p.chart.series.iter().map(|s| s.points.len()).collect(),
        Drawing::Panels(p) => p
            .plots
            .iter()
            .flat_map(|p| p.chart.series.iter().map(|s| s.points.len()))
            .collect(),
        Drawing::Geometry(g) => vec![g.shapes().len()],
    }
}

#[test]
fn every_figure_builds_draws_and_is_deterministic() {
    let start = std::time::Instant::now();
    let a = figures::all().expect("figures build");
    let built = start.elapsed();
    println!("all figures' data in {built:?}");
    let names: Vec<&str> = a.iter().map(|f| f.name).collect();
    assert_eq!(names, figures::NAMES.to_vec());
    let b = figures::all().expect("figures build twice");
    for (f, g) in a.iter().zip(&b) {
        let counts = series_counts(f);
        assert!(!counts.is_empty(), "{}: no series", f.name);
        assert!(
            counts.iter().all(|&n| n > 0),
            "{}: an empty series {counts:?}",
            f.name
        );
        assert!(f.caption.len() > 100, "{}: caption too short", f.name);
        assert!(!f.title.is_empty());
        let svg = f.drawing.to_svg(760, 480).expect("draws");
        assert!(svg.starts_with("<svg") && svg.len() > 2000, "{}", f.name);
        assert!(
            !svg.contains("NaN") && !svg.contains("inf"),
            "{}: NaN in the SVG",
            f.name
        );
        assert!(!f.caption.contains("NaN"), "{}: NaN in the caption", f.name);
        let svg2 = g.drawing.to_svg(760, 480).expect("draws");
        assert_eq!(svg, svg2, "{}: two builds differ", f.name);
    }
}

#[test]
fn figures_can_be_built_by_name() {
    let f = figures::by_name("stability-map")
        .expect("known")
        .expect("builds");
    assert_eq!(f.name, "stability-map");
    let some = figures::some(&["tek02", "fig1", "tek02"]).expect("builds");
    let names: Vec<&str> = some.iter().map(|f| f.name).collect();
    assert_eq!(names, ["tek02", "fig1"]);
    assert!(figures::by_name("fig99").is_none());
}

/// Writes every figure as PNG to /tmp/fig_NAME.png for looking at:
/// `cargo test --release --test figures -- --ignored`.
#[test]
#[ignore]
fn write_pngs_for_inspection() {
    for f in figures::all().expect("figures build") {
        let path = std::path::PathBuf::from(format!("/tmp/fig_{}.png", f.name));
        f.drawing.to_png(&path).expect("png");
        let svg = f.drawing.to_svg(760, 480).expect("svg");
        std::fs::write(format!("/tmp/fig_{}.svg", f.name), svg).expect("write svg");
        println!("{}: {}\n  {}\n", f.name, f.title, f.caption);
    }
}
