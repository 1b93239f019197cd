//! The work-precision diagram of a scene: error against work for every method.
//!
//! - RK4 over a sweep of fixed steps $h = T/n$, $n = 2^{8+j}$, $j = 0..8$ (powers of two: see
//!   [`super::reference`] on RK4's time);
//! - DOPRI5 and DOP853 over $\mathrm{rtol} = 10^{-3}, \dots, 10^{-13}$ with
//!   $\mathrm{atol} = 10^{-2}\,\mathrm{rtol}$ (the scenes' states are of order 0.1 to 10 in SI
//!   units, so the relative tolerance governs).
//!
//! **Observed order.** A method of order $p$ has a global error $e \propto h^p$. The number of
//! right-hand-side evaluations $W$ is proportional to the number of steps, $W \propto 1/h$ (for
//! the adaptive methods, $1/\bar h$ with $\bar h$ the mean step), so $e \propto W^{-p}$ and the
//! order in the step size is minus the slope of $\log e$ against $\log W$, fitted by least
//! squares over the points whose error lies between $10^{-2}$ (beyond it the asymptotic regime
//! has not begun) and 100 times the reference's uncertainty (below it the reference and the
//! round-off floor take over). Nominal orders: RK4 4, DOPRI5 5, DOP853 8.

use super::measure::{recorded_wall, trace_with, Timing};
use super::reference::{label, Reference, ReferenceOptions};
use crate::error::StudyError;
use numerics::fit::log_log_slope;
use physics::scene::Scene;
use physics::solve::{Ending, Engine, Method, Settings, SettingsError};
use serde::Serialize;

/// What to measure.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StudyOptions {
    /// RK4 step counts over the scene's time span.
    pub rk4_steps: Vec<u32>,
    /// Relative tolerances for DOPRI5 and DOP853.
    pub rtols: Vec<f64>,
    /// `atol` = `atol_per_rtol` * `rtol`.
    pub atol_per_rtol: f64,
    /// How each point is timed.
    pub timing: Timing,
    /// The reference.
    pub reference: ReferenceOptions,
}

impl Default for StudyOptions {
    fn default() -> Self {
        Self {
            rk4_steps: (0..9).map(|j| 256 << j).collect(),
            rtols: (3..=13).map(|e| 10f64.powi(-e)).collect(),
            atol_per_rtol: 1e-2,
            timing: Timing::default(),
            reference: ReferenceOptions::default(),
        }
    }
}

impl StudyOptions {
    /// A coarse sweep timed once: for tests and quick looks (the times are only indicative).
    pub fn quick() -> Self {
        Self {
            rk4_steps: (0..5).map(|j| 256 << (2 * j)).collect(),
            rtols: vec![1e-3, 1e-5, 1e-7, 1e-9, 1e-11, 1e-13],
            timing: Timing::ONCE,
            ..Self::default()
        }
    }
}

/// One point of the diagram.
#[derive(Debug, Clone, Serialize)]
pub struct Point {
    /// The method.
    pub method: Method,
    /// "rk4 h 4.000e-2", "dop853 rtol 1e-10".
    pub label: String,
    /// The full settings.
    pub settings: Settings,
    /// Right-hand-side evaluations of the main pass.
    pub evaluations: u64,
    /// Accepted steps.
    pub accepted: u64,
    /// Rejected steps.
    pub rejected: u64,
    /// Median wall time of one integration (s).
    pub wall_seconds: f64,
    /// Median wall time (s) of the same run sampled at the scene's rate with its quantities
    /// recorded, as `simulate` runs it: what a user pays (None for the `ode_solvers` engine).
    pub sampled_wall_seconds: Option<f64>,
    /// Error at the final time.
    pub final_error: f64,
    /// Largest error over the sample times.
    pub trajectory_error: f64,
    /// Relative energy change from start to end.
    pub energy_change: f64,
    /// Why the run ended.
    pub ending: Ending,
}

/// All points of one method, with its observed order.
#[derive(Debug, Clone, Serialize)]
pub struct Series {
    /// The method.
    pub method: Method,
    /// Its nominal order $p$.
    pub nominal_order: u32,
    /// The observed order in the step size (see the module docs), when at least three points
    /// lie in the fitting window.
    pub observed_order: Option<f64>,
    /// How many points the fit used.
    pub fitted_points: usize,
    /// The points, from the cheapest to the most expensive.
    pub points: Vec<Point>,
}

/// A scene's work-precision study.
#[derive(Debug, Clone, Serialize)]
pub struct Study {
    /// The scene's name.
    pub scene: String,
    /// The reference and its validation.
    pub reference: Reference,
    /// One series per method.
    pub series: Vec<Series>,
}

/// The nominal order of a method.
pub fn nominal_order(m: Method) -> u32 {
    match m {
        Method::Rk4 => 4,
        Method::Dopri5 => 5,
        Method::Dop853 => 8,
    }
}

/// Measures the work-precision diagram of `scene`.
pub fn study(scene: &Scene, opts: &StudyOptions) -> Result<Study, SettingsError> {
    study_with_progress(scene, opts, &|_, _, _| {})
}

