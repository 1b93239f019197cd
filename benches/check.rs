//! The whole `rolling-disk check`: every equation and claim check, on all cores, as the command
//! runs them (issue target: under 5 s in release on a 2-core machine).

use checks::check::{run_checks, Selection};
use checks::equations::Bench;
use criterion::{criterion_group, criterion_main, Criterion};
use std::time::Duration;

fn whole_check(c: &mut Criterion) {
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    let mut g = c.benchmark_group("check");
    g.sample_size(10).measurement_time(Duration::from_secs(15));
    g.bench_function("all equations and claims", |b| {
        b.iter(|| {
            run_checks(
                &Bench::default(),
                &Selection::default(),
                threads,
                &|_, _| {},
            )
            .unwrap()
        })
    });
    g.finish();
}

criterion_group!(benches, whole_check);
criterion_main!(benches);
