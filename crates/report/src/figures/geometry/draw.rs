//! Drawing figure 1's shapes on a plotters backend: projection, lines, arrows, labels, dashes.

use super::{register_font, FigureError, Geometry, HPos, Line, Pos, Shape, VPos, V3};
use plotters::prelude::*;

impl Geometry {
    /// Draws the figure on any plotters backend; `scale` multiplies fonts and line widths.
    pub fn draw<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, plotters::coord::Shift>,
        scale: f64,
    ) -> Result<(), FigureError> {
        register_font();
        let err = |e: DrawingAreaErrorKind<DB::ErrorType>| FigureError::Draw(e.to_string());
        root.fill(&WHITE).map_err(err)?;
        let (w, h) = root.dim_in_pixel();
        let (w, h) = (w as f64, h as f64);
        let font = |size: f64| (crate::figures::chart::FIGURE_FONT, size * scale).into_font();
        let title_band = 34.0 * scale;
        let foot = self.footnote(root, w, scale);
        let foot_band = (30.0 + 15.0 * (foot.len() - 1) as f64) * scale;
        // Fit the projected scene into the area, same scale on both axes.
        let shapes = self.shapes();
        let (x0, x1, y0, y1) = self.extent(&shapes);
        if !(x1 > x0 && y1 > y0) {
            return Err("the geometry has no extent".into());
        }
        let margin = 24.0 * scale;
        let avail_w = w - 2.0 * margin;
        let avail_h = h - title_band - foot_band - 2.0 * margin;
        let k = (avail_w / (x1 - x0)).min(avail_h / (y1 - y0));
        let cx = 0.5 * w - k * 0.5 * (x0 + x1);
        let cy = title_band + margin + 0.5 * avail_h + k * 0.5 * (y0 + y1);
        let px = |p: V3| -> (i32, i32) {
            let (x, y) = self.view.project(p);
            ((cx + k * x).round() as i32, (cy - k * y).round() as i32)
        };
        let lw = |v: f64| ((v * scale).round() as u32).max(1);
        let col = |c: [u8; 3]| RGBColor(c[0], c[1], c[2]);
        let centred = |size: f64, c: [u8; 3]| {
            font(size)
                .color(&col(c))
                .pos(Pos::new(HPos::Center, VPos::Center))
        };
        for s in &shapes {
            match s {
                Shape::Fill {
                    points,
                    color,
                    opacity,
                } => {
                    let poly: Vec<(i32, i32)> = points.iter().map(|p| px(*p)).collect();
                    root.draw(&Polygon::new(poly, col(*color).mix(*opacity).filled()))
                        .map_err(err)?;
                }
                Shape::Path {
                    points,
                    line,
                    color,
                } => {
                    let poly: Vec<(i32, i32)> = points.iter().map(|p| px(*p)).collect();
                    let c = col(*color);
                    match line {
                        Line::Thin => root
                            .draw(&PathElement::new(poly, c.stroke_width(lw(1.3))))
                            .map_err(err)?,
                        Line::Thick => root
                            .draw(&PathElement::new(poly, c.stroke_width(lw(2.4))))
                            .map_err(err)?,
                        Line::Dashed | Line::Dotted => {
                            let (on, off) = if *line == Line::Dashed {
                                (7.0 * scale, 5.0 * scale)
                            } else {
                                (2.0 * scale, 4.0 * scale)
                            };
                            for seg in dash(&poly, on, off) {
                                root.draw(&PathElement::new(seg, c.stroke_width(lw(1.3))))
                                    .map_err(err)?;
                            }
                        }
                    }
                }
                Shape::Arrow {
                    from,
                    to,
                    label,
                    color,
                    nudge,
                } => arrow(root, (px(*from), px(*to)), label, *color, *nudge, scale)?,
                Shape::Dot { at, label, offset } => dot(root, px(*at), label, *offset, scale)?,
                Shape::Label { at, text, color } => {
                    root.draw(&Text::new(text.clone(), px(*at), centred(16.0, *color)))
                        .map_err(err)?;
                }
            }
        }
        root.draw(&Text::new(
            self.title.clone(),
            ((0.5 * w) as i32, (16.0 * scale) as i32),
            font(17.0)
                .color(&BLACK)
                .pos(Pos::new(HPos::Center, VPos::Center)),
        ))
        .map_err(err)?;
        for (i, line) in foot.iter().enumerate() {
            let from_bottom = (16.0 + 15.0 * (foot.len() - 1 - i) as f64) * scale;
            root.draw(&Text::new(
                line.clone(),
                ((0.5 * w) as i32, (h - from_bottom) as i32),
                font(12.0)
                    .color(&RGBColor(70, 70, 70))
                    .pos(Pos::new(HPos::Center, VPos::Center)),
            ))
            .map_err(err)?;
        }
        root.present().map_err(err)
    }
    /// The footnote of lengths and rates, on one line, or on two where one does not fit (the
    /// figure at the paper's 3 in width).
    fn footnote<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, plotters::coord::Shift>,
        w: f64,
        scale: f64,
    ) -> Vec<String> {
        let font = |size: f64| (crate::figures::chart::FIGURE_FONT, size * scale).into_font();
        let lengths = format!(
            "a = {:.1} mm, α = {:.2} rad, b = {:.2}a, r = b + a cos α = {:.2}a",
            self.a * 1e3,
            self.alpha,
            self.b / self.a,
            self.r / self.a,
        );
        let rates = format!(
            "Ω₀ = {:.2} rad/s, ω₁₀ = {:.2} rad/s (eqs 28-29)",
            self.precession, self.spin
        );
        let one = format!("{lengths}; {rates}");
        let fits = root
            .estimate_text_size(&one, &font(12.0).into_text_style(root))
            .map_or(true, |(tw, _)| (tw as f64) < w - 16.0 * scale);
        if fits {
            vec![one]
        } else {
            vec![lengths, rates]
        }
    }

    /// The projected extent of `shapes`: (x0, x1, y0, y1).
    fn extent(&self, shapes: &[Shape]) -> (f64, f64, f64, f64) {
        let mut pts = Vec::new();
        for s in shapes {
            match s {
                Shape::Fill { points, .. } | Shape::Path { points, .. } => {
                    pts.extend(points.iter().map(|p| self.view.project(*p)))
                }
                Shape::Arrow { from, to, .. } => {
                    pts.push(self.view.project(*from));
                    pts.push(self.view.project(*to));
                }
                Shape::Dot { at, .. } | Shape::Label { at, .. } => pts.push(self.view.project(*at)),
            }
        }
        pts.iter().fold(
            (
                f64::INFINITY,
                f64::NEG_INFINITY,
                f64::INFINITY,
                f64::NEG_INFINITY,
            ),
            |(x0, x1, y0, y1), &(x, y)| (x0.min(x), x1.max(x), y0.min(y), y1.max(y)),
        )
    }
}

