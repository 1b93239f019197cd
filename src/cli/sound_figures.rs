//! The figures `experiment analyze FILE --out DIR` draws for a sound recording: its spectrogram
//! with the law the analysis reports and its harmonics, and, when that law is eq 79 fitted to
//! the phase, the phase's residuals (the report's own figure functions,
//! [`report::figures::sound`]).

use experiment::spectrogram::spectrogram;
use experiment::{SoundAnalysis, Trace};
use std::path::{Path, PathBuf};

/// The spectrogram's cells for `trace` at `sample_rate`, up to `f_max` Hz: about 300 frames.
fn cells(trace: &Trace, sample_rate: f64, f_max: f64) -> experiment::spectrogram::Spectrogram {
    let span = trace.v.len() as f64 / sample_rate;
    let hop = (span / 300.0).max(0.1);
    spectrogram(trace, 2.0 * hop, hop, f_max, 80)
}

/// Writes `spectrogram.svg` of a refused analysis of `trace` into `dir`: the track made before
/// the refusal, up to the fourth harmonic of its fastest pitch (else up to 2 kHz), and the
/// reason on it; returns the path written.
pub fn write_refused(
    r: &experiment::refusal::SoundRefusal,
    trace: &Trace,
    dir: &Path,
) -> anyhow::Result<Vec<PathBuf>> {
    let rate = 1.0 / trace.sample_interval();
    let top = r
        .track
        .iter()
        .flat_map(|t| &t.points)
        .map(|p| p.omega)
        .fold(0.0, f64::max)
        / std::f64::consts::TAU;
    let f_max = if top > 0.0 { 4.5 * top } else { 2000.0 }.clamp(50.0, 0.5 * rate);
    let sp = cells(trace, rate, f_max);
    let fig = report::figures::sound::refused_spectrogram(
        &trace.source,
        r.track.as_ref(),
        &sp,
        &r.error.to_string(),
    );
    let svg = fig.drawing.to_svg(900, 600)?;
    let path = dir.join("spectrogram.svg");
    files::output::write_set_file(&path, svg.as_bytes())?;
    Ok(vec![path])
}

/// Writes `spectrogram.svg` (and `phase-residuals.svg` when the phase's fit is the result) of the
/// analysis `a` of `trace` into `dir`, each atomically; returns the paths written.
pub fn write(a: &SoundAnalysis, trace: &Trace, dir: &Path) -> anyhow::Result<Vec<PathBuf>> {
    // Up to the fourth harmonic of the fastest fitted pitch, below the Nyquist frequency.
    let top = a.track.points.iter().map(|p| p.omega).fold(0.0, f64::max) / std::f64::consts::TAU;
    let f_max = (4.5 * top).clamp(50.0, 0.5 * a.track.sample_rate);
    let sp = cells(trace, a.track.sample_rate, f_max);
    let about = match &a.recording {
        Some(r) => format!("a recording ({r})"),
        None => "a recording".to_string(),
    };
    let mut figures = vec![(
        "spectrogram.svg",
        report::figures::sound::spectrogram(a, &sp, &about)?,
    )];
    // The phase's residuals only when the phase's fit is the result: no empty frame.
    if a.law().from_phase {
        figures.push((
            "phase-residuals.svg",
            report::figures::sound::phase_residuals(a),
        ));
    }
    let mut out = Vec::new();
    for (name, fig) in figures {
        let svg = fig.drawing.to_svg(900, 600)?;
        let path = dir.join(name);
        files::output::write_set_file(&path, svg.as_bytes())?;
        out.push(path);
    }
    Ok(out)
}
