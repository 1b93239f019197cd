//! Criterion benchmark of the solver's work and its cost per evaluation and per step, on the
//! benchmark scene (10 s, uniform disk): the crate's own DOP853 against `ode_solvers`' DOP853
//! at rtol 1e-6, 1e-9, 1e-12 (atol = 1e-2 rtol), and one right-hand side alone.
//!
//! The counts (evaluations, accepted and rejected steps) are deterministic and printed first;
//! criterion then reports each integration's time with its throughput in evaluations, so
//! `1 / thrpt` is the time per evaluation, to set against the `rhs` line's time:
//!
//! ```text
//! cargo bench --bench solver_steps
//! ```

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use rolling_disk::model::rolling::Rolling;
use rolling_disk::model::{Extras, Model};
use rolling_disk::scene::Scene;
use rolling_disk::solve::{solve_with, Dynamics, Engine, Method, Problem, Settings, State};
use std::hint::black_box;

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

criterion_group!(benches, solver_steps);
criterion_main!(benches);
