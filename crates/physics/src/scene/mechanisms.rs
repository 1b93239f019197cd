//! The scene key of the dissipation mechanisms (`crate::model::mechanism`):
//! `mechanisms:`, a list for `model: dissipative`, each entry one mechanism by name with its
//! coefficient, besides or instead of eq 75's `dissipation:` law.
//!
//! ```yaml
//! model: dissipative
//! mechanisms:
//!   - viscous_rolling: { time: 2.0e-4 }        # P = -tau F_z v_p^2 / a        (beta 2)
//!   - rolling_friction: { coefficient: 1e-4 }  # P = -c F_z v_p                (beta 1)
//!   - rolling_resistance: { lever: 1e-6 }      # P = -delta F_z |omega_t|      (beta -1)
//!   - pivoting: { mu_radius: 1e-5 }            # P = -(2/3) mu r_p F_z |omega_z| (beta -3)
//!   - air_film: {}                             # Moffatt's film, air's viscosity (beta 4)
//!   - air_layer: { viscosity: 1.8e-5, kinematic: 1.5e-5 }   # boundary layer (beta 5/2)
//! ```

use super::{ModelKind, SceneSpec, Validator};
use crate::model::mechanism::{Mechanism, AIR_KINEMATIC_VISCOSITY, AIR_VISCOSITY};
use crate::scene::SceneError;
use serde::Deserialize;

/// One entry of `mechanisms:` as written: exactly one of the names.
#[derive(Debug, Clone, Copy, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct MechanismSpec {
    rolling_friction: Option<Coefficient>,
    viscous_rolling: Option<Time>,
    rolling_resistance: Option<Lever>,
    pivoting: Option<MuRadius>,
    air_film: Option<Viscosity>,
    air_layer: Option<Air>,
}

#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
struct Coefficient {
    coefficient: f64,
}

#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
struct Time {
    time: f64,
}

#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
struct Lever {
    lever: f64,
}

#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
struct MuRadius {
    mu_radius: f64,
}

#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
struct Viscosity {
    #[serde(default = "air_viscosity")]
    viscosity: f64,
}

#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
struct Air {
    #[serde(default = "air_viscosity")]
    viscosity: f64,
    #[serde(default = "air_kinematic")]
    kinematic: f64,
}

fn air_viscosity() -> f64 {
    AIR_VISCOSITY
}

fn air_kinematic() -> f64 {
    AIR_KINEMATIC_VISCOSITY
}

/// The names, as a user writes them.
const NAMES: &str =
    "rolling_friction, viscous_rolling, rolling_resistance, pivoting, air_film, air_layer";

impl MechanismSpec {
    /// The mechanisms named in this entry (one when well formed).
    fn named(&self) -> Vec<Mechanism> {
        let mut out = Vec::new();
        if let Some(c) = self.rolling_friction {
            out.push(Mechanism::RollingFriction {
                coefficient: c.coefficient,
            });
        }
        if let Some(t) = self.viscous_rolling {
            out.push(Mechanism::ViscousRolling { time: t.time });
        }
        if let Some(l) = self.rolling_resistance {
            out.push(Mechanism::RollingResistance { lever: l.lever });
        }
        if let Some(p) = self.pivoting {
            out.push(Mechanism::Pivoting {
                mu_radius: p.mu_radius,
            });
        }
        if let Some(v) = self.air_film {
            out.push(Mechanism::AirFilm {
                viscosity: v.viscosity,
            });
        }
        if let Some(a) = self.air_layer {
            out.push(Mechanism::AirLayer {
                viscosity: a.viscosity,
                kinematic: a.kinematic,
            });
        }
        out
    }
}

impl Validator<'_> {
    /// `mechanisms:`: only the dissipative model has them as torques; each entry names one
    /// mechanism, with a finite, non-negative coefficient.
    pub(super) fn mechanisms(&self, s: &SceneSpec) -> Result<Vec<Mechanism>, SceneError> {
        if s.mechanisms.is_empty() {
            return Ok(Vec::new());
        }
        if s.model != ModelKind::Dissipative {
            return Err(self.absent_from_model(
                s,
                "mechanisms",
                "dissipation mechanisms",
                ModelKind::Dissipative,
            ));
        }
        if s.mechanisms.len() > crate::budget::MAX_MECHANISMS {
            return Err(self.err(
                &["mechanisms"],
                format!(
                    "mechanisms: {} entries, more than the limit of {}; list each kind \
                     of mechanism once, with its coefficient",
                    s.mechanisms.len(),
                    crate::budget::MAX_MECHANISMS
                ),
            ));
        }
        let mut out = Vec::new();
        for (i, entry) in s.mechanisms.iter().enumerate() {
            let named = entry.named();
            let [m] = named[..] else {
                return Err(self.err(
                    &["mechanisms"],
                    format!(
                        "mechanisms: entry {} names {} mechanisms; give each its own entry, \
                         one of {NAMES} (e.g. - viscous_rolling: {{ time: 2.0e-4 }})",
                        i + 1,
                        named.len()
                    ),
                ));
            };
            if !m.is_valid() {
                return Err(self.err(
                    &["mechanisms"],
                    format!(
                        "mechanisms: entry {} ({}) needs a finite, non-negative `{}` in {} (and \
                         an air layer a positive `kinematic` viscosity in m^2/s), got {}",
                        i + 1,
                        m.name(),
                        m.key(),
                        m.unit(),
                        m.coefficient()
                    ),
                ));
            }
            out.push(m);
        }
        Ok(out)
    }
}
