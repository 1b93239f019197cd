//! Figure 1, the geometry of the rolling disk, drawn from the model's own definitions.
//!
//! The triad is built from the tilt $\alpha$ and the heading $\psi$ as the paper defines it
//! (eqs 1-9): $\hat{\mathbf 2} = (\cos\psi, \sin\psi, 0)$ horizontal, $\hat{\mathbf r} =
//! \hat{\mathbf 2}\times\hat{\mathbf z}$, $\hat{\mathbf 3} = \cos\alpha\,\hat{\mathbf r} -
//! \sin\alpha\,\hat{\mathbf z}$ (centre to contact, $\alpha$ below the horizontal) and
//! $\hat{\mathbf 1} = -\sin\alpha\,\hat{\mathbf r} - \cos\alpha\,\hat{\mathbf z}$ (eq 8), so that
//! $\hat{\mathbf 2} = \hat{\mathbf 3}\times\hat{\mathbf 1}$. The lengths $b$ and $r$ come from a
//! steady motion of the model ([`steady_motion`]): $b = a\omega_{10}/\Omega_0$ (eq 28) and
//! $r = b + a\cos\alpha_0$ (eq 29's $b = r - a\cos\alpha$). With the axis of the circular motion
//! at the origin, the contact point is $r\hat{\mathbf r}$ and the centre of mass
//! $r\hat{\mathbf r} - a\hat{\mathbf 3} = b\hat{\mathbf r} + a\sin\alpha\,\hat{\mathbf z}$ (eq 14).
//!
//! The picture is a 3-D scene of lines, arrows, dots and labels ([`Geometry::shapes`]),
//! projected orthographically from an oblique viewpoint and drawn with plotters primitives on
//! any backend.

use crate::disk::Disk;
use crate::figures::chart::register_font;
use crate::figures::FigureError;
use crate::model::steady::steady_motion;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use serde::Serialize;

/// A 3-vector (lab coordinates, z up).
pub type V3 = [f64; 3];

fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn mul(s: f64, a: V3) -> V3 {
    [s * a[0], s * a[1], s * a[2]]
}

/// Cross product.
pub fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// Dot product.
pub fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The paper's unit vectors at tilt `alpha` and heading `psi`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Triad {
    /// $\hat{\mathbf 1}$, the symmetry axis.
    pub e1: V3,
    /// $\hat{\mathbf 2}$, horizontal, in the disk's plane, along the contact point's velocity.
    pub e2: V3,
    /// $\hat{\mathbf 3}$, from the centre to the contact point.
    pub e3: V3,
    /// $\hat{\mathbf r} = \hat{\mathbf 2}\times\hat{\mathbf z}$, horizontal.
    pub r: V3,
    /// $\hat{\mathbf z}$, vertically up.
    pub z: V3,
}

impl Triad {
    /// The triad at tilt `alpha` and heading `psi` (the angle of $\hat{\mathbf 2}$ from x).
    pub fn new(alpha: f64, psi: f64) -> Self {
        let (sa, ca) = alpha.sin_cos();
        let (sp, cp) = psi.sin_cos();
        let z = [0.0, 0.0, 1.0];
        let e2 = [cp, sp, 0.0];
        let r = cross(e2, z);
        let e3 = add(mul(ca, r), mul(-sa, z));
        let e1 = add(mul(-sa, r), mul(-ca, z));
        Self { e1, e2, e3, r, z }
    }
}

/// How a line is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Line {
    /// Solid, thin.
    Thin,
    /// Solid, thick (the disk's rim).
    Thick,
    /// Dashed.
    Dashed,
    /// Dotted.
    Dotted,
}

/// One element of the 3-D scene.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum Shape {
    /// A filled polygon (no outline).
    Fill {
        /// Its corners.
        points: Vec<V3>,
        /// RGB.
        color: [u8; 3],
        /// Opacity 0-1.
        opacity: f64,
    },
    /// A polyline.
    Path {
        /// Its points.
        points: Vec<V3>,
        /// How it is drawn.
        line: Line,
        /// RGB.
        color: [u8; 3],
    },
    /// An arrow from `from` to `to` with a label beyond its tip.
    Arrow {
        /// Its tail.
        from: V3,
        /// Its tip.
        to: V3,
        /// The label.
        label: String,
        /// RGB.
        color: [u8; 3],
        /// A shift of the label from its place beyond the tip (screen px at scale 1, y down).
        nudge: (f64, f64),
    },
    /// A dot with a label.
    Dot {
        /// Where.
        at: V3,
        /// The label, placed to the side given by `offset` (screen px at scale 1, y down).
        label: String,
        /// Label offset.
        offset: (f64, f64),
    },
    /// A label at a point (centred).
    Label {
        /// Where.
        at: V3,
        /// The text.
        text: String,
        /// RGB.
        color: [u8; 3],
    },
}

