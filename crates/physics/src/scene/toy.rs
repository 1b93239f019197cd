//! The scene keys of the real toy (sliding model only, each modelled only when written):
//!
//! ```yaml
//! model: sliding
//! disk: { radius: 0.0375, mass: 0.4, thickness: 0.0128, fillet: 0.002 }   # k computed
//! friction: { static: 0.3, kinetic: 0.25 }     # instead of mu (then both are mu)
//! resistance: { rolling: 1e-5, boring: 1e-4 }  # lever arms of the contact moments (m)
//! ```
//!
//! See [`crate::model::sliding`]'s `toy.rs` for what each means. A thick disk's `steady` start
//! is the solid's own steady rolling, eqs 29-30 solved for its thickness and rim
//! ([`crate::model::steady_solid`]); a `b` on the wrong side of its edge is refused with the
//! edge.

use super::{ModelKind, SceneSpec, Validator};
use crate::model::sliding::{Resistance, Solid, Toy};
use crate::scene::SceneError;
use serde::Deserialize;

/// `resistance:` as written (m).
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct ResistanceSpec {
    #[serde(default)]
    rolling: f64,
    #[serde(default)]
    boring: f64,
}

impl Validator<'_> {
    /// The inertia factor $k = I_{22}/ma^2$ and the solid: `k` as written for a thin disk; for a
    /// disk with `thickness` (sliding model only) the solid's moments, with $k$ from its $I_{22}$.
    pub(super) fn solid(&self, s: &SceneSpec) -> Result<(f64, Option<Solid>), SceneError> {
        let d = &s.disk;
        let Some(t) = d.thickness else {
            if d.fillet.is_some() {
                return Err(self.err(
                    &["disk", "fillet"],
                    "disk: a fillet rounds the rim of a disk of finite thickness: add \
                     `thickness` (m) or remove `fillet`",
                ));
            }
            return match d.k {
                Some(k) => Ok((k, None)),
                None => Err(self.err(
                    &["disk"],
                    "disk: give the inertia factor k (0.25 for a uniform thin disk), or a \
                     thickness (m) with model: sliding to have the moments computed",
                )),
            };
        };
        if !s.model.has_coulomb_friction() {
            return Err(self.err(
                &["disk", "thickness"],
                format!(
                    "disk: the {} model is a thin disk; a finite thickness is modelled by \
                     model: sliding only: remove `thickness` (and `fillet`), or use model: sliding",
                    s.model
                ),
            ));
        }
        if d.k.is_some() {
            return Err(self.err(
                &["disk", "k"],
                "disk: the moments of a disk with a thickness are computed (a uniform solid): \
                 remove k",
            ));
        }
        let a = d.radius;
        if !(t.is_finite() && t > 0.0 && t <= 2.0 * a.abs()) {
            return Err(self.err(
                &["disk", "thickness"],
                format!(
                    "disk: thickness must be a positive number of metres at most the diameter \
                     (2 radius = {}), got {t}",
                    2.0 * a
                ),
            ));
        }
        let f = d.fillet.unwrap_or(0.0);
        if !(f.is_finite() && f >= 0.0 && f <= 0.5 * t && f < a.abs()) {
            return Err(self.err(
                &["disk", "fillet"],
                format!(
                    "disk: fillet must lie between 0 (sharp edges) and half the thickness ({}), \
                     got {f}",
                    0.5 * t
                ),
            ));
        }
        if !(a.is_finite() && a > 0.0 && d.mass.is_finite() && d.mass > 0.0) {
            // The radius and mass are refused with their own messages by `Disk::new`.
            return Ok((0.25, None));
        }
        let solid = Solid::new(a, d.mass, t, f);
        Ok((solid.i22 / (d.mass * a * a), Some(solid)))
    }

    /// The toy's additions: the solid, $\mu_k$ when `friction` gives `static` and `kinetic`,
    /// and `resistance`, refused for models other than sliding.
    pub(super) fn toy(&self, s: &SceneSpec, solid: Option<Solid>) -> Result<Toy, SceneError> {
        let kinetic = self.kinetic(s)?;
        let resistance = match s.resistance {
            None => None,
            Some(_) if !s.model.has_coulomb_friction() => {
                return Err(self.absent_from_model(
                    s,
                    "resistance",
                    "contact moments",
                    ModelKind::Sliding,
                ))
            }
            Some(r) => {
                for (key, v) in [("rolling", r.rolling), ("boring", r.boring)] {
                    if !(v.is_finite() && v >= 0.0 && v < s.disk.radius) {
                        return Err(self.err(
                            &["resistance", key],
                            format!(
                                "resistance: {key} is a lever arm in metres, 0 or more and below \
                                 the radius ({}), got {v}",
                                s.disk.radius
                            ),
                        ));
                    }
                }
                Some(Resistance {
                    rolling: r.rolling,
                    boring: r.boring,
                })
            }
        };
        Ok(Toy {
            solid,
            kinetic,
            resistance,
        })
    }
}
