//! Numerically stable forms of eq 29 ($\Omega_0^2$) and eq 54 ($\varpi^2$) at the extremes.
//!
//! **Where the printed forms lose precision.** Eq 29 as printed,
//! $$\Omega_0^2 = \frac{g\cot\alpha_0}{k a\cos\alpha_0 + (2k+1)b}, \qquad (29)$$
//! and eq 54,
//! $$\frac{\varpi^2}{\Omega_0^2}(k+1) = 3k\cos^2\alpha_0 + \sin^2\alpha_0 +
//!   \frac ba\left((6k+1)\cos\alpha_0 - (2k+1)\frac{\sin^2\alpha_0}{\cos\alpha_0}\right) +
//!   2\frac{b^2}{a^2}(2k+1), \qquad (54)$$
//! lose precision in two places.
//!
//! 1. *Near $\alpha_0 = \pi/2$.* $\cos\alpha_0$ at $\alpha_0 = \pi/2 - \delta$ has condition
//!    number $\alpha_0\tan\alpha_0 \approx 1.57/\delta$: storing $\alpha_0$ in a double already
//!    rounds $\delta$ by up to $2^{-53}\cdot 1.57 \approx 1.1\times10^{-16}$ absolute, so at
//!    $\delta = 10^{-9}$ every $\cos\alpha_0$ (and with it $\Omega_0^2$ when $b \ne 0$) is wrong
//!    by $\sim 10^{-7}$ relative, however carefully it is then evaluated. In eq 54 the ratio
//!    $\sin^2\alpha_0/\cos\alpha_0$ grows as $1/\delta$ while $\Omega_0^2$ falls as $\delta$, so
//!    $\varpi^2/\Omega_0^2$ overflows the product it is meant for, which stays finite.
//! 2. *Near eq 30's bound $b \to b_{\min} = -a k\cos\alpha_0/(2k+1)$.* The denominator of eq 29
//!    is a difference of nearly equal terms: it equals $(2k+1)(b - b_{\min})$, and computed
//!    from $b$ it carries an absolute error of order $\varepsilon\,k a\cos\alpha_0$, which is
//!    a relative error $\varepsilon\,k a\cos\alpha_0 / ((2k+1)(b - b_{\min}))$ — and $b$ itself,
//!    stored as a double, has already lost the digits of its excess over the bound.
//!
//! **The stable forms.** Carry the two small quantities themselves: the complement
//! $\delta = \pi/2 - \alpha_0$ and the excess $\Delta = b - b_{\min}$ (a [`SteadyParams`]).
//! With $c = \cos\alpha_0 = \sin\delta$ and $s = \sin\alpha_0 = \cos\delta$, both computed to
//! full relative precision,
//! $$\Omega_0^2 = \frac{g\,c/s}{(2k+1)\Delta},$$
//! and eq 54 multiplied through by $\Omega_0^2$, the $1/c$ cancelled analytically
//! ($\Omega_0^2\,s^2/c = g s/((2k+1)\Delta)$):
//! $$\varpi^2(k+1) = \Omega_0^2\left[3k c^2 + s^2 + (6k+1)\frac ba c + 2(2k+1)\frac{b^2}{a^2}\right] -
//!   \frac{b}{a}\,\frac{g s}{\Delta}.$$
//! No term is then a difference of nearly equal numbers, and at $\delta = 0$ it gives the
//! upright limit $\varpi^2 \to -g/a(k+1)$ for any $b > 0$ (the disk falls over at the rate of
//! eq 53's threshold).

use physics::disk::Disk;
use physics::model::steady::{b_bound, precession_squared};
use std::f64::consts::FRAC_PI_2;

/// A steady motion's parameters held without loss: $\delta = \pi/2 - \alpha_0$ and
/// $\Delta = b - b_{\min}$, the excess of $b$ over eq 30's bound.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyParams {
    /// $\delta = \pi/2 - \alpha_0$ (rad), in $(0, \pi/2)$.
    pub delta: f64,
    /// $\Delta = b - b_{\min}(\alpha_0) > 0$ (m).
    pub excess: f64,
}

impl SteadyParams {
    /// From the complement of the tilt and $b$ (the excess is then computed, with the loss of
    /// digits that implies when $b$ is near the bound).
    pub fn from_delta_b(disk: &Disk, delta: f64, b: f64) -> Self {
        Self {
            delta,
            excess: b - bound_at(disk, delta),
        }
    }

    /// From the tilt and $b$ as stored doubles (what the printed forms see).
    pub fn from_alpha_b(disk: &Disk, alpha0: f64, b: f64) -> Self {
        Self {
            delta: FRAC_PI_2 - alpha0,
            excess: b - b_bound(disk, alpha0),
        }
    }

    /// $b = b_{\min} + \Delta$ (m).
    pub fn b(&self, disk: &Disk) -> f64 {
        bound_at(disk, self.delta) + self.excess
    }
}

/// Eq 30's bound from the complement: $b_{\min} = -a k\sin\delta/(2k+1)$.
fn bound_at(disk: &Disk, delta: f64) -> f64 {
    -disk.a * disk.k * delta.sin() / (2.0 * disk.k + 1.0)
}

/// Eq 29 as printed, from the stored $\alpha_0$ and $b$ (see the module docs for where it
/// loses precision).
pub fn precession_squared_printed(disk: &Disk, alpha0: f64, b: f64) -> f64 {
    precession_squared(disk, alpha0, b)
}

/// Eq 29 in the stable form $\Omega_0^2 = g\,(\sin\delta/\cos\delta)/((2k+1)\Delta)$.
pub fn precession_squared_stable(disk: &Disk, p: &SteadyParams) -> f64 {
    let (c, s) = p.delta.sin_cos();
    disk.g * (c / s) / ((2.0 * disk.k + 1.0) * p.excess)
}

/// Eq 54 as printed: $\varpi^2 = \Omega_0^2 \cdot [\text{eq 54's right-hand side}]/(k+1)$,
/// from the stored $\alpha_0$ and $b$.
pub fn varpi_squared_printed(disk: &Disk, alpha0: f64, b: f64) -> f64 {
    let k = disk.k;
    let (s, c) = alpha0.sin_cos();
    let r = b / disk.a;
    let ratio = 3.0 * k * c * c
        + s * s
        + r * ((6.0 * k + 1.0) * c - (2.0 * k + 1.0) * s * s / c)
        + 2.0 * r * r * (2.0 * k + 1.0);
    precession_squared(disk, alpha0, b) * ratio / (k + 1.0)
}

/// Eq 54 multiplied through by $\Omega_0^2$, in $(\delta, \Delta)$ (see the module docs).
pub fn varpi_squared_stable(disk: &Disk, p: &SteadyParams) -> f64 {
    let k = disk.k;
    let (c, s) = p.delta.sin_cos();
    let b = p.b(disk);
    let r = b / disk.a;
    let om2 = precession_squared_stable(disk, p);
    let bracket = 3.0 * k * c * c + s * s + (6.0 * k + 1.0) * r * c + 2.0 * (2.0 * k + 1.0) * r * r;
    (om2 * bracket - r * disk.g * s / p.excess) / (k + 1.0)
}
