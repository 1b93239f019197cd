//! Dissipation by the power law of eq 75, $P = -\epsilon m a g \Omega^\beta$, applied to the
//! rolling model as a torque.
//!
//! The paper gives only the power. To turn it into dynamics we apply, about the centre of mass, a
//! torque anti-parallel to the disk's angular velocity,
//! $\mathbf N = -\dfrac{\epsilon m a g |\Omega|^\beta}{|\vec\omega|^2}\,\vec\omega$.
//! The contact point does not slip, so the contact force does no work and
//! $dE/dt = \mathbf N\cdot\vec\omega = -\epsilon m a g |\Omega|^\beta$ exactly: the energy of
//! eq 26 falls at the rate of eq 75 whatever the state. (For $b = 0$, $\vec\omega$ lies along
//! $\hat{\mathbf 3}$ by eq 38, so the torque acts about the line from the centre to the contact.)

use crate::disk::Disk;
use crate::model::Motion;
use num_dual::DualNum;
use serde::{Deserialize, Serialize};

/// The power law of eq 75 (eq 74 is the case $\beta = 1$).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PowerLaw {
    /// $\epsilon$, dimensionless for $\beta = 1$; in general with units $s^{\beta}$ so that
    /// $\epsilon\Omega^\beta$ is dimensionless.
    pub epsilon: f64,
    /// $\beta$: the drag force varies as $\Omega^{\beta - 1}$.
    pub beta: f64,
}

impl PowerLaw {
    /// Eq 75: the power dissipated, $P = -\epsilon m a g |\Omega|^\beta$ (W, negative).
    pub fn power(&self, disk: &Disk, precession: f64) -> f64 {
        -self.epsilon * disk.m * disk.a * disk.g * precession.abs().powf(self.beta)
    }

    /// The torque about the centre of mass divided by $m a^2$, in the triad
    /// $(\hat{\mathbf 1}, \hat{\mathbf 2}, \hat{\mathbf 3})$, whose power is eq 75.
    /// Zero when the disk does not rotate.
    pub fn torque_per_ma2<T: DualNum<f64> + Copy>(&self, disk: &Disk, m: &Motion<T>) -> [T; 3] {
        // P / (m a^2) = -epsilon (g/a) |Omega|^beta
        let power = -(m.precession.abs().powf(self.beta) * (self.epsilon * disk.g_over_a()));
        against_omega(m, power)
    }
}

/// The torque about the centre of mass divided by $m a^2$, in the triad, anti-parallel to
/// $\vec\omega = (\omega_1, \dot\alpha, -\Omega\sin\alpha)$, whose power is `power_per_ma2`
/// (W per kg m^2, zero or negative): $\mathbf N/ma^2 = (P/ma^2)\,\vec\omega/|\vec\omega|^2$.
/// Zero when the disk does not rotate. The one home of this construction: eq 75's law and the
/// mechanisms of [`crate::model::mechanism`] both act through it.
pub fn against_omega<T: DualNum<f64> + Copy>(m: &Motion<T>, power_per_ma2: T) -> [T; 3] {
    let w = [m.spin, m.alpha_dot, -(m.precession * m.alpha.sin())];
    let w2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
    if w2.re() == 0.0 {
        return [T::zero(); 3];
    }
    let c = power_per_ma2 / w2;
    [c * w[0], c * w[1], c * w[2]]
}
