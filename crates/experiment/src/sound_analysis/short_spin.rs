//! A short spin: one whose pitch track holds fewer frames of the disk's line than a fit of eq 79
//! to the track is judged on ([`SOUND_MIN_FRAMES`]), analysed from its phase. A track of enough
//! frames whose own fit its checks refuse (frames off the line, a fit that cannot start or
//! explains too little, a rise too small) is analysed from its phase the same way, on its frames
//! that hold the line (the stray ones left out), and stands or is refused by the same rules.
//!
//! A spin of 1-3 s of sound from 4-30 Hz holds 5-100 turns but only a few frames of a quarter of
//! a second: too few for the track's own fit, enough for the heading. The track's frames
//! $(t_k, \Omega_k, \sigma_k)$ still fix eq 79,
//! $$\ln\Omega = \frac{\ln C - \ln(t_0 - t)}{\beta + 2} \quad (79),$$
//! up to the trade between $\beta$ and $t_0$ that so few frames leave open. So the law is
//! **seeded by a search**: for each $(\beta, t_0)$ on a grid ($\beta$ by [`BETA_STEP`], $t_0$
//! after the last frame by ratios of [`T0_RATIO`] of its distance from the last frame's middle)
//! $\ln C$ is the frames' weighted mean, the grid points whose frames' $\chi^2$ is within
//! [`CHI2_MARGIN`] of the least are kept (the $\chi^2$ scaled by the least's per degree of
//! freedom, $\chi^2_{min}/(n - 3)$, where that exceeds 1: a frame that holds the spin's
//! faded-in start or a nuisance lies off the line by more than its sigma, and the frames'
//! scatter, not their sigmas, then says which laws they allow), and of these the law under which the recording's
//! phase blocks ([`phase_blocks`](crate::sound_analysis::phase_blocks)) hold most of the
//! disk's lines, $\sum_k \sum_h \ln \mathrm{snr}_{h,k}$ over the harmonics $h$ each block
//! demodulates (a line off the disk's, or past its end, holds noise, whose
//! $\ln\mathrm{snr}$ averages $-\gamma \approx -0.58$; behind a phone's high-pass far above the
//! fundamental the harmonics, not the fundamental, hold the heading), is the seed; the search is
//! repeated on a grid a fifth as coarse about it. The heading is then fitted to the phase from that seed as for a long spin
//! ([`phase_fit`](crate::sound_analysis::phase_fit)), to at least [`MIN_SHORT_BLOCKS`] blocks,
//! with its interval from its residuals.
//!
//! **Its interval.** The residuals of $n$ blocks measure the sigmas' common scale with
//! $n - 4$ degrees of freedom, few for a short spin, so the fit's sigmas are widened by
//! Student's $t_{0.975}(n-4)/z_{0.975}$ ([`student_975`]), and the 95 % interval
//! $\pm 1.96\,\sigma$ is Student's. Where the harmonics' phases read a high-pass's corner
//! that the fit does not take out, the shift its lead would make is stated as the corner's
//! uncertainty by the phase fit itself, as for a long spin
//! ([`PhaseFit::t0_high_pass`](crate::sound_analysis::phase_fit::PhaseFit::t0_high_pass)): a
//! short spin's heading is followed over few turns at rates far below a phone's corner, where
//! the lead it leaves in moves $t_0$ by milliseconds.
//!
//! **When it is the result.** The phase's fit stands in for the track's only where it holds on
//! its own evidence: it is plausible ([`SoundAnalysis::phase_implausible`]: $t_0$ after the
//! last frame, $\beta$ determined, residuals without structure), every frame of the track lies
//! within [`FRAME_SIGMAS`] of its own sigma, beyond half a turn's worth of its rate, of the law's
//! mean over the frame,
//! $$|\bar\Omega_k - \Omega_k| \le 5\,\sigma_k + \frac{\Omega_k}{2N},$$
//! $N$ the turns fitted (the track and the phase follow the same line: a fit that slipped by a
//! turn moves the rate by about $\Omega/N$, one locked onto another line by far more, while a
//! frame that holds the spin's faded-in start or a nuisance may be off by more than its sigma),
//! its $\beta$ lies in the checks' range, and the rate rises by the checks' `min_rise` across
//! its blocks. Otherwise the track's refusal stands, with why the phase did
//! not stand in.

use crate::fit::law_choice::compare;
use crate::fit::law_fit::LawFit;
use crate::fit::least_squares::Problem;
use crate::fit::plausibility::{Evidence, Plausibility, Points, SOUND_MIN_FRAMES};
use crate::sound_analysis::analysed::SoundAnalysis;
use crate::sound_analysis::mains::hum::subtract_hum;
use crate::sound_analysis::phase_blocks::{blocks, BlockSettings, Samples};
use crate::sound_analysis::phase_fit::{fit_phase, PhaseFit};
use crate::sound_analysis::refusal::RISES;
use crate::sound_analysis::track::FrequencyTrack;
use crate::sound_analysis::track_law::{TrackFit, TrackLaw};
use crate::trace::Trace;
use nalgebra::SVector;
use statrs::distribution::{ContinuousCDF, StudentsT};
use std::borrow::Cow;
use std::f64::consts::TAU;

