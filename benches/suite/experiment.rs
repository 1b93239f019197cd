//! The analysis of a paper-sized trace (50,000 samples at 5 kS/s): peaks, rates, both fits and
//! the model choice; and of a 10 s sound recording at 8 kHz (80,000 samples): the spectral
//! track and its fits; and of a phone's minute at 48 kHz (2,880,000 samples).

use criterion::Criterion;
use experiment::plausibility::Plausibility;
use experiment::{
    analyze, analyze_sound, law_sound, law_trace, AnalysisSettings, Artifacts, Law, LightModel,
    Microphone, TrackSettings,
};
use physics::Disk;
use std::hint::black_box;

fn analysis(c: &mut Criterion) {
    let disk = Disk::uniform(0.0375);
    let fit = paper::Paper::built_in().expect("the built-in paper").fit;
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
    // A phone's minute at 48 kHz (2,880,000 samples), the spin-down ending 1.5 s before its end.
    let minute = Microphone {
        samples: 2_880_000,
        end_at: 58.5,
        ..Microphone::phone(48_000, 3)
    };
    let slow = Law {
        beta: 2.0,
        c: 100f64.powi(4) * 58.0,
    };
    let long = law_sound(&slow, &minute, &Artifacts::none()).expect("a valid recording");
    let mut group = c.benchmark_group("experiment/analyze_sound 60 s at 48 kHz");
    group.sample_size(10);
    group.bench_function("2.88M samples", |b| {
        b.iter(|| analyze_sound(black_box(&long), &track, &checks).expect("analysable"))
    });
    // The same minute with 2 % of 50 Hz hum, which the analysis finds and subtracts.
    let hum = Artifacts {
        hum: 0.02,
        seed: 3,
        ..Artifacts::none()
    };
    let hummed = law_sound(&slow, &minute, &hum).expect("a valid recording");
    group.bench_function("2.88M samples with 2 % hum", |b| {
        b.iter(|| analyze_sound(black_box(&hummed), &track, &checks).expect("analysable"))
    });
    group.finish();
}

/// Every benchmark of this module.
pub fn all(c: &mut Criterion) {
    analysis(c);
}
