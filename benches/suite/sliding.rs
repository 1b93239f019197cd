//! The sliding model's cost (the goal: a 10 s scene with slip-stick switching in under 20 ms in
//! release): the built-in `slip-stick` scene end to end through
//! [`physics::run::run`], recording every accepted step, and with the scene's own 1 ms
//! sampling (10 001 rows, each re-integrated from the step before it).

use criterion::Criterion;
use physics::run::run;
use physics::scene::Scene;
use std::hint::black_box;

fn sliding(c: &mut Criterion) {
    let mut group = c.benchmark_group("sliding");
    group.sample_size(10);
    let sampled = Scene::load("slip-stick").expect("a built-in scene");
    let steps = Scene {
        sample: None,
        ..sampled.clone()
    };
    group.bench_function("slip-stick 10 s, steps", |b| {
        b.iter(|| black_box(run(black_box(&steps), None).expect("runs")))
    });
    group.bench_function("slip-stick 10 s, sampled every 1 ms", |b| {
        b.iter(|| black_box(run(black_box(&sampled), None).expect("runs")))
    });
    group.finish();
}

/// Every benchmark of this module.
pub fn all(c: &mut Criterion) {
    sliding(c);
}
