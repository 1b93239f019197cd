//! Steady rolling of a disk of finite thickness with a rounded rim: eq 29's precession and
//! eq 30's condition on $b$ for the solid of [`crate::model::sliding::Solid`].
//!
//! **Kinematics.** The triad turns at $\Omega\hat{\mathbf z}$, the tilt is constant, and the
//! contact point, seen from the centre, is $\boldsymbol\rho = p\hat{\mathbf 1} + q\hat{\mathbf 3}$
//! (the solid's offsets; $p = 0$, $q = a$ for the thin disk). With $\hat{\mathbf r}$ the
//! horizontal unit vector from the centre toward the contact in the meridian plane, the centre
//! is at the height $h = q\sin\alpha + p\cos\alpha$ above the contact and at the horizontal
//! distance $x = q\cos\alpha - p\sin\alpha$ behind it. The angular velocity is
//! $\boldsymbol\omega = \omega_1\hat{\mathbf 1} - \Omega\sin\alpha\,\hat{\mathbf 3}$ (eq 12 at
//! $\dot\alpha = 0$). The centre goes round a vertical axis at the signed distance $b$ along
//! $\hat{\mathbf r}$ (eq 27), so rolling, $\mathbf v = \boldsymbol\omega\times(-\boldsymbol\rho)$,
//! gives
//! $$ \omega_1 = \Omega\,\frac{b - p\sin\alpha}{q}\qquad(\text{eq 28 at } p = 0). $$
//!
//! **Dynamics.** The components of $\mathbf L = I_{11}\omega_1\hat{\mathbf 1} -
//! I_{22}\Omega\sin\alpha\,\hat{\mathbf 3}$ on the turning triad are constant, so
//! $\dot{\mathbf L} = \Omega\hat{\mathbf z}\times\mathbf L$; the contact force is
//! $\mathbf F = mg\hat{\mathbf z} - m\Omega^2 b\,\hat{\mathbf r}$ and its moment about the centre
//! is $\boldsymbol\rho\times\mathbf F$. Both lie along $\hat{\mathbf 2}$, and equating them gives
//! $$ \Omega_0^2 = \frac{m g\,x}{D_0 + b\,D_1},\qquad
//!    D_0 = I_{22}\sin\alpha_0\cos\alpha_0 - I_{11}\frac{p\sin^2\alpha_0}{q},\qquad
//!    D_1 = m h + I_{11}\frac{\sin\alpha_0}{q}. $$
//! For the thin disk ($p = 0$, $q = a$, $I_{11} = 2kma^2$, $I_{22} = kma^2$) this is eq 29,
//! $\Omega_0^2 = g\cot\alpha_0/(ka\cos\alpha_0 + (2k+1)b)$.
//!
//! **The condition on $b$.** $D_1 > 0$, so a steady motion exists exactly when $D_0 + bD_1$ has
//! the sign of $x$, on one side of the edge $b_* = -D_0/D_1$:
//! - while the contact is ahead of the centre ($x > 0$), $b > b_*$ (eq 30 for the thin disk,
//!   $b_* = -ak\cos\alpha_0/(2k+1)$);
//! - once the centre is beyond the contact ($x < 0$, a thick disk near upright), $b < b_*$;
//! - where $x = 0$ the solid balances at rest on its rim.
//!
//! A thick disk's $D_0$ changes sign where $I_{22}\cos\alpha_0\,q = I_{11}\,p\sin\alpha_0$, so at
//! steeper tilts $b_* > 0$ while $x > 0$: there the disk cannot spin with its centre at rest.

use crate::disk::Disk;
use crate::model::sliding::Solid;
use crate::model::Motion;
use numerics::oscillation::bisect;
use serde::Serialize;
use std::f64::consts::FRAC_PI_2;
use thiserror::Error;

/// A solid disk rolling: what its steady motions depend on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollingSolid {
    /// Radius $a$ (m).
    pub a: f64,
    /// Mass $m$ (kg).
    pub m: f64,
    /// $g$ (m/s²).
    pub g: f64,
    /// $I_{11}$ (kg m²).
    pub i11: f64,
    /// $I_{22}$ (kg m²).
    pub i22: f64,
    /// The shape of the rim: `None` for the thin disk ($p = 0$, $q = a$).
    pub solid: Option<Solid>,
}

