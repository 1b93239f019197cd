//! The analysis of a paper-sized trace (50,000 samples at 5 kS/s): peaks, rates, both fits and
//! the model choice; and of a 10 s sound recording at 8 kHz (80,000 samples): the spectral
//! track and its fits.

use criterion::{criterion_group, criterion_main, Criterion};
use rolling_disk::experiment::plausibility::Plausibility;
use rolling_disk::experiment::{
    analyze, analyze_sound, law_sound, law_trace, AnalysisSettings, Artifacts, Law, LightModel,
    Microphone, TrackSettings,
};
use rolling_disk::Disk;
use std::hint::black_box;

fn analysis(c: &mut Criterion) {
    let disk = Disk::uniform(0.0375);
    let fit = rolling_disk::paper::Paper::built_in()
        .expect("the built-in paper")
        .fit;
    let trace = law_trace(
        &Law::from_fit(fit.beta, fit.c_inv_root),
        &disk,
        &LightModel::default(),
    )
    .expect("a valid law");
    let settings = AnalysisSettings::default();
    c.bench_function("experiment/analyze 50k samples", |b| {
        b.iter(|| analyze(black_box(&trace), &settings).expect("analysable"))
    });
    let law = Law {
        beta: 2.0,
        c: 100f64.powi(4) * 7.0,
    };
    let sound =
        law_sound(&law, &Microphone::default(), &Artifacts::none()).expect("a valid recording");
    let (track, checks) = (TrackSettings::default(), Plausibility::default());
    c.bench_function("experiment/analyze_sound 80k samples", |b| {
        b.iter(|| analyze_sound(black_box(&sound), &track, &checks).expect("analysable"))
    });
}

criterion_group!(benches, analysis);
criterion_main!(benches);
