//! The whole `rolling-disk report` computation: every study (side by side, as the command runs
//! them), the figures and the three renderings, in memory (no files written); and the toy's
//! studies alone, the report's longest.

use checks::equations::Bench;
use criterion::Criterion;
use std::hint::black_box;
use std::time::Duration;

fn whole_report(c: &mut Criterion) {
    let mut g = c.benchmark_group("report");
    g.sample_size(10).measurement_time(Duration::from_secs(30));
    g.bench_function("every study, figure and rendering", |b| {
        b.iter(|| {
            let (report, figures) = report::build::build(&Bench::default(), &|_| {}).unwrap();
            black_box(report::render::html(&report).unwrap());
            black_box(report::render::latex(&report).unwrap());
            black_box(report::render::json(&report).unwrap());
            figures.len()
        })
    });
    g.bench_function("the toy's studies", |b| {
        b.iter(|| black_box(studies::toy::compute().unwrap()))
    });
    g.finish();
}

/// Every benchmark of this module.
pub fn all(c: &mut Criterion) {
    whole_report(c);
}