/// The grid's step in $\beta$.
pub const BETA_STEP: f64 = 0.25;

/// The grid's ratio between successive distances of $t_0$ from the last frame's middle.
pub const T0_RATIO: f64 = 1.12;

/// Grid points whose frames' $\chi^2$ exceeds the least by more than this are not searched.
pub const CHI2_MARGIN: f64 = 9.0;

/// How many of the frames' sigmas a frame may lie from the law the phase states.
pub const FRAME_SIGMAS: f64 = 5.0;

/// The fewest blocks a short spin's heading is fitted to: twice the heading's four parameters.
pub const MIN_SHORT_BLOCKS: usize = 8;

/// The normal distribution's 97.5 % quantile.
const NORMAL_975: f64 = 1.959_963_984_540_054;

/// Student's $t$ distribution's 97.5 % quantile for $\nu$ degrees of freedom,
/// $$t_{0.975}(\nu) = F_\nu^{-1}(0.975), \qquad
///   F_\nu(t) = 1 - \tfrac12 I_{\nu/(\nu + t^2)}\left(\tfrac{\nu}{2}, \tfrac12\right) \ (t > 0),$$
/// $I$ the regularized incomplete beta function, from the maintained `statrs` crate; the
/// normal's $z_{0.975}$ where $\nu$ is not a positive number.
pub fn student_975(nu: f64) -> f64 {
    StudentsT::new(0.0, 1.0, nu).map_or(NORMAL_975, |t| t.inverse_cdf(0.975))
}

/// How the analysis from the phase is named for a track of `frames` frames of the line: "as a
/// short spin" where they are fewer than [`SOUND_MIN_FRAMES`], else "from its phase alone" (a
/// track of enough frames whose own fit its checks refuse).
pub fn named(frames: usize) -> &'static str {
    if frames < SOUND_MIN_FRAMES {
        "as a short spin"
    } else {
        "from its phase alone"
    }
}

/// The frames of the track: middles (s), $\ln\Omega$ and its sigma.
struct Frames {
    t: Vec<f64>,
    ln_omega: Vec<f64>,
    sigma: Vec<f64>,
}

impl Frames {
    fn of(track: &FrequencyTrack) -> Self {
        let pts = &track.points;
        Self {
            t: pts.iter().map(|p| 0.5 * (p.a + p.b)).collect(),
            ln_omega: pts.iter().map(|p| p.omega.ln()).collect(),
            sigma: pts.iter().map(|p| p.sigma / p.omega).collect(),
        }
    }

    /// $\ln C$ for $(\beta, t_0)$, the frames' weighted mean, and the frames' $\chi^2$.
    fn ln_c(&self, beta: f64, t0: f64) -> (f64, f64) {
        let (mut num, mut den) = (0.0, 0.0);
        let each: Vec<(f64, f64)> = self
            .t
            .iter()
            .zip(&self.ln_omega)
            .zip(&self.sigma)
            .map(|((t, l), s)| ((beta + 2.0) * l + (t0 - t).ln(), (beta + 2.0) * s))
            .collect();
        for (v, s) in &each {
            num += v / (s * s);
            den += 1.0 / (s * s);
        }
        let ln_c = num / den;
        let chi2 = each.iter().map(|(v, s)| ((v - ln_c) / s).powi(2)).sum();
        (ln_c, chi2)
    }
}

