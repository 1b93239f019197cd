//! Charts as plain data, and one drawing routine for every backend: the same code makes the SVG
//! of the HTML report and the print-resolution PNG of the LaTeX report.
//!
//! A [`Chart`] is axes (linear or logarithmic, automatic or fixed ranges), [`Series`] drawn in one
//! of several [`Style`]s, reference lines across the plot ([`Mark`]) and text placed in data
//! coordinates ([`Note`]). Build one with a struct literal (`..Default::default()` for what you do
//! not set) or with [`Chart::new`] and its builder methods. Drawing is in `canvas.rs`.

pub use super::font::{register_font, FIGURE_FONT, FIGURE_FONT_FILE};
use super::legend::Layout;
pub use super::legend::Legend;
use crate::figures::FigureError;
use plotters::prelude::*;
use serde::Serialize;

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Style {
    /// A solid line.
    Line,
    /// A dashed line (predictions, references).
    Dashed,
    /// A dotted line (secondary references).
    Dotted,
    /// Filled circles only (measurements).
    Points,
    /// Open squares.
    Squares,
    /// Filled triangles.
    Triangles,
    /// Crosses (x).
    Crosses,
    /// Filled rectangular cells centred on the points, as large as the smallest spacing of the
    /// points in x and in y (a map on a regular grid), drawn translucent.
    Cells,
}

/// One curve or point set.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Series {
    /// Legend text; empty for no legend entry.
    pub label: String,
    /// The points.
    pub points: Vec<(f64, f64)>,
    /// How it is drawn.
    pub style: Style,
}

impl Series {
    /// A series from a label, points and a style, coloured by its position in the chart.
    pub fn new(label: impl Into<String>, points: Vec<(f64, f64)>, style: Style) -> Self {
        Self {
            label: label.into(),
            points,
            style,
        }
    }
}

/// Which axis a [`Mark`] is a value of.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Axis {
    /// A vertical line at an x value.
    X,
    /// A horizontal line at a y value.
    Y,
}

/// A reference line across the whole plot, with a short label at its end.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Mark {
    /// Vertical (`X`) or horizontal (`Y`).
    pub axis: Axis,
    /// Where, in data units.
    pub at: f64,
    /// Its label (may be empty).
    pub label: String,
}

/// A text placed at a point of the plot, in data coordinates (its upper left corner).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Note {
    /// x (data units).
    pub x: f64,
    /// y (data units).
    pub y: f64,
    /// The text.
    pub text: String,
}

/// A chart: axes with quantities and units, linear or logarithmic, and series. What else a
/// figure needs (fixed ranges, colours, reference lines, text) is in [`Options`]; a [`Plot`] is
/// the two together.
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct Chart {
    /// Title drawn above the plot.
    pub title: String,
    /// x-axis label: quantity and unit.
    pub x_label: String,
    /// y-axis label: quantity and unit.
    pub y_label: String,
    /// Logarithmic x axis.
    pub x_log: bool,
    /// Logarithmic y axis.
    pub y_log: bool,
    /// The series, drawn in order.
    pub series: Vec<Series>,
}

/// How a chart is drawn beyond its series: ranges, colours, reference lines, text, legend.
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct Options {
    /// A fixed x range; `None` fits the data (5 % margins).
    pub x_range: Option<(f64, f64)>,
    /// A fixed y range; `None` fits the data (5 % margins).
    pub y_range: Option<(f64, f64)>,
    /// Where the legend goes.
    pub legend: Legend,
    /// Reference lines, drawn under the series.
    pub marks: Vec<Mark>,
    /// Text in the plot.
    pub notes: Vec<Note>,
    /// Colour of series `i` (RGB); missing or `None` takes the palette's colour `i`.
    pub colors: Vec<Option<[u8; 3]>>,
    /// One unit as long on both (linear) axes: a circle looks round. One range is widened.
    pub equal_aspect: bool,
}

/// A chart with its [`Options`]: what the figures build.
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct Plot {
    /// The axes and series.
    pub chart: Chart,
    /// Everything else.
    pub options: Options,
}

