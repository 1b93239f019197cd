//! The sliding study of the report: the built-in slip-stick scene run by the sliding model
//! (recording the contact's path too), and the studies of [`crate::sliding`] at the scene's
//! solver settings.

use crate::error::StudyError;
use crate::sliding::Studies;
use experiment::law::Law;
use physics::run::{run, Run};
use physics::scene::Scene;

/// The slip-stick scene's run and the sliding studies: what the friction figures and the
/// report's friction section are drawn from.
#[derive(Debug, Clone)]
pub struct SlipStick {
    /// The built-in slip-stick scene, run by the sliding model.
    pub slip_stick: Run,
    /// Its Coulomb coefficient.
    pub mu: f64,
    /// Its disk's weight $mg$ (N).
    pub weight: f64,
    /// The friction studies ([`studies::sliding::studies`]).
    pub studies: Studies,
}

/// Runs the slip-stick scene and the sliding studies, the mechanisms held against `record`
/// (the law of sec. 11's record).
pub fn compute(record: &Law) -> Result<SlipStick, StudyError> {
    let scene = Scene::load("slip-stick")?;
    let mu = scene
        .friction
        .ok_or("the slip-stick scene has no friction law")?
        .mu;
    let settings = scene.settings;
    let (slip_stick, studies) = rayon::join(
        || run(&scene, None),
        || crate::sliding::studies(&settings, record),
    );
    Ok(SlipStick {
        slip_stick: slip_stick?,
        mu,
        weight: scene.disk.m * scene.disk.g,
        studies: studies?,
    })
}
