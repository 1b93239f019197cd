//! The analysis of a sound recording: its pitch track ([`track`](crate::sound_analysis::track)),
//! eq 79 fitted to it, the model choice and the spin-down checks.
//!
//! Eq 79 is fitted to the track as [`track_law`](crate::sound_analysis::track_law) states;
//! what the analysis holds is [`SoundAnalysis`](crate::sound_analysis::analysed::SoundAnalysis).

use crate::error::ExperimentError;
use crate::fit::eq84_85::{start84, FixedBeta};
use crate::fit::law_choice::compare;
use crate::fit::law_fit::LawFit;
use crate::fit::least_squares::{solve, FitError, Scale};
use crate::fit::plausibility::{Evidence, Plausibility, Points, SOUND_MIN_FRAMES};
use crate::formats::decimate::to_band;
pub use crate::sound_analysis::analysed::SoundAnalysis;
use crate::sound_analysis::phase_blocks::{BlockSettings, Samples};
use crate::sound_analysis::phase_fit::{fit_phase, PhaseFit};
use crate::sound_analysis::refusal::{what_was_heard, SoundRefusal};
use crate::sound_analysis::short_spin;
use crate::sound_analysis::track::rising::{rises, LineEnd};
use crate::sound_analysis::track::{frequency_track, FrequencyTrack, TrackPoint, TrackSettings};
pub use crate::sound_analysis::track_law::TrackFit;
pub(crate) use crate::sound_analysis::track_law::TrackLaw;
use crate::sound_analysis::turn_count::TurnCount;
use crate::trace::Trace;
use nalgebra::{SMatrix, SVector};
use physics::budget::Work;
use std::f64::consts::PI;
use std::fmt;

/// Analyses a sound recording.
pub fn analyze_sound(
    trace: &Trace,
    settings: &TrackSettings,
    checks: &Plausibility,
) -> Result<SoundAnalysis, ExperimentError> {
    let work = Work::start(format!("the analysis of {}", trace.source));
    analyze_sound_within(trace, settings, checks, &work)
}

/// [`analyze_sound`] as part of `work`: each stage checks its budget and reports its progress.
pub fn analyze_sound_within(
    trace: &Trace,
    settings: &TrackSettings,
    checks: &Plausibility,
    work: &Work<'_>,
) -> Result<SoundAnalysis, ExperimentError> {
    analyze_sound_keeping_track(trace, settings, checks, work).map_err(|r| r.error)
}