/// The viewpoint: an orthographic projection from azimuth and elevation (rad).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct View {
    /// Azimuth of the viewer from the x axis.
    pub azimuth: f64,
    /// Elevation of the viewer above the table.
    pub elevation: f64,
}

impl View {
    /// Screen coordinates (right, up) of a lab point.
    pub fn project(&self, p: V3) -> (f64, f64) {
        let (st, ct) = self.azimuth.sin_cos();
        let (sf, cf) = self.elevation.sin_cos();
        let right = [-st, ct, 0.0];
        let up = [-sf * ct, -sf * st, cf];
        (dot(p, right), dot(p, up))
    }
}

/// Figure 1 as data: the disk in a steady motion, its triad and its lengths.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Geometry {
    /// Title drawn above the picture.
    pub title: String,
    /// Radius $a$ (m).
    pub a: f64,
    /// Tilt $\alpha$ (rad).
    pub alpha: f64,
    /// Heading $\psi$ (rad).
    pub heading: f64,
    /// $b$ (m), from eq 28.
    pub b: f64,
    /// $r$ (m), from eq 29's $b = r - a\cos\alpha$.
    pub r: f64,
    /// The steady precession $\Omega_0$ (rad/s, eq 29).
    pub precession: f64,
    /// The steady spin $\omega_{10}$ (rad/s, eq 28).
    pub spin: f64,
    /// The triad.
    pub triad: Triad,
    /// The centre of mass (m), the axis of the circular motion at the origin.
    pub centre: V3,
    /// The contact point (m).
    pub contact: V3,
    /// The viewpoint.
    pub view: View,
}

const INK: [u8; 3] = [20, 20, 20];
const GREY: [u8; 3] = [120, 120, 120];
const BLUE: [u8; 3] = [0, 114, 178];
const VERMILION: [u8; 3] = [213, 94, 0];
const GREEN: [u8; 3] = [0, 140, 100];

impl Geometry {
    /// The geometry of the disk in the steady motion at tilt `alpha0` with radius `b` of the
    /// centre of mass's circle (eqs 28-29), seen from `view`.
    pub fn steady(
        disk: &Disk,
        alpha0: f64,
        b: f64,
        heading: f64,
        view: View,
    ) -> Result<Self, FigureError> {
        let m = steady_motion(disk, alpha0, b).map_err(|e| FigureError::Data(e.to_string()))?;
        // Eq 28 read backwards: b = a omega_10 / Omega_0; then r = b + a cos(alpha0).
        let b = disk.a * m.spin / m.precession;
        let r = b + disk.a * alpha0.cos();
        let triad = Triad::new(alpha0, heading);
        let contact = mul(r, triad.r);
        let centre = add(contact, mul(-disk.a, triad.e3));
        Ok(Self {
            title: format!(
                "The rolling disk in steady motion (α = {:.0}°, b = {:.2}a)",
                alpha0.to_degrees(),
                b / disk.a
            ),
            a: disk.a,
            alpha: alpha0,
            heading,
            b,
            r,
            precession: m.precession,
            spin: m.spin,
            triad,
            centre,
            contact,
            view,
        })
    }

