//! Criterion benchmarks of the solver on the benchmark scene (10 s of a uniform disk rolling
//! near a steady motion), per method and tolerance.

use criterion::{BenchmarkId, Criterion};
use physics::model::rolling::Rolling;
use physics::model::{Extras, Model};
use physics::scene::Scene;
use physics::solve::{solve, Method, Problem, Settings};
use std::hint::black_box;

fn solver(c: &mut Criterion) {
    let scene = Scene::load("benchmark").expect("the built-in benchmark scene");
    let model = Rolling::<4>::new(scene.disk, Extras::default(), None);
    let y0 = model.state(&scene.start);
    let t_end = scene.stop.time;
    let mut group = c.benchmark_group("solver/benchmark");
    group.sample_size(20);
    let mut cases: Vec<(String, Settings)> = [1024u32, 8192]
        .iter()
        .map(|&n| {
            let s = Settings {
                method: Method::Rk4,
                step: t_end / f64::from(n),
                ..Settings::default()
            };
            (format!("rk4/{n}-steps"), s)
        })
        .collect();
    for method in [Method::Dopri5, Method::Dop853] {
        for rtol in [1e-6, 1e-9, 1e-12] {
            let s = Settings {
                method,
                rtol,
                atol: 1e-2 * rtol,
                ..Settings::default()
            };
            cases.push((format!("{method}/rtol-{rtol:.0e}"), s));
        }
    }
    for (name, s) in cases {
        group.bench_with_input(BenchmarkId::from_parameter(name), &s, |b, s| {
            b.iter(|| {
                let sol = solve(Problem::new(&model, 0.0, black_box(y0), t_end), s);
                black_box(sol.map(|s| s.last()))
            })
        });
    }
    group.finish();
}

/// Every benchmark of this module.
pub fn all(c: &mut Criterion) {
    solver(c);
}