/// The seed of eq 79 for a short spin (see the module's documentation): $(\beta, t_0, \ln C)$
/// and the $t_0$ grid's step there (s); `None` where fewer than two frames hold the line or the
/// line runs to the recording's end (no end time after it is left to search).
pub fn seed(
    rec: &Samples<'_>,
    track: &FrequencyTrack,
    first: f64,
) -> Option<(SVector<f64, 3>, f64)> {
    let fr = Frames::of(track);
    if fr.t.len() < 2 {
        return None;
    }
    let end = rec.t_start + rec.x.len() as f64 * rec.dt;
    let last = *fr.t.last()?;
    let t_last_b = track.points.last()?.b;
    let score = |p: &SVector<f64, 3>| -> f64 {
        let s = BlockSettings {
            min_snr: 0.0,
            ..BlockSettings::default()
        };
        let stop = (p[1] - 1e-3).min(end);
        blocks(rec, p, 0.0, (first, stop), false, &s)
            .iter()
            .flat_map(|b| b.snrs)
            .filter(|x| x.is_finite())
            .map(|x| x.max(1e-3).ln())
            .sum()
    };
    let search = |betas: Vec<f64>, t0s: Vec<f64>| -> Option<(SVector<f64, 3>, f64)> {
        let mut grid: Vec<(f64, SVector<f64, 3>)> = Vec::new();
        for &beta in &betas {
            for &t0 in t0s.iter().filter(|&&t0| t0 > t_last_b) {
                let (ln_c, chi2) = fr.ln_c(beta, t0);
                if chi2.is_finite() && ln_c.is_finite() {
                    grid.push((chi2, SVector::<f64, 3>::new(beta, t0, ln_c)));
                }
            }
        }
        let least = grid.iter().map(|g| g.0).fold(f64::INFINITY, f64::min);
        let dof = fr.t.len().saturating_sub(3).max(1) as f64;
        let scale = (least / dof).max(1.0);
        grid.into_iter()
            .filter(|g| g.0 <= least + CHI2_MARGIN * scale)
            .map(|g| (g.1, score(&g.1)))
            .filter(|g| g.1.is_finite())
            .max_by(|a, b| a.1.total_cmp(&b.1))
    };
    let distances = |from: f64, to: f64, ratio: f64| -> Vec<f64> {
        let mut d = Vec::new();
        let mut x = from;
        while x <= to {
            d.push(x);
            x *= ratio;
        }
        d
    };
    let coarse_t0: Vec<f64> = distances(0.005, (end - last).max(0.01), T0_RATIO)
        .into_iter()
        .map(|d| last + d)
        .collect();
    let coarse_beta: Vec<f64> = (0..=18).map(|k| 0.5 + BETA_STEP * f64::from(k)).collect();
    let (c, _) = search(coarse_beta, coarse_t0)?;
    let d0 = c[1] - last;
    let fine_ratio = T0_RATIO.powf(0.2);
    let fine_t0: Vec<f64> = (-5..=5).map(|k| last + d0 * fine_ratio.powi(k)).collect();
    let fine_beta: Vec<f64> = (-5..=5)
        .map(|k| c[0] + 0.2 * BETA_STEP * f64::from(k))
        .collect();
    let (p, _) = search(fine_beta, fine_t0)?;
    Some((p, (p[1] - last) * (fine_ratio - 1.0)))
}

/// The heading fitted to the phase of `rec` from `first` (s), seeded at `p0` with $t_0$'s grid
/// step `step` (s), to at least [`MIN_SHORT_BLOCKS`] blocks, its sigmas widened by Student's
/// $t$ (see the module's documentation).
fn short_phase(
    rec: &Samples<'_>,
    track: &FrequencyTrack,
    first: f64,
    p0: SVector<f64, 3>,
    step: f64,
) -> Result<PhaseFit, String> {
    let settings = BlockSettings {
        min_blocks: MIN_SHORT_BLOCKS,
        ..BlockSettings::default()
    };
    let mut ph = fit_phase(
        rec,
        &track.hum,
        first,
        p0,
        (step / 3.0).max(1e-3),
        &settings,
    )
    .map_err(|e| format!("the phase of the short spin could not be fitted ({e})"))?;
    // The residuals measure the sigmas' scale with n - 4 degrees of freedom.
    let widen = student_975(ph.n as f64 - 4.0) / NORMAL_975;
    for v in [
        &mut ph.parameters.beta_sigma,
        &mut ph.parameters.t0_sigma,
        &mut ph.parameters.ln_c_sigma,
    ] {
        *v *= widen;
    }
    Ok(ph)
}

/// [`seed`] scored on the record `rec` with the mains lines the track found subtracted (a hum
/// line's window sidelobes would otherwise reach the blocks' lines and noise probes; the
/// heading's fit subtracts them itself, where the disk keeps clear of them); why not, for the
/// refusal, where the line runs to the recording's end.
fn seed_heard(
    trace: &Trace,
    track: &FrequencyTrack,
    rec: &Samples<'_>,
    first: f64,
) -> Result<(SVector<f64, 3>, f64), String> {
    let clean: Cow<'_, [f64]> = if track.hum.is_empty() {
        Cow::Borrowed(&trace.v)
    } else {
        let mut v = trace.v.clone();
        subtract_hum(&mut v, track.sample_rate, &track.hum);
        Cow::Owned(v)
    };
    let heard = Samples {
        x: &clean,
        t_start: rec.t_start,
        dt: rec.dt,
    };
    seed(&heard, track, first).ok_or_else(|| {
        "the line runs to the recording's end, so no end time after it is left to search: \
         record until the disk is silent"
            .to_string()
    })
}