    /// The scene as 3-D shapes, in drawing order.
    pub fn shapes(&self) -> Vec<Shape> {
        let (a, t, c, p) = (self.a, self.triad, self.centre, self.contact);
        let h = a * self.alpha.sin();
        let origin = [0.0, 0.0, 0.0];
        let ring = |centre: V3, u: V3, v: V3, radius: f64, n: usize| -> Vec<V3> {
            (0..=n)
                .map(|i| {
                    let s = std::f64::consts::TAU * i as f64 / n as f64;
                    add(
                        centre,
                        add(mul(radius * s.cos(), u), mul(radius * s.sin(), v)),
                    )
                })
                .collect()
        };
        let x = [1.0, 0.0, 0.0];
        let y = [0.0, 1.0, 0.0];
        let mut out = Vec::new();
        // The table: a square around the contact circle.
        let half = 1.25 * self.r.max(a) + 0.3 * a;
        let corners = vec![
            add(mul(-half, x), mul(-half, y)),
            add(mul(half, x), mul(-half, y)),
            add(mul(half, x), mul(half, y)),
            add(mul(-half, x), mul(half, y)),
        ];
        out.push(Shape::Fill {
            points: corners.clone(),
            color: [236, 236, 236],
            opacity: 1.0,
        });
        let mut edge = corners;
        edge.push(edge[0]);
        out.push(Shape::Path {
            points: edge,
            line: Line::Thin,
            color: [190, 190, 190],
        });
        // The circle of the contact point (radius r) on the table, and the circle of the centre
        // of mass (radius b) at its height.
        out.push(Shape::Path {
            points: ring(origin, x, y, self.r, 144),
            line: Line::Dashed,
            color: VERMILION,
        });
        if self.b.abs() > 1e-9 {
            out.push(Shape::Path {
                points: ring([0.0, 0.0, h], x, y, self.b.abs(), 144),
                line: Line::Dotted,
                color: GREEN,
            });
        }
        // The vertical axis of the circular motion.
        out.push(Shape::Path {
            points: vec![origin, [0.0, 0.0, h + 1.1 * a]],
            line: Line::Dashed,
            color: GREY,
        });
        // The disk.
        let rim = ring(c, t.e2, t.e3, a, 144);
        out.push(Shape::Fill {
            points: rim.clone(),
            color: [86, 180, 233],
            opacity: 0.28,
        });
        out.push(Shape::Path {
            points: rim,
            line: Line::Thick,
            color: [40, 70, 110],
        });
        // Lengths: r on the table from the axis to the contact; b from the axis to the centre
        // at the centre's height; a from the centre to the contact.
        out.push(Shape::Path {
            points: vec![origin, p],
            line: Line::Thin,
            color: VERMILION,
        });
        out.push(Shape::Label {
            at: add(mul(0.5, p), mul(-0.22 * a, t.e2)),
            text: "r".into(),
            color: VERMILION,
        });
        out.push(Shape::Path {
            points: vec![[0.0, 0.0, h], c],
            line: Line::Thin,
            color: GREEN,
        });
        out.push(Shape::Label {
            at: add(
                add([0.0, 0.0, h], mul(0.5 * self.b, t.r)),
                [0.0, 0.0, 0.11 * a],
            ),
            text: "b".into(),
            color: GREEN,
        });
        out.push(Shape::Path {
            points: vec![c, p],
            line: Line::Thin,
            color: INK,
        });
        out.push(Shape::Label {
            at: add(add(c, mul(0.85 * a, t.e3)), mul(0.16 * a, t.e2)),
            text: "a".into(),
            color: INK,
        });
        // The angle alpha between r (horizontal) and 3, at the centre.
        let arc: Vec<V3> = (0..=24)
            .map(|i| {
                let s = self.alpha * i as f64 / 24.0;
                add(c, mul(0.3 * a, add(mul(s.cos(), t.r), mul(-s.sin(), t.z))))
            })
            .collect();
        out.push(Shape::Path {
            points: arc,
            line: Line::Thin,
            color: INK,
        });
        let mid = 0.5 * self.alpha;
        out.push(Shape::Label {
            at: add(
                c,
                mul(0.4 * a, add(mul(mid.cos(), t.r), mul(-mid.sin(), t.z))),
            ),
            text: "α".into(),
            color: INK,
        });
        // The unit vectors at the centre.
        let arrow =
            |v: V3, len: f64, label: &str, color: [u8; 3], nudge: (f64, f64)| Shape::Arrow {
                from: c,
                to: add(c, mul(len * a, v)),
                label: label.into(),
                color,
                nudge,
            };
        out.push(arrow(t.z, 0.65, "z", INK, (0.0, 0.0)));
        out.push(arrow(t.r, 0.65, "r", INK, (0.0, 0.0)));
        out.push(arrow(t.e1, 0.6, "1", BLUE, (-2.0, -12.0)));
        out.push(arrow(t.e2, 0.6, "2", BLUE, (0.0, 0.0)));
        out.push(arrow(t.e3, 0.55, "3", BLUE, (-16.0, -4.0)));
        out.push(Shape::Dot {
            at: c,
            label: "centre of mass".into(),
            offset: (55.0, -100.0),
        });
        out.push(Shape::Dot {
            at: p,
            label: "contact point".into(),
            offset: (8.0, 12.0),
        });
        out.push(Shape::Dot {
            at: origin,
            label: "axis of the circular motion".into(),
            offset: (-30.0, 66.0),
        });
        out
    }

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
        let font = |size: f64| ("sans-serif", size * scale).into_font();
        let title_band = 34.0 * scale;
        let foot_band = 30.0 * scale;
        // Fit the projected scene into the area, same scale on both axes.
        let shapes = self.shapes();
        let mut pts = Vec::new();
        for s in &shapes {
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
        let (mut x0, mut x1, mut y0, mut y1) = (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        );
        for (x, y) in &pts {
            x0 = x0.min(*x);
            x1 = x1.max(*x);
            y0 = y0.min(*y);
            y1 = y1.max(*y);
        }
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
                } => {
                    let (p, q) = (px(*from), px(*to));
                    let c = col(*color);
                    let (dx, dy) = ((q.0 - p.0) as f64, (q.1 - p.1) as f64);
                    let len = (dx * dx + dy * dy).sqrt().max(1e-9);
                    let (ux, uy) = (dx / len, dy / len);
                    let head = 11.0 * scale;
                    let base = (q.0 as f64 - head * ux, q.1 as f64 - head * uy);
                    let side = 4.5 * scale;
                    root.draw(&PathElement::new(
                        vec![p, (base.0.round() as i32, base.1.round() as i32)],
                        c.stroke_width(lw(2.0)),
                    ))
                    .map_err(err)?;
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
                    .map_err(err)?;
                    let off = 11.0 * scale;
                    let at = (
                        (q.0 as f64 + off * ux + nudge.0 * scale).round() as i32,
                        (q.1 as f64 + off * uy + nudge.1 * scale).round() as i32,
                    );
                    root.draw(&Text::new(label.clone(), at, centred(17.0, *color)))
                        .map_err(err)?;
                    // The hat of a unit vector, drawn (a combining circumflex does not render).
                    let (hw, hy, hh) = (
                        (4.0 * scale).round() as i32,
                        at.1 - (12.0 * scale).round() as i32,
                        (3.5 * scale).round() as i32,
                    );
                    root.draw(&PathElement::new(
                        vec![(at.0 - hw, hy + hh), (at.0, hy), (at.0 + hw, hy + hh)],
                        c.stroke_width(lw(1.4)),
                    ))
                    .map_err(err)?;
                }
                Shape::Dot { at, label, offset } => {
                    let p = px(*at);
                    root.draw(&Circle::new(p, lw(3.5), BLACK.filled()))
                        .map_err(err)?;
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
                        // A leader line from the dot to the label.
                        let gap = (4.0 * scale).round() as i32;
                        let end = (q.0 - gap * offset.0.signum() as i32, q.1);
                        root.draw(&PathElement::new(
                            vec![p, end],
                            RGBColor(90, 90, 90).stroke_width(lw(0.8)),
                        ))
                        .map_err(err)?;
                    }
                    root.draw(&Text::new(
                        label.clone(),
                        q,
                        font(12.5)
                            .color(&RGBColor(60, 60, 60))
                            .pos(Pos::new(hpos, VPos::Center)),
                    ))
                    .map_err(err)?;
                }
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
        let foot = format!(
            "a = {:.1} mm, α = {:.2} rad, b = {:.2}a, r = b + a cos α = {:.2}a; \
             Ω0 = {:.2} rad/s, ω10 = {:.2} rad/s (eqs 28-29)",
            self.a * 1e3,
            self.alpha,
            self.b / self.a,
            self.r / self.a,
            self.precession,
            self.spin
        );
        root.draw(&Text::new(
            foot,
            ((0.5 * w) as i32, (h - 16.0 * scale) as i32),
            font(12.0)
                .color(&RGBColor(70, 70, 70))
                .pos(Pos::new(HPos::Center, VPos::Center)),
        ))
        .map_err(err)?;
        root.present().map_err(err)
    }
}