/// Which side of the edge $b_*$ the steady motions are on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Side {
    /// $b > b_*$: the contact is ahead of the centre ($x > 0$).
    Above,
    /// $b < b_*$: the centre is beyond the contact ($x < 0$).
    Below,
    /// $x = 0$: no steady rolling, the solid balances at rest.
    Balanced,
}

/// Eq 30 for the solid at one tilt: the edge and the side.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Edge {
    /// $b_* = -D_0/D_1$ (m).
    pub b: f64,
    /// Which side of it the steady motions are on.
    pub side: Side,
}

/// Why the solid has no steady motion there.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SolidSteadyError {
    /// The tilt is outside $(0, \pi/2)$.
    #[error(
        "steady rolling at alpha0 = {0} rad: the tilt must be between 0 and pi/2 (1.5707963...)"
    )]
    Angle(f64),
    /// $b$ is on the wrong side of the edge.
    #[error(
        "steady rolling with b = {b} m does not exist at alpha0 = {alpha0} for this disk: eq 30 \
         for its thickness needs b {} {:.6} m: {}",
        if *above { ">" } else { "<" }, bound, if *above { "raise b" } else { "lower b" }
    )]
    Radius {
        /// The b asked for.
        b: f64,
        /// At this tilt.
        alpha0: f64,
        /// The edge $b_*$.
        bound: f64,
        /// True when $b$ must be above the edge.
        above: bool,
    },
    /// The centre is above the contact: the solid balances at rest there.
    #[error("at alpha0 = {0} rad this disk's centre is above its contact: it balances at rest and cannot roll steadily")]
    Balanced(f64),
}

impl RollingSolid {
    /// The thin `disk` (eq 18's moments) or, with `solid`, the solid of its radius and mass.
    pub fn of(disk: &Disk, solid: Option<Solid>) -> Self {
        let (i11, i22) = match &solid {
            Some(s) => (s.i11, s.i22),
            None => (disk.i11(), disk.i22()),
        };
        RollingSolid {
            a: disk.a,
            m: disk.m,
            g: disk.g,
            i11,
            i22,
            solid,
        }
    }

    /// $(p, q)$ at the tilt.
    fn offsets(&self, alpha0: f64) -> (f64, f64) {
        match &self.solid {
            Some(s) => s.offsets(self.a, alpha0.cos(), alpha0.sin()),
            None => (0.0, self.a),
        }
    }

    /// $(x, D_0, D_1)$ at the tilt (module documentation).
    fn terms(&self, alpha0: f64) -> (f64, f64, f64) {
        let (p, q) = self.offsets(alpha0);
        let (s, c) = alpha0.sin_cos();
        let h = q * s + p * c;
        let x = q * c - p * s;
        let d0 = self.i22 * s * c - self.i11 * p * s * s / q;
        let d1 = self.m * h + self.i11 * s / q;
        (x, d0, d1)
    }

    /// $\omega_1/\Omega = (b - p\sin\alpha_0)/q$ (module documentation; eq 28's $b/a$ thin).
    pub fn spin_ratio(&self, alpha0: f64, b: f64) -> f64 {
        let (p, q) = self.offsets(alpha0);
        (b - p * alpha0.sin()) / q
    }

    /// Eq 30 for the solid at `alpha0`: the edge $b_*$ and the side of it steady motions are on.
    pub fn edge(&self, alpha0: f64) -> Edge {
        let (x, d0, d1) = self.terms(alpha0);
        let side = if x > 0.0 {
            Side::Above
        } else if x < 0.0 {
            Side::Below
        } else {
            Side::Balanced
        };
        Edge { b: -d0 / d1, side }
    }

    /// The tilt where the centre is above the contact ($x = 0$), the solid balancing on its
    /// rim; `None` when that is only upright ($\pi/2$): the thin disk, and a solid whose rim is
    /// rounded whole (fillet half the thickness), whose $x$ is positive below $\pi/2$. Between
    /// it and $\pi/2$ gravity tips the solid back toward upright.
    pub fn balance_tilt(&self) -> Option<f64> {
        self.solid?;
        if self.terms(FRAC_PI_2).0 > 0.0 {
            return None;
        }
        let (lo, hi) = bisect(0.0, FRAC_PI_2, 0.0, |alpha| self.terms(alpha).0 <= 0.0);
        Some(0.5 * (lo + hi))
    }