impl Plot {
    /// An empty plot with a title and axis labels (linear axes, automatic ranges).
    pub fn new(
        title: impl Into<String>,
        x_label: impl Into<String>,
        y_label: impl Into<String>,
    ) -> Self {
        Self {
            chart: Chart {
                title: title.into(),
                x_label: x_label.into(),
                y_label: y_label.into(),
                ..Chart::default()
            },
            options: Options::default(),
        }
    }

    /// Logarithmic axes.
    pub fn log(mut self, x: bool, y: bool) -> Self {
        self.chart.x_log = x;
        self.chart.y_log = y;
        self
    }

    /// Adds a series in the palette's colour for its position.
    pub fn with(mut self, s: Series) -> Self {
        self.chart.series.push(s);
        self
    }

    /// Adds a series in colour `rgb`.
    pub fn with_colored(mut self, s: Series, rgb: [u8; 3]) -> Self {
        let i = self.chart.series.len();
        self.chart.series.push(s);
        if self.options.colors.len() <= i {
            self.options.colors.resize(i + 1, None);
        }
        self.options.colors[i] = Some(rgb);
        self
    }

    /// Fixes the x range.
    pub fn x_range(mut self, lo: f64, hi: f64) -> Self {
        self.options.x_range = Some((lo, hi));
        self
    }

    /// Fixes the y range.
    pub fn y_range(mut self, lo: f64, hi: f64) -> Self {
        self.options.y_range = Some((lo, hi));
        self
    }

    /// Makes a unit as long on both axes.
    pub fn equal_aspect(mut self) -> Self {
        self.options.equal_aspect = true;
        self
    }

    /// Places the legend.
    pub fn legend_at(mut self, legend: Legend) -> Self {
        self.options.legend = legend;
        self
    }

    /// Adds a reference line.
    pub fn mark(mut self, axis: Axis, at: f64, label: impl Into<String>) -> Self {
        self.options.marks.push(Mark {
            axis,
            at,
            label: label.into(),
        });
        self
    }

    /// Adds a text at (x, y), data coordinates (its upper left corner; lines split at `\n`).
    pub fn note(mut self, x: f64, y: f64, text: impl Into<String>) -> Self {
        self.options.notes.push(Note {
            x,
            y,
            text: text.into(),
        });
        self
    }

    /// Draws the plot on any plotters backend (see [`Chart::draw`]).
    pub fn draw<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, plotters::coord::Shift>,
        scale: f64,
    ) -> Result<(), FigureError> {
        self.chart.draw_with(root, scale, &self.options)
    }

    /// Where the legend goes and what it covers, and the labelled ticks, when drawn at `dim`
    /// pixels and `scale` (see [`Chart::layout`]).
    pub fn layout(&self, dim: (u32, u32), scale: f64) -> Result<Layout, FigureError> {
        self.chart.layout(dim, scale, &self.options)
    }
}

/// The Okabe-Ito palette: distinguishable with colour-vision deficiencies and in grey print.
pub const PALETTE: [[u8; 3]; 7] = [
    [0, 114, 178],
    [213, 94, 0],
    [0, 158, 115],
    [204, 121, 167],
    [230, 159, 0],
    [86, 180, 233],
    [0, 0, 0],
];

/// A tick label: plain decimals between 1e-3 and 1e4, otherwise `2e-5` style; at most four
/// significant digits, no trailing zeros.
pub fn tick_label(v: f64) -> String {
    if !v.is_finite() {
        return String::new();
    }
    let a = v.abs();
    if a < 1e-12 * 1e-3 || a == 0.0 {
        return "0".into();
    }
    nonzero_tick_label(v)
}

/// A tick label of a logarithmic axis, where no value is zero (so none is rounded to zero).
pub fn nonzero_tick_label(v: f64) -> String {
    if !v.is_finite() {
        return String::new();
    }
    let a = v.abs();
    if !(1e-3..1e4).contains(&a) {
        let s = format!("{v:.3e}");
        let (m, e) = s.split_once('e').unwrap_or((&s, "0"));
        let m = trim_zeros(m);
        return format!("{m}e{e}");
    }
    let decimals = (3 - a.log10().floor() as i32).clamp(0, 8) as usize;
    trim_zeros(&format!("{v:.decimals$}"))
}

fn trim_zeros(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}
