//! What one evaluation of the right-hand side costs, and how the energy drift grows on long runs.
//!
//! **Overhead.** A run's wall time $T$ is the cost of its $W$ right-hand-side evaluations,
//! $W\,c_f$, plus the solver's own work (error norms, step control, storing the steps). The
//! ratio $T / (W c_f)$ is 1 for a solver with no overhead; [`rhs_nanoseconds`] measures $c_f$
//! as the throughput of independent evaluations. A Runge-Kutta step cannot overlap its stages
//! (each argument needs the previous stage's result), so it pays the evaluation's latency,
//! [`rhs_latency_nanoseconds`], a little more; the overhead per evaluation is the time per
//! evaluation minus that.
//!
//! **Energy drift.** A conservative scene's energy $E$ (eq 26) is constant. After $n$ steps,
//! round-off alone moves it by about $\sqrt n\,\varepsilon$ relative if the errors of the steps
//! are independent (a random walk), up to $n\,\varepsilon$ if they are systematic
//! ($\varepsilon = 2^{-52}$); the truncation error of an adaptive method adds a drift that grows
//! linearly in time. [`energy_drift`] measures $|E(t) - E(0)|/|E(0)|$ at checkpoints and fits its
//! growth exponent $\gamma$ in $|\Delta E| \propto t^\gamma$ ($\frac12$: random walk, 1: linear).

use super::measure::median;
use super::PrecisionError;
use numerics::fit::log_log_slope;
use physics::dispatch::{dispatch, Visit};
use physics::model::Model;
use physics::scene::Scene;
use physics::solve::{onto_level, solve, Ending, Problem, Projection, Settings, State};
use serde::Serialize;
use std::f64::consts::PI;
use std::hint::black_box;
use std::time::Instant;

/// The median cost of one right-hand-side evaluation of `scene`'s model at its start state, in
/// nanoseconds (5 batches of 20 000 evaluations).
pub fn rhs_nanoseconds(scene: &Scene) -> f64 {
    dispatch(scene, RhsCost)
}

struct RhsCost;

impl Visit for RhsCost {
    type Out = f64;

    fn visit<M: Model<N>, const N: usize>(self, model: &M, scene: &Scene) -> f64 {
        let y0 = model.state(&scene.start);
        let mut dy = State::<N>::zeros();
        median_batch_nanoseconds(|| {
            model.rhs(black_box(&y0), &mut dy);
            black_box(&dy);
        })
    }
}

/// The median cost of one right-hand-side evaluation of `scene`'s model when each evaluation's
/// argument depends on the previous one's result, as a Runge-Kutta step's stages do, in
/// nanoseconds (5 batches of 20 000): the processor cannot overlap them, so this is their
/// latency, what an integration pays per evaluation.
pub fn rhs_latency_nanoseconds(scene: &Scene) -> f64 {
    dispatch(scene, RhsLatency)
}

struct RhsLatency;

impl Visit for RhsLatency {
    type Out = f64;

    fn visit<M: Model<N>, const N: usize>(self, model: &M, scene: &Scene) -> f64 {
        let y0 = model.state(&scene.start);
        let mut dy = State::<N>::zeros();
        median_batch_nanoseconds(|| {
            // Zero, but the compiler must compute it (0 * x is not 0 for every x), so the next
            // argument waits for this result.
            let mut y = y0;
            y[0] += 0.0 * dy[N - 1];
            model.rhs(black_box(&y), &mut dy);
            black_box(&dy);
        })
    }
}

/// The median over 5 batches of 20 000 calls of `once`, in nanoseconds per call.
fn median_batch_nanoseconds(mut once: impl FnMut()) -> f64 {
    const BATCH: u32 = 20_000;
    let mut ns: Vec<f64> = (0..5)
        .map(|_| {
            let t = Instant::now();
            for _ in 0..BATCH {
                once();
            }
            t.elapsed().as_secs_f64() * 1e9 / f64::from(BATCH)
        })
        .collect();
    median(&mut ns)
}

/// One checkpoint of a long run.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct DriftPoint {
    /// Time (s).
    pub t: f64,
    /// Precession periods elapsed.
    pub periods: f64,
    /// Accepted steps so far.
    pub steps: u64,
    /// $(E(t) - E(0)) / |E(0)|$.
    pub drift: f64,
}

