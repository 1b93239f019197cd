//! The real toy in the sliding model: a uniform solid disk of finite thickness with a rounded
//! rim, two friction coefficients (static and kinetic), and rolling and boring resistance.
//! Each is modelled only when a scene asks for it; without them the model is the thin disk of
//! [`super`] with one coefficient, and every expression below reduces to the thin one.
//!
//! **The solid.** A cylinder of radius $a$ and thickness $t = 2c$ whose two rim edges are
//! rounded with a fillet of radius $f \le \min(c, a)$: in a meridian section the corner squares
//! of side $f$ are replaced by quarter circles. At the height $z$ above the mid-plane the
//! section is a disk of radius $R(z) = a$ for $|z| \le c - f$ and
//! $R(z) = a - f + \sqrt{f^2 - (|z| - c + f)^2}$ on the fillet. A uniform solid of mass $m$ has
//! $$ I_{11} = \frac m V\int_{-c}^{c}\frac{\pi R^4}{2}\,dz,\qquad
//!    I_{22} = \frac m V\int_{-c}^{c}\pi\left(\frac{R^4}{4} + R^2z^2\right)dz,\qquad
//!    V = \int_{-c}^{c}\pi R^2\,dz $$
//! (a stack of thin disks, each with eq 18's moments about its own centre and the parallel-axis
//! term). The fillet part is integrated in the angle $\varphi$ with $|z| - c + f = f\sin\varphi$,
//! where the integrand is smooth (composite Simpson, 2048 intervals). With $f = 0$:
//! $I_{11} = \frac12 ma^2$, $I_{22} = \frac14 ma^2 + \frac1{12}mt^2$.
//!
//! **The contact point** is the support point of the solid in the direction $-\hat{\mathbf z}$.
//! The rounded edge is the torus swept by a ball of radius $f$ whose centre runs round the
//! circle of radius $a - f$ at the axial offset $c - f$ on the lower face's side; its lowest
//! point is that circle's lowest point moved down by $f$. With $-\hat{\mathbf z} =
//! \sin\alpha\,\hat{\mathbf 3} + \cos\alpha\,\hat{\mathbf 1}$ and $\sigma = \mathrm{sign}\cos\alpha$
//! (the lower face is on the $+\hat{\mathbf 1}$ side while $\alpha < \pi/2$):
//! $$ \boldsymbol\rho = p\,\hat{\mathbf 1} + q\,\hat{\mathbf 3},\qquad
//!    p = \sigma(c - f) + f\cos\alpha,\qquad q = a - f + f\sin\alpha. $$
//! Its geometric rate: $\dot{\boldsymbol\rho} = \dot p\,\hat{\mathbf 1} + p\,\dot{\hat{\mathbf 1}} +
//! \dot q\,\hat{\mathbf 3} + q\,\dot{\hat{\mathbf 3}}$ with $\dot{\hat{\mathbf 1}} =
//! \boldsymbol\omega\times\hat{\mathbf 1}$, $\frac{d}{dt}\cos\alpha = -\dot{\hat{\mathbf 1}}\cdot\hat{\mathbf z}$,
//! $\frac{d}{dt}\sin\alpha = -\cot\alpha\,\frac{d}{dt}\cos\alpha$. At $\alpha = \pi/2$ the solid
//! stands on a line and $\sigma$ jumps: the model is a point contact, so a run of a thick disk
//! stops where $\cos\alpha$ changes sign (`scene.rs`).
//!
//! **The contact condition** with a general $\boldsymbol\rho$ is no longer diagonal in the triad:
//! $$ A\mathbf x = \frac{\mathbf x}{m} - \boldsymbol\rho\times\left(J^{-1}(\boldsymbol\rho\times\mathbf x)\right) +
//! \left((J^{-1}\boldsymbol\mu)\times\boldsymbol\rho\right)x_z, $$
//! $J^{-1} = \frac1{I_{22}}\mathbb 1 + \left(\frac1{I_{11}} - \frac1{I_{22}}\right)\hat{\mathbf 1}\hat{\mathbf 1}^T$
//! (lab), the last term the resistance below, which is proportional to $F_z$.
//!
//! **Resistance.** A contact patch that deforms resists rolling and boring with moments
//! proportional to the normal force, each with its own lever arm (m):
//! $\mathbf M = F_z\boldsymbol\mu$,
//! $\boldsymbol\mu = -\ell_r\,\mathrm{sign}(\boldsymbol\omega\cdot\hat{\mathbf r})\,\hat{\mathbf r} -
//! \ell_b\,\mathrm{sign}(\omega_z)\,\hat{\mathbf z}$:
//! rolling resistance against the rotation about $\hat{\mathbf r}$ (the horizontal axis across the
//! rolling direction $\hat{\mathbf 2}$), boring resistance against the rotation about the
//! vertical. Their power $-F_z(\ell_r|\boldsymbol\omega\cdot\hat{\mathbf r}| + \ell_b|\omega_z|)$ is
//! booked in the dissipated energy $W$ in every contact mode.
//!
//! **Two coefficients.** Sticking holds while $|\mathbf F_t| \le \mu_s F_z$ (the scene's
//! `static`, stored as [`super::Friction::mu`]); a slip is opposed by $\mu_k F_z$ (`kinetic`).

