//! The sound of the synthetic experiment ([`studies::sound`]): its spectrogram with the fitted
//! pitch and harmonics, and the residuals of eq 79's heading fitted to its phase.

use crate::figures::chart::{Axis, Legend, Plot, Series, Style};
use crate::figures::{Drawing, Figure, FigureError};
use crate::number::measured;
use experiment::spectrogram::Spectrogram;
use experiment::SoundAnalysis;
use studies::sound::SoundStudy;

/// The loudness bands drawn (dB relative to the loudest cell), loudest last.
const BANDS: [(f64, f64); 3] = [(-30.0, -20.0), (-20.0, -10.0), (-10.0, 0.1)];

/// What the report's sound is.
const PHONE: &str = "the built-in spin-down as a phone beside the disk records it (48 kS/s, \
    harmonics, the level rising to the end, a rattle, clicks, room noise, 2 % of 50 Hz hum)";

/// The sound's two figures.
pub fn figures(s: &SoundStudy) -> Result<Vec<Figure>, FigureError> {
    Ok(vec![
        spectrogram(&s.analysis, &s.spectrogram, PHONE)?,
        phase_residuals(&s.analysis),
    ])
}

/// The spectrogram `sp` of the recording `about` describes, as loudness bands, with
/// $h\Omega/2\pi$ of the law the analysis `a` reports over it (eq 79 fitted to the phase, or to
/// the pitch track when the phase's fit is not the result).
pub fn spectrogram(
    a: &SoundAnalysis,
    sp: &Spectrogram,
    about: &str,
) -> Result<Figure, FigureError> {
    let mut plot = bands(
        Plot::new(
            "Spectrogram of the sound, with eq 79's pitch and harmonics",
            "time t (s)",
            "frequency f (Hz)",
        ),
        sp,
    );
    let law = a.law();
    let f_top = sp.f.last().copied().unwrap_or(1000.0);
    // The law the analysis reports: eq 79 fitted to the phase, or to the pitch track when the
    // phase's fit is not the result; drawn over the span that fit used.
    let (fitted_on, ln_c, span) = match &a.phase {
        Some(p) if law.from_phase => (
            "the phase",
            p.ln_c,
            p.points
                .first()
                .zip(p.points.last())
                .map(|(f, l)| (f.a, l.b)),
        ),
        _ => (
            "the pitch track",
            a.fit.ln_c,
            a.track
                .points
                .first()
                .zip(a.track.points.last())
                .map(|(f, l)| (f.a, l.b)),
        ),
    };
    if let Some((start, end)) = span {
        for h in 1..=4 {
            let pts: Vec<(f64, f64)> = (0..=200)
                .map(|i| start + (end - start) * f64::from(i) / 200.0)
                .filter(|t| *t < law.t0)
                .map(|t| {
                    let q = 1.0 / (law.beta + 2.0);
                    let omega = (q * (ln_c - (law.t0 - t).ln())).exp();
                    (t, f64::from(h) * omega / std::f64::consts::TAU)
                })
                .filter(|(_, f)| *f <= f_top)
                .collect();
            let label = if h == 1 {
                format!(
                    "eq 79 on {fitted_on}: hΩ/2π, h = 1..4 (β = {})",
                    measured(law.beta, law.beta_sigma)
                )
            } else {
                String::new()
            };
            plot = plot.with_colored(Series::new(label, pts, Style::Line), [0, 0, 0]);
        }
    }
    let plot = plot.y_range(0.0, f_top).legend_at(Legend::UpperLeft);
    Ok(Figure {
        name: "sound-spectrogram",
        title: "Spectrogram of the disk's sound with the fitted pitch".into(),
        caption: super::captions::caption(
            "sound-spectrogram",
            &serde_json::json!({
                "source": a.source,
                "about": about,
                "frame_s": format!(
                    "{:.2}",
                    sp.t.get(1).zip(sp.t.first()).map_or(0.0, |(b, a)| b - a)
                ),
                "band_hz": format!(
                    "{:.0}",
                    sp.f.get(1).zip(sp.f.first()).map_or(0.0, |(b, a)| b - a)
                ),
                "fitted_on": fitted_on,
            }),
        )?,
        drawing: Drawing::Plot(plot),
    })
}

/// `plot` with the spectrogram `sp` as loudness [`BANDS`].
fn bands(mut plot: Plot, sp: &Spectrogram) -> Plot {
    for (lo, hi) in BANDS {
        let cells: Vec<(f64, f64)> =
            sp.t.iter()
                .zip(&sp.db)
                .flat_map(|(t, row)| {
                    sp.f.iter()
                        .zip(row)
                        .filter(move |(_, d)| **d >= lo && **d < hi)
                        .map(move |(f, _)| (*t, *f))
                })
                .collect();
        let label = format!("{} to {} dB", lo.round(), hi.round());
        plot = plot.with(Series::new(label, cells, Style::Cells));
    }
    plot
}

