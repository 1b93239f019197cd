//! Figure 1, the geometry of the rolling disk, drawn from the model's own definitions.
//!
//! The triad is built from the tilt $\alpha$ and the heading $\psi$ as the paper defines it
//! (eqs 1-9): $\hat{\mathbf 2} = (\cos\psi, \sin\psi, 0)$ horizontal, $\hat{\mathbf r} =
//! \hat{\mathbf 2}\times\hat{\mathbf z}$, $\hat{\mathbf 3} = \cos\alpha\,\hat{\mathbf r} -
//! \sin\alpha\,\hat{\mathbf z}$ (centre to contact, $\alpha$ below the horizontal) and
//! $\hat{\mathbf 1} = -\sin\alpha\,\hat{\mathbf r} - \cos\alpha\,\hat{\mathbf z}$ (eq 8), so that
//! $\hat{\mathbf 2} = \hat{\mathbf 3}\times\hat{\mathbf 1}$. The lengths $b$ and $r$ come from a
//! steady motion of the model (the study [`crate::study::SteadyMotion`]): $b = a\omega_{10}/\Omega_0$ (eq 28) and
//! $r = b + a\cos\alpha_0$ (eq 29's $b = r - a\cos\alpha$). With the axis of the circular motion
//! at the origin, the contact point is $r\hat{\mathbf r}$ and the centre of mass
//! $r\hat{\mathbf r} - a\hat{\mathbf 3} = b\hat{\mathbf r} + a\sin\alpha\,\hat{\mathbf z}$ (eq 14).
//!
//! The picture is a 3-D scene of lines, arrows, dots and labels ([`Geometry::shapes`]),
//! projected orthographically from an oblique viewpoint and drawn with plotters primitives on
//! any backend.

use crate::figures::chart::register_font;
use crate::figures::FigureError;
use crate::study::steady_motion::SteadyDisk;
use nalgebra::Vector3;

use plotters::style::text_anchor::{HPos, Pos, VPos};
use serde::Serialize;

mod draw;
#[cfg(test)]
mod tests;

/// A 3-vector (lab coordinates, z up).
pub type V3 = Vector3<f64>;

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
        let z = V3::new(0.0, 0.0, 1.0);
        let e2 = V3::new(cp, sp, 0.0);
        let r = e2.cross(&z);
        let e3 = r * ca - z * sa;
        let e1 = -r * sa - z * ca;
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
        let right = V3::new(-st, ct, 0.0);
        let up = V3::new(-sf * ct, -sf * st, cf);
        (p.dot(&right), p.dot(&up))
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
    /// The geometry of the disk in the steady motion `steady` (eqs 28-29), heading `heading`,
    /// seen from `view`.
    pub fn steady(steady: &SteadyDisk, heading: f64, view: View) -> Self {
        let (m, a) = (&steady.motion, steady.a);
        let alpha0 = m.alpha;
        // Eq 28 read backwards: b = a omega_10 / Omega_0; then r = b + a cos(alpha0).
        let b = a * m.spin / m.precession;
        let r = b + a * alpha0.cos();
        let triad = Triad::new(alpha0, heading);
        let contact = triad.r * r;
        let centre = contact + (triad.e3 * -a);
        Self {
            title: format!(
                "The rolling disk in steady motion (α = {:.0}°, b = {:.2}a)",
                alpha0.to_degrees(),
                b / a
            ),
            a,
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
        }
    }

    /// The scene as 3-D shapes, in drawing order.
    pub fn shapes(&self) -> Vec<Shape> {
        let (a, t, c, p) = (self.a, self.triad, self.centre, self.contact);
        let h = a * self.alpha.sin();
        let origin = V3::new(0.0, 0.0, 0.0);
        let ring = |centre: V3, u: V3, v: V3, radius: f64, n: usize| -> Vec<V3> {
            (0..=n)
                .map(|i| {
                    let s = std::f64::consts::TAU * i as f64 / n as f64;
                    centre + (u * s.cos() + v * s.sin()) * radius
                })
                .collect()
        };
        let x = V3::new(1.0, 0.0, 0.0);
        let y = V3::new(0.0, 1.0, 0.0);
        let mut out = Vec::new();
        // The table: a square around the contact circle.
        let half = 1.25 * self.r.max(a) + 0.3 * a;
        let corners = vec![
            (-x - y) * half,
            (x - y) * half,
            (x + y) * half,
            (y - x) * half,
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
                points: ring(V3::new(0.0, 0.0, h), x, y, self.b.abs(), 144),
                line: Line::Dotted,
                color: GREEN,
            });
        }
        // The vertical axis of the circular motion.
        out.push(Shape::Path {
            points: vec![origin, V3::new(0.0, 0.0, h + 1.1 * a)],
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
            at: p * 0.5 - t.e2 * 0.22 * a,
            text: "r".into(),
            color: VERMILION,
        });
        out.push(Shape::Path {
            points: vec![V3::new(0.0, 0.0, h), c],
            line: Line::Thin,
            color: GREEN,
        });
        out.push(Shape::Label {
            at: V3::new(0.0, 0.0, h + 0.11 * a) + t.r * 0.5 * self.b,
            text: "b".into(),
            color: GREEN,
        });
        out.push(Shape::Path {
            points: vec![c, p],
            line: Line::Thin,
            color: INK,
        });
        out.push(Shape::Label {
            at: c + t.e3 * 0.85 * a + t.e2 * 0.16 * a,
            text: "a".into(),
            color: INK,
        });
        // The angle alpha between r (horizontal) and 3, at the centre.
        let arc: Vec<V3> = (0..=24)
            .map(|i| {
                let s = self.alpha * i as f64 / 24.0;
                c + (t.r * s.cos() - t.z * s.sin()) * 0.3 * a
            })
            .collect();
        out.push(Shape::Path {
            points: arc,
            line: Line::Thin,
            color: INK,
        });
        let mid = 0.5 * self.alpha;
        out.push(Shape::Label {
            at: c + (t.r * mid.cos() - t.z * mid.sin()) * 0.4 * a,
            text: "α".into(),
            color: INK,
        });
        // The unit vectors at the centre.
        let arrow =
            |v: V3, len: f64, label: &str, color: [u8; 3], nudge: (f64, f64)| Shape::Arrow {
                from: c,
                to: (c + (v * len * a)),
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
}