/// Splits a screen polyline into dashes of length `on` separated by gaps `off` (px).
pub(super) fn dash(poly: &[(i32, i32)], on: f64, off: f64) -> Vec<Vec<(i32, i32)>> {
    let mut out = Vec::new();
    let mut cur: Vec<(i32, i32)> = Vec::new();
    let (mut drawing, mut left) = (true, on);
    for w in poly.windows(2) {
        let (p, q) = (
            (w[0].0 as f64, w[0].1 as f64),
            (w[1].0 as f64, w[1].1 as f64),
        );
        let len = ((q.0 - p.0).powi(2) + (q.1 - p.1).powi(2)).sqrt();
        let mut s = 0.0;
        let at = |s: f64| {
            let f = if len > 0.0 { s / len } else { 0.0 };
            (
                (p.0 + f * (q.0 - p.0)).round() as i32,
                (p.1 + f * (q.1 - p.1)).round() as i32,
            )
        };
        if drawing && cur.is_empty() {
            cur.push(at(0.0));
        }
        while len - s > left {
            s += left;
            if drawing {
                cur.push(at(s));
                out.push(std::mem::take(&mut cur));
                left = off;
            } else {
                cur.push(at(s));
                left = on;
            }
            drawing = !drawing;
        }
        left -= len - s;
        if drawing {
            cur.push(at(len));
        }
    }
    if cur.len() > 1 {
        out.push(cur);
    }
    out
}

