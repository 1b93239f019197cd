//! The report's figures: each builds, has data, draws to SVG without NaN, and is the same bytes
//! on every build.

use checks::equations::Bench;
use report::figures::{self, Drawing, Figure};
use report::pipeline::{compute, RunConfig};
use report::results::Results;
use report::study;

/// The studies every figure is drawn from, computed once by the report's pipeline.
fn computed() -> Results {
    let config = RunConfig::figures(Bench::default(), &figures::names()).expect("known figures");
    compute(&config, &|_| {}).expect("the studies compute")
}

/// Every figure, from freshly computed studies.
fn all() -> Vec<Figure> {
    figures::all(&computed()).expect("figures build")
}

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
        Drawing::Premises(g) => vec![g.nodes.len(), g.edges.len()],
    }
}

#[test]
fn every_figure_builds_draws_and_is_deterministic() {
    let start = std::time::Instant::now();
    let results = computed();
    let a = figures::all(&results).expect("figures build");
    let built = start.elapsed();
    // One pipeline: the figures need every study but the checks and the corrections (which
    // feed the summary, not a figure), and each ran once.
    let figures_read: Vec<&str> = study::names(study::ALL)
        .into_iter()
        .filter(|s| !["checks", "corrections"].contains(s))
        .collect();
    crate::common::assert_computed_once(&results, figures_read);
    println!("all figures' data in {built:?}");
    let names: Vec<&str> = a.iter().map(|f| f.name).collect();
    assert_eq!(names, figures::names());
    // A second computation gives the same figures.
    let b = all();
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
        // One well-formed document holding the whole drawing: a panel that closed the
        // document early left the later panels after `</svg>`.
        assert_eq!(svg.matches("</svg>").count(), 1, "{}", f.name);
        assert!(
            svg.trim_end().ends_with("</svg>"),
            "{}: drawing after </svg>",
            f.name
        );
        if let Err(e) = roxmltree::Document::parse(&svg) {
            panic!("{}: the SVG is not well formed: {e}", f.name);
        }
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

/// The axis labels of every plot of a drawing.
fn axis_labels(f: &Figure) -> Vec<(String, String)> {
    let of = |c: &report::figures::Chart| (c.x_label.clone(), c.y_label.clone());
    match &f.drawing {
        Drawing::Chart(c) => vec![of(c)],
        Drawing::Plot(p) => vec![of(&p.chart)],
        Drawing::Panels(p) => p.plots.iter().map(|p| of(&p.chart)).collect(),
        Drawing::Geometry(_) | Drawing::Premises(_) => vec![],
    }
}

/// Every plot, at every size the report draws (SVG 760 x 480 at scale 1, PNG 1800 x 1200 at
/// scale 3, and the paper's figures again at the paper's 3.0 in: SVG 360 x 270, PNG 1080 x 810):
/// its legend covers no plotted pixel (bounding boxes, as plotters lays the legend out), each
/// axis has at least three labelled ticks and a label.
#[test]
fn legends_cover_no_data_and_every_axis_has_ticks_and_a_label() {
    use report::figures::paper_scale;
    let mut defects = Vec::new();
    for f in all() {
        let mut sizes = vec![(760, 480, 1.0), (1800, 1200, 3.0)];
        if paper_scale::paper_figure(f.name).is_some() {
            let (w, h) = paper_scale::size(f.name);
            let s = paper_scale::PAPER_WIDTH_IN * 360.0 / w as f64;
            sizes.push((w, h, 1.0));
            sizes.push(((w as f64 * s) as u32, (h as f64 * s) as u32, s));
        }
        for (w, h, scale) in sizes {
            for (i, l) in f
                .drawing
                .layouts(w, h, scale)
                .expect("lays out")
                .iter()
                .enumerate()
            {
                let at = format!("{} (plot {i}, {w}x{h})", f.name);
                if l.covered > 0 {
                    defects.push(format!(
                        "{at}: the legend at {:?} covers {} plotted pixels",
                        l.legend, l.covered
                    ));
                }
                if l.x_ticks < 3 || l.y_ticks < 3 {
                    defects.push(format!(
                        "{at}: {} x ticks, {} y ticks",
                        l.x_ticks, l.y_ticks
                    ));
                }
            }
        }
        for (x, y) in axis_labels(&f) {
            if x.trim().is_empty() || y.trim().is_empty() {
                defects.push(format!("{}: an unlabelled axis ({x:?}, {y:?})", f.name));
            }
        }
    }
    assert!(defects.is_empty(), "{}", defects.join("\n"));
}

/// The bounding-box test can fail: a legend pinned over a line through the plot is caught.
#[test]
fn a_legend_over_the_data_is_caught() {
    use report::figures::{Legend, Plot, Series, Style};
    let line: Vec<(f64, f64)> = (0..=100).map(|i| (i as f64, i as f64)).collect();
    let plot = Plot::new("diagonal", "x (m)", "y (m)").with(Series::new(
        "a line from corner to corner",
        line,
        Style::Line,
    ));
    // Asked for the upper right, which the line crosses, the legend goes to the free corner.
    let pinned = plot
        .legend_at(Legend::UpperRight)
        .layout((760, 480), 1.0)
        .unwrap();
    assert_eq!(pinned.covered, 0, "{pinned:?}");
    assert_eq!(pinned.legend, Some(Legend::UpperLeft));
    // Lines across the whole plot and a fixed range leave no free corner: the test's count
    // sees the overlap.
    let mut full = Plot::new("full", "x (m)", "y (m)").y_range(0.0, 1.0);
    for k in 0..=20 {
        let y = k as f64 / 20.0;
        let label = if k == 0 { "lines" } else { "" };
        full = full.with(Series::new(label, vec![(0.0, y), (1.0, y)], Style::Line));
    }
    let full = full.layout((760, 480), 1.0).unwrap();
    assert!(full.covered > 0, "{full:?}");
}

#[test]
fn figures_can_be_built_by_name() {
    let wanted = ["tek02", "fig1", "tek02"];
    let config = RunConfig::figures(Bench::default(), &wanted).expect("known");
    assert_eq!(config.study_names(), vec!["experiment", "steady-motion"]);
    let results = compute(&config, &|_| {}).expect("computes");
    let some = figures::some(&wanted, &results).expect("builds");
    let names: Vec<&str> = some.iter().map(|f| f.name).collect();
    assert_eq!(names, ["tek02", "fig1"]);
    assert!(figures::some(&["fig99"], &results).is_err());
    assert!(RunConfig::figures(Bench::default(), &["fig99"]).is_err());
}

/// Writes every figure as PNG to /tmp/fig_NAME.png for looking at:
/// `cargo test --release --test integration figures:: -- --ignored`.
#[test]
#[ignore]
fn write_pngs_for_inspection() {
    for f in all() {
        let path = std::path::PathBuf::from(format!("/tmp/fig_{}.png", f.name));
        f.drawing.to_png(&path).expect("png");
        let svg = f.drawing.to_svg(760, 480).expect("svg");
        std::fs::write(format!("/tmp/fig_{}.svg", f.name), svg).expect("write svg");
        println!("{}: {}\n  {}\n", f.name, f.title, f.caption);
    }
}

/// The characters of every `<text>` of an SVG (entities decoded).
fn svg_text_chars(svg: &str) -> Vec<char> {
    let mut out = Vec::new();
    let mut rest = svg;
    while let Some(i) = rest.find("<text") {
        let Some(open) = rest[i..].find('>') else {
            break;
        };
        let body = &rest[i + open + 1..];
        let end = body.find("</text>").unwrap_or(body.len());
        let text = body[..end]
            .replace("&lt;", "<")
            .replace("&gt;", ">")
            .replace("&quot;", "\"")
            .replace("&#39;", "'")
            .replace("&amp;", "&");
        out.extend(text.chars());
        rest = &body[end..];
    }
    out
}

/// Every character any figure draws has a glyph in the figure font (no tofu boxes in the PNGs,
/// no fallback to another font in the SVGs), and the check can fail: a character the font
/// lacks (a CJK ideograph) is caught.
#[test]
fn every_character_of_every_figure_is_in_the_figure_font() {
    use ab_glyph::Font;
    let font = ab_glyph::FontRef::try_from_slice(report::figures::chart::FIGURE_FONT_FILE)
        .expect("the figure font parses");
    let missing = |chars: &[char]| -> Vec<char> {
        let mut m: Vec<char> = chars
            .iter()
            .copied()
            .filter(|c| !c.is_whitespace() && font.glyph_id(*c).0 == 0)
            .collect();
        m.sort();
        m.dedup();
        m
    };
    let mut seen = 0;
    for f in all() {
        let svg = f.drawing.to_svg(760, 480).expect("draws");
        assert!(
            !svg.contains("font-family=\"sans-serif\""),
            "{}: a text is not in the figure font",
            f.name
        );
        let chars = svg_text_chars(&svg);
        seen += chars.len();
        let m = missing(&chars);
        assert!(m.is_empty(), "{}: no glyph for {m:?}", f.name);
    }
    assert!(seen > 1000, "only {seen} characters of text found");
    assert_eq!(missing(&['α', 'Ω', '₀', '图']), vec!['图']);
}

/// The light signal's reference lines say which is the truth (the model's own end) and which
/// the fit (eq 84's t0), each with its time.
#[test]
fn the_light_signals_marks_say_truth_or_fit() {
    let wanted = ["tek01", "tek02", "tek04"];
    let config = RunConfig::figures(Bench::default(), &wanted).expect("known");
    let results = compute(&config, &|_| {}).expect("computes");
    for f in figures::some(&wanted, &results).expect("builds") {
        let Drawing::Plot(p) = &f.drawing else {
            panic!("{} is not a plot", f.name);
        };
        let labels: Vec<&str> = p.options.marks.iter().map(|m| m.label.as_str()).collect();
        assert!(
            labels
                .iter()
                .all(|l| (l.starts_with("truth: ") || l.starts_with("fit: ")) && l.ends_with(" s")),
            "{}: {labels:?}",
            f.name
        );
        assert!(
            labels.iter().any(|l| l.starts_with("truth: ")),
            "{}: {labels:?}",
            f.name
        );
        if f.name != "tek04" {
            assert!(
                labels.iter().any(|l| l.starts_with("fit: ")),
                "{}: {labels:?}",
                f.name
            );
        }
    }
}

/// Every axis label names its quantity and, in brackets at its end, a unit (or
/// "dimensionless") that is not the quantity's own symbol written again.
#[test]
fn every_axis_label_ends_with_its_unit_written_once() {
    let mut bad = Vec::new();
    for f in all() {
        for (x, y) in axis_labels(&f) {
            for label in [x, y] {
                let unit = label
                    .strip_suffix(')')
                    .and_then(|l| l.rsplit_once(" ("))
                    .map(|(quantity, unit)| (quantity.split_whitespace().last(), unit));
                match unit {
                    Some((Some(last), unit)) if last != unit => {}
                    _ => bad.push(format!("{}: {label:?}", f.name)),
                }
            }
        }
    }
    assert!(
        bad.is_empty(),
        "axis labels without a unit, or with it twice:\n{}",
        bad.join("\n")
    );
}