/// The analysis of a short spin from its phase, seeded by [`seed`], where it stands on its own
/// evidence (see the module's documentation); else why not, for the refusal.
pub fn analysed(
    trace: &Trace,
    track: &FrequencyTrack,
    checks: &Plausibility,
    track_refusal: &str,
) -> Result<SoundAnalysis, String> {
    let rec = Samples {
        x: &trace.v,
        t_start: trace.t[0],
        dt: 1.0 / track.sample_rate,
    };
    let pts = &track.points;
    if pts.len() < 2 {
        return Err(format!(
            "{} frame of the track holds the line, fewer than the 2 the phase of a short spin is \
             seeded from",
            pts.len()
        ));
    }
    let (lo_f, hi_f) = (pts[0].omega, pts[pts.len() - 1].omega);
    if hi_f < RISES * lo_f {
        return Err(format!(
            "the line the track followed does not rise ({:.1} Hz to {:.1} Hz), so it is not a \
             settling disk's",
            lo_f / TAU,
            hi_f / TAU
        ));
    }
    let first = pts[0].a;
    let (p0, step) = seed_heard(trace, track, &rec, first)?;
    let ph = short_phase(&rec, track, first, p0, step)?;
    let law = SVector::<f64, 3>::new(ph.beta, ph.t0, ph.ln_c);
    // The track's frames against the phase's law, each as the law's mean over its frame.
    let (fa, fb, fy): (Vec<f64>, Vec<f64>, Vec<f64>) = (
        pts.iter().map(|p| p.a).collect(),
        pts.iter().map(|p| p.b).collect(),
        pts.iter().map(|p| p.omega).collect(),
    );
    let frames = TrackLaw {
        a: &fa,
        b: &fb,
        y: &fy,
    };
    let slip = 0.5 / ph.turns.max(1.0);
    let off = pts
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let d = (frames.model(&law, i).0 - p.omega).abs();
            (d - slip * p.omega).max(0.0) / p.sigma
        })
        .fold(0.0, f64::max);
    let fr = Frames::of(track);
    if off.is_nan() || off > FRAME_SIGMAS {
        return Err(format!(
            "the phase's fit of the short spin (beta = {:.3}, t0 = {:.4} s) misses a frame of the \
             track by {off:.1} of its sigmas beyond half a turn's worth of its rate over the \
             {:.1} turns fitted, more than {FRAME_SIGMAS}: the two do not follow one line",
            ph.beta, ph.t0, ph.turns
        ));
    }
    let (lo, hi) = checks.beta_range;
    if !(lo..=hi).contains(&ph.beta) {
        return Err(format!(
            "the phase's fit of the short spin gives beta = {:.3}, outside {lo} .. {hi}",
            ph.beta
        ));
    }
    let y: Vec<f64> = pts.iter().map(|p| p.omega).collect();
    let model: Vec<f64> = (0..pts.len()).map(|i| frames.model(&p0, i).0).collect();
    let residual: Vec<f64> = y.iter().zip(&model).map(|(a, b)| a - b).collect();
    let (_, chi2) = fr.ln_c(p0[0], p0[1]);
    let fit = TrackFit {
        parameters: LawFit {
            beta: p0[0],
            beta_sigma: BETA_STEP,
            t0: p0[1],
            t0_sigma: p0[1] - fr.t[fr.t.len() - 1],
            ln_c: p0[2],
            ln_c_sigma: f64::NAN,
        },
        rms: (residual.iter().map(|r| r * r).sum::<f64>() / y.len() as f64).sqrt(),
        chi2_dof: chi2 / (y.len() as f64 - 2.0).max(1.0),
        n: y.len(),
        model,
    };
    let last_b = pts[pts.len() - 1].b;
    let verdict = checks.judge_points(
        &Evidence {
            t: &fr.t,
            omega: &y,
            anomalous: track.stray,
            y: &y,
            residual: &residual,
            crossover_residual_ss: None,
            beta: p0[0],
            t0: p0[1],
            t_first: first,
            t_last: last_b,
        },
        Points::Frames(SOUND_MIN_FRAMES),
    );
    let mut a = SoundAnalysis {
        source: trace.source.clone(),
        recording: None,
        track: track.clone(),
        fit,
        phase: Some(ph),
        phase_refused: None,
        turn_count: None,
        models: compare(y.len(), Vec::new()),
        verdict,
        rise_on_phase: None,
        short_spin: Some(track_refusal.to_string()),
        truth: trace.truth.clone(),
    };
    if let Some(why) = a.phase_implausible() {
        return Err(format!(
            "the phase's fit of the short spin is not the result: {why}"
        ));
    }
    match a.phase_rise() {
        Some(r) if r >= checks.min_rise => {
            a.rise_on_phase = Some(r);
            Ok(a)
        }
        r => Err(format!(
            "the phase's fit of the short spin rises by a factor {:.2} over its blocks, less than \
             the {} a spin-down is judged on",
            r.unwrap_or(f64::NAN),
            checks.min_rise
        )),
    }
}

#[cfg(test)]
mod tests;
