//! Dissipation mechanisms from their physics, as optional terms of the rolling model: each
//! gives the power it takes from the disk as a function of the state, and acts, like eq 75's
//! law ([`crate::model::dissipation`]), as a torque about the centre of mass anti-parallel to
//! $\vec\omega$ whose power is that, so that $dE/dt = P$ exactly.
//!
//! Eq 75 writes the dissipation as $P = -\epsilon m a g\Omega^\beta$ and sec. 11 assigns
//! $\beta$ by the speed a drag force "sees": $\beta = 2$ for a rolling friction proportional to
//! the contact point's velocity, 3 for an air drag quadratic in it, 4 for Moffatt's air film.
//! Near the end of a spin-down the speeds of the disk differ by orders of magnitude, so the
//! exponent a mechanism gives depends on which speed drives it. With $b = 0$ and a small tilt
//! (steady motion, eq 29: $\Omega^2\sin\alpha = g/ka$, so $\alpha \propto \Omega^{-2}$; $F_z = mg$):
//!
//! - the contact point runs over the table and round the rim at
//!   $v_p = a|\omega_1 + \Omega\cos\alpha| \approx a\Omega$ (eq 11's relative spin; the material
//!   point at the contact is at rest);
//! - the material turns at $|\vec\omega| = \sqrt{\omega_1^2 + \dot\alpha^2 + \Omega^2\sin^2\alpha}
//!   \approx \Omega\alpha \propto \Omega^{-1}$ (the face of the coin turns slowly while the
//!   contact whirls);
//! - about the vertical (pivoting at the contact) it turns at
//!   $\omega_z = \Omega\sin^2\alpha - \omega_1\cos\alpha \approx \Omega\alpha^2 \propto \Omega^{-3}$
//!   ($\hat{\mathbf z} = -\cos\alpha\,\hat{\mathbf 1} - \sin\alpha\,\hat{\mathbf 3}$);
//! - the air under the disk is pumped out and in through a gap $a\alpha$ as the wedge turns:
//!   the volume swept, $\sim a^3\alpha\Omega$ per unit time, leaves through a rim opening
//!   $\sim a\cdot a\alpha$, so the air moves at $\sim a\Omega$ whatever the gap.
//!
//! Hence the exponents of [`Mechanism::exponent`]. Each is hand-written because the power
//! laws of a rolling contact are this field's own; no crate models them.
//!
//! The torque is put along $-\vec\omega$ for every mechanism: it fixes $dE/dt$, which is what a
//! spin-down's $\Omega(t)$ follows adiabatically; a pivoting torque acts about the vertical and
//! a rolling-resistance torque about the rolling axis, which changes the nutation but not the
//! rate at which the energy goes. $F_z$ is taken as $mg$: the centre of mass's height changes
//! only by the nutation, whose relative amplitude the spin-down keeps small.

use crate::disk::Disk;
use crate::model::air_film::SqueezeFilm;
use crate::model::dissipation::against_omega;
use crate::model::Motion;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Air's dynamic viscosity at room temperature (Pa s); the paper's $1.8\times10^{-4}$ g/(cm s).
pub const AIR_VISCOSITY: f64 = 1.8e-5;
/// Air's kinematic viscosity at room temperature (m^2/s).
pub const AIR_KINEMATIC_VISCOSITY: f64 = 1.5e-5;

/// One mechanism and its coefficient.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum Mechanism {
    /// Rolling friction by hysteresis: the energy lost per unit length rolled is a fixed
    /// fraction $c$ of the load, $P = -c F_z v_p$ ($\beta = 1$).
    RollingFriction {
        /// $c$, dimensionless.
        coefficient: f64,
    },
    /// Rolling friction that grows with the rolling speed (a viscoelastic contact below its
    /// relaxation rate): the fraction is $\tau v_p/a$, $P = -\tau F_z v_p^2/a$ ($\beta = 2$: the
    /// paper's "rolling frictional force proportional to the velocity of the contact point").
    ViscousRolling {
        /// $\tau$ (s).
        time: f64,
    },
    /// Rolling resistance as for a wheel: the normal force acts a lever $\delta$ ahead of the
    /// contact, a torque $\delta F_z$ against the material's rolling,
    /// $P = -\delta F_z|\vec\omega_t|$ with $\vec\omega_t$ the part of $\vec\omega$ along the
    /// table ($\beta = -1$).
    RollingResistance {
        /// $\delta$ (m).
        lever: f64,
    },
    /// Sliding friction in a contact patch of radius $r_p$ that pivots (Contensou's torque for
    /// a uniform pressure, $\frac23\mu F_z r_p$): $P = -\frac23\mu r_p F_z|\omega_z|$
    /// ($\beta = -3$: no finite-time singularity, which eq 79 has only for $\beta > -2$).
    Pivoting {
        /// $\mu r_p$ (m).
        mu_radius: f64,
    },
    /// Moffatt's squeeze film ([`crate::model::air_film`]):
    /// $P = -12 I\eta a^3\Omega^2/\alpha$ ($\beta = 4$), valid while the gap $a\alpha$ is
    /// thinner than the viscous layer $\sqrt{\nu/\Omega}$.
    AirFilm {
        /// $\eta$ (Pa s).
        viscosity: f64,
    },
    /// The same pumped flow when the gap is thicker than the viscous layer: the shear
    /// $\eta a\Omega/\delta$ acts across $\delta = \sqrt{\nu/\Omega}$ over the face, so
    /// $P = -\pi\eta a^4\Omega^{5/2}/\sqrt{\nu}$ up to a factor of order one, set to 1 here
    /// ($\beta = 5/2$, the exponent the paper quotes for Moffatt's revised model).
    AirLayer {
        /// $\eta$ (Pa s).
        viscosity: f64,
        /// $\nu$ (m^2/s).
        kinematic: f64,
    },
}