/// The error of a drawing call, as a figure error.
fn drawn<E: std::error::Error + Send + Sync>(e: DrawingAreaErrorKind<E>) -> FigureError {
    FigureError::Draw(e.to_string())
}

/// A line `px` pixels wide at `scale`, at least one.
fn lw(v: f64, scale: f64) -> u32 {
    ((v * scale).round() as u32).max(1)
}

/// An arrow from `p` to `q` (pixels) with its head, and its label beyond the head with the hat
/// of a unit vector drawn over it (a combining circumflex does not render).
fn arrow<DB: DrawingBackend>(
    root: &DrawingArea<DB, plotters::coord::Shift>,
    (p, q): ((i32, i32), (i32, i32)),
    label: &str,
    color: [u8; 3],
    nudge: (f64, f64),
    scale: f64,
) -> Result<(), FigureError> {
    let c = RGBColor(color[0], color[1], color[2]);
    let (dx, dy) = ((q.0 - p.0) as f64, (q.1 - p.1) as f64);
    let len = (dx * dx + dy * dy).sqrt().max(1e-9);
    let (ux, uy) = (dx / len, dy / len);
    let head = 11.0 * scale;
    let base = (q.0 as f64 - head * ux, q.1 as f64 - head * uy);
    let side = 4.5 * scale;
    root.draw(&PathElement::new(
        vec![p, (base.0.round() as i32, base.1.round() as i32)],
        c.stroke_width(lw(2.0, scale)),
    ))
    .map_err(drawn)?;
    root.draw(&Polygon::new(
        vec![
            q,
            (
                (base.0 - side * uy).round() as i32,
                (base.1 + side * ux).round() as i32,
            ),
            (
                (base.0 + side * uy).round() as i32,
                (base.1 - side * ux).round() as i32,
            ),
        ],
        c.filled(),
    ))
    .map_err(drawn)?;
    let off = 11.0 * scale;
    let at = (
        (q.0 as f64 + off * ux + nudge.0 * scale).round() as i32,
        (q.1 as f64 + off * uy + nudge.1 * scale).round() as i32,
    );
    let style = (crate::figures::chart::FIGURE_FONT, 17.0 * scale)
        .into_font()
        .color(&c)
        .pos(Pos::new(HPos::Center, VPos::Center));
    root.draw(&Text::new(label.to_string(), at, style))
        .map_err(drawn)?;
    let (hw, hy, hh) = (
        (4.0 * scale).round() as i32,
        at.1 - (12.0 * scale).round() as i32,
        (3.5 * scale).round() as i32,
    );
    root.draw(&PathElement::new(
        vec![(at.0 - hw, hy + hh), (at.0, hy), (at.0 + hw, hy + hh)],
        c.stroke_width(lw(1.4, scale)),
    ))
    .map_err(drawn)
}

/// A dot at `p` (pixels) with its label at `offset`, and a leader line to a label placed far.
fn dot<DB: DrawingBackend>(
    root: &DrawingArea<DB, plotters::coord::Shift>,
    p: (i32, i32),
    label: &str,
    offset: (f64, f64),
    scale: f64,
) -> Result<(), FigureError> {
    root.draw(&Circle::new(p, lw(3.5, scale), BLACK.filled()))
        .map_err(drawn)?;
    let hpos = if offset.0 < 0.0 {
        HPos::Right
    } else {
        HPos::Left
    };
    let q = (
        p.0 + (offset.0 * scale).round() as i32,
        p.1 + (offset.1 * scale).round() as i32,
    );
    if offset.0.hypot(offset.1) > 30.0 {
        let gap = (4.0 * scale).round() as i32;
        let end = (q.0 - gap * offset.0.signum() as i32, q.1);
        root.draw(&PathElement::new(
            vec![p, end],
            RGBColor(90, 90, 90).stroke_width(lw(0.8, scale)),
        ))
        .map_err(drawn)?;
    }
    let style = (crate::figures::chart::FIGURE_FONT, 12.5 * scale)
        .into_font()
        .color(&RGBColor(60, 60, 60))
        .pos(Pos::new(hpos, VPos::Center));
    root.draw(&Text::new(label.to_string(), q, style))
        .map_err(drawn)
}
