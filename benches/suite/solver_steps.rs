//! Criterion benchmark of the solver's work and its cost per evaluation and per step, on the
//! benchmark scene (10 s, uniform disk): the crate's own DOP853 against `ode_solvers`' DOP853
//! at rtol 1e-6, 1e-9, 1e-12 (atol = 1e-2 rtol), and one right-hand side alone.
//!
//! The counts (evaluations, accepted and rejected steps) are deterministic and printed first;
//! criterion then reports each integration's time with its throughput in evaluations, so
//! `1 / thrpt` is the time per evaluation, to set against the `rhs` lines' times. The right-hand
//! side is timed twice: at one fixed state (`rolling`), and over the 2530 states the solver
//! actually visits at rtol 1e-9 (`rolling-visited`, per state), whose varying angles make
//! `sin` and `cos` slower; the second is the cost the solver's evaluations really pay, and the
//! overhead per evaluation is the integration's time per evaluation minus it:
//!
//! ```text
//! cargo bench --bench benches -- solver_steps
//! ```

use criterion::{BenchmarkId, Criterion, Throughput};
use physics::model::rolling::Rolling;
use physics::model::{Extras, Model};
use physics::scene::Scene;
use physics::solve::{solve_with, Dynamics, Engine, Method, Problem, Settings, State};
use std::cell::RefCell;
use std::hint::black_box;

/// The model, remembering every state it is evaluated at.
struct Recording<'a> {
    model: &'a Rolling<4>,
    visited: RefCell<Vec<State<4>>>,
}

impl Dynamics<4> for Recording<'_> {
    fn rhs(&self, y: &State<4>, dy: &mut State<4>) {
        self.visited.borrow_mut().push(*y);
        self.model.rhs(y, dy);
    }
}

fn solver_steps(c: &mut Criterion) {
    let scene = Scene::load("benchmark").expect("the built-in benchmark scene");
    let model = Rolling::<4>::new(scene.disk, Extras::default(), None);
    let y0 = model.state(&scene.start);
    let t_end = scene.stop.time;

    let mut group = c.benchmark_group("solver_steps/rhs");
    group.throughput(Throughput::Elements(1));
    group.bench_function("rolling", |b| {
        let mut dy = State::<4>::zeros();
        b.iter(|| {
            model.rhs(black_box(&y0), &mut dy);
            black_box(dy[1])
        })
    });
    let recording = Recording {
        model: &model,
        visited: RefCell::new(Vec::new()),
    };
    let s = Settings::dop853(1e-9, 1e-11);
    if solve_with(Problem::new(&recording, 0.0, y0, t_end), &s, Engine::Own).is_err() {
        panic!("own dop853 at rtol 1e-9: settings refused")
    }
    let visited = recording.visited.into_inner();
    group.throughput(Throughput::Elements(visited.len() as u64));
    group.bench_function("rolling-visited", |b| {
        let mut dy = State::<4>::zeros();
        b.iter(|| {
            let mut acc = 0.0;
            for y in black_box(&visited) {
                model.rhs(y, &mut dy);
                acc += dy[1];
            }
            black_box(acc)
        })
    });
    // As in a Runge-Kutta step, each evaluation's argument here depends on the previous
    // evaluation's result (through a term that is zero but the compiler cannot drop), so the
    // processor cannot overlap successive evaluations: this times their latency, which is
    // what a step pays, where the two lines above time their throughput.
    group.bench_function("rolling-visited-chained", |b| {
        let mut dy = State::<4>::zeros();
        b.iter(|| {
            for y in black_box(&visited) {
                let mut arg = *y;
                arg[0] += 0.0 * dy[1];
                model.rhs(&arg, &mut dy);
            }
            black_box(dy[1])
        })
    });
    group.finish();

    let mut group = c.benchmark_group("solver_steps/benchmark");
    group.sample_size(30);
    for (engine, name) in [(Engine::Own, "own"), (Engine::OdeSolvers, "ode_solvers")] {
        for rtol in [1e-6, 1e-9, 1e-12] {
            let s = Settings {
                method: Method::Dop853,
                rtol,
                atol: 1e-2 * rtol,
                ..Settings::default()
            };
            let run = || solve_with(Problem::new(&model, 0.0, y0, t_end), &s, engine);
            let Ok(sol) = run() else {
                panic!("{name} dop853 at rtol {rtol:e}: settings refused")
            };
            let st = sol.stats;
            eprintln!(
                "dop853 {name:<11} rtol {rtol:.0e}: {} evaluations, {} accepted, {} rejected",
                st.evaluations, st.accepted, st.rejected
            );
            group.throughput(Throughput::Elements(st.evaluations));
            let id = format!("dop853-{name}/rtol-{rtol:.0e}");
            group.bench_with_input(BenchmarkId::from_parameter(id), &s, |b, s| {
                b.iter(|| {
                    let sol =
                        solve_with(Problem::new(&model, 0.0, black_box(y0), t_end), s, engine);
                    black_box(sol.map(|s| s.last()))
                })
            });
        }
    }
    group.finish();
}

/// Every benchmark of this module.
pub fn all(c: &mut Criterion) {
    solver_steps(c);
}
