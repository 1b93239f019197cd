//! The scene keys of the sliding model: `model: sliding`, `friction: { mu,
//! restitution }`, a start slip `start: { ..., slip: { forward, sideways } }`, and the record
//! quantities only the lab-frame and sliding models provide (`slip_speed`, `cm_speed`,
//! `contact_gap`, `dissipated`).
//!
//! ```yaml
//! model: sliding
//! friction: { mu: 0.3, restitution: 0.0 }      # Coulomb's mu >= 0; Newton's e in [0, 1]
//! start: { explicit: { alpha: 1.5707963, spin: 0 }, slip: { forward: 1.0, sideways: 0.0 } }
//! record: [alpha, slip_speed, cm_speed, normal_force, contact_gap, energy, dissipated]
//! ```

use super::{ModelKind, SceneSpec, Validator};
use crate::model::sliding::{Friction, Slip};
use crate::model::Quantity;
use crate::scene::SceneError;
use serde::Deserialize;

/// The largest Coulomb coefficient a scene may give: far above real pairs of surfaces (below
/// about 1.5).
const MU_MOST: f64 = 10.0;

/// `friction:` as written.
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FrictionSpec {
    #[serde(default)]
    mu: Option<f64>,
    #[serde(default, rename = "static")]
    stat: Option<f64>,
    #[serde(default)]
    kinetic: Option<f64>,
    #[serde(default)]
    restitution: f64,
}

/// `slip:` inside `start:` as written (m/s).
#[derive(Debug, Clone, Copy, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SlipSpec {
    #[serde(default)]
    pub(super) forward: f64,
    #[serde(default)]
    pub(super) sideways: f64,
}

impl Validator<'_> {
    /// The friction law and the start slip of a scene: required and checked for
    /// `model: sliding`, refused for every other model.
    pub(super) fn friction(&self, s: &SceneSpec) -> Result<(Option<Friction>, Slip), SceneError> {
        let sliding = s.model.has_coulomb_friction();
        let slip = s.start.slip.unwrap_or_default();
        if !sliding {
            if s.friction.is_some() {
                return Err(self.absent_from_model(
                    s,
                    "friction",
                    "friction law",
                    ModelKind::Sliding,
                ));
            }
            if s.start.slip.is_some() {
                return Err(self.err(
                    &["start", "slip"],
                    format!(
                        "start: the {} model cannot start slipping (its contact point {}): remove \
                         `slip`, or use model: sliding",
                        s.model,
                        if s.model.is_frictionless() {
                            "slides freely, with no friction to compare a slip against"
                        } else {
                            "is at rest by construction"
                        }
                    ),
                ));
            }
            return Ok((None, Slip::default()));
        }
        let Some(f) = s.friction else {
            return Err(self.err(
                &["model"],
                "the sliding model needs a friction law: add `friction: { mu: 0.3, restitution: 0.0 }`",
            ));
        };
        let mu = self.static_mu(&f)?;
        if !(f.restitution.is_finite() && (0.0..=1.0).contains(&f.restitution)) {
            return Err(self.err(
                &["friction", "restitution"],
                format!(
                    "friction: restitution must lie between 0 (plastic landing) and 1 (elastic), got {}",
                    f.restitution
                ),
            ));
        }
        for (key, v) in [("forward", slip.forward), ("sideways", slip.sideways)] {
            if !v.is_finite() {
                return Err(self.err(
                    &["start", "slip", key],
                    format!("start: slip {key} must be a finite speed in m/s, got {v}"),
                ));
            }
        }
        Ok((
            Some(Friction {
                mu,
                restitution: f.restitution,
            }),
            Slip {
                forward: slip.forward,
                sideways: slip.sideways,
            },
        ))
    }

    /// Coulomb's static coefficient: `mu`, or `static` beside `kinetic` (toy scenes).
    fn static_mu(&self, f: &FrictionSpec) -> Result<f64, SceneError> {
        let (key, mu) = match (f.mu, f.stat, f.kinetic) {
            (Some(mu), None, None) => ("mu", mu),
            (None, Some(st), Some(_)) => ("static", st),
            (Some(_), _, _) => {
                return Err(self.err(
                    &["friction", "mu"],
                    "friction: give either mu (one coefficient) or static and kinetic, not both: remove mu or the other two",
                ))
            }
            _ => {
                return Err(self.err(
                    &["friction"],
                    "friction: give mu, or both static and kinetic (e.g. { static: 0.3, kinetic: 0.25 })",
                ))
            }
        };
        if !((0.0..=MU_MOST).contains(&mu)) {
            return Err(self.err(
                &["friction", key],
                format!(
                    "friction: {key} must be a number from 0 (frictionless) to {MU_MOST} (real \
                     pairs of surfaces have mu below about 1.5), got {mu}"
                ),
            ));
        }
        Ok(mu)
    }

    /// The kinetic coefficient when `friction` gives one that differs from `static`;
    /// refused above `static` (a slip would need more force than sticking allows).
    pub(super) fn kinetic(&self, s: &SceneSpec) -> Result<Option<f64>, SceneError> {
        let Some(f) = s.friction else {
            return Ok(None);
        };
        let (Some(st), Some(k)) = (f.stat, f.kinetic) else {
            return Ok(None);
        };
        if !(k.is_finite() && k >= 0.0 && k <= st) {
            return Err(self.err(
                &["friction", "kinetic"],
                format!(
                    "friction: kinetic must lie between 0 and static ({st}), got {k}: the coefficient of a slip is at most the one that holds a stick"
                ),
            ));
        }
        Ok((k != st).then_some(k))
    }

    /// Refuses a record quantity that `model` cannot provide (the contact quantities of the
    /// lab-frame and sliding models).
    pub(super) fn contact_quantity(&self, q: Quantity, model: ModelKind) -> Result<(), SceneError> {
        let contact_only = matches!(
            q,
            Quantity::SlipSpeed
                | Quantity::CmSpeed
                | Quantity::ContactGap
                | Quantity::Dissipated
                | Quantity::ContactPath
        );
        let lab = model.is_lab_frame();
        if contact_only && !lab {
            return Err(self.err(
                &["record"],
                format!(
                    "record: {} needs the contact point's motion, which only the lab-frame and \
                     sliding models integrate; remove it or use model: sliding",
                    q.name()
                ),
            ));
        }
        Ok(())
    }
}
