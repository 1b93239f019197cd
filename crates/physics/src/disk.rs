//! The disk: a thin, circularly symmetric rigid body.
//!
//! The paper (eq 18) writes its principal moments about the centre of mass as
//! $I_{11} = 2kma^2,\ I_{22} = I_{33} = kma^2$, so a disk is fully described by its radius
//! $a$, the inertia factor $k$ ($k = 1/4$ uniform disk, $k = 1/2$ hoop), its mass $m$ and
//! the gravitational acceleration $g$ it rolls under. All quantities are SI.

use serde::{Deserialize, Serialize};
use thiserror::Error;

/// A thin disk of radius `a` (m), inertia factor `k`, mass `m` (kg) under gravity `g` (m/s^2).
///
/// Build it with [`Disk::new`], which refuses values that have no physical meaning.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Disk {
    /// Radius $a$ in metres.
    pub a: f64,
    /// Inertia factor $k$: $I_{22} = k m a^2$ (eq 18).
    pub k: f64,
    /// Mass $m$ in kilograms.
    pub m: f64,
    /// Gravitational acceleration $g$ in m/s^2.
    pub g: f64,
}

/// Why a disk could not be built: each names the parameter and what a valid value is.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum DiskError {
    /// The radius is zero, negative or not a finite number.
    #[error("the radius must be a positive number of metres, got {0}")]
    Radius(f64),
    /// The inertia factor is zero, negative or not finite.
    #[error(
        "the inertia factor k must be positive (1/4 for a uniform disk, 1/2 for a hoop), got {0}"
    )]
    InertiaFactor(f64),
    /// The mass is zero, negative or not finite.
    #[error("the mass must be a positive number of kilograms, got {0}")]
    Mass(f64),
    /// Gravity is zero, negative or not finite.
    #[error("gravity g must be a positive number of m/s^2 (9.81 on Earth), got {0}")]
    Gravity(f64),
}

fn positive(x: f64) -> bool {
    x.is_finite() && x > 0.0
}

impl Disk {
    /// A validated disk. Every parameter must be finite and strictly positive.
    pub fn new(a: f64, k: f64, m: f64, g: f64) -> Result<Self, DiskError> {
        if !positive(a) {
            return Err(DiskError::Radius(a));
        }
        if !positive(k) {
            return Err(DiskError::InertiaFactor(k));
        }
        if !positive(m) {
            return Err(DiskError::Mass(m));
        }
        if !positive(g) {
            return Err(DiskError::Gravity(g));
        }
        Ok(Self { a, k, m, g })
    }

    /// The paper's uniform disk (k = 1/4) with the size of the Euler's Disk toy's a = 37.5 mm.
    pub fn uniform(a: f64) -> Self {
        Self {
            a,
            k: 0.25,
            m: 0.4,
            g: 9.81,
        }
    }

    /// $g/a$, the natural squared rate of the problem (s^-2).
    pub fn g_over_a(&self) -> f64 {
        self.g / self.a
    }

    /// $I_{11} = 2 k m a^2$ (eq 18): moment about the symmetry axis.
    pub fn i11(&self) -> f64 {
        2.0 * self.k * self.m * self.a * self.a
    }

    /// $I_{22} = I_{33} = k m a^2$ (eq 18): moment about a diameter.
    pub fn i22(&self) -> f64 {
        self.k * self.m * self.a * self.a
    }
}

/// A disk of the Euler's Disk toy's size (radius 37.5 mm, mass 0.4 kg, $g$ = 9.81 m/s^2) with
/// inertia factor `k` (`k` > 0).
pub fn toy_sized(k: f64) -> Disk {
    Disk::new(0.0375, k, 0.4, 9.81).expect("a valid disk: the inertia factor must be positive")
}

/// The toy disk of the studies: a uniform disk ($k = 1/4$) of the toy's size.
pub fn toy_disk() -> Disk {
    toy_sized(0.25)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refuses_unphysical_parameters() {
        assert_eq!(
            Disk::new(-1.0, 0.25, 1.0, 9.81),
            Err(DiskError::Radius(-1.0))
        );
        assert_eq!(Disk::new(0.0, 0.25, 1.0, 9.81), Err(DiskError::Radius(0.0)));
        assert_eq!(
            Disk::new(1.0, 0.0, 1.0, 9.81),
            Err(DiskError::InertiaFactor(0.0))
        );
        assert!(matches!(
            Disk::new(1.0, f64::NAN, 1.0, 9.81),
            Err(DiskError::InertiaFactor(_))
        ));
        assert_eq!(Disk::new(1.0, 0.25, -2.0, 9.81), Err(DiskError::Mass(-2.0)));
        assert_eq!(Disk::new(1.0, 0.25, 1.0, 0.0), Err(DiskError::Gravity(0.0)));
        assert!(Disk::new(0.0375, 0.25, 0.4, 9.81).is_ok());
    }

    #[test]
    fn moments_follow_the_perpendicular_axis_theorem() {
        let d = Disk::new(0.1, 0.25, 2.0, 9.81).unwrap();
        assert!((d.i11() - 2.0 * d.i22()).abs() < 1e-18);
        assert!((d.i22() - 0.25 * 2.0 * 0.01).abs() < 1e-15);
    }
}
