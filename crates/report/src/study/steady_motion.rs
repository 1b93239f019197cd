//! The steady motion figure 1 draws: a uniform disk of the toy's radius (a = 37.5 mm) at
//! $\alpha_0 = 1$ rad with $b = 0.6a$, its $\Omega_0$ from eq 29 and $\omega_{10} = b\Omega_0/a$
//! from eq 28.

use super::{Observer, Study};
use crate::error::ReportError;
use checks::equations::Bench;
use physics::model::steady::steady_motion;
use physics::model::Motion;
use physics::Disk;

/// The steady motion of figure 1.
pub struct SteadyMotion;

/// A disk's radius and a steady motion of it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyDisk {
    /// The disk's radius $a$ (m).
    pub a: f64,
    /// The steady motion: $\alpha_0$, $\Omega_0$ and $\omega_{10}$.
    pub motion: Motion,
}

/// The disk's radius (m): the toy's.
const RADIUS: f64 = 0.0375;
/// The tilt $\alpha_0$ (rad).
const ALPHA0: f64 = 1.0;
/// The radius $b$ of the centre of mass's circle, in units of $a$.
const B_OVER_A: f64 = 0.6;

impl Study for SteadyMotion {
    type Output = SteadyDisk;
    const NAME: &'static str = "steady-motion";

    fn compute(&self, _: &Bench, _: &Observer) -> Result<SteadyDisk, ReportError> {
        let disk = Disk::uniform(RADIUS);
        let motion = steady_motion(&disk, ALPHA0, B_OVER_A * disk.a).map_err(|e| e.to_string())?;
        Ok(SteadyDisk { a: disk.a, motion })
    }
}
