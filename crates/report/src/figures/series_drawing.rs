//! Drawing a [`Chart`]'s series in their styles with their legend entries, its notes, and the
//! legend's box; the axes, the reference lines and the legend's place are `canvas.rs`'s.

use super::canvas::{font, px, Ctx};
use super::chart::{Chart, Legend, Options, Series, Style};
use super::ranges::{grid_step, merge_cells};
use crate::figures::{Drawn, FigureError};
use plotters::coord::ranged1d::Ranged;
use plotters::prelude::*;

/// An axis of plain numbers, linear or logarithmic.
pub(super) trait NumberAxis: Ranged<ValueType = f64> {}

impl<T: Ranged<ValueType = f64>> NumberAxis for T {}

impl Chart {
    /// One series in its style and colour, with its legend entry when it has a label.
    pub(super) fn draw_series<'a, DB: DrawingBackend + 'a, XC: NumberAxis, YC: NumberAxis>(
        &self,
        chart: &mut Ctx<'a, DB, XC, YC>,
        scale: f64,
        s: &Series,
        color: RGBColor,
    ) -> Result<(), FigureError> {
        let width = px(1.6, scale).max(1);
        let pts: Vec<(f64, f64)> = s
            .points
            .iter()
            .copied()
            .filter(|p| self.inside(*p))
            .collect();
        let r = px(2.6, scale).max(1) as i32;
        let thin = color.stroke_width(px(1.3, scale).max(1));
        let anno = match s.style {
            // plotters turns a thick polyline into one polygon whose inner corners spike at
            // sharp reversals (a min/max envelope); at print scale each segment is drawn alone,
            // with round joins.
            Style::Line if scale >= 1.5 && pts.len() > 2 => {
                let half = (width / 2).max(1);
                chart
                    .draw_series(
                        pts[1..pts.len() - 1]
                            .iter()
                            .map(|p| Circle::new(*p, half, color.filled())),
                    )
                    .drawn()?;
                chart
                    .draw_series(
                        pts.windows(2)
                            .map(|w| PathElement::new(vec![w[0], w[1]], color.stroke_width(width))),
                    )
                    .drawn()?
            }
            Style::Line => chart
                .draw_series(LineSeries::new(pts, color.stroke_width(width)))
                .drawn()?,
            Style::Dashed | Style::Dotted => {
                let (dash, gap) = if s.style == Style::Dashed {
                    (6.0, 4.0)
                } else {
                    (1.6, 3.0)
                };
                chart
                    .draw_series(DashedLineSeries::new(
                        pts,
                        px(dash, scale),
                        px(gap, scale),
                        color.stroke_width(width),
                    ))
                    .drawn()?
            }
            Style::Points => chart
                .draw_series(pts.into_iter().map(|p| Circle::new(p, r, color.filled())))
                .drawn()?,
            Style::Squares => chart
                .draw_series(
                    pts.into_iter()
                        .map(|p| EmptyElement::at(p) + Rectangle::new([(-r, -r), (r, r)], thin)),
                )
                .drawn()?,
            Style::Triangles => chart
                .draw_series(pts.into_iter().map(|p| {
                    EmptyElement::at(p)
                        + Polygon::new(vec![(0, -r - 1), (r + 1, r), (-r - 1, r)], color.filled())
                }))
                .drawn()?,
            Style::Crosses => chart
                .draw_series(pts.into_iter().map(|p| {
                    EmptyElement::at(p)
                        + PathElement::new(vec![(-r, -r), (r, r)], thin)
                        + PathElement::new(vec![(-r, r), (r, -r)], thin)
                }))
                .drawn()?,
            Style::Cells => {
                let finite = |h: f64| if h.is_finite() { h } else { 0.0 };
                let hx = finite(0.5 * grid_step(pts.iter().map(|p| p.0).collect()));
                let hy = finite(0.5 * grid_step(pts.iter().map(|p| p.1).collect()));
                let fill = color.mix(0.45).filled();
                chart
                    .draw_series(merge_cells(pts, hy).into_iter().map(|(a, b0, b1)| {
                        Rectangle::new([(a - hx, b0 - hy), (a + hx, b1 + hy)], fill)
                    }))
                    .drawn()?
            }
        };
        if s.label.is_empty() {
            return Ok(());
        }
        let glyph = Glyph::of(s.style, px(20.0, scale) as i32, r);
        let stroke = color.stroke_width(width);
        let fill = if s.style == Style::Cells {
            color.mix(0.45).filled()
        } else {
            color.filled()
        };
        anno.label(s.label.clone()).legend(move |(x, y)| {
            let p = |i: usize| PathElement::new(glyph.paths[i].clone(), stroke);
            EmptyElement::at((x, y))
                + p(0)
                + p(1)
                + p(2)
                + p(3)
                + Polygon::new(glyph.fill.clone(), fill)
        });
        Ok(())
    }

