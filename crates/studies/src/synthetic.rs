//! The synthetic experiment of section 11 (the paper's data are not published): the built-in
//! spin-down scene seen through the default light model and scope, analysed as the paper did
//! (peak times, $\Omega_i$, $d\Omega_i/dt$) and fitted (eqs 84 and 85).

use crate::error::StudyError;
use experiment::{Analysis, AnalysisSettings, LightModel, Trace};
use physics::scene::Scene;

/// The synthetic trace and its analysis.
#[derive(Debug, Clone)]
pub struct Synthetic {
    /// The scope trace.
    pub trace: Trace,
    /// Its analysis.
    pub analysis: Analysis,
    /// Eq 84 fitted to the simulated motion's exact passage times over the analysis's cycles
    /// ([`experiment::motion_law`]): what the law says of the model without the light.
    pub motion_law: Option<experiment::fit::Eq84Fit>,
}

/// Simulates the built-in spin-down through the default light model and scope, and analyses
/// the trace as the paper did.
pub fn compute() -> Result<Synthetic, StudyError> {
    let scene = Scene::load("spin-down")?;
    let light = LightModel::default();
    let scope = &light.scope;
    let motion = experiment::simulate::simulate_motion(
        &scene,
        scope.end_at,
        scope.sample_rate,
        scope.samples,
    )?;
    let trace = experiment::simulate::trace_of_motion(&motion, &light, &scene.name);
    let analysis = experiment::analyze(&trace, &AnalysisSettings::default())?;
    let motion_law = Some(experiment::motion_law::law_of_motion(
        &motion, &light, &analysis,
    )?);
    Ok(Synthetic {
        trace,
        analysis,
        motion_law,
    })
}
