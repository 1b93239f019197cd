//! Where a legend may go without hiding data: the legend's box in pixels, computed as plotters
//! lays it out (`SeriesLabelStyle::draw`: lines of text 1.25 font heights apart, the glyph area
//! and a margin on each side, 5 px from the plot's edge), and the data's pixels, so that the
//! automatic placement ([`super::Legend::Auto`]) and the figure tests ask the same question:
//! how many plotted pixels fall inside the box.
//!
//! The geometry is plotters', restated because plotters does not expose it; the placement rule
//! (first free corner, else the least covered) is this crate's.

use super::{Drawn, FigureError};
use plotters::style::{FontDesc, IntoFont};
use serde::Serialize;

/// Where the legend goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
pub enum Legend {
    /// The first corner that covers no plotted point (see [`choose`]); when
    /// every corner covers some and the y range is automatic, the range grows at the top until
    /// the upper corners are free. The default.
    #[default]
    Auto,
    /// Upper right corner.
    UpperRight,
    /// Upper left corner.
    UpperLeft,
    /// Lower right corner.
    LowerRight,
    /// Lower left corner.
    LowerLeft,
    /// Middle of the right side.
    MiddleRight,
    /// No legend.
    Hidden,
}

/// A rectangle in pixels relative to the plotting area's upper left corner, inclusive.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Rect {
    /// Left.
    pub x0: i32,
    /// Top.
    pub y0: i32,
    /// Right.
    pub x1: i32,
    /// Bottom.
    pub y1: i32,
}

impl Rect {
    /// Whether the pixel is inside.
    pub fn contains(&self, (x, y): (i32, i32)) -> bool {
        (self.x0..=self.x1).contains(&x) && (self.y0..=self.y1).contains(&y)
    }
}

/// Where a legend went and what it covers, and the number of labelled ticks on each axis.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Layout {
    /// The corner chosen, `None` when there is no legend.
    pub legend: Option<Legend>,
    /// Its box.
    pub rect: Option<Rect>,
    /// Plotted pixels inside the box.
    pub covered: usize,
    /// Labelled ticks on the x axis.
    pub x_ticks: usize,
    /// Labelled ticks on the y axis.
    pub y_ticks: usize,
}

/// The legend's size in pixels for these labels, at the font size and spacing the chart uses.
pub fn size(
    labels: &[&str],
    font_px: f64,
    glyph_area: i32,
    margin: i32,
) -> Result<(i32, i32), FigureError> {
    let font: FontDesc = (super::font::FIGURE_FONT, font_px).into_font();
    let line = font_px * 1.25;
    let (mut w, mut h) = (0i32, 0i32);
    for (i, l) in labels.iter().enumerate() {
        let (dx, dy) = font.box_size(l).drawn()?;
        let y = (i as f64 * line).round() as i32;
        w = w.max(dx as i32);
        h = h.max(y + dy as i32);
    }
    Ok((w + glyph_area + 2 * margin, h + 2 * margin))
}

/// The legend's box at `position` in a plotting area of `area` pixels.
pub fn rect(position: Legend, (w, h): (i32, i32), (aw, ah): (u32, u32)) -> Option<Rect> {
    let (aw, ah) = (aw as i32, ah as i32);
    let (x, y) = match position {
        Legend::UpperLeft => (5, 5),
        Legend::UpperRight => (aw - w - 5, 5),
        Legend::LowerLeft => (5, ah - h - 5),
        Legend::LowerRight => (aw - w - 5, ah - h - 5),
        Legend::MiddleRight => (aw - w - 5, (ah - h) / 2),
        Legend::Hidden | Legend::Auto => return None,
    };
    Some(Rect {
        x0: x,
        y0: y,
        x1: x + w,
        y1: y + h,
    })
}

/// The pixels of a polyline, one every pixel or so along each segment.
pub fn densify(pts: &[(i32, i32)]) -> Vec<(i32, i32)> {
    let mut out = Vec::with_capacity(pts.len() * 2);
    if let Some(p) = pts.first() {
        out.push(*p);
    }
    for w in pts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let n = (a.0 - b.0).abs().max((a.1 - b.1).abs()).clamp(1, 4000);
        for k in 1..=n {
            let t = k as f64 / n as f64;
            out.push((
                (a.0 as f64 + t * (b.0 - a.0) as f64).round() as i32,
                (a.1 as f64 + t * (b.1 - a.1) as f64).round() as i32,
            ));
        }
    }
    out
}

/// How many of `pixels` fall in `r`.
pub fn covered(r: &Rect, pixels: &[(i32, i32)]) -> usize {
    pixels.iter().filter(|p| r.contains(**p)).count()
}

/// The automatic placement: the first of the upper corners, the lower corners and the middle
/// right that covers no plotted pixel; else the one covering the fewest.
pub fn choose(size: (i32, i32), area: (u32, u32), pixels: &[(i32, i32)]) -> (Legend, Rect, usize) {
    let mut best: Option<(Legend, Rect, usize)> = None;
    for pos in [
        Legend::UpperRight,
        Legend::UpperLeft,
        Legend::LowerRight,
        Legend::LowerLeft,
        Legend::MiddleRight,
    ] {
        let Some(r) = rect(pos, size, area) else {
            continue;
        };
        let c = covered(&r, pixels);
        if c == 0 {
            return (pos, r, 0);
        }
        if best.as_ref().is_none_or(|b| c < b.2) {
            best = Some((pos, r, c));
        }
    }
    best.unwrap_or((
        Legend::UpperRight,
        Rect {
            x0: 0,
            y0: 0,
            x1: 0,
            y1: 0,
        },
        0,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_line_through_a_corner_sends_the_legend_elsewhere() {
        super::super::font::register_font();
        let area = (600, 400);
        let s = size(&["one", "two"], 12.0, 28, 8).unwrap();
        assert!(s.0 > 36 && s.1 > 16, "{s:?}");
        // A diagonal from lower left to upper right: both of those corners are hit.
        let line = densify(&[(0, 399), (599, 0)]);
        let (pos, r, c) = choose(s, area, &line);
        assert_eq!((pos, c), (Legend::UpperLeft, 0), "{r:?}");
        assert!(covered(&rect(Legend::UpperRight, s, area).unwrap(), &line) > 0);
    }
}
