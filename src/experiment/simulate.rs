//! The synthetic experiment: the dissipative spin-down (eq 75 as a torque on eqs 23-25),
//! integrated with the heading so that the face normal is known, seen through a [`LightModel`].

use crate::experiment::error::ExperimentError;
use crate::experiment::light::LightModel;
use crate::experiment::trace::{Trace, Truth};
use crate::model::rolling::Rolling;
use crate::model::{Extras, Model};
use crate::scene::{ModelKind, Scene};
use crate::solve::{solve, Ending, Event, Problem, Solution, State};

/// States: the core four and the heading.
const N: usize = 5;
/// Index of the heading in the state.
const HEADING: usize = 4;

/// Simulates the scope trace of a dissipative scene.
///
/// The scene's model must be `dissipative`, and its stop must end the spin-down: `alpha_below`
/// (the floor $\alpha_{min}$) and/or `lift_off`. Three integrations through [`solve`]: one to
/// find when the spin-down ends ($t_{stop}$), one to the start of the record,
/// $t_{stop}$ minus the scope's `end_at`, and one sampled at the scope's rate from there to
/// $t_{stop}$. After $t_{stop}$ the disk lies flat and the signal is constant. The truth's $t_0$
/// is defined in [`Truth`].
pub fn simulate_trace(scene: &Scene, light: &LightModel) -> Result<Trace, ExperimentError> {
    let scene_err = |message: String| ExperimentError::Scene {
        scene: scene.name.clone(),
        message,
    };
    light.validate().map_err(ExperimentError::Setting)?;
    if scene.model != ModelKind::Dissipative {
        return Err(scene_err(format!(
            "the experiment needs a spinning-down disk: model must be dissipative, not {}",
            scene.model
        )));
    }
    let law = scene
        .dissipation
        .ok_or_else(|| scene_err("a dissipative scene needs a dissipation law".into()))?;
    if scene.stop.alpha_below.is_none() && !scene.stop.lift_off {
        return Err(scene_err(
            "the spin-down must end inside the record: add stop.alpha_below (e.g. 1.0e-4) or \
             stop.lift_off: true"
                .into(),
        ));
    }
    let extras = Extras {
        heading: true,
        path: false,
        face: false,
    };
    let model = Rolling::<N>::new(scene.disk, extras, Some(law));
    let y0 = model.state(&scene.start);
    let stopped = |t0: f64, y0: State<N>, t_end: f64, sample: Option<f64>| {
        let mut p = Problem::new(&model, t0, y0, t_end);
        if let Some(b) = scene.stop.alpha_below {
            p = p.stop_when(Event::new("alpha_min", move |y: &State<N>| y[0] - b));
        }
        if scene.stop.lift_off {
            p = p.stop_when(Event::new("lift-off", |y: &State<N>| {
                let mut f = Vec::with_capacity(1);
                model.record(y, crate::model::Quantity::NormalForce, &mut f);
                f[0]
            }));
        }
        if let Some(dt) = sample {
            p = p.sampled(dt);
        }
        solve(p, &scene.settings).map_err(|e| scene_err(e.to_string()))
    };
    let ended = |s: &Solution<N>| -> Result<f64, ExperimentError> {
        match &s.ending {
            Ending::Event { t, .. } => Ok(*t),
            other => Err(scene_err(format!(
                "the spin-down did not end ({other}); raise stop.time or alpha_below"
            ))),
        }
    };

    // 1. When does the spin-down end?
    let first = stopped(0.0, y0, scene.stop.time, None)?;
    let t_stop = ended(&first)?;
    let scope = &light.scope;
    let t_start = t_stop - scope.end_at;
    if t_start <= 0.0 {
        return Err(scene_err(format!(
            "the spin-down lasts {t_stop:.3} s, but the record starts {} s before its end: \
             start at a larger alpha0 or lower epsilon",
            scope.end_at
        )));
    }
    // 2. The state at the start of the record.
    let to_start = solve(Problem::new(&model, 0.0, y0, t_start), &scene.settings)
        .map_err(|e| scene_err(e.to_string()))?;
    let (_, y_start) = to_start.last();
    // 3. Sampled from there to the end.
    let dt = scope.dt();
    let run = stopped(t_start, y_start, t_stop + 1.0, Some(dt))?;
    let t_end = ended(&run)?;
    let (_, y_end) = run.last();

    let times = scope.times();
    let flat = light.intensity(0.0, 0.0);
    let mut v: Vec<f64> = vec![flat; times.len()];
    // The last point of a sampled solution is the event, off the grid: skip it.
    let on_grid = run.t.len().saturating_sub(1);
    for (j, y) in run.y.iter().take(on_grid.min(v.len())).enumerate() {
        v[j] = light.intensity(y[0], y[HEADING]);
    }
    scope.record(&mut v);

    let beta = law.beta;
    let tau_rem = 2.0 * y_end[0] / ((beta + 2.0) * y_end[1].abs().max(f64::MIN_POSITIVE));
    let t_stop_rec = t_end - t_start;
    Ok(Trace {
        source: format!("synthetic:{}", scene.name),
        t: times,
        v,
        truth: Some(Truth {
            beta,
            t0: t_stop_rec + tau_rem,
            t_stop: t_stop_rec,
            tau_rem,
            c: None,
            origin: format!(
                "dissipative model, beta = {beta}, epsilon = {}, scene {}",
                law.epsilon, scene.name
            ),
        }),
    })
}
