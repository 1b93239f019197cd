//! The lab-frame study: the paper's reduced equations of motion (eqs 23-25, four states) and
//! the independent Newton-Euler model in lab coordinates (thirteen states) integrated from the
//! same start by DOP853 at rtol 1e-12, atol 1e-14, sampled at the same times.

use crate::error::StudyError;
use physics::model::lab_frame::{Contact, LabFrame};
use physics::model::rolling::Rolling;
use physics::model::{Extras, Model, Motion};
use physics::scene::Scene;
use physics::solve::{solve, Problem, Settings, Solution};

/// The two panels' scenes, with how often (s) the two models are compared on each.
pub const SCENES: [(&str, f64); 2] = [("nutating-coin", 0.002), ("wheel-straight", 0.01)];

/// One scene integrated by the reduced (eqs 23-25) and by the lab-frame model, sampled at the
/// same times (computed by [`compute`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Compared {
    /// The scene's name.
    pub scene: String,
    /// Sample times (s).
    pub t: Vec<f64>,
    /// The paper's variables from the reduced model.
    pub reduced: Vec<Motion>,
    /// The same from the lab-frame model.
    pub lab: Vec<Motion>,
}

/// Both models integrated from `scene`'s start, sampled every `every` seconds.
fn both(scene: &Scene, every: f64) -> Result<Compared, StudyError> {
    let settings = Settings::dop853(1e-12, 1e-14);
    let reduced = Rolling::<4>::new(scene.disk, Extras::default(), None);
    let lab = LabFrame::new(scene.disk, Contact::Rolling);
    let t_end = scene.stop.time;
    let a: Solution<4> = solve(
        Problem::new(&reduced, 0.0, reduced.state(&scene.start), t_end).sampled(every),
        &settings,
    )?;
    let b: Solution<13> = solve(
        Problem::new(
            &lab,
            0.0,
            lab.state_from(&scene.start, 0.0, [0.0, 0.0], 0.0),
            t_end,
        )
        .sampled(every),
        &settings,
    )?;
    if !(a.ending.is_complete() && b.ending.is_complete()) {
        return Err(format!(
            "{}: the integrations did not finish (reduced: {}; lab frame: {})",
            scene.name, a.ending, b.ending
        )
        .into());
    }
    let n = a.t.len().min(b.t.len());
    Ok(Compared {
        scene: scene.name.clone(),
        t: a.t[..n].to_vec(),
        reduced: a.y[..n].iter().map(|y| reduced.motion(y)).collect(),
        lab: b.y[..n].iter().map(|y| lab.motion(y)).collect(),
    })
}

/// The scenes of the lab-frame figure, compared in parallel, in the figure's order.
pub fn compute() -> Result<Vec<Compared>, StudyError> {
    use rayon::prelude::*;
    SCENES
        .par_iter()
        .map(|(name, every)| {
            let scene = Scene::load(name)?;
            both(&scene, *every)
        })
        .collect()
}
