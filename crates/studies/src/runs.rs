//! The scene runs the figures draw: the path scenes (rolling in a circle, the nutating coin)
//! and the single run of the built-in spin-down (eqs 23-25 with eq 75's power as a torque),
//! which records $\alpha$, $\dot\alpha$ and the path so that the spin-down figure and the path
//! figure's third panel read the same run.

use crate::error::StudyError;
use physics::model::Quantity;
use physics::run::{run, Run};
use physics::scene::Scene;
use physics::solve::Ending;

/// The scenes of the figure's panels, left to right, with a short description of each. The
/// run of each (recording the path) is computed by the report's pipeline.
pub const SCENES: [(&str, &str); 3] = [
    ("rolling-circle", "rolling in a circle"),
    ("nutating-coin", "nutating coin"),
    ("spin-down", "spin-down (eq 75)"),
];

/// A scene's path: the times and (x, y) of the centre of mass (m), and how the run ended.
#[derive(Debug, Clone, PartialEq)]
pub struct PathRun {
    /// The scene's name.
    pub scene: String,
    /// Sample times (s).
    pub t: Vec<f64>,
    /// The centre of mass in the plane (m).
    pub xy: Vec<(f64, f64)>,
    /// How the run ended, in words.
    pub ending: String,
}

impl PathRun {
    /// The path read from a run that recorded it (columns `x_m`, `y_m`).
    pub fn from_run(r: &Run) -> Result<PathRun, StudyError> {
        let missing = |c: &str| format!("the run of {} did not record {c}", r.scene);
        let x = r.column("x_m").ok_or_else(|| missing("x_m"))?;
        let y = r.column("y_m").ok_or_else(|| missing("y_m"))?;
        let t = r.column("t_s").ok_or_else(|| missing("t_s"))?;
        if t.is_empty() {
            return Err(format!("the run of {} recorded no samples", r.scene).into());
        }
        Ok(PathRun {
            scene: r.scene.clone(),
            t,
            xy: x.into_iter().zip(y).collect(),
            ending: r.ending.to_string(),
        })
    }
}

/// The one run of the built-in spin-down scene (recording $\alpha$, $\dot\alpha$ and the path)
/// and the constants of its law: computed once by the report's pipeline and read by this figure
/// and by the path figure's third panel.
#[derive(Debug, Clone)]
pub struct SpinDown {
    /// The run.
    pub run: Run,
    /// Its path in the plane (the path figure's last panel).
    pub path: PathRun,
    /// When it stopped (the event's time, s).
    pub t_stop: f64,
    /// The dissipation law's exponent $\beta$ (eq 75).
    pub beta: f64,
    /// Its constant $\epsilon$ (eq 75).
    pub epsilon: f64,
    /// $g/(a k)$ of the disk (1/s^2).
    pub g_ak: f64,
}

/// A built-in scene with `extra` quantities recorded too.
fn scene_recording(name: &str, extra: &[Quantity]) -> Result<Scene, StudyError> {
    let mut scene = Scene::load(name)?;
    for q in extra {
        if !scene.record.contains(q) {
            scene.record.push(*q);
        }
    }
    Ok(scene)
}

/// The path scenes of the figure but the spin-down (which [`spin_down`] runs), in parallel,
/// in the figure's order.
pub fn paths() -> Result<Vec<PathRun>, StudyError> {
    use rayon::prelude::*;
    SCENES
        .par_iter()
        .filter(|(name, _)| *name != "spin-down")
        .map(|(name, _)| {
            let scene = scene_recording(name, &[Quantity::Path])?;
            let r = run(&scene, None)?;
            PathRun::from_run(&r)
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
pub fn spin_down() -> Result<SpinDown, StudyError> {
    let mut scene = scene_recording(
        "spin-down",
        &[Quantity::Alpha, Quantity::AlphaDot, Quantity::Path],
    )?;
    scene.sample = Some(SPIN_DOWN_SAMPLE);
    let law = scene
        .dissipation
        .ok_or("the spin-down scene has no dissipation")?;
    let r = run(&scene, None)?;
    let t_stop = match &r.ending {
        Ending::Event { t, .. } => *t,
        other => return Err(format!("the spin-down did not end: {other}").into()),
    };
    let d = scene.disk;
    Ok(SpinDown {
        path: PathRun::from_run(&r)?,
        run: r,
        t_stop,
        beta: law.beta,
        epsilon: law.epsilon,
        g_ak: d.g / (d.a * d.k),
    })
}