/// [`analyze_sound_within`], whose refusal keeps the pitch track made before it.
pub fn analyze_sound_keeping_track(
    trace: &Trace,
    settings: &TrackSettings,
    checks: &Plausibility,
    work: &Work<'_>,
) -> Result<SoundAnalysis, Box<SoundRefusal>> {
    let early = |e: ExperimentError| Box::new(SoundRefusal::before_track(e));
    work.stage("following the pitch")
        .map_err(|e| early(e.into()))?;
    let track = track_of(trace, settings).map_err(early)?;
    let keep = |error: ExperimentError| {
        Box::new(SoundRefusal {
            error,
            track: Some(track.clone()),
        })
    };
    work.stage("fitting eq 79").map_err(|e| keep(e.into()))?;
    let file = trace.source.clone();
    let heard = what_was_heard(&track, trace.t.last().copied().unwrap_or(0.0));
    // A track whose own fit is refused (too few frames for it, or frames its checks refuse) is
    // analysed from its phase, seeded by the track's frames on the line, before it is refused.
    let refuse = |reason: String| match short_spin::analysed(trace, &track, checks, &reason) {
        Ok(a) => Ok(a),
        Err(why) => Err(keep(ExperimentError::Refused {
            file: file.clone(),
            reason: format!(
                "{reason}; {heard}; nor can it be analysed {}: {why}",
                short_spin::named(track.points.len())
            ),
        })),
    };
    let pts = &track.points;
    if pts.len() < 6 {
        return refuse(format!(
            "{} frames hold a tone ({} silent, {} stray, {} smeared, {} outside the line): no rising line to follow",
            pts.len(),
            track.silent,
            track.stray,
            track.smeared,
            track.outside
        ));
    }
    let a: Vec<f64> = pts.iter().map(|p| p.a).collect();
    let b: Vec<f64> = pts.iter().map(|p| p.b).collect();
    let y: Vec<f64> = pts.iter().map(|p| p.omega).collect();
    let mid: Vec<f64> = a.iter().zip(&b).map(|(a, b)| 0.5 * (a + b)).collect();
    let inv: Vec<f64> = y.iter().map(|o| 1.0 / o).collect();
    let bmax = b.iter().copied().fold(f64::MIN, f64::max);
    let w: Vec<f64> = pts.iter().map(|p| p.sigma.powi(2)).collect();
    let law = TrackLaw {
        a: &a,
        b: &b,
        y: &y,
    };
    let fitted = start84(&mid, &inv, bmax)
        .ok_or(FitError::Shape("the rate does not rise toward an end time"))
        .and_then(|p0| solve(&law, &w, p0, Scale::Unknown));
    let s = match fitted {
        Ok(s) => s,
        Err(m) => return refuse(format!("eq 79 cannot be fitted to the track ({m})")),
    };
    let fit = TrackFit {
        parameters: LawFit::of(&s),
        rms: (s.residual.iter().map(|r| r * r).sum::<f64>() / y.len() as f64).sqrt(),
        chi2_dof: s.s2,
        n: y.len(),
        model: s.model.clone(),
    };
    let verdict = checks.judge_points(
        &Evidence {
            t: &mid,
            omega: &y,
            anomalous: track.stray,
            y: &y,
            residual: &s.residual,
            crossover_residual_ss: None,
            beta: fit.beta,
            t0: fit.t0,
            t_first: a[0],
            t_last: bmax,
        },
        Points::Frames(SOUND_MIN_FRAMES),
    );
    // A track whose frames rise too little, all else passing, is judged again on the rise of the
    // phase it holds ([`rise`](crate::sound_analysis::rise)).
    let rise_alone = verdict.refusals.len() == 1 && verdict.rise < checks.min_rise;
    if !verdict.refusals.is_empty() && !rise_alone {
        return refuse(verdict.refusals.join("; "));
    }
    let mut candidates = vec![(
        "beta free".to_string(),
        format!("beta = {:.3} +- {:.3}", fit.beta, fit.beta_sigma),
        3,
        s.chi2,
        0.0,
    )];
    for beta in [1.0, 2.0, 3.0, 4.0] {
        let fixed = FixedBeta {
            law: TrackLaw {
                a: &a,
                b: &b,
                y: &y,
            },
            beta,
        };
        let m = y.len() / 2;
        let ln_c = (beta + 2.0) * y[m].ln() + (fit.t0 - mid[m]).ln();
        if let Ok(f) = solve(
            &fixed,
            &w,
            SVector::<f64, 2>::new(fit.t0, ln_c),
            Scale::Unknown,
        ) {
            candidates.push((
                format!("beta = {beta}"),
                format!("t0 = {:.4} +- {:.4} s", f.p[0], f.cov[(0, 0)].sqrt()),
                2,
                f.chi2,
                0.0,
            ));
        }
    }
    work.stage("following the phase")
        .map_err(|e| keep(e.into()))?;
    let (phase, phase_refused, turn_count) = phase_of(trace, &track, a[0], &fit, &s.cov);
    let analysis = SoundAnalysis {
        source: trace.source.clone(),
        recording: None,
        phase,
        phase_refused,
        turn_count,
        models: compare(y.len(), candidates),
        track,
        fit,
        verdict,
        rise_on_phase: None,
        short_spin: None,
        truth: trace.truth.clone(),
    };
    analysis.judged_on_phase(rise_alone, checks, file, &heard)
}

