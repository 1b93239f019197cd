//! The sampled side of `scripts/compare`, over a tolerance sweep, each run's error in $\alpha$
//! measured over every row against a reference sampled on the same grid, one row every
//! [`SAMPLE`] seconds, timed two ways so that each compares with a SciPy side doing the same
//! work:
//!
//! - the states alone at the rows, as `solve_ivp`'s `t_eval` returns them: the solver layer's
//!   sampled run (`physics::solve::solve`, the samples of each step evaluated together from its
//!   dense output and handed to a sink a batch at a time, then discarded), against `solve_ivp`
//!   with `t_eval`;
//! - the benchmark scene run as `simulate` runs it, with its recorded quantities (the state and
//!   the energy, the energy's largest change, the loss of contact looked for:
//!   [`physics::run::run_streamed_rows`], rows discarded), against `solve_ivp` with `t_eval`
//!   followed by the same quantities in numpy (`scripts/compare.py`).
//!
//! The two sides are compared at equal error in $\alpha$, sampling included on both.

use physics::dispatch::{dispatch, problem, Visit};
use physics::model::Model;
use physics::run::{run_streamed, run_streamed_rows};
use physics::scene::Scene;
use physics::solve::{solve, Batch, Method, Settings};
use serde_json::{json, Value};
use std::hint::black_box;
use std::time::Instant;
use studies::precision::Timing;

/// The sampling interval of both sides (s): 10,001 rows over the benchmark scene's 10 s.
pub const SAMPLE: f64 = 1e-3;

/// The reference's tolerances: DOP853 at rtol 1e-14, each row landed on by its own step
/// rather than interpolated, so that the reference carries no interpolant's error.
const REFERENCE_RTOL: f64 = 1e-14;

/// `scene` with its sampling and solver settings replaced.
fn sampled(scene: &Scene, settings: Settings) -> Scene {
    let mut s = scene.clone();
    s.sample = Some(SAMPLE);
    s.settings = settings;
    s
}

/// The times and $\alpha$ of every row of a run of `scene` (the scene records $\alpha$
/// first).
fn alpha_rows(scene: &Scene) -> (Vec<f64>, Vec<f64>) {
    let (mut t, mut alpha) = (Vec::new(), Vec::new());
    let mut sink = |row: &[f64]| {
        t.push(row[0]);
        alpha.push(row[1]);
    };
    run_streamed(scene, None, &mut sink).expect("the benchmark scene runs");
    (t, alpha)
}

/// The reference's $\alpha$ on the grid: each row landed on by the integration
/// (`Problem::dense_samples` off), at [`REFERENCE_RTOL`], atol 1e-2 rtol.
fn reference(scene: &Scene) -> (Vec<f64>, Vec<f64>) {
    use physics::solve::solve_with;
    struct Landed;
    impl Visit for Landed {
        type Out = (Vec<f64>, Vec<f64>);
        fn visit<M: Model<N>, const N: usize>(self, model: &M, scene: &Scene) -> Self::Out {
            let y0 = model.state(&scene.start);
            let mut p = problem(model, scene, y0, scene.stop.time).sampled(SAMPLE);
            p.dense_samples = false;
            let s = Settings::dop853(REFERENCE_RTOL, 1e-2 * REFERENCE_RTOL);
            let sol = solve_with(p, &s, physics::solve::Engine::Own).expect("reference");
            (sol.t, sol.y.iter().map(|y| y[0]).collect())
        }
    }
    dispatch(scene, Landed)
}

/// The states of a run of `scene` at its samples and nothing else, as `solve_ivp`'s `t_eval`
/// returns them: its model integrated by the solver layer with the scene's events, each sample
/// taken from the dense output, a step's samples evaluated together and handed to a sink as a
/// batch; returns how many samples were made.
fn states_only(scene: &Scene) -> u64 {
    struct States;
    impl Visit for States {
        type Out = u64;
        fn visit<M: Model<N>, const N: usize>(self, model: &M, scene: &Scene) -> u64 {
            let y0 = model.state(&scene.start);
            let mut samples = 0u64;
            let mut sink = |batch: &Batch<N>| {
                black_box(batch);
                samples += batch.len() as u64;
            };
            let mut p = problem(model, scene, y0, scene.stop.time);
            p.sample = scene.sample;
            p.on_batch = Some(&mut sink);
            let sol = solve(p, &scene.settings).expect("the benchmark scene runs");
            black_box(&sol);
            samples + sol.t.len() as u64
        }
    }
    dispatch(scene, States)
}

/// The median wall time of `run` (s) and how many runs it took, within `timing`'s budget.
fn median_seconds(timing: &Timing, mut run: impl FnMut()) -> (f64, usize) {
    let started = Instant::now();
    let mut times = Vec::new();
    while times.len() < timing.max_runs.max(1)
        && (times.len() < timing.min_runs
            || started.elapsed().as_secs_f64() < timing.budget_seconds)
    {
        let t0 = Instant::now();
        run();
        times.push(t0.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    (times[times.len() / 2], times.len())
}

/// The sweep: for DOP853 at rtol 1e-5 to 1e-13 (atol 1e-2 rtol), the median wall time of a
/// sampled run with its recorded quantities (rows made, then discarded) and of the states
/// alone at the same rows, and its largest error in $\alpha$ over the rows; with the
/// reference's grid and $\alpha$ for the Python side.
pub fn sweep(scene: &Scene, timing: &Timing) -> Value {
    let (t_ref, alpha_ref) = reference(scene);
    let mut points = Vec::new();
    for e in 5..=13 {
        let rtol = 10f64.powi(-e);
        let settings = Settings {
            method: Method::Dop853,
            rtol,
            atol: 1e-2 * rtol,
            ..Settings::default()
        };
        let s = sampled(scene, settings);
        let (t, alpha) = alpha_rows(&s);
        assert_eq!(t.len(), t_ref.len(), "the same grid on both runs");
        let alpha_error = alpha
            .iter()
            .zip(&alpha_ref)
            .map(|(a, r)| (a - r).abs())
            .fold(0.0, f64::max);
        let recorded = median_seconds(timing, || {
            let mut rows = 0u64;
            let mut sink = |batch: &[f64]| rows += black_box(batch).len() as u64;
            black_box(run_streamed_rows(&s, None, &mut sink).expect("runs"));
        });
        let states = median_seconds(timing, || {
            black_box(states_only(&s));
        });
        points.push(json!({
            "method": "dop853", "rtol": rtol, "atol": settings.atol,
            "rows": t.len(), "wall_seconds": recorded.0, "runs": recorded.1,
            "states_wall_seconds": states.0, "states_runs": states.1,
            "alpha_error": alpha_error,
        }));
    }
    json!({
        "sample": SAMPLE,
        "reference_rtol": REFERENCE_RTOL,
        "t": t_ref,
        "alpha": alpha_ref,
        "rust": points,
    })
}
