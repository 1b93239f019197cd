//! Starting states: steady motion from $(\alpha_0, b)$ by eqs 28-29, a disk spinning about a
//! vertical diameter, a wheel rolling straight.

use crate::disk::Disk;
use crate::model::Motion;
use std::f64::consts::FRAC_PI_2;
use thiserror::Error;

/// Why a steady motion does not exist.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SteadyError {
    /// The tilt is outside $(0, \pi/2)$.
    #[error(
        "steady motion at alpha0 = {0} rad does not exist: eq 29 needs 0 < alpha0 < pi/2 (1.5707963...); \
         for a disk upright use start: {{ vertical_spin: ... }} or {{ rolling_straight: ... }}"
    )]
    Angle(f64),
    /// $b$ is at or below eq 30's bound.
    #[error(
        "steady motion with b = {b} m does not exist at alpha0 = {alpha0}: eq 30 needs b > -a k cos(alpha0)/(2k+1) = {bound:.6} m: raise b"
    )]
    Radius {
        /// The b asked for.
        b: f64,
        /// At this tilt.
        alpha0: f64,
        /// Eq 30's bound.
        bound: f64,
    },
}

/// Eq 30's lower bound on $b$: $-a k\cos\alpha_0 / (2k + 1)$.
pub fn b_bound(disk: &Disk, alpha0: f64) -> f64 {
    -disk.a * disk.k * alpha0.cos() / (2.0 * disk.k + 1.0)
}

/// Eq 29: $\Omega_0^2 = \dfrac{g\cot\alpha_0}{k a\cos\alpha_0 + (2k+1) b}$.
pub fn precession_squared(disk: &Disk, alpha0: f64, b: f64) -> f64 {
    let k = disk.k;
    disk.g / alpha0.tan() / (k * disk.a * alpha0.cos() + (2.0 * k + 1.0) * b)
}

/// Eq 29 at $b = 0$ inverted for the tilt: $\Omega_0^2 = g/(k a\sin\alpha_0)$, so
/// $\sin\alpha_0 = g/(k a\Omega_0^2)$; $\pi/2$ (upright) where $\Omega_0^2 \le g/(ka)$, below
/// which no tilted $b = 0$ steady motion turns that slowly.
pub fn tilt_at_b0(disk: &Disk, precession: f64) -> f64 {
    (disk.g / (disk.k * disk.a * precession * precession))
        .min(1.0)
        .asin()
}

/// Steady motion at tilt $\alpha_0$ with the centre of mass on a circle of radius $b$: $\Omega_0$
/// from eq 29 and $\omega_{10} = b\Omega_0/a$ from eq 28. Following the paper's convention
/// $\omega_1 \ge 0$, a negative $b$ comes with a negative $\Omega_0$.
pub fn steady_motion(disk: &Disk, alpha0: f64, b: f64) -> Result<Motion, SteadyError> {
    if !(alpha0.is_finite() && alpha0 > 0.0 && alpha0 < FRAC_PI_2) {
        return Err(SteadyError::Angle(alpha0));
    }
    let bound = b_bound(disk, alpha0);
    if !(b.is_finite() && b > bound) {
        return Err(SteadyError::Radius { b, alpha0, bound });
    }
    let magnitude = precession_squared(disk, alpha0, b).sqrt();
    let precession = if b < 0.0 { -magnitude } else { magnitude };
    Ok(Motion {
        alpha: alpha0,
        alpha_dot: 0.0,
        precession,
        spin: b / disk.a * precession,
    })
}

/// A disk upright ($\alpha = \pi/2$) spinning about its vertical diameter at rate $\Omega_0$.
pub fn vertical_spin(precession: f64) -> Motion {
    Motion {
        alpha: FRAC_PI_2,
        alpha_dot: 0.0,
        precession,
        spin: 0.0,
    }
}

/// A wheel upright rolling in a straight line at spin $\omega_{10}$.
pub fn rolling_straight(spin: f64) -> Motion {
    Motion {
        alpha: FRAC_PI_2,
        alpha_dot: 0.0,
        precession: 0.0,
        spin,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The inverse gives back the tilt of eq 29's b = 0 motion, and upright below the slowest
    /// tilted motion.
    #[test]
    fn tilt_at_b0_inverts_eq_29() {
        let d = Disk::uniform(0.0375);
        for alpha0 in [0.01, 0.3, 1.0, 1.5] {
            let m = steady_motion(&d, alpha0, 0.0).unwrap();
            assert!((tilt_at_b0(&d, m.precession) - alpha0).abs() < 1e-12);
        }
        let slowest = (d.g / (d.k * d.a)).sqrt();
        assert_eq!(tilt_at_b0(&d, 0.9 * slowest), FRAC_PI_2);
    }
}