/// The pitch track of `trace`: with `settings`, and where that holds fewer than
/// [`SOUND_MIN_FRAMES`] frames of a line that rises as a disk's does ([`rises`]; a spin of a
/// few seconds of sound holds only a few search frames of the default length), with search
/// frames halved down to 0.125 s, and where none holds that many, the same lengths again at a
/// signal-to-noise threshold [`WEAK_LINE`] times lower; of the tracks whose line rises, else of
/// all, the track of most frames kept (the first error when none could be made).
///
/// **The frame length is chosen for the lowest line.** A search frame of $T$ seconds holds
/// `cycles` periods of a line at $f$ only where $fT \ge$ `cycles` (and the search band starts at
/// $2.5/T$): a frame shorter than that cannot hold the disk's fundamental, and a track made of
/// such frames follows a harmonic or a stray tone, in more frames than the longer frames held
/// the line in. So once a track whose line rises is held, a shorter search frame is tried only
/// where it still holds `cycles` periods of that line's lowest pitch ([`holds_line`]); a short
/// spin's few frames of its fundamental are then kept, and analysed from its phase
/// ([`short_spin`]).
fn track_of(trace: &Trace, settings: &TrackSettings) -> Result<FrequencyTrack, ExperimentError> {
    let mut best = frequency_track(trace, settings);
    let mut s = *settings;
    let span = trace.t.last().copied().unwrap_or(0.0) - trace.t.first().copied().unwrap_or(0.0);
    // A track whose line rises as a disk's does ranks above one whose line holds still.
    let held = |t: &Result<FrequencyTrack, ExperimentError>| {
        t.as_ref()
            .map_or((false, 0), |t| (track_rises(t, span), t.points.len()))
    };
    let enough = |k: (bool, usize)| k.0 && k.1 >= SOUND_MIN_FRAMES;
    let room = |best: &Result<FrequencyTrack, ExperimentError>, search: f64| {
        best.as_ref().map_or(true, |t| {
            !track_rises(t, span) || holds_line(t, search, settings.cycles)
        })
    };
    while !enough(held(&best)) && s.search > 0.125 + 1e-9 && room(&best, 0.5 * s.search) {
        s.search = (0.5 * s.search).max(0.125);
        s.max_frame = s.max_frame.min(s.search);
        let shorter = frequency_track(trace, &s);
        if held(&shorter) > held(&best) {
            best = shorter;
        }
    }
    // A line too weak for `min_snr` in every frame length (a low line behind a phone's
    // high-pass, a quiet spin in room noise) is looked for again at a third of it.
    let mut weak = *settings;
    weak.min_snr = settings.min_snr / WEAK_LINE;
    while !enough(held(&best)) && weak.search > 0.125 - 1e-9 && room(&best, weak.search) {
        let again = frequency_track(trace, &weak);
        if held(&again) > held(&best) {
            best = again;
        }
        weak.search *= 0.5;
        weak.max_frame = weak.max_frame.min(weak.search);
    }
    best
}

/// Whether search frames of `search` seconds hold `cycles` periods of the lowest pitch of the
/// line `track` follows (see [`track_of`]).
fn holds_line(track: &FrequencyTrack, search: f64, cycles: f64) -> bool {
    let lowest = track
        .points
        .iter()
        .map(|p| p.omega / (2.0 * PI))
        .fold(f64::INFINITY, f64::min);
    lowest * search >= cycles
}

/// Whether the line `track` holds, from its first point to its last, rises as a disk's does in
/// a recording of `span` seconds ([`rises`]).
fn track_rises(track: &FrequencyTrack, span: f64) -> bool {
    let end = |p: &TrackPoint| LineEnd {
        t: 0.5 * (p.a + p.b),
        f: p.omega,
        sigma: p.sigma,
    };
    match (track.points.first(), track.points.last()) {
        (Some(a), Some(b)) => rises(end(a), end(b), span),
        _ => false,
    }
}

/// How much lower the signal-to-noise threshold is where no frame length holds a line at the
/// settings' own: a third (from 30 to 10 at the defaults, 10 dB over the noise per bin).
const WEAK_LINE: f64 = 3.0;

