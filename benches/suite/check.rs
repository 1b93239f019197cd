//! The whole `rolling-disk check`: every equation and claim check, on all cores, as the command
//! runs them; and each prose claim's check alone, on one thread, to find a slow one.

use checks::check::{run_checks, Selection};
use checks::equations::Bench;
use criterion::Criterion;
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

fn each_claim(c: &mut Criterion) {
    let mut g = c.benchmark_group("claim");
    g.sample_size(10).measurement_time(Duration::from_secs(2));
    let bench = Bench::default();
    for claim in checks::equations::claims::CLAIMS {
        g.bench_function(claim.id, |b| b.iter(|| (claim.check)(&bench)));
    }
    g.finish();
}

/// Every benchmark of this module.
pub fn all(c: &mut Criterion) {
    whole_check(c);
    each_claim(c);
}
