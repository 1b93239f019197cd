//! Drawing a [`Chart`] on any plotters backend: ranges with margins, axes and their ticks, the
//! series in their styles, reference lines, notes and the legend. One routine for the SVG of the
//! HTML report and the print-resolution PNG of the LaTeX report; the chart itself is plain data
//! (`chart.rs`).

use super::chart::{
    nonzero_tick_label, register_font, tick_label, Axis, Chart, Legend, Options, Style, PALETTE,
};
use super::legend::{self, Layout};
use super::mark_label;
use super::ranges::{bounds, checked};
use super::ticks;
use crate::figures::{Drawn, FigureError};
use plotters::coord::ranged1d::{AsRangedCoord, BoldPoints, Ranged, ValueFormatter};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::FontDesc;

fn rgb(c: [u8; 3]) -> RGBColor {
    RGBColor(c[0], c[1], c[2])
}

impl Chart {
    fn x_bounds(&self, o: &Options) -> (f64, f64) {
        o.x_range.unwrap_or_else(|| {
            bounds(
                self.series
                    .iter()
                    .flat_map(|s| s.points.iter().map(|p| p.0)),
                self.x_log,
            )
        })
    }

    fn y_bounds(&self, o: &Options) -> (f64, f64) {
        o.y_range.unwrap_or_else(|| {
            bounds(
                self.series
                    .iter()
                    .flat_map(|s| s.points.iter().map(|p| p.1)),
                self.y_log,
            )
        })
    }