/// Eq 79's heading fitted to the phase of `trace` from `first` (s), started from the track's fit
/// `fit` (covariance `cov`); the phase, or why it is not used, and the turns counted. A record
/// sampled faster than the band the phase uses needs is read decimated to the band's rate
/// ([`to_band`]), its hum removal and blocks at a fraction of the samples.
fn phase_of(
    trace: &Trace,
    track: &FrequencyTrack,
    first: f64,
    fit: &TrackFit,
    cov: &SMatrix<f64, 3, 3>,
) -> (Option<PhaseFit>, Option<String>, Option<TurnCount>) {
    // Read at the band's rate where the record is sampled faster (8 kS/s from 48 kS/s).
    let band = to_band(&trace.v, track.sample_rate);
    let samples = match &band {
        Some((x, q)) => Samples {
            x,
            t_start: trace.t[0],
            dt: *q as f64 / track.sample_rate,
        },
        None => Samples {
            x: &trace.v,
            t_start: trace.t[0],
            dt: 1.0 / track.sample_rate,
        },
    };
    let law = |beta: f64, t0: f64, ln_c: f64| SVector::<f64, 3>::new(beta, t0, ln_c);
    match fit_phase(
        &samples,
        &track.hum,
        first,
        law(fit.beta, fit.t0, fit.ln_c),
        fit.t0_sigma,
        &BlockSettings::default(),
    ) {
        Ok(p) => {
            let span = (
                p.points.first().map_or(f64::NAN, |b| b.a),
                p.points.last().map_or(f64::NAN, |b| b.b),
            );
            let count = TurnCount::of(
                &law(p.beta, p.t0, p.ln_c),
                &law(fit.beta, fit.t0, fit.ln_c),
                cov,
                span,
            );
            if count.miscounted() {
                (
                    None,
                    Some(format!("{count}: a turn was miscounted")),
                    Some(count),
                )
            } else {
                (Some(p), None, Some(count))
            }
        }
        Err(e) => (
            None,
            Some(format!("the phase could not be fitted ({e})")),
            None,
        ),
    }
}

impl fmt::Display for SoundAnalysis {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (t, x) = (&self.track, &self.fit);
        writeln!(f, "sound: {}", self.source)?;
        if let Some(r) = &self.recording {
            writeln!(f, "  recording: {r}")?;
        }
        writeln!(
            f,
            "  {} frames of {:.1} to {:.1} ms at {:.0} S/s; {} on the line Omega/2pi ({} silent, {} stray, {} smeared left out; {} before or after the line skipped)",
            t.frames,
            1e3 * t.frame_span.0,
            1e3 * t.frame_span.1,
            t.sample_rate,
            t.points.len(),
            t.silent,
            t.stray,
            t.smeared,
            t.outside
        )?;
        if !t.hum.is_empty() {
            let lines: Vec<String> = t.hum.iter().map(|h| format!("{h:.2}")).collect();
            writeln!(f, "  mains hum subtracted at {} Hz", lines.join(", "))?;
        }
        if let (Some(p), Some(q)) = (t.points.first(), t.points.last()) {
            writeln!(
                f,
                "  Omega rises from {:.1} rad/s ({:.2} Hz) at {:.3} s to {:.1} rad/s ({:.2} Hz) at {:.3} s",
                p.omega,
                p.omega / (2.0 * PI),
                0.5 * (p.a + p.b),
                q.omega,
                q.omega / (2.0 * PI),
                0.5 * (q.a + q.b)
            )?;
        }
        writeln!(
            f,
            "  eq 79 on the pitch: beta = {:.4} +- {:.4}, t0 = {:.5} +- {:.5} s, ln C = {:.3} +- {:.3} (rms residual {:.3} rad/s, n = {}, chi2/dof {:.2}; errors scaled by the residuals)",
            x.beta, x.beta_sigma, x.t0, x.t0_sigma, x.ln_c, x.ln_c_sigma, x.rms, x.n, x.chi2_dof
        )?;
        match (&self.phase, &self.phase_refused) {
            (Some(p), _) => writeln!(
                f,
                "  eq 79 on the phase ({}): beta = {:.5} +- {:.5}, t0 = {:.6} +- {:.6} s, ln C = {:.4} +- {:.4} ({:.1} turns in {} blocks, rms residual {:.4} rad, chi2/dof {:.2}; errors scaled by the residuals)",
                self.phase_implausible().map_or_else(
                    || "the result".to_string(),
                    |why| format!("not the result: {why}; the pitch's fit is reported")
                ),
                p.beta, p.beta_sigma, p.t0, p.t0_sigma, p.ln_c, p.ln_c_sigma, p.turns, p.n, p.rms, p.chi2_dof
            )
            .and_then(|()| match &self.turn_count {
                Some(c) => writeln!(f, "  turns counted: {c}"),
                None => Ok(()),
            })
            .and_then(|()| {
                let l = self.law();
                if l.from_phase {
                    writeln!(f, "  stated: {}", l.describe_terms(p))?;
                }
                match (p.structure, self.disagreement_note()) {
                    (_, Some(d)) => writeln!(f, "  disagreement: {d}"),
                    (Some(s), None) => writeln!(
                        f,
                        "  phase residuals: {s}: {}",
                        if s.shown() && self.phase_implausible().is_some() {
                            "structure, so the phase's fit is not the result"
                        } else if s.shown() {
                            "structure, with the law's drift across the record stated, and the fits agree within their noise"
                        } else {
                            "noise"
                        }
                    ),
                    (None, None) => Ok(()),
                }
            })
            .and_then(|()| match &p.law {
                Some(l) if l.drifts => writeln!(
                    f,
                    "  the law across the record: the later {} blocks (from t = {:.4} s) give beta = {:.5} +- {:.5}, t0 = {:.6} +- {:.6} s; eq 79 drifts over the record, so the shifts are the law's systematic uncertainty: beta = {:.5} +- {:.5} (stat) +- {:.5} (law), t0 = {:.6} +- {:.6} (stat) +- {:.6} (law) s",
                    l.cycles, l.t_from, l.beta, l.beta_sigma, l.t0, l.t0_sigma,
                    p.beta, p.beta_sigma, l.beta_systematic(), p.t0, p.t0_sigma, l.t0_systematic()
                ),
                _ => Ok(()),
            })?,
            (None, Some(why)) => writeln!(f, "  phase not used: {why}")?,
            (None, None) => {}
        }
        if let Some(why) = &self.short_spin {
            let what = match self.track.points.len() < SOUND_MIN_FRAMES {
                true => "a short spin",
                false => "analysed from its phase alone",
            };
            writeln!(
                f,
                "  {what}: the track alone is refused ({why}); the phase's fit, seeded by a search over beta and t0 on the track's frames, is the result"
            )?;
        }
        if let Some(r) = self.rise_on_phase {
            writeln!(
                f,
                "  rise: Omega rises by a factor {:.2} over the track's frames, {r:.2} over the phase's blocks, on which the spin-down is judged (the track ends before the phase does)",
                self.verdict.rise
            )?;
        }
        writeln!(f, "  model choice: {}", self.models.summary)?;
        for c in &self.models.candidates {
            writeln!(
                f,
                "    {:<12} {:<28} dAIC {:>9.1}  dBIC {:>9.1}  weight {:.3}",
                c.name, c.parameters, c.delta_aic, c.delta_bic, c.weight
            )?;
        }
        if let Some(tr) = &self.truth {
            let l = self.law();
            writeln!(
                f,
                "  truth: beta = {}, t0 = {:.5} s; pulls: beta {:+.2}, t0 {:+.2} ({:+.3} ms)",
                tr.beta,
                tr.t0,
                (l.beta - tr.beta) / l.beta_sigma,
                (l.t0 - tr.t0) / l.t0_sigma,
                1e3 * (l.t0 - tr.t0)
            )?;
        }
        Ok(())
    }
}