/// The energy drift of a long run.
#[derive(Debug, Clone, Serialize)]
pub struct Drift {
    /// The scene.
    pub scene: String,
    /// The settings.
    pub settings: Settings,
    /// One precession period of the start, $2\pi/|\Omega(0)|$ (s).
    pub period_seconds: f64,
    /// The checkpoints.
    pub checkpoints: Vec<DriftPoint>,
    /// Largest $|E(t) - E(0)|/|E(0)|$ over the checkpoints.
    pub max_abs_drift: f64,
    /// Fitted $\gamma$ in $|\Delta E| \propto t^\gamma$ (None when the drift is zero throughout).
    pub growth_exponent: Option<f64>,
    /// $\sqrt n\,\varepsilon$ for the $n$ steps taken: round-off as a random walk.
    pub random_walk_bound: f64,
    /// $n\,\varepsilon$: round-off adding up systematically.
    pub linear_bound: f64,
    /// Right-hand-side evaluations.
    pub evaluations: u64,
    /// Wall time of the whole run (s).
    pub wall_seconds: f64,
    /// Why the run ended (the first chunk that did not complete ends it).
    pub ending: Ending,
}

/// Integrates a conservative scene over `periods` precession periods of its start in
/// `checkpoints` chunks (each restarted from the last state, so memory stays bounded; the
/// scene's stop events are ignored) and measures the drift of its energy. A scene with
/// `project: energy` is projected onto its start's energy after every step, always onto the
/// energy at the start (not each chunk's), so that the drift it shows is the projection's own.
pub fn energy_drift(
    scene: &Scene,
    settings: &Settings,
    periods: f64,
    checkpoints: u32,
) -> Result<Drift, PrecisionError> {
    if !scene.model.conserves_energy() || scene.model.is_lab_frame() {
        return Err(PrecisionError::NotConservative(scene.model));
    }
    let om = scene.start.precession.abs();
    if om == 0.0 || !om.is_finite() {
        return Err(PrecisionError::NoPrecession);
    }
    dispatch(
        scene,
        DriftJob {
            settings,
            period: 2.0 * PI / om,
            periods,
            checkpoints: checkpoints.max(1),
        },
    )
}

struct DriftJob<'a> {
    settings: &'a Settings,
    period: f64,
    periods: f64,
    checkpoints: u32,
}

impl Visit for DriftJob<'_> {
    type Out = Result<Drift, PrecisionError>;

    fn visit<M: Model<N>, const N: usize>(self, model: &M, scene: &Scene) -> Self::Out {
        let mut y = model.state(&scene.start);
        let e0 = model.energy(&y);
        let chunk = self.period * self.periods / f64::from(self.checkpoints);
        let (mut t, mut steps, mut evaluations) = (0.0, 0u64, 0u64);
        let mut checkpoints = Vec::new();
        let mut ending = Ending::TimeReached;
        let started = Instant::now();
        for i in 1..=self.checkpoints {
            let t_end = chunk * f64::from(i);
            let mut problem = Problem::new(model, t, y, t_end);
            if scene.projection == Some(Projection::Energy) {
                problem.project = Some(Box::new(move |y: &mut State<N>| {
                    onto_level(|y| model.energy(y), e0, y)
                }));
            }
            let sol = solve(problem, self.settings)?;
            steps += sol.stats.accepted;
            evaluations += sol.stats.evaluations;
            (t, y) = sol.last();
            checkpoints.push(DriftPoint {
                t,
                periods: t / self.period,
                steps,
                drift: (model.energy(&y) - e0) / e0.abs(),
            });
            if !sol.ending.is_complete() {
                ending = sol.ending;
                break;
            }
        }
        let wall_seconds = started.elapsed().as_secs_f64();
        let max_abs_drift = checkpoints
            .iter()
            .map(|c| c.drift.abs())
            .fold(0.0, f64::max);
        let (ts, ds): (Vec<f64>, Vec<f64>) =
            checkpoints.iter().map(|c| (c.t, c.drift.abs())).unzip();
        let gamma = log_log_slope(&ts, &ds);
        let n = steps as f64;
        Ok(Drift {
            scene: scene.name.clone(),
            settings: *self.settings,
            period_seconds: self.period,
            checkpoints,
            max_abs_drift,
            growth_exponent: gamma.is_finite().then_some(gamma),
            random_walk_bound: n.sqrt() * f64::EPSILON,
            linear_bound: n * f64::EPSILON,
            evaluations,
            wall_seconds,
            ending,
        })
    }
}