impl Mechanism {
    /// Every mechanism with a coefficient of 1 in its own units (air: room-temperature air).
    pub fn all_unit() -> [Mechanism; 6] {
        [
            Mechanism::RollingFriction { coefficient: 1.0 },
            Mechanism::ViscousRolling { time: 1.0 },
            Mechanism::RollingResistance { lever: 1.0 },
            Mechanism::Pivoting { mu_radius: 1.0 },
            Mechanism::AirFilm {
                viscosity: AIR_VISCOSITY,
            },
            Mechanism::AirLayer {
                viscosity: AIR_VISCOSITY,
                kinematic: AIR_KINEMATIC_VISCOSITY,
            },
        ]
    }

    /// A stable name for tables and figures.
    pub fn name(&self) -> &'static str {
        match self {
            Mechanism::RollingFriction { .. } => "rolling friction (hysteresis)",
            Mechanism::ViscousRolling { .. } => "viscous rolling friction",
            Mechanism::RollingResistance { .. } => "rolling resistance (lever)",
            Mechanism::Pivoting { .. } => "pivoting friction",
            Mechanism::AirFilm { .. } => "air film (lubrication)",
            Mechanism::AirLayer { .. } => "air boundary layer",
        }
    }

    /// The exponent $\beta$ of eq 75 this mechanism gives at $b = 0$ and small tilt (module doc).
    pub fn exponent(&self) -> f64 {
        match self {
            Mechanism::RollingFriction { .. } => 1.0,
            Mechanism::ViscousRolling { .. } => 2.0,
            Mechanism::RollingResistance { .. } => -1.0,
            Mechanism::Pivoting { .. } => -3.0,
            Mechanism::AirFilm { .. } => 4.0,
            Mechanism::AirLayer { .. } => 2.5,
        }
    }

    /// The coefficient, in the mechanism's own units.
    pub fn coefficient(&self) -> f64 {
        match *self {
            Mechanism::RollingFriction { coefficient } => coefficient,
            Mechanism::ViscousRolling { time } => time,
            Mechanism::RollingResistance { lever } => lever,
            Mechanism::Pivoting { mu_radius } => mu_radius,
            Mechanism::AirFilm { viscosity } | Mechanism::AirLayer { viscosity, .. } => viscosity,
        }
    }

    /// The scene key of [`Mechanism::coefficient`] (the YAML field under the mechanism's name).
    pub fn key(&self) -> &'static str {
        match self {
            Mechanism::RollingFriction { .. } => "coefficient",
            Mechanism::ViscousRolling { .. } => "time",
            Mechanism::RollingResistance { .. } => "lever",
            Mechanism::Pivoting { .. } => "mu_radius",
            Mechanism::AirFilm { .. } | Mechanism::AirLayer { .. } => "viscosity",
        }
    }

    /// The unit of [`Mechanism::coefficient`].
    pub fn unit(&self) -> &'static str {
        match self {
            Mechanism::RollingFriction { .. } => "1",
            Mechanism::ViscousRolling { .. } => "s",
            Mechanism::RollingResistance { .. } | Mechanism::Pivoting { .. } => "m",
            Mechanism::AirFilm { .. } | Mechanism::AirLayer { .. } => "Pa s",
        }
    }

    /// The same mechanism with its coefficient multiplied by `factor` (the power scales with it).
    pub fn scaled(&self, factor: f64) -> Mechanism {
        match *self {
            Mechanism::RollingFriction { coefficient } => Mechanism::RollingFriction {
                coefficient: coefficient * factor,
            },
            Mechanism::ViscousRolling { time } => Mechanism::ViscousRolling {
                time: time * factor,
            },
            Mechanism::RollingResistance { lever } => Mechanism::RollingResistance {
                lever: lever * factor,
            },
            Mechanism::Pivoting { mu_radius } => Mechanism::Pivoting {
                mu_radius: mu_radius * factor,
            },
            Mechanism::AirFilm { viscosity } => Mechanism::AirFilm {
                viscosity: viscosity * factor,
            },
            Mechanism::AirLayer {
                viscosity,
                kinematic,
            } => Mechanism::AirLayer {
                viscosity: viscosity * factor,
                kinematic,
            },
        }
    }

    /// The power taken from the disk in state `m` (W, zero or negative).
    pub fn power(&self, disk: &Disk, m: &Motion) -> f64 {
        let fz = disk.m * disk.g;
        let (s, c) = m.alpha.sin_cos();
        let contact_speed = disk.a * (m.spin + m.precession * c).abs();
        let w2 = m.spin * m.spin + m.alpha_dot * m.alpha_dot + (m.precession * s).powi(2);
        let wz = m.precession * s * s - m.spin * c;
        let om = m.precession.abs();
        -match *self {
            Mechanism::RollingFriction { coefficient } => coefficient * fz * contact_speed,
            Mechanism::ViscousRolling { time } => time * fz * contact_speed.powi(2) / disk.a,
            Mechanism::RollingResistance { lever } => lever * fz * (w2 - wz * wz).max(0.0).sqrt(),
            Mechanism::Pivoting { mu_radius } => 2.0 / 3.0 * mu_radius * fz * wz.abs(),
            Mechanism::AirFilm { viscosity } => {
                SqueezeFilm::solved().dissipation(disk, viscosity, m.alpha.abs(), om)
            }
            Mechanism::AirLayer {
                viscosity,
                kinematic,
            } => PI * viscosity * disk.a.powi(4) * om.powf(2.5) / kinematic.sqrt(),
        }
    }

    /// The torque about the centre of mass divided by $m a^2$, in the triad, anti-parallel to
    /// $\vec\omega = (\omega_1, \dot\alpha, -\Omega\sin\alpha)$ with power [`Mechanism::power`].
    pub fn torque_per_ma2(&self, disk: &Disk, m: &Motion) -> [f64; 3] {
        against_omega(m, self.power(disk, m) / (disk.m * disk.a * disk.a))
    }

    /// True when the coefficient is finite and non-negative (and air's $\nu$ positive).
    pub fn is_valid(&self) -> bool {
        let ok = self.coefficient().is_finite() && self.coefficient() >= 0.0;
        match *self {
            Mechanism::AirLayer { kinematic, .. } => ok && kinematic.is_finite() && kinematic > 0.0,
            _ => ok,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::rolling::energy;
    use crate::model::steady::steady_motion;
    use num_dual::Dual64;

    fn disk() -> Disk {
        crate::disk::toy_disk()
    }

    /// Along steady motion with $b = 0$, the local slope of $\ln|P|$ against $\ln\Omega$
    /// approaches the stated exponent as the tilt vanishes (measured between $\alpha$ = 2e-4
    /// and 1e-4 rad, where the small-angle forms hold to 1e-4).
    #[test]
    fn each_power_has_its_stated_exponent_at_small_tilt() {
        let d = disk();
        for mech in Mechanism::all_unit() {
            let at = |alpha: f64| {
                let m = steady_motion(&d, alpha, 0.0).unwrap();
                (m.precession.ln(), (-mech.power(&d, &m)).ln())
            };
            let (x1, y1) = at(2e-4);
            let (x2, y2) = at(1e-4);
            let slope = (y2 - y1) / (x2 - x1);
            assert!(
                (slope - mech.exponent()).abs() < 1e-3,
                "{}: slope {slope}, stated {}",
                mech.name(),
                mech.exponent()
            );
        }
    }

    /// The torque's power is the mechanism's power: the rate of eq 26's energy along the
    /// torqued rates (differentiated exactly) equals $P$.
    #[test]
    fn the_torque_takes_energy_at_the_stated_rate() {
        let d = disk();
        let m = Motion {
            alpha: 0.3,
            alpha_dot: 0.7,
            precession: 12.0,
            spin: 2.5,
        };
        for mech in Mechanism::all_unit() {
            let n = mech.torque_per_ma2(&d, &m);
            let r = crate::model::rolling::rates(&d, &m, n);
            let dual = Motion {
                alpha: Dual64::new(m.alpha, m.alpha_dot),
                alpha_dot: Dual64::new(m.alpha_dot, r.alpha_ddot),
                precession: Dual64::new(m.precession, r.precession_dot),
                spin: Dual64::new(m.spin, r.spin_dot),
            };
            let rate = energy(&d, &dual).eps;
            let p = mech.power(&d, &m);
            assert!(p < 0.0, "{}", mech.name());
            assert!(
                (rate - p).abs() <= 1e-10 * p.abs(),
                "{}: dE/dt {rate}, P {p}",
                mech.name()
            );
        }
    }
}
