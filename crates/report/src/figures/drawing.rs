//! What a figure draws ([`Drawing`]: a chart, a plot, side-by-side panels, figure 1's geometry
//! or the premises graph) and its renderer: on any plotters backend, as an SVG document, or as
//! a PNG file ([`super::png`]).

use super::chart::{self, Chart, Options, Plot};
use super::error::{Drawn, FigureError};
use super::geometry::Geometry;
use super::legend::Layout;
use super::premises;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use serde::Serialize;

/// Side-by-side plots under one title.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Panels {
    /// The overall title.
    pub title: String,
    /// The plots, left to right.
    pub plots: Vec<Plot>,
}

/// What a figure draws.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum Drawing {
    /// A chart with default options.
    Chart(Chart),
    /// A chart with options (ranges, colours, reference lines, notes).
    Plot(Plot),
    /// Several plots side by side.
    Panels(Panels),
    /// Figure 1's geometry.
    Geometry(Geometry),
    /// The premises graph, coloured by verdict ([`checks::cause::graph`]).
    Premises(checks::cause::graph::PremisesGraph),
}

impl Drawing {
    /// Draws on any plotters backend; `scale` multiplies fonts and line widths.
    pub fn draw<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, plotters::coord::Shift>,
        scale: f64,
    ) -> Result<(), FigureError> {
        match self {
            Drawing::Chart(c) => {
                c.draw(root, scale)?;
                root.present().drawn()
            }
            Drawing::Plot(p) => {
                p.draw(root, scale)?;
                root.present().drawn()
            }
            Drawing::Geometry(g) => g.draw(root, scale),
            Drawing::Premises(g) => premises::draw(g, root, scale),
            Drawing::Panels(p) => {
                chart::register_font();
                root.fill(&WHITE).drawn()?;
                let band = (36.0 * scale).round() as u32;
                let (top, inner) = root.split_vertically(band);
                let (w, _) = top.dim_in_pixel();
                top.draw(&Text::new(
                    p.title.clone(),
                    ((w / 2) as i32, (band / 2) as i32),
                    (chart::FIGURE_FONT, 17.0 * scale)
                        .into_font()
                        .color(&BLACK)
                        .pos(Pos::new(HPos::Center, VPos::Center)),
                ))
                .drawn()?;
                let n = p.plots.len().max(1);
                for (area, plot) in inner.split_evenly((1, n)).iter().zip(&p.plots) {
                    plot.draw(area, scale)?;
                }
                root.present().drawn()
            }
        }
    }

    /// For each plot of the drawing (one, or one per panel; none for a geometry): where its
    /// legend goes, how many plotted pixels it covers, and its labelled ticks per axis, when
    /// drawn at `width` x `height` px and `scale` (the report's sizes: 760 x 480 at 1, and
    /// 1800 x 1200 at 3).
    pub fn layouts(&self, width: u32, height: u32, scale: f64) -> Result<Vec<Layout>, FigureError> {
        chart::register_font();
        match self {
            Drawing::Chart(c) => Ok(vec![c.layout(
                (width, height),
                scale,
                &Options::default(),
            )?]),
            Drawing::Plot(p) => Ok(vec![p.layout((width, height), scale)?]),
            Drawing::Geometry(_) | Drawing::Premises(_) => Ok(vec![]),
            Drawing::Panels(p) => {
                // The same split as `draw`: a title band, then equal columns.
                let band = (36.0 * scale).round() as u32;
                let n = p.plots.len().max(1) as u32;
                let dim = (width / n, height.saturating_sub(band));
                p.plots.iter().map(|plot| plot.layout(dim, scale)).collect()
            }
        }
    }

    /// The drawing as an SVG document, `width` x `height` px.
    pub fn to_svg(&self, width: u32, height: u32) -> Result<String, FigureError> {
        let mut out = String::new();
        {
            let root = SVGBackend::with_string(&mut out, (width, height)).into_drawing_area();
            self.draw(&root, 1.0)?;
        }
        Ok(out)
    }

    /// The drawing as a PNG file at `path`: 1800 x 1200 px (6 x 4 in at 300 dpi), scale 3.
    pub fn to_png(&self, path: &std::path::Path) -> Result<(), FigureError> {
        self.to_png_sized(path, (600, 400), 3.0)
    }

    /// The drawing as a PNG file at `path` laid out on `size` px with fonts and lines of their
    /// usual size, every length then multiplied by `scale` for resolution.
    pub fn to_png_sized(
        &self,
        path: &std::path::Path,
        size: (u32, u32),
        scale: f64,
    ) -> Result<(), FigureError> {
        let px = |v: u32| (v as f64 * scale).round() as u32;
        let (w, h) = (px(size.0), px(size.1));
        let mut rgb = vec![0u8; 3 * w as usize * h as usize];
        {
            let root = BitMapBackend::with_buffer(&mut rgb, (w, h)).into_drawing_area();
            self.draw(&root, scale)?;
            root.present().drawn()?;
        }
        super::png::write(path, &rgb, (w, h))
    }
}