/// The spectrogram `sp` of a recording whose analysis was refused, as loudness bands, with the
/// pitch track made before the refusal (its frames' $\Omega/2\pi$, when one was made) and the
/// refusal written on it, so that the user sees what the analysis saw.
pub fn refused_spectrogram(
    source: &str,
    track: Option<&experiment::track::FrequencyTrack>,
    sp: &Spectrogram,
    reason: &str,
) -> Figure {
    let mut plot = bands(
        Plot::new(
            "Spectrogram of the sound: the analysis was refused",
            "time t (s)",
            "frequency f (Hz)",
        ),
        sp,
    );
    let f_top = sp.f.last().copied().unwrap_or(1000.0);
    let pts: Vec<(f64, f64)> = track
        .map(|t| {
            t.points
                .iter()
                .map(|p| (0.5 * (p.a + p.b), p.omega / std::f64::consts::TAU))
                .filter(|(_, f)| *f <= f_top)
                .collect()
        })
        .unwrap_or_default();
    let n = pts.len();
    plot = plot.with_colored(
        Series::new(
            format!("the pitch track's frames, Ω/2π ({n})"),
            pts,
            Style::Points,
        ),
        [0, 0, 0],
    );
    let t_start = sp.t.first().copied().unwrap_or(0.0);
    let note = format!("refused: {}", wrap(reason, 80));
    let plot =
        plot.y_range(0.0, f_top)
            .legend_at(Legend::LowerRight)
            .note(t_start, 0.98 * f_top, note);
    Figure {
        name: "sound-spectrogram",
        title: "Spectrogram of the refused sound with its pitch track".into(),
        caption: format!(
            "{source}: the analysis was refused ({reason}). The spectrogram in three bands of \
             loudness relative to the loudest cell, with the frames of the pitch track made before \
             the refusal ({n})."
        ),
        drawing: Drawing::Plot(plot),
    }
}

/// `text` cut into lines of at most `width` characters at spaces.
fn wrap(text: &str, width: usize) -> String {
    let mut lines: Vec<String> = vec![String::new()];
    for word in text.split_whitespace() {
        let last = lines.last_mut().map_or(0, |l| l.chars().count());
        if last > 0 && last + 1 + word.chars().count() > width {
            lines.push(String::new());
        }
        if let Some(l) = lines.last_mut() {
            if !l.is_empty() {
                l.push(' ');
            }
            l.push_str(word);
        }
    }
    lines.join("\n")
}

/// The residuals of eq 79's heading, block by block, in units of their own sigma.
pub fn phase_residuals(a: &SoundAnalysis) -> Figure {
    let pts: Vec<(f64, f64)> = a
        .phase
        .as_ref()
        .map(|p| {
            p.points
                .iter()
                .map(|b| (b.t, b.residual / b.sigma))
                .collect()
        })
        .unwrap_or_default();
    let plot = Plot::new(
        "Residuals of eq 79's heading fitted to the sound's phase",
        "time t (s)",
        "residual / σ (dimensionless)",
    )
    .with(Series::new("blocks of whole turns", pts, Style::Points))
    .mark(Axis::Y, 0.0, "")
    .legend_at(Legend::Hidden);
    let caption = match &a.phase {
        Some(p) => format!(
            "{}: each block's heading minus eq 79's fitted heading, over the block's standard \
             uncertainty from the noise ({} blocks, {:.0} turns; reduced chi2 {:.2}, rms {:.4} \
             rad). A slow wave far above the noise is the law's own departure from the motion \
             (eq 79 drifts over the record{}).",
            a.source,
            p.n,
            p.turns,
            p.chi2_dof,
            p.rms,
            match &p.law {
                Some(l) if l.drifts => format!(
                    ": the later half's fit moves beta by {:+.4} and t0 by {:+.2} ms",
                    l.beta_shift,
                    1e3 * l.t0_shift
                ),
                _ => ", by no more than the noise says".into(),
            }
        ),
        None => format!(
            "{}: the phase was not fitted ({}).",
            a.source,
            a.phase_refused.as_deref().unwrap_or("no reason given")
        ),
    };
    Figure {
        name: "sound-residuals",
        title: "Residuals of eq 79 on the sound's phase".into(),
        caption,
        drawing: Drawing::Plot(plot),
    }
}
