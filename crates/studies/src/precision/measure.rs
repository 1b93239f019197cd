//! One integration of a scene, measured: the solver's work, the median wall time of repeated
//! runs, the final state and (optionally) the state at fixed sample times.

use physics::dispatch::sliding_model;
use physics::dispatch::{dispatch, problem, Visit};
use physics::model::Model;
use physics::run::run_streamed;
use physics::run::sliding::{integrate, integrate_sampled};
use physics::scene::{ModelKind, Scene};
use physics::solve::{solve_with, Ending, Engine, Settings, SettingsError, Stats};
use serde::Serialize;
use std::time::Instant;

/// How long to time each integration: at least `min_runs` runs, then more until `budget_seconds`
/// of wall time have been spent or `max_runs` runs made. The median run is reported.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Timing {
    /// Fewest runs.
    pub min_runs: usize,
    /// Most runs.
    pub max_runs: usize,
    /// Wall time (s) after which no run is started once `min_runs` are done.
    pub budget_seconds: f64,
}

impl Timing {
    /// A single run: the time is then only indicative.
    pub const ONCE: Timing = Timing {
        min_runs: 1,
        max_runs: 1,
        budget_seconds: 0.0,
    };

    /// Runs `run` as this timing asks and returns the first run's result, the median wall time
    /// (s) of the runs and how many were made; the first error ends the runs.
    pub fn repeat<T, E>(
        &self,
        mut run: impl FnMut() -> Result<T, E>,
    ) -> Result<(T, f64, usize), E> {
        let started = Instant::now();
        let mut walls = Vec::new();
        let mut first = None;
        loop {
            let t = Instant::now();
            let out = run()?;
            walls.push(t.elapsed().as_secs_f64());
            first.get_or_insert(out);
            let n = walls.len();
            if n >= self.max_runs.max(1)
                || (n >= self.min_runs && started.elapsed().as_secs_f64() >= self.budget_seconds)
            {
                break;
            }
        }
        let runs = walls.len();
        Ok((first.expect("at least one run"), median(&mut walls), runs))
    }
}

impl Default for Timing {
    /// 3 to 21 runs within a quarter of a second.
    fn default() -> Self {
        Self {
            min_runs: 3,
            max_runs: 21,
            budget_seconds: 0.25,
        }
    }
}

/// One integration of a scene, measured.
#[derive(Debug, Clone, Serialize)]
pub struct Trace {
    /// The settings integrated with.
    pub settings: Settings,
    /// The work of the main pass (the sampled re-run's extra evaluations are not counted).
    pub stats: Stats,
    /// Why it ended.
    pub ending: Ending,
    /// The final time (s).
    pub t_final: f64,
    /// The final state.
    pub y_final: Vec<f64>,
    /// Sample times (s), when sampling was asked for; the last is the final time.
    pub sample_t: Vec<f64>,
    /// States at the sample times.
    #[serde(skip)]
    pub samples: Vec<Vec<f64>>,
    /// Median wall time of one integration (s), sampling excluded.
    pub wall_seconds: f64,
    /// How many timed runs the median is of.
    pub runs: usize,
    /// Relative change of the model's energy from start to end, $(E_{end} - E_0)/|E_0|$.
    pub energy_change: f64,
}

/// Integrates `scene` with `settings`, timed by `timing`; with `sample` = Some(dt), once more
/// sampled every `dt` seconds (untimed) for the error over the trajectory.
pub fn trace(
    scene: &Scene,
    settings: &Settings,
    sample: Option<f64>,
    timing: &Timing,
) -> Result<Trace, SettingsError> {
    trace_with(scene, settings, sample, timing, Engine::Own)
}

/// [`trace`] with a chosen DOP853 engine (the crate's own, or `ode_solvers`' for comparison).
pub fn trace_with(
    scene: &Scene,
    settings: &Settings,
    sample: Option<f64>,
    timing: &Timing,
    engine: Engine,
) -> Result<Trace, SettingsError> {
    if scene.model == ModelKind::Sliding {
        return trace_sliding(scene, settings, sample, timing);
    }
    dispatch(
        scene,
        TraceJob {
            settings,
            sample,
            timing,
            engine,
        },
    )
}

struct TraceJob<'a> {
    settings: &'a Settings,
    sample: Option<f64>,
    timing: &'a Timing,
    engine: Engine,
}

