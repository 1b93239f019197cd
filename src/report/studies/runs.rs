//! The scene runs the figures draw: the path scenes (rolling in a circle, the nutating coin)
//! and the single run of the built-in spin-down (eqs 23-25 with eq 75's power as a torque),
//! which records $\alpha$, $\dot\alpha$ and the path so that the spin-down figure and the path
//! figure's third panel read the same run.

use crate::figures::path::{PathRun, SCENES};
use crate::figures::spin_down::SpinDown;
use crate::model::Quantity;
use crate::report::error::ReportError;
use crate::run::run;
use crate::scene::Scene;
use crate::solve::Ending;

/// A built-in scene with `extra` quantities recorded too.
fn scene_recording(name: &str, extra: &[Quantity]) -> Result<Scene, ReportError> {
    let mut scene = Scene::load(name).map_err(|e| ReportError::Input(e.to_string()))?;
    for q in extra {
        if !scene.record.contains(q) {
            scene.record.push(*q);
        }
    }
    Ok(scene)
}

/// The path scenes of the figure but the spin-down (which [`spin_down`] runs), in parallel,
/// in the figure's order.
pub fn paths() -> Result<Vec<PathRun>, ReportError> {
    use rayon::prelude::*;
    SCENES
        .par_iter()
        .filter(|(name, _)| *name != "spin-down")
        .map(|(name, _)| {
            let scene = scene_recording(name, &[Quantity::Path])?;
            let r = run(&scene, None).map_err(|e| ReportError::Input(e.to_string()))?;
            Ok(PathRun::from_run(&r)?)
        })
        .collect()
}

/// How often the spin-down is sampled (s). The path figure draws one loop of the centre at
/// 5, 50, 90 and 99 % of the run; the last of these, about 0.14 s before the end, has
/// $\alpha \approx 0.014$ rad and, with $\Omega \approx \sqrt{g/(a k \alpha)}$ (steady motion at
/// small tilt), a period near 23 ms: 0.5 ms gives it some 46 points, where the solver's own
/// steps drew 7-point polygons (27,000 rows for the 13.6 s run; finer sampling cost seconds).
pub const SPIN_DOWN_SAMPLE: f64 = 5e-4;

/// The one run of the built-in spin-down scene, to its stopping event, sampled every
/// [`SPIN_DOWN_SAMPLE`].
pub fn spin_down() -> Result<SpinDown, ReportError> {
    let mut scene = scene_recording(
        "spin-down",
        &[Quantity::Alpha, Quantity::AlphaDot, Quantity::Path],
    )?;
    scene.sample = Some(SPIN_DOWN_SAMPLE);
    let law = scene
        .dissipation
        .ok_or("the spin-down scene has no dissipation")?;
    let r = run(&scene, None).map_err(|e| ReportError::Input(e.to_string()))?;
    let t_stop = match &r.ending {
        Ending::Event { t, .. } => *t,
        other => return Err(format!("the spin-down did not end: {other}").into()),
    };
    let d = scene.disk;
    Ok(SpinDown {
        run: r,
        t_stop,
        beta: law.beta,
        epsilon: law.epsilon,
        g_ak: d.g / (d.a * d.k),
    })
}