use super::Sliding;
use crate::model::lab_frame::Snapshot;
use crate::solve::State;
use nalgebra::{Matrix3, Vector3};
use serde::Serialize;

/// Composite Simpson intervals for the fillet's integrals.
const SIMPSON: usize = 2048;

/// A uniform solid disk of finite thickness with a rounded rim (module documentation).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Solid {
    /// Thickness $t$ (m).
    pub thickness: f64,
    /// Fillet radius $f$ of the rim's edges (m).
    pub fillet: f64,
    /// $I_{11}$ about the symmetry axis (kg m²).
    pub i11: f64,
    /// $I_{22} = I_{33}$ about a diameter through the centre (kg m²).
    pub i22: f64,
    /// The volume $V$ (m³).
    pub volume: f64,
}

impl Solid {
    /// The solid of radius `a`, mass `m`, thickness `t` and fillet `f` (validated by the scene:
    /// $t > 0$, $0 \le f \le \min(t/2, a)$), its moments computed (module documentation).
    pub fn new(a: f64, m: f64, t: f64, f: f64) -> Self {
        let c = 0.5 * t;
        let core = c - f;
        // Straight part, |z| <= c - f (both halves).
        let mut vol = 2.0 * a * a * core;
        let mut r4 = 2.0 * a.powi(4) * core;
        let mut r2z2 = 2.0 * a * a * core.powi(3) / 3.0;
        // Fillet part: |z| = core + f sin(phi), R = a - f + f cos(phi), dz = f cos(phi) dphi.
        if f > 0.0 {
            let h = std::f64::consts::FRAC_PI_2 / SIMPSON as f64;
            let (mut sv, mut s4, mut s2) = (0.0, 0.0, 0.0);
            for i in 0..=SIMPSON {
                let phi = i as f64 * h;
                let w = if i == 0 || i == SIMPSON {
                    1.0
                } else if i % 2 == 1 {
                    4.0
                } else {
                    2.0
                };
                let (sn, cs) = phi.sin_cos();
                let r = a - f + f * cs;
                let z = core + f * sn;
                let dz = f * cs;
                sv += w * r * r * dz;
                s4 += w * r.powi(4) * dz;
                s2 += w * r * r * z * z * dz;
            }
            vol += 2.0 * sv * h / 3.0;
            r4 += 2.0 * s4 * h / 3.0;
            r2z2 += 2.0 * s2 * h / 3.0;
        }
        Self {
            thickness: t,
            fillet: f,
            i11: m * 0.5 * r4 / vol,
            i22: m * (0.25 * r4 + r2z2) / vol,
            volume: std::f64::consts::PI * vol,
        }
    }

