//! Criterion benchmarks of every built-in scene, run end to end through
//! [`physics::run::run`] (model, integration with the scene's own settings, recording).

use criterion::Criterion;
use physics::run::run;
use physics::scene::builtin::BUILTIN;
use physics::scene::Scene;
use std::hint::black_box;

fn scenes(c: &mut Criterion) {
    let mut group = c.benchmark_group("scene");
    group.sample_size(10);
    for (name, _) in BUILTIN {
        let scene = Scene::load(name).expect("built-in scenes are valid");
        group.bench_function(*name, |b| {
            b.iter(|| black_box(run(black_box(&scene), None).expect("runs")))
        });
    }
    group.finish();
}

/// Every benchmark of this module.
pub fn all(c: &mut Criterion) {
    scenes(c);
}
