//! The whole `rolling-disk report` computation: every study (side by side, as the command runs
//! them), the figures and the three renderings, in memory (no files written), with no cache (a
//! cold one costs the same and one write) and with a warm cache (the toy's result read back, as
//! every report after the first of a build); and the toy's studies alone.

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
    let cache =
        std::env::temp_dir().join(format!("rolling-disk-bench-cache-{}", std::process::id()));
    let config = report::pipeline::RunConfig::report(Bench::default())
        .with_cache(Some(report::cache::Cache::at(&cache)));
    report::build::build_from(&config, &|_| {}, None).unwrap();
    g.bench_function("every study, figure and rendering, warm cache", |b| {
        b.iter(|| {
            let (report, figures) = report::build::build_from(&config, &|_| {}, None).unwrap();
            black_box(report::render::html(&report).unwrap());
            black_box(report::render::latex(&report).unwrap());
            black_box(report::render::json(&report).unwrap());
            figures.len()
        })
    });
    let _ = std::fs::remove_dir_all(&cache);
    g.bench_function("the toy's studies", |b| {
        b.iter(|| black_box(studies::toy::compute().unwrap()))
    });
    g.finish();
}

/// Every benchmark of this module.
pub fn all(c: &mut Criterion) {
    whole_report(c);
}