    /// Eq 29 for the solid: $\Omega_0^2 = mgx/(D_0 + bD_1)$, of either sign when no steady
    /// motion exists.
    pub fn precession_squared(&self, alpha0: f64, b: f64) -> f64 {
        let (x, d0, d1) = self.terms(alpha0);
        self.m * self.g * x / (d0 + b * d1)
    }

    /// The steady motion at `alpha0` with the centre on a circle of signed radius `b`: eq 29's
    /// $\Omega_0$ for the solid and its spin, with $\Omega_0$ taking the sign of $b$ as eq 28 does
    /// (positive at $b = 0$).
    pub fn steady(&self, alpha0: f64, b: f64) -> Result<Motion, SolidSteadyError> {
        if !(alpha0.is_finite() && alpha0 > 0.0 && alpha0 < FRAC_PI_2) {
            return Err(SolidSteadyError::Angle(alpha0));
        }
        let edge = self.edge(alpha0);
        let above = match edge.side {
            Side::Above => true,
            Side::Below => false,
            Side::Balanced => return Err(SolidSteadyError::Balanced(alpha0)),
        };
        let squared = self.precession_squared(alpha0, b);
        if !(b.is_finite() && squared.is_finite() && squared > 0.0) {
            return Err(SolidSteadyError::Radius {
                b,
                alpha0,
                bound: edge.b,
                above,
            });
        }
        let magnitude = squared.sqrt();
        let precession = if b < 0.0 { -magnitude } else { magnitude };
        Ok(Motion {
            alpha: alpha0,
            alpha_dot: 0.0,
            precession,
            spin: self.spin_ratio(alpha0, b) * precession,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::steady::{b_bound, precession_squared};

    fn thin(k: f64) -> RollingSolid {
        RollingSolid::of(&Disk::new(0.0375, k, 0.4, 9.81).unwrap(), None)
    }

    /// The thin disk's edge and precession are eqs 29-30, at several k, tilts and radii.
    #[test]
    fn the_thin_limit_is_eqs_29_and_30() {
        for k in [0.25, 0.5] {
            let disk = Disk::new(0.0375, k, 0.4, 9.81).unwrap();
            let s = RollingSolid::of(&disk, None);
            for alpha0 in [0.1, 0.7, 1.4] {
                let e = s.edge(alpha0);
                assert_eq!(e.side, Side::Above);
                assert!((e.b - b_bound(&disk, alpha0)).abs() < 1e-15, "{e:?}");
                for b in [-0.005, 0.0, 0.02] {
                    let (ours, eq29) = (
                        s.precession_squared(alpha0, b),
                        precession_squared(&disk, alpha0, b),
                    );
                    assert!((ours / eq29 - 1.0).abs() < 1e-12, "{ours} {eq29}");
                }
            }
        }
    }

    /// A thick disk's edge rises above 0 at steep tilts and its side flips past the balance.
    #[test]
    fn the_toy_cannot_spin_in_place_between_its_two_turning_tilts() {
        let (a, m) = (0.0375, 0.4);
        let solid = Solid::new(a, m, 0.0128, 0.002);
        let s = RollingSolid {
            a,
            m,
            g: 9.81,
            i11: solid.i11,
            i22: solid.i22,
            solid: Some(solid),
        };
        assert!(s.steady(1.0, 0.0).is_ok());
        let e = s.edge(80f64.to_radians());
        assert_eq!(e.side, Side::Above);
        assert!(e.b > 0.0, "{e:?}");
        let err = s.steady(80f64.to_radians(), 0.0).unwrap_err().to_string();
        assert!(err.contains("raise b"), "{err}");
        assert_eq!(s.edge(85f64.to_radians()).side, Side::Below);
        // The balance: the centre above the contact, (a - f) cos = (c - f) sin near upright.
        let balance = s.balance_tilt().unwrap();
        let (p, q) = solid.offsets(a, balance.cos(), balance.sin());
        assert!((q * balance.cos() - p * balance.sin()).abs() < 1e-15);
        assert!((82.0..84.0).contains(&balance.to_degrees()), "{balance}");
        assert_eq!(thin(0.25).balance_tilt(), None);
        assert!(s.steady(85f64.to_radians(), 0.0).is_ok());
    }
}