    /// $(p, q)$ of $\boldsymbol\rho = p\hat{\mathbf 1} + q\hat{\mathbf 3}$ for radius `a` at the tilt
    /// $(\cos\alpha, \sin\alpha)$ (module documentation).
    pub fn offsets(&self, a: f64, cos_alpha: f64, sin_alpha: f64) -> (f64, f64) {
        let (c, f) = (0.5 * self.thickness, self.fillet);
        let side = if cos_alpha >= 0.0 { 1.0 } else { -1.0 };
        (side * (c - f) + f * cos_alpha, a - f + f * sin_alpha)
    }
}

/// Rolling and boring resistance: lever arms of the contact moments (m).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct Resistance {
    /// $\ell_r$: against the rotation about $\hat{\mathbf r}$.
    pub rolling: f64,
    /// $\ell_b$: against the rotation about the vertical.
    pub boring: f64,
}

/// What a scene adds to the thin disk with one coefficient (each `None` when not asked for).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct Toy {
    /// The solid of finite thickness.
    pub solid: Option<Solid>,
    /// $\mu_k$ when it differs from the static coefficient.
    pub kinetic: Option<f64>,
    /// Rolling and boring resistance.
    pub resistance: Option<Resistance>,
}

impl Toy {
    /// True for the thin disk with one coefficient and no resistance.
    pub fn is_thin(&self) -> bool {
        *self == Toy::default()
    }
}

impl Sliding {
    /// The geometry of `y`: [`Snapshot::of`] with the solid's contact point when the disk is
    /// thick (module documentation).
    pub fn snapshot<const N: usize>(&self, y: &State<N>) -> Snapshot {
        let mut s = Snapshot::of(self.disk.a, y);
        let Some(solid) = self.toy.solid else {
            return s;
        };
        let a = self.disk.a;
        let (p, q) = solid.offsets(a, s.cos_alpha, s.sin_alpha);
        let e1_dot = s.omega.cross(&s.e1);
        let cos_dot = -e1_dot.z;
        let sin_dot = -s.cos_alpha / s.sin_alpha * cos_dot;
        let e3_dot = s.rho_dot / a;
        let f = solid.fillet;
        s.rho = p * s.e1 + q * s.e3;
        s.rho_dot = f * cos_dot * s.e1 + p * e1_dot + f * sin_dot * s.e3 + q * e3_dot;
        s.contact_velocity = s.velocity + s.omega.cross(&s.rho);
        s.height = s.centre.z + s.rho.z;
        s
    }

    /// $(I_{11}, I_{22}, I_{33})$ in body axes: the solid's, or eq 18's.
    pub fn inertia(&self) -> Vector3<f64> {
        match self.toy.solid {
            Some(s) => Vector3::new(s.i11, s.i22, s.i22),
            None => crate::model::lab_frame::inertia(&self.disk),
        }
    }

    /// $\mu_k$, the coefficient a slip is opposed by.
    pub fn mu_kinetic(&self) -> f64 {
        self.toy.kinetic.unwrap_or(self.friction.mu)
    }

    /// $\boldsymbol\mu$ (lab, m): the resistance moment per unit normal force (module
    /// documentation); zero without resistance.
    pub fn resistance_arm(&self, s: &Snapshot) -> Vector3<f64> {
        let Some(r) = self.toy.resistance else {
            return Vector3::zeros();
        };
        -r.rolling * sign(s.omega.dot(&s.r)) * s.r - r.boring * sign(s.omega.z) * Vector3::z()
    }

    /// $J^{-1}\mathbf x$ for a lab vector (module documentation).
    pub(crate) fn inverse_inertia(&self, s: &Snapshot, x: &Vector3<f64>) -> Vector3<f64> {
        let i = self.inertia();
        x / i.y + s.e1 * (x.dot(&s.e1) * (1.0 / i.x - 1.0 / i.y))
    }

