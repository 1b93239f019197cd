//! The synthetic experiment: the dissipative spin-down (eq 75 as a torque on eqs 23-25),
//! integrated with the heading so that the face normal is known, seen through a [`LightModel`];
//! or the same spin-down in the sliding model (Coulomb friction, lift-off and landing; see
//! [`sliding_motion`]).

use crate::error::ExperimentError;
use crate::synthetic::light::LightModel;
use crate::synthetic::sliding_record::sliding_motion;
use crate::trace::{Motion, Trace, Truth};
use physics::model::rolling::Rolling;
use physics::model::{Extras, Model};
use physics::scene::Scene;
use physics::solve::{solve, Ending, Event, Problem, Solution, State};

/// States: the core four and the heading.
const N: usize = 5;
/// Index of the heading in the state.
const HEADING: usize = 4;

/// Simulates the scope trace of a dissipative scene.
///
/// The scene's model must be `dissipative` or `sliding` (with `dissipation`), and its stop must
/// end the spin-down: `alpha_below`
/// (the floor $\alpha_{min}$) and/or `lift_off`. Three integrations through [`solve`]: one to
/// find when the spin-down ends ($t_{stop}$), one to the start of the record,
/// $t_{stop}$ minus the scope's `end_at`, and one sampled at the scope's rate from there to
/// $t_{stop}$. After $t_{stop}$ the disk lies flat and the signal is constant. The truth's $t_0$
/// is defined in [`Truth`].
pub fn simulate_trace(scene: &Scene, light: &LightModel) -> Result<Trace, ExperimentError> {
    light.validate()?;
    let scope = &light.scope;
    let m = simulate_motion(scene, scope.end_at, scope.sample_rate, scope.samples)?;
    Ok(trace_of_motion(&m, light, &scene.name))
}

/// The scope trace of a simulated motion (sampled at the light's scope rate) seen through
/// `light`; `name` is the scene's.
pub fn trace_of_motion(m: &Motion, light: &LightModel, name: &str) -> Trace {
    let scope = &light.scope;
    let flat = light.intensity(0.0, 0.0);
    let mut v: Vec<f64> = m
        .alpha
        .iter()
        .zip(&m.heading)
        .map(|(&a, &h)| {
            if a.is_nan() {
                flat
            } else {
                light.intensity(a, h)
            }
        })
        .collect();
    scope.record(&mut v);
    Trace {
        source: format!("synthetic:{name}"),
        t: m.t.clone(),
        v,
        truth: Some(m.truth.clone()),
    }
}

/// Integrates a dissipative or sliding scene and samples its tilt and heading at `rate` for `samples`
/// samples, the spin-down ending at record time `end_at` (see [`simulate_trace`]).
pub fn simulate_motion(
    scene: &Scene,
    end_at: f64,
    rate: f64,
    samples: usize,
) -> Result<Motion, ExperimentError> {
    let scene_err = |message: String| ExperimentError::in_scene(&scene.name, message);
    if !(rate.is_finite() && rate > 0.0 && end_at.is_finite() && end_at > 0.0) {
        return Err(scene_err(format!(
            "the record needs a positive sample rate and end time, got {rate} S/s and {end_at} s"
        )));
    }
    if !scene.model.spins_down_in_motion() {
        return Err(scene_err(format!(
            "the experiment needs a spinning-down disk: model must be dissipative (rolling) or \
             sliding (with friction), not {}",
            scene.model
        )));
    }
    // The trace's truth (beta, t0) is eq 75's law; mechanisms would add torques it does not
    // describe.
    if !scene.mechanisms.is_empty() {
        return Err(scene_err(
            "the experiment's synthetic record follows eq 75's law alone: remove `mechanisms` \
             (the mechanisms' spin-downs are in the report's friction section)"
                .into(),
        ));
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
    if scene.model.has_coulomb_friction() {
        return sliding_motion(scene, law, end_at, rate, samples);
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
                model.record(y, physics::model::Quantity::NormalForce, &mut f);
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
    let t_start = t_stop - end_at;
    if t_start <= 0.0 {
        return Err(scene_err(format!(
            "the spin-down lasts {t_stop:.3} s, but the record starts {} s before its end: \
             start at a larger alpha0 or lower epsilon",
            end_at
        )));
    }
    // 2. The state at the start of the record.
    let to_start = solve(Problem::new(&model, 0.0, y0, t_start), &scene.settings)
        .map_err(|e| scene_err(e.to_string()))?;
    let (_, y_start) = to_start.last();
    // 3. Sampled from there to the end: every sample, or every `stride`-th where that would
    // record more rows than the solver keeps, the samples between interpolated.
    let dt = 1.0 / rate;
    let rows = (t_stop + 1.0 - t_start) * rate;
    let stride = (rows / (0.9 * physics::budget::MAX_ROWS as f64))
        .ceil()
        .max(1.0) as usize;
    let run = stopped(t_start, y_start, t_stop + 1.0, Some(stride as f64 * dt))?;
    let t_end = ended(&run)?;
    let (_, y_end) = run.last();

    let times: Vec<f64> = (0..samples).map(|j| j as f64 * dt).collect();
    // The last point of a sampled solution is the event, off the grid: skip it.
    let on_grid = run.t.len().saturating_sub(1);
    let coarse = |k: usize| -> Vec<f64> { run.y[..on_grid].iter().map(|y| y[k]).collect() };
    let alpha = between(&coarse(0), stride, samples);
    let heading = between(&coarse(HEADING), stride, samples);

    Ok(Motion {
        t: times,
        alpha,
        heading,
        truth: Truth::at_stop(
            law.beta,
            t_end - t_start,
            y_end[0],
            y_end[1],
            format!(
                "dissipative model, beta = {}, epsilon = {}, scene {}",
                law.beta, law.epsilon, scene.name
            ),
        ),
    })
}

/// `samples` values at every sample from `coarse`, known at every `stride`-th: the known ones
/// kept, those between by the cubic through the four nearest known ones (the two nearest at
/// the ends), NaN past the last known one. With `stride` 1, `coarse` itself.
fn between(coarse: &[f64], stride: usize, samples: usize) -> Vec<f64> {
    let n = coarse.len();
    (0..samples)
        .map(|j| {
            let (i, r) = (j / stride, j % stride);
            if r == 0 {
                return coarse.get(i).copied().unwrap_or(f64::NAN);
            }
            if i + 1 >= n {
                return f64::NAN;
            }
            let x = r as f64 / stride as f64;
            if i == 0 || i + 2 >= n {
                return coarse[i] + x * (coarse[i + 1] - coarse[i]);
            }
            // Lagrange's cubic through the known points at -1, 0, 1, 2 (in strides).
            let [a, b, c, d] = [coarse[i - 1], coarse[i], coarse[i + 1], coarse[i + 2]];
            -a * x * (x - 1.0) * (x - 2.0) / 6.0 + b * (x + 1.0) * (x - 1.0) * (x - 2.0) / 2.0
                - c * (x + 1.0) * x * (x - 2.0) / 2.0
                + d * (x + 1.0) * x * (x - 1.0) / 6.0
        })
        .collect()
}