impl Visit for TraceJob<'_> {
    type Out = Result<Trace, SettingsError>;

    fn visit<M: Model<N>, const N: usize>(self, model: &M, scene: &Scene) -> Self::Out {
        let y0 = model.state(&scene.start);
        let t_end = scene.stop.time;
        let (sol, wall_seconds, runs) = self
            .timing
            .repeat(|| solve_with(problem(model, scene, y0, t_end), self.settings, self.engine))?;
        let (t_final, y_end) = sol.last();
        let (mut sample_t, mut samples) = (Vec::new(), Vec::new());
        if let Some(dt) = self.sample {
            // Re-integrated samples, so that they lie on the timed run's steps: dense samples
            // integrate at tightened tolerances (`Problem::dense_samples`), another run.
            let mut p = problem(model, scene, y0, t_end).sampled(dt);
            p.dense_samples = false;
            let s = solve_with(p, self.settings, self.engine)?;
            debug_assert_eq!(s.stats.evaluations, sol.stats.evaluations);
            sample_t = s.t;
            samples = s.y.iter().map(|y| y.iter().copied().collect()).collect();
        }
        let e0 = model.energy(&y0);
        Ok(Trace {
            settings: *self.settings,
            stats: sol.stats,
            ending: sol.ending,
            t_final,
            y_final: y_end.iter().copied().collect(),
            sample_t,
            samples,
            wall_seconds,
            runs,
            energy_change: (model.energy(&y_end) - e0) / e0.abs(),
        })
    }
}

/// The median wall time (s) of `scene` run as `simulate` runs it (its samples and recorded
/// quantities, rows discarded as they are made), with `settings`, timed by `timing`: what a
/// user pays for the run, sampling included.
pub fn recorded_wall(
    scene: &Scene,
    settings: &Settings,
    timing: &Timing,
) -> Result<f64, SettingsError> {
    let mut scene = scene.clone();
    scene.settings = *settings;
    let (_, wall_seconds, _) = timing.repeat(|| {
        let mut rows = 0u64;
        let mut sink = |row: &[f64]| rows += std::hint::black_box(row).len() as u64;
        run_streamed(&scene, None, &mut sink)
    })?;
    Ok(wall_seconds)
}

/// [`trace`] of a sliding scene: the whole run through the hybrid driver, its switches between
/// rolling, slipping and flight located as events, as `simulate` runs it (the engine is the
/// hybrid driver's).
fn trace_sliding(
    scene: &Scene,
    settings: &Settings,
    sample: Option<f64>,
    timing: &Timing,
) -> Result<Trace, SettingsError> {
    let mut scene = scene.clone();
    scene.settings = *settings;
    let model = sliding_model(&scene);
    let (sol, wall_seconds, runs) = timing.repeat(|| integrate(&model, &scene, None))?;
    let last = sol.y.len() - 1;
    let (t_final, y_end) = (sol.t[last], sol.y[last]);
    let (mut sample_t, mut samples) = (Vec::new(), Vec::new());
    if let Some(dt) = sample {
        // Re-integrated samples, on the timed run's steps (see `TraceJob`).
        let s = integrate_sampled(&model, &scene, Some(dt), false)?;
        // A jump repeats its time: the state after it stands for that time.
        for (t, y) in s.t.iter().zip(&s.y) {
            if sample_t.last() == Some(t) {
                samples.pop();
                sample_t.pop();
            }
            sample_t.push(*t);
            samples.push(y.iter().copied().collect());
        }
    }
    let start = model.enter_contact(&model.start_state(&scene.start)).1;
    let e0 = model.energy(&start);
    Ok(Trace {
        settings: *settings,
        stats: sol.stats,
        ending: sol.ending,
        t_final,
        y_final: y_end.iter().copied().collect(),
        sample_t,
        samples,
        wall_seconds,
        runs,
        energy_change: (model.energy(&y_end) - e0) / e0.abs(),
    })
}

/// The median of `xs` (sorted in place); NaN when empty.
pub(crate) fn median(xs: &mut [f64]) -> f64 {
    if xs.is_empty() {
        return f64::NAN;
    }
    xs.sort_by(f64::total_cmp);
    let n = xs.len();
    if n % 2 == 1 {
        xs[n / 2]
    } else {
        0.5 * (xs[n / 2 - 1] + xs[n / 2])
    }
}