/// [`study`], calling `progress(done, total, what)` after the reference and after each point
/// (`total` counts the reference as one), so a long run can say where it is.
pub fn study_with_progress(
    scene: &Scene,
    opts: &StudyOptions,
    progress: &dyn Fn(usize, usize, &str),
) -> Result<Study, SettingsError> {
    let total = 1 + opts.rk4_steps.len() + 2 * opts.rtols.len();
    let reference = Reference::compute(scene, &opts.reference)?;
    progress(1, total, "reference");
    let mut done = 1;
    let span = scene.stop.time;
    let base = Settings {
        max_steps: scene.settings.max_steps,
        ..Settings::default()
    };
    let mut series = Vec::new();
    let rk4: Vec<Settings> = opts
        .rk4_steps
        .iter()
        .map(|&n| Settings {
            method: Method::Rk4,
            step: span / f64::from(n),
            max_steps: base.max_steps.max(n + 1),
            ..base
        })
        .collect();
    let adaptive = |method| -> Vec<Settings> {
        opts.rtols
            .iter()
            .map(|&rtol| Settings {
                method,
                rtol,
                atol: rtol * opts.atol_per_rtol,
                ..base
            })
            .collect()
    };
    for (method, sweep) in [
        (Method::Rk4, rk4),
        (Method::Dopri5, adaptive(Method::Dopri5)),
        (Method::Dop853, adaptive(Method::Dop853)),
    ] {
        let mut points = Vec::new();
        for s in sweep {
            let p = measure_point(scene, &s, &reference, &opts.timing)?;
            done += 1;
            progress(done, total, &p.label);
            points.push(p);
        }
        points.sort_by_key(|p| p.evaluations);
        let (observed_order, fitted_points) = observed_order(&points, reference.uncertainty);
        series.push(Series {
            method,
            nominal_order: nominal_order(method),
            observed_order,
            fitted_points,
            points,
        });
    }
    Ok(Study {
        scene: scene.name.clone(),
        reference,
        series,
    })
}

/// Measures one point against the reference.
pub fn measure_point(
    scene: &Scene,
    settings: &Settings,
    reference: &Reference,
    timing: &Timing,
) -> Result<Point, SettingsError> {
    measure_point_with(scene, settings, reference, timing, Engine::Own)
}

/// [`measure_point`] with a chosen DOP853 engine.
pub fn measure_point_with(
    scene: &Scene,
    settings: &Settings,
    reference: &Reference,
    timing: &Timing,
    engine: Engine,
) -> Result<Point, SettingsError> {
    let t = trace_with(
        scene,
        settings,
        Some(reference.sample_every),
        timing,
        engine,
    )?;
    let (final_error, trajectory_error) = reference.errors(&t);
    Ok(Point {
        method: settings.method,
        label: label(settings),
        settings: *settings,
        evaluations: t.stats.evaluations,
        accepted: t.stats.accepted,
        rejected: t.stats.rejected,
        wall_seconds: t.wall_seconds,
        sampled_wall_seconds: match engine {
            Engine::Own => Some(recorded_wall(scene, settings, timing)?),
            Engine::OdeSolvers => None,
        },
        final_error,
        trajectory_error,
        energy_change: t.energy_change,
        ending: t.ending,
    })
}

/// Minus the slope of log(final error) against log(evaluations) over the fitting window
/// $(100\,u, 10^{-2})$, with $u$ the reference's uncertainty; None with fewer than 3 points.
pub fn observed_order(points: &[Point], uncertainty: f64) -> (Option<f64>, usize) {
    let floor = (100.0 * uncertainty).max(1e-300);
    let (x, y): (Vec<f64>, Vec<f64>) = points
        .iter()
        .filter(|p| p.ending.is_complete() && p.final_error > floor && p.final_error < 1e-2)
        .map(|p| (p.evaluations as f64, p.final_error))
        .unzip();
    if x.len() < 3 {
        return (None, x.len());
    }
    (Some(-log_log_slope(&x, &y)), x.len())
}

/// What "cheapest" means.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Cost {
    /// Fewest right-hand-side evaluations (deterministic).
    Evaluations,
    /// Least median wall time (what a user waits for).
    WallTime,
}

/// The cheapest point of the study whose error over the whole trajectory is at most `target`
/// (and which completed). None when no measured point reaches it; then the target is below what
/// the measured settings reach, or below the reference's uncertainty, which no point can be
/// shown to beat.
pub fn cheapest(study: &Study, target: f64, by: Cost) -> Option<&Point> {
    if target < study.reference.uncertainty {
        return None;
    }
    study
        .series
        .iter()
        .flat_map(|s| &s.points)
        .filter(|p| p.ending.is_complete() && p.trajectory_error <= target)
        .min_by(|a, b| match by {
            Cost::Evaluations => a.evaluations.cmp(&b.evaluations),
            Cost::WallTime => a.wall_seconds.total_cmp(&b.wall_seconds),
        })
}

/// The study the report shows: the built-in benchmark scene, quick options, timed once.
pub fn benchmark_study() -> Result<Study, StudyError> {
    let scene = Scene::load("benchmark")?;
    let mut opts = StudyOptions::quick();
    opts.timing = Timing::ONCE;
    Ok(study(&scene, &opts)?)
}