impl SoundAnalysis {
    /// The analysis as pretty JSON, with the result ([`SoundResult`](crate::sound_analysis::result::SoundResult)) under `result`.
    pub fn to_json(&self) -> String {
        let mut v = serde_json::to_value(self).unwrap_or_default();
        if let (Some(m), Ok(r)) = (v.as_object_mut(), serde_json::to_value(self.result())) {
            m.insert("result".into(), r);
        }
        serde_json::to_string_pretty(&v).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }

    /// The frequency track as CSV ([`FrequencyTrack::csv`]).
    pub fn track_csv(&self) -> String {
        self.track.csv()
    }
}

/// Writes a sound analysis to `dir` (`analysis.json`, `track.csv`, and `phase.csv` when the phase
/// was fitted), each file atomically, and returns the paths written.
pub fn write_sound_analysis(
    a: &SoundAnalysis,
    dir: &std::path::Path,
) -> Result<Vec<std::path::PathBuf>, ExperimentError> {
    let io = |p: &std::path::Path, e: std::io::Error| ExperimentError::Io {
        file: p.display().to_string(),
        message: format!("cannot write ({e})"),
    };
    std::fs::create_dir_all(dir).map_err(|e| io(dir, e))?;
    let mut out = Vec::new();
    let mut texts = vec![("analysis.json", a.to_json()), ("track.csv", a.track_csv())];
    if let Some(p) = &a.phase {
        texts.push(("phase.csv", p.csv()));
    }
    for (name, text) in texts {
        let p = dir.join(name);
        files::output::write_set_file(&p, text.as_bytes()).map_err(|e| io(&p, e))?;
        out.push(p);
    }
    Ok(out)
}