/// Splits a screen polyline into dashes of length `on` separated by gaps `off` (px).
fn dash(poly: &[(i32, i32)], on: f64, off: f64) -> Vec<Vec<(i32, i32)>> {
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

#[cfg(test)]
mod tests {
    use super::*;

    fn norm(v: V3) -> f64 {
        dot(v, v).sqrt()
    }

    #[test]
    fn the_triad_is_the_papers() {
        for &(alpha, psi) in &[(0.3, 0.0), (1.0, 1.2), (1.4, -2.0)] {
            let t = Triad::new(alpha, psi);
            for v in [t.e1, t.e2, t.e3, t.r, t.z] {
                assert!((norm(v) - 1.0).abs() < 1e-14);
            }
            // 2 = 3 x 1 (right-handed), horizontal; r = 2 x z.
            let e2 = cross(t.e3, t.e1);
            assert!(norm(add(e2, mul(-1.0, t.e2))) < 1e-14);
            assert!(t.e2[2].abs() < 1e-15 && t.r[2].abs() < 1e-15);
            assert!(norm(add(cross(t.e2, t.z), mul(-1.0, t.r))) < 1e-14);
            // 1 makes angle alpha with -z; 3 is alpha below the horizontal.
            assert!((dot(t.e1, mul(-1.0, t.z)).acos() - alpha).abs() < 1e-12);
            assert!(((-t.e3[2]).asin() - alpha).abs() < 1e-12);
            // Eq 3: z = -cos(alpha) 1 - sin(alpha) 3.
            let z = add(mul(-alpha.cos(), t.e1), mul(-alpha.sin(), t.e3));
            assert!(norm(add(z, mul(-1.0, t.z))) < 1e-14);
        }
    }

    #[test]
    fn drawn_arrows_point_along_the_triad_and_lengths_follow_eqs_28_29() {
        let disk = Disk::uniform(0.0375);
        let view = View {
            azimuth: -0.9,
            elevation: 0.4,
        };
        let g = Geometry::steady(&disk, 1.0, 0.6 * disk.a, 1.9, view).unwrap();
        assert!((g.b - 0.6 * disk.a).abs() < 1e-15);
        assert!((g.r - (0.6 + 1f64.cos()) * disk.a).abs() < 1e-15);
        // The centre is at height a sin(alpha), horizontal distance b from the axis.
        assert!((g.centre[2] - disk.a * 1f64.sin()).abs() < 1e-15);
        assert!((g.centre[0].hypot(g.centre[1]) - g.b).abs() < 1e-15);
        assert!(g.contact[2].abs() < 1e-15);
        let t = g.triad;
        let mut seen = 0;
        for s in g.shapes() {
            if let Shape::Arrow {
                from, to, label, ..
            } = s
            {
                let d = add(to, mul(-1.0, from));
                let d = mul(1.0 / norm(d), d);
                let want = match label.as_str() {
                    "1" => t.e1,
                    "2" => t.e2,
                    "3" => t.e3,
                    "r" => t.r,
                    "z" => t.z,
                    other => panic!("unexpected arrow {other}"),
                };
                assert!(norm(add(d, mul(-1.0, want))) < 1e-12, "{label}");
                if label.starts_with('2') {
                    assert!(d[2].abs() < 1e-15, "2-hat is horizontal");
                }
                if label.starts_with('1') {
                    assert!((dot(d, [0.0, 0.0, -1.0]).acos() - 1.0).abs() < 1e-12);
                }
                seen += 1;
            }
        }
        assert_eq!(seen, 5);
        // And the projection keeps them: a projected arrow is the projection of its vector.
        let (x, y) = view.project(t.e2);
        let (x0, y0) = view.project([0.0; 3]);
        assert!(((x - x0).hypot(y - y0) - 1.0).abs() < 1.0);
    }

    #[test]
    fn dashes_cover_the_line() {
        let d = dash(&[(0, 0), (100, 0)], 10.0, 5.0);
        assert_eq!(d.len(), 7);
        assert_eq!(d[0], vec![(0, 0), (10, 0)]);
    }
}