    /// The notes, each at its point, a line per line of text.
    pub(super) fn draw_notes<'a, DB: DrawingBackend + 'a, XC: NumberAxis, YC: NumberAxis>(
        &self,
        chart: &mut Ctx<'a, DB, XC, YC>,
        scale: f64,
        o: &Options,
    ) -> Result<(), FigureError> {
        for n in o.notes.iter().filter(|n| self.inside((n.x, n.y))) {
            let step = px(14.0, scale) as i32;
            chart
                .draw_series(n.text.lines().enumerate().map(|(i, l)| {
                    EmptyElement::at((n.x, n.y))
                        + Text::new(
                            l.to_string(),
                            (0, i as i32 * step),
                            font(11.5, scale).color(&BLACK),
                        )
                }))
                .drawn()?;
        }
        Ok(())
    }

    /// The legend's box at the corner chosen (none when hidden or when no series has a label).
    pub(super) fn draw_legend_box<'a, DB: DrawingBackend + 'a, XC: NumberAxis, YC: NumberAxis>(
        &self,
        chart: &mut Ctx<'a, DB, XC, YC>,
        scale: f64,
        chosen: Legend,
    ) -> Result<(), FigureError> {
        let position = match chosen {
            Legend::Auto | Legend::UpperRight => SeriesLabelPosition::UpperRight,
            Legend::UpperLeft => SeriesLabelPosition::UpperLeft,
            Legend::LowerRight => SeriesLabelPosition::LowerRight,
            Legend::LowerLeft => SeriesLabelPosition::LowerLeft,
            Legend::MiddleRight => SeriesLabelPosition::MiddleRight,
            Legend::Hidden => return Ok(()),
        };
        if self.series.iter().all(|s| s.label.is_empty()) {
            return Ok(());
        }
        chart
            .configure_series_labels()
            .legend_area_size(px(28.0, scale))
            .margin(px(8.0, scale))
            .label_font(font(12.0, scale))
            .background_style(WHITE.mix(0.88))
            .border_style(RGBColor(180, 180, 180))
            .position(position)
            .draw()
            .drawn()
    }
}

/// A legend glyph in pixels relative to the legend's anchor: four polylines (unused ones empty)
/// and one filled polygon (possibly empty), one fixed shape for every style.
#[derive(Clone)]
struct Glyph {
    paths: [Vec<(i32, i32)>; 4],
    fill: Vec<(i32, i32)>,
}

impl Glyph {
    /// The glyph of `style`, `len` px long, markers of radius `r` px.
    fn of(style: Style, len: i32, r: i32) -> Self {
        let c = len / 2;
        let mut paths: [Vec<(i32, i32)>; 4] = Default::default();
        let mut fill = Vec::new();
        let seg = |a: i32, b: i32| vec![(a, 0), (b, 0)];
        match style {
            Style::Line => paths[0] = seg(0, len),
            Style::Dashed => {
                let d = len / 4;
                paths[0] = seg(0, d);
                paths[1] = seg(3 * d / 2, 5 * d / 2);
                paths[2] = seg(3 * d, len);
            }
            Style::Dotted => {
                let d = len / 7;
                for (i, p) in paths.iter_mut().enumerate() {
                    let a = 2 * d * i as i32;
                    *p = seg(a, a + d);
                }
            }
            Style::Points => {
                fill = (0..12)
                    .map(|i| {
                        let t = std::f64::consts::TAU * i as f64 / 12.0;
                        (
                            c + (r as f64 * t.cos()).round() as i32,
                            (r as f64 * t.sin()).round() as i32,
                        )
                    })
                    .collect()
            }
            Style::Squares => {
                paths[0] = vec![
                    (c - r, -r),
                    (c + r, -r),
                    (c + r, r),
                    (c - r, r),
                    (c - r, -r),
                ]
            }
            Style::Triangles => fill = vec![(c, -r - 1), (c + r + 1, r), (c - r - 1, r)],
            Style::Crosses => {
                paths[0] = vec![(c - r, -r), (c + r, r)];
                paths[1] = vec![(c - r, r), (c + r, -r)];
            }
            Style::Cells => fill = vec![(0, -r - 1), (len, -r - 1), (len, r + 1), (0, r + 1)],
        }
        Self { paths, fill }
    }
}
