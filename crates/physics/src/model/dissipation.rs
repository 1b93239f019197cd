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
    /// $\epsilon$, in $s^{\beta - 1}$ (dimensionless for $\beta = 1$, seconds for
    /// $\beta = 2$), so that $\epsilon m a g\Omega^\beta$ is a power.
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
        self.placed_torque_per_ma2(disk, m, Placement::AgainstOmega)
    }

    /// [`PowerLaw::torque_per_ma2`] with the torque along `placement`'s axis.
    pub fn placed_torque_per_ma2<T: DualNum<f64> + Copy>(
        &self,
        disk: &Disk,
        m: &Motion<T>,
        placement: Placement,
    ) -> [T; 3] {
        // P / (m a^2) = -epsilon (g/a) |Omega|^beta
        let power = -(m.precession.abs().powf(self.beta) * (self.epsilon * disk.g_over_a()));
        match placement {
            Placement::AgainstOmega => against_omega(m, power),
            Placement::ContactDiameter => about_axis(m, power, [T::zero(), T::zero(), T::one()]),
            Placement::AcrossPath => {
                let (s, c) = m.alpha.sin_cos();
                about_axis(m, power, [-s, T::zero(), c])
            }
        }
    }
}

/// Where the torque that dissipates eq 75's power acts: the paper gives only the power, so
/// any axis along which the angular velocity has a component carries it. Each placement has
/// $dE/dt = P$ exactly; they differ in how the tilt and the precession share the loss.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Placement {
    /// Anti-parallel to $\vec\omega$ (the default).
    #[default]
    AgainstOmega,
    /// About the diameter through the contact point, $\hat{\mathbf 3}$.
    ContactDiameter,
    /// About the horizontal axis across the path, $\hat{\mathbf r} = \hat{\mathbf 2}\times
    /// \hat{\mathbf z} = -\sin\alpha\,\hat{\mathbf 1} + \cos\alpha\,\hat{\mathbf 3}$.
    AcrossPath,
}

/// The torque about the centre of mass divided by $m a^2$, in the triad, along the unit axis
/// $\hat{\mathbf u}$ (triad components), whose power is `power_per_ma2`:
/// $\mathbf N/ma^2 = (P/ma^2)\,\hat{\mathbf u}/(\vec\omega\cdot\hat{\mathbf u})$. Zero when
/// the disk does not turn about that axis.
pub fn about_axis<T: DualNum<f64> + Copy>(m: &Motion<T>, power_per_ma2: T, u: [T; 3]) -> [T; 3] {
    let w = [m.spin, m.alpha_dot, -(m.precession * m.alpha.sin())];
    let along = w[0] * u[0] + w[1] * u[1] + w[2] * u[2];
    if along.re() == 0.0 {
        return [T::zero(); 3];
    }
    let c = power_per_ma2 / along;
    [c * u[0], c * u[1], c * u[2]]
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
