//! The analysis of a paper-sized trace (50,000 samples at 5 kS/s): peaks, rates and both fits.

use criterion::{criterion_group, criterion_main, Criterion};
use rolling_disk::experiment::{analyze, law_trace, AnalysisSettings, Law, LightModel};
use rolling_disk::Disk;
use std::hint::black_box;

fn analysis(c: &mut Criterion) {
    let disk = Disk::uniform(0.0375);
    let trace = law_trace(&Law::paper(), &disk, &LightModel::default()).expect("a valid law");
    let settings = AnalysisSettings::default();
    c.bench_function("experiment/analyze 50k samples", |b| {
        b.iter(|| analyze(black_box(&trace), &settings).expect("analysable"))
    });
}

criterion_group!(benches, analysis);
criterion_main!(benches);