    /// Draws the chart on any plotters backend; `scale` multiplies font sizes and line widths
    /// (1 for the screen's SVG, about 3 for a 300-dpi PNG).
    pub fn draw<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, plotters::coord::Shift>,
        scale: f64,
    ) -> Result<(), FigureError> {
        self.draw_with(root, scale, &Options::default())
    }

    /// Draws the chart with `options` on any plotters backend.
    pub fn draw_with<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, plotters::coord::Shift>,
        scale: f64,
        o: &Options,
    ) -> Result<(), FigureError> {
        self.render(root, scale, o).map(|_| ())
    }

    /// Where the legend goes and what it covers, and the labelled ticks, when the chart is drawn
    /// at `dim` pixels and `scale`: the same computation as drawing, on a scratch canvas.
    pub fn layout(&self, dim: (u32, u32), scale: f64, o: &Options) -> Result<Layout, FigureError> {
        let mut scratch = String::new();
        let root = SVGBackend::with_string(&mut scratch, dim).into_drawing_area();
        self.render(&root, scale, o)
    }

    /// Draws with the legend moved to a free corner, or else the y range grown at the top, so
    /// that the legend covers no data.
    fn render<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, plotters::coord::Shift>,
        scale: f64,
        o: &Options,
    ) -> Result<Layout, FigureError> {
        if o.legend == Legend::Hidden || o.y_range.is_some() {
            return self.render_with_headroom(root, scale, o, 0.0);
        }
        let mut scratch = String::new();
        let probe = SVGBackend::with_string(&mut scratch, root.dim_in_pixel()).into_drawing_area();
        let first = self.render_with_headroom(&probe, scale, o, 0.0)?;
        drop(probe);
        let headroom = match (first.covered, first.rect) {
            (0, _) | (_, None) => 0.0,
            (_, Some(r)) => {
                let (_, ph) = self.plot_area(root.dim_in_pixel(), scale)?;
                // The share of the plot's height the legend takes from the top, plus a gap.
                ((r.y1 - r.y0 + 12) as f64 / ph).min(0.6)
            }
        };
        self.render_with_headroom(root, scale, o, headroom)
    }

    /// Draws with the top `headroom` share of the plot's height kept free of data.
    fn render_with_headroom<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, plotters::coord::Shift>,
        scale: f64,
        o: &Options,
        headroom: f64,
    ) -> Result<Layout, FigureError> {
        register_font();
        root.fill(&WHITE).drawn()?;
        let (mut x0, mut x1) = checked(self.x_bounds(o), self.x_log, "x")?;
        let (mut y0, mut y1) = checked(self.y_bounds(o), self.y_log, "y")?;
        if headroom > 0.0 {
            // Grow the top so that the data keep the lower (1 - headroom) of the height.
            let grow = headroom / (1.0 - headroom);
            if self.y_log {
                y1 = 10f64.powf(y1.log10() + grow * (y1.log10() - y0.log10()));
            } else {
                y1 += grow * (y1 - y0);
            }
        }
        if o.equal_aspect && !self.x_log && !self.y_log {
            // Widen one range so that a unit is as long on both axes.
            let (pw, ph) = self.plot_area(root.dim_in_pixel(), scale)?;
            let (sx, sy) = ((x1 - x0) / pw, (y1 - y0) / ph);
            if sx > sy {
                let (c, h) = (0.5 * (y0 + y1), 0.5 * sx * ph);
                (y0, y1) = (c - h, c + h);
            } else {
                let (c, h) = (0.5 * (x0 + x1), 0.5 * sy * pw);
                (x0, x1) = (c - h, c + h);
            }
        }
        // Log axes carry their own ticks (see `ticks`).
        let log_axis = ticks::LogAxis::new;
        match (self.x_log, self.y_log) {
            (false, false) => self.draw_in(root, scale, o, x0..x1, y0..y1, (x0, x1), (y0, y1)),
            (true, false) => {
                self.draw_in(root, scale, o, log_axis(x0, x1), y0..y1, (x0, x1), (y0, y1))
            }
            (false, true) => {
                self.draw_in(root, scale, o, x0..x1, log_axis(y0, y1), (x0, x1), (y0, y1))
            }
            (true, true) => self.draw_in(
                root,
                scale,
                o,
                log_axis(x0, x1),
                log_axis(y0, y1),
                (x0, x1),
                (y0, y1),
            ),
        }
    }

    /// The chart's frame: title, margins and label areas.
    fn builder<'a, 'b, DB: DrawingBackend>(
        &self,
        root: &'a DrawingArea<DB, plotters::coord::Shift>,
        scale: f64,
    ) -> ChartBuilder<'a, 'b, DB> {
        let px = |v: f64| (v * scale).round() as u32;
        let mut b = ChartBuilder::on(root);
        b.caption(
            &self.title,
            (super::chart::FIGURE_FONT, 17.0 * scale).into_font(),
        )
        .margin(px(12.0))
        .margin_right(px(22.0))
        .x_label_area_size(px(48.0))
        .y_label_area_size(px(72.0));
        b
    }

    /// The size in pixels of the plotting area inside a drawing of `dim` pixels, measured on a
    /// scratch canvas (the layout depends only on the size, the scale and the font).
    fn plot_area(&self, dim: (u32, u32), scale: f64) -> Result<(f64, f64), FigureError> {
        let mut scratch = String::new();
        let root = SVGBackend::with_string(&mut scratch, dim).into_drawing_area();
        let chart = self
            .builder(&root, scale)
            .build_cartesian_2d(0.0..1.0, 0.0..1.0)
            .drawn()?;
        let (w, h) = chart.plotting_area().dim_in_pixel();
        Ok((w.max(1) as f64, h.max(1) as f64))
    }

    #[allow(clippy::too_many_arguments)]
    fn draw_in<DB, X, Y>(
        &self,
        root: &DrawingArea<DB, plotters::coord::Shift>,
        scale: f64,
        o: &Options,
        x: X,
        y: Y,
        xr: (f64, f64),
        yr: (f64, f64),
    ) -> Result<Layout, FigureError>
    where
        DB: DrawingBackend,
        X: AsRangedCoord<Value = f64>,
        Y: AsRangedCoord<Value = f64>,
        X::CoordDescType: ValueFormatter<f64>,
        Y::CoordDescType: ValueFormatter<f64>,
    {
        let mut chart = self.builder(root, scale).build_cartesian_2d(x, y).drawn()?;
        // As many tick labels as fit: about one per 60 px across, one per 40 px up.
        let (pw, ph) = chart.plotting_area().dim_in_pixel();
        let fit = |len: u32, per: f64| ((len as f64 / (per * scale)) as usize).clamp(4, 8);
        let (nx, ny) = (fit(pw, 60.0), fit(ph, 40.0));
        // A linear axis asks plotters for more ticks until three fall inside its range; a log
        // axis has its own (the hint is then ignored).
        let (x_hint, y_hint) = (
            ticks::linear_hint(xr.0, xr.1, nx),
            ticks::linear_hint(yr.0, yr.1, ny),
        );
        let plain = |v: &f64| tick_label(*v);
        let log = |v: &f64| nonzero_tick_label(*v);
        let x_fmt: &dyn Fn(&f64) -> String = if self.x_log { &log } else { &plain };
        let y_fmt: &dyn Fn(&f64) -> String = if self.y_log { &log } else { &plain };
        let spec = chart.as_coord_spec();
        let labelled = |keys: Vec<f64>, f: &dyn Fn(&f64) -> String| {
            keys.iter().filter(|k| !f(k).is_empty()).count()
        };
        let x_ticks = labelled(spec.x_spec().key_points(BoldPoints(x_hint)), x_fmt);
        let y_ticks = labelled(spec.y_spec().key_points(BoldPoints(y_hint)), y_fmt);
        chart
            .configure_mesh()
            .x_desc(&self.x_label)
            .y_desc(&self.y_label)
            .label_style(font(12.0, scale))
            .axis_desc_style(font(14.0, scale))
            .light_line_style(RGBColor(235, 235, 235))
            .bold_line_style(RGBColor(215, 215, 215))
            .x_labels(x_hint)
            .y_labels(y_hint)
            .x_label_formatter(x_fmt)
            .y_label_formatter(y_fmt)
            .draw()
            .drawn()?;
        let mut layout = Layout {
            legend: None,
            rect: None,
            covered: 0,
            x_ticks,
            y_ticks,
        };
        let pixels = self.plotted_pixels(&chart, o, xr, yr);
        let area = chart.plotting_area().dim_in_pixel();
        let chosen = self.place_legend(scale, o, area, &pixels, &mut layout)?;
        self.draw_marks(&mut chart, scale, o, xr, yr, layout.rect)?;
        for (i, s) in self.series.iter().enumerate() {
            let color = rgb(o
                .colors
                .get(i)
                .copied()
                .flatten()
                .unwrap_or(PALETTE[i % PALETTE.len()]));
            self.draw_series(&mut chart, scale, s, color)?;
        }
        self.draw_notes(&mut chart, scale, o)?;
        self.draw_legend_box(&mut chart, scale, chosen)?;
        // No `present` here: a plot may be one panel of several, and presenting an SVG
        // backend closes its document (the later panels fell outside `</svg>`). The
        // drawing's owner presents once, at the end (`Drawing::draw`).
        Ok(layout)
    }

    /// True when point `p` can be drawn: finite, and positive on a log axis.
    pub(super) fn inside(&self, (a, b): (f64, f64)) -> bool {
        a.is_finite() && b.is_finite() && (!self.x_log || a > 0.0) && (!self.y_log || b > 0.0)
    }

    /// Every plotted pixel, relative to the plotting area, for placing the legend: the series
    /// and the reference lines.
    fn plotted_pixels<DB, XC, YC>(
        &self,
        chart: &Ctx<'_, DB, XC, YC>,
        o: &Options,
        xr: (f64, f64),
        yr: (f64, f64),
    ) -> Vec<(i32, i32)>
    where
        DB: DrawingBackend,
        XC: Ranged<ValueType = f64>,
        YC: Ranged<ValueType = f64>,
    {
        let base = chart.plotting_area().get_base_pixel();
        let to_pixel = |p: &(f64, f64)| {
            let (a, b) = chart.backend_coord(p);
            (a - base.0, b - base.1)
        };
        let mut pixels: Vec<(i32, i32)> = Vec::new();
        for m in o.marks.iter().filter(|m| m.at.is_finite()) {
            let ends = match m.axis {
                Axis::X => [(m.at, yr.0), (m.at, yr.1)],
                Axis::Y => [(xr.0, m.at), (xr.1, m.at)],
            };
            let line: Vec<(i32, i32)> = ends.iter().map(to_pixel).collect();
            pixels.extend(legend::densify(&line));
        }
        for s in &self.series {
            let pts: Vec<(i32, i32)> = s
                .points
                .iter()
                .filter(|p| self.inside(**p))
                .map(to_pixel)
                .collect();
            match s.style {
                Style::Line | Style::Dashed | Style::Dotted => pixels.extend(legend::densify(&pts)),
                _ => pixels.extend(pts),
            }
        }
        pixels
    }

    /// Chooses the legend's corner (recorded in `layout`): a position the figure asks for is a
    /// preference, and if it would hide data and another corner would not, the legend goes
    /// there.
    fn place_legend(
        &self,
        scale: f64,
        o: &Options,
        area: (u32, u32),
        pixels: &[(i32, i32)],
        layout: &mut Layout,
    ) -> Result<Legend, FigureError> {
        let labels: Vec<&str> = self
            .series
            .iter()
            .filter(|s| !s.label.is_empty())
            .map(|s| s.label.as_str())
            .collect();
        if labels.is_empty() {
            return Ok(Legend::Hidden);
        }
        let size = legend::size(
            &labels,
            12.0 * scale,
            px(28.0, scale) as i32,
            px(8.0, scale) as i32,
        )?;
        let nowhere = legend::Rect {
            x0: 0,
            y0: 0,
            x1: 0,
            y1: 0,
        };
        let (pos, rect, covered) = match o.legend {
            Legend::Auto => legend::choose(size, area, pixels),
            fixed => match legend::rect(fixed, size, area) {
                Some(r) => match legend::covered(&r, pixels) {
                    0 => (fixed, r, 0),
                    c => match legend::choose(size, area, pixels) {
                        (p, r2, 0) => (p, r2, 0),
                        _ => (fixed, r, c),
                    },
                },
                None => (fixed, nowhere, 0),
            },
        };
        if pos != Legend::Hidden {
            layout.legend = Some(pos);
            layout.rect = Some(rect);
            layout.covered = covered;
        }
        Ok(pos)
    }

    /// The reference lines, under the data, and their labels placed by `mark_label` clear of
    /// the legend (`legend_rect`), of each other and of the data.
    fn draw_marks<'a, DB, XC, YC>(
        &self,
        chart: &mut Ctx<'a, DB, XC, YC>,
        scale: f64,
        o: &Options,
        xr: (f64, f64),
        yr: (f64, f64),
        legend_rect: Option<legend::Rect>,
    ) -> Result<(), FigureError>
    where
        DB: DrawingBackend + 'a,
        XC: Ranged<ValueType = f64>,
        YC: Ranged<ValueType = f64>,
    {
        let grey = RGBColor(110, 110, 110);
        let base = chart.plotting_area().get_base_pixel();
        let mut placed: Vec<legend::Rect> = Vec::new();
        for m in o.marks.iter().filter(|m| m.at.is_finite()) {
            let pts = match m.axis {
                Axis::X => vec![(m.at, yr.0), (m.at, yr.1)],
                Axis::Y => vec![(xr.0, m.at), (xr.1, m.at)],
            };
            chart
                .draw_series(DashedLineSeries::new(
                    pts,
                    px(4.0, scale),
                    px(3.0, scale),
                    grey.stroke_width(px(1.2, scale).max(1)),
                ))
                .drawn()?;
            if m.label.is_empty() {
                continue;
            }
            // The label just inside the plot, at the top of a vertical line or the left end of
            // a horizontal one.
            let at = match m.axis {
                Axis::X => (m.at, yr.1),
                Axis::Y => (xr.0, m.at),
            };
            let frac = if self.x_log {
                (m.at.ln() - xr.0.ln()) / (xr.1.ln() - xr.0.ln())
            } else {
                (m.at - xr.0) / (xr.1 - xr.0)
            };
            let (tw, th) = font(11.0, scale).box_size(&m.label).drawn()?;
            let (ax, ay) = chart.backend_coord(&at);
            let x_edge = |x: f64| chart.backend_coord(&(x, yr.1)).0 - base.0;
            let covered = |r: &legend::Rect| {
                self.series
                    .iter()
                    .flat_map(|s| s.points.iter())
                    .filter(|p| self.inside(**p))
                    .filter(|p| {
                        let (x, y) = chart.backend_coord(p);
                        r.contains((x - base.0, y - base.1))
                    })
                    .count()
            };
            let label = mark_label::Label {
                vertical: m.axis == Axis::X,
                at: (ax - base.0, ay - base.1),
                size: (tw as i32, th as i32),
                frac,
                plot_x: (x_edge(xr.0), x_edge(xr.1)),
                unit: scale,
            };
            let p = mark_label::place(&label, legend_rect, &placed, &covered);
            placed.push(p.rect);
            let hpos = if p.left { HPos::Right } else { HPos::Left };
            chart
                .draw_series(std::iter::once(
                    EmptyElement::at(at)
                        + Text::new(
                            m.label.clone(),
                            p.offset,
                            font(11.0, scale)
                                .color(&grey)
                                .pos(Pos::new(hpos, VPos::Top)),
                        ),
                ))
                .drawn()?;
        }
        Ok(())
    }
}

/// A chart's drawing context on backend `DB` with coordinates `XC` across and `YC` up.
pub(super) type Ctx<'a, DB, XC, YC> = ChartContext<'a, DB, Cartesian2d<XC, YC>>;

/// `v` screen pixels at `scale`, rounded.
pub(super) fn px(v: f64, scale: f64) -> u32 {
    (v * scale).round() as u32
}

/// The figures' font at `size` screen pixels, at `scale`.
pub(super) fn font(size: f64, scale: f64) -> FontDesc<'static> {
    (super::chart::FIGURE_FONT, size * scale).into_font()
}
