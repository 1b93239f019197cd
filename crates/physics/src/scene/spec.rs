//! The scene file as written: the YAML keys, their defaults, and nothing checked yet.

use super::{
    friction, mechanisms, toy, Deserialize, Method, ModelKind, PowerLaw, Projection, Quantity,
    Settings,
};

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SceneSpec {
    pub(super) name: String,
    #[serde(default)]
    pub(super) description: String,
    pub(super) disk: DiskSpec,
    pub(super) model: ModelKind,
    #[serde(default)]
    pub(super) dissipation: Option<PowerLaw>,
    #[serde(default)]
    pub(super) mechanisms: Vec<mechanisms::MechanismSpec>,
    #[serde(default)]
    pub(super) friction: Option<friction::FrictionSpec>,
    #[serde(default)]
    pub(super) resistance: Option<toy::ResistanceSpec>,
    pub(super) start: StartSpec,
    pub(super) stop: StopSpec,
    #[serde(default)]
    pub(super) record: Vec<Quantity>,
    #[serde(default)]
    pub(super) sample: Option<f64>,
    #[serde(default)]
    pub(super) solver: SolverSpec,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct DiskSpec {
    pub(super) radius: f64,
    #[serde(default)]
    pub(super) k: Option<f64>,
    pub(super) mass: f64,
    #[serde(default)]
    pub(super) thickness: Option<f64>,
    #[serde(default)]
    pub(super) fillet: Option<f64>,
    #[serde(default = "earth_gravity")]
    pub(super) g: f64,
}

pub(super) fn earth_gravity() -> f64 {
    9.81
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct StartSpec {
    pub(super) steady: Option<SteadySpec>,
    pub(super) vertical_spin: Option<VerticalSpinSpec>,
    pub(super) rolling_straight: Option<RollingStraightSpec>,
    pub(super) explicit: Option<MotionSpec>,
    pub(super) perturb: Option<MotionSpec>,
    pub(super) slip: Option<friction::SlipSpec>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SteadySpec {
    pub(super) alpha0: f64,
    pub(super) b: f64,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct VerticalSpinSpec {
    pub(super) precession: f64,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RollingStraightSpec {
    pub(super) spin: f64,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct MotionSpec {
    #[serde(default)]
    pub(super) alpha: f64,
    #[serde(default)]
    pub(super) alpha_dot: f64,
    #[serde(default)]
    pub(super) precession: f64,
    #[serde(default)]
    pub(super) spin: f64,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct StopSpec {
    pub(super) time: Option<f64>,
    pub(super) alpha_below: Option<f64>,
    #[serde(default)]
    pub(super) lift_off: bool,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SolverSpec {
    #[serde(default = "default_method")]
    pub(super) method: Method,
    #[serde(default = "default_rtol")]
    pub(super) rtol: f64,
    #[serde(default = "default_atol")]
    pub(super) atol: f64,
    #[serde(default = "default_step")]
    pub(super) step: f64,
    #[serde(default = "default_max_steps", deserialize_with = "whole_steps")]
    pub(super) max_steps: u32,
    #[serde(default)]
    pub(super) project: Option<Projection>,
}

pub(super) fn default_method() -> Method {
    Settings::default().method
}
pub(super) fn default_rtol() -> f64 {
    Settings::default().rtol
}
pub(super) fn default_atol() -> f64 {
    Settings::default().atol
}
pub(super) fn default_step() -> f64 {
    Settings::default().step
}
/// `max_steps`: a whole number from 1 to [`crate::budget::MAX_STEPS_LIMIT`], written as an
/// integer or in floating-point form; outside that range the message gives the range.
fn whole_steps<'de, D: serde::Deserializer<'de>>(d: D) -> Result<u32, D::Error> {
    use serde::de::Error;
    let x = f64::deserialize(d)?;
    let limit = crate::budget::MAX_STEPS_LIMIT as f64;
    if x.fract() == 0.0 && (1.0..=limit).contains(&x) {
        Ok(x as u32)
    } else {
        Err(D::Error::custom(format!(
            "max_steps must lie between 1 and {limit:e} (a whole number), found {x}: give \
             max_steps in that range"
        )))
    }
}

pub(super) fn default_max_steps() -> u32 {
    Settings::default().max_steps
}

impl Default for SolverSpec {
    fn default() -> Self {
        Self {
            method: default_method(),
            rtol: default_rtol(),
            atol: default_atol(),
            step: default_step(),
            max_steps: default_max_steps(),
            project: None,
        }
    }
}