    /// The matrix $A$ of the contact condition in the lab (module documentation), for a thick
    /// disk or one with resistance; `None` for the thin disk, whose $A$ is diagonal in the triad.
    /// `arm` is the resistance arm the moment has ([`Sliding::held_arm`]).
    pub(crate) fn full_contact_matrix(
        &self,
        s: &Snapshot,
        arm: &Vector3<f64>,
    ) -> Option<Matrix3<f64>> {
        if self.toy.solid.is_none() && self.toy.resistance.is_none() {
            return None;
        }
        let mut a = Matrix3::zeros();
        for j in 0..3 {
            let x = Vector3::ith(j, 1.0);
            let col = x / self.disk.m - s.rho.cross(&self.inverse_inertia(s, &s.rho.cross(&x)));
            a.set_column(j, &col);
        }
        let lever = self.inverse_inertia(s, arm).cross(&s.rho);
        for i in 0..3 {
            a[(i, 2)] += lever[i];
        }
        Some(a)
    }
}

/// The sign of `x`: 1, -1, or 0 at zero (where `f64::signum` says 1).
pub(super) fn sign(x: f64) -> f64 {
    if x > 0.0 {
        1.0
    } else if x < 0.0 {
        -1.0
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn moments_of_a_plain_cylinder_and_the_thin_limit() {
        let (a, m, t) = (0.0375, 0.4, 0.0128);
        let s = Solid::new(a, m, t, 0.0);
        assert!((s.i11 - 0.5 * m * a * a).abs() < 1e-15);
        assert!((s.i22 - (0.25 * m * a * a + m * t * t / 12.0)).abs() < 1e-15);
        let thin = Solid::new(a, m, 1e-9, 0.0);
        assert!((thin.i22 / (m * a * a) - 0.25).abs() < 1e-12);
    }

    #[test]
    fn a_fillet_of_half_the_thickness_is_a_torus_rim() {
        // f = c: the rim is a half torus; its volume by Pappus:
        // V = pi (a - c)^2 t + (pi c^2 / 2)(2 pi)(a - c + 4c/(3 pi)).
        let (a, t) = (0.04, 0.01);
        let c = t / 2.0;
        let s = Solid::new(a, 1.0, t, c);
        let pi = std::f64::consts::PI;
        let v = pi * (a - c).powi(2) * t + pi * c * c * pi * (a - c + 4.0 * c / (3.0 * pi));
        assert!((s.volume - v).abs() < 1e-12 * v, "{} {v}", s.volume);
        // I11 / m for the same solid by slices in r (shells of height 2 sqrt(c^2 - (r-a+c)^2)).
        let n = 200_000;
        let (mut vol, mut i11) = (0.0, 0.0);
        for k in 0..n {
            let r = (k as f64 + 0.5) / n as f64 * a;
            let h = if r <= a - c {
                t
            } else {
                2.0 * (c * c - (r - a + c).powi(2)).max(0.0).sqrt()
            };
            let dv = 2.0 * pi * r * h * a / n as f64;
            vol += dv;
            i11 += dv * r * r;
        }
        assert!((vol - v).abs() < 1e-6 * v, "{vol} {v}");
        assert!(
            (s.i11 - i11 / vol).abs() < 1e-6 * s.i11,
            "{} {}",
            s.i11,
            i11 / vol
        );
    }

    #[test]
    fn the_contact_offsets_are_the_lowest_point() {
        let s = Solid::new(0.04, 1.0, 0.012, 0.003);
        for alpha in [0.2_f64, 0.9, 1.5, 1.7, 2.8] {
            let (p, q) = s.offsets(0.04, alpha.cos(), alpha.sin());
            // Height of the centre above the contact = -rho . z = p cos(alpha) + q sin(alpha);
            // it must be the largest over the rim's points (a brute-force scan of the section).
            let depth = p * alpha.cos() + q * alpha.sin();
            let mut best = f64::MIN;
            for i in 0..=20_000 {
                let phi = i as f64 / 20_000.0 * std::f64::consts::PI;
                for side in [1.0, -1.0] {
                    let (x, r) = (
                        side * (0.006 - 0.003 + 0.003 * phi.cos()),
                        0.04 - 0.003 + 0.003 * phi.sin(),
                    );
                    best = best.max(x * alpha.cos() + r * alpha.sin());
                }
            }
            assert!((depth - best).abs() < 1e-9, "alpha {alpha}: {depth} {best}");
        }
    }
}
