//! The friction study of the report: the built-in slip-stick scene run by the sliding model
//! (recording the contact's path too), and the friction studies of [`crate::friction`] at the
//! scene's solver settings.

use crate::experiment::law::Law;
use crate::figures::friction::FrictionResults;
use crate::paper::printed::Fit;
use crate::report::error::ReportError;
use crate::run::run;
use crate::scene::Scene;

/// Runs the slip-stick scene and the friction studies, the mechanisms held against the
/// paper's fit of sec. 11 (`fit`).
pub fn compute(fit: &Fit) -> Result<FrictionResults, ReportError> {
    let scene = Scene::load("slip-stick").map_err(|e| ReportError::Input(e.to_string()))?;
    let mu = scene
        .friction
        .ok_or("the slip-stick scene has no friction law")?
        .mu;
    let settings = scene.settings;
    let (slip_stick, studies) = rayon::join(
        || run(&scene, None).map_err(|e| ReportError::Input(e.to_string())),
        || {
            crate::friction::studies(&settings, &Law::from_fit(fit.beta, fit.c_inv_root))
                .map_err(|e| ReportError::Input(e.to_string()))
        },
    );
    Ok(FrictionResults {
        slip_stick: slip_stick?,
        mu,
        weight: scene.disk.m * scene.disk.g,
        studies: studies?,
    })
}
