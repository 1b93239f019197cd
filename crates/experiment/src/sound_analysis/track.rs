//! A pitch track from a sound recording, in seconds and hertz, whatever the sample rate.
//!
//! **Which line is followed.** The sound of a spinning disk is at the contact point's rate,
//! $\Omega/2\pi$, with harmonics at $h\Omega/2\pi$ (see [`sound`](crate::synthetic::sound)).
//! Each frame's fundamental is found by its harmonic family (each harmonic's power over its own
//! noise floor) and refined by reassignment, with a parabola as the cross-check ([`spectrum`](crate::sound_analysis::spectrum)). Mains hum is
//! subtracted first ([`hum`](crate::sound_analysis::mains::hum)).
//!
//! **Frames follow the pitch.** Frames are contiguous and do not overlap (their errors are
//! independent). Until a line is held, frames of `search` seconds look for a fundamental
//! between 5 Hz and 2 kHz. Once three frames in a row hold it (one line: each searched frame's
//! fundamental within [`STEP`] of the one before; a tone that stops where the disk's line
//! starts, as a mains line's residue in a silent lead-in, is not one line with it), the next
//! frame's length is
//! chosen from the line's motion $\dot f$ so that the pitch moves by at most `kappa` of a
//! frequency resolution across it,
//! $$T = \min\left(T_{max}, \sqrt{\kappa/|\dot f|}\right),$$
//! long early where the pitch moves slowly, short near $t_0$, and at most half the time left
//! to the singularity that $\dot f \propto f^q$ (fitted to the last three frames) predicts, so
//! that no frame runs past the disk's end; a line too low for `cycles` periods in that frame
//! (below 12 Hz at the defaults, or where a noisy $q$ predicts the end too near) is followed in
//! frames of `cycles` periods, up to [`LOW_FRAME`] (a 4 Hz line is followed, not cut), where
//! its motion allows them; and the search narrows to
//! $\pm 20\,\%$ about the predicted pitch. A frame so searched that lies more than [`JUMP`]
//! off the predicted pitch, and more than twice the predicted motion (a bump, a hum line's
//! subharmonic), is stray and left out of the prediction; after [`LOST_AFTER`] such frames in
//! a row the line is lost and searched for anew. The track ends where $T$ would hold fewer than
//! `cycles` periods (the line smears near $t_0$) after four frames in a row held the line;
//! that end counts as one smeared frame.
//!
//! **A line held still is not followed** ([`still`]): its frames are left off every line, its
//! pitch is masked in the frames searched over the whole band as the hum's lines are.
//!
//! **Each point's uncertainty** is the noise's (from the frame's own power over its noise, see
//! [`spectrum`](crate::sound_analysis::spectrum)) and the pitch's motion within the frame, in
//! quadrature. The fit takes the rate's mean over the frame weighted by the window's energy
//! $w^2$; the estimate may miss the curvature's part of it, about
//! $|\ddot f|\,\mathrm{Var}_{w^2}(t)/2$ with $\mathrm{Var}_{w^2}(t) = T^2(1/4 - 15/(8\pi^2))/3$
//! the time variance of $w^2$, which is taken as that part's standard deviation ($\ddot f$
//! from the neighbouring points).
//!
//! **Left out.** Frames off the line the track follows (cut where a searched frame's
//! fundamental jumps by more than [`STEP`] from the last one held; the longest run is the line,
//! the longest of those that rise as eq 79 does where any does, see [`rising`]):
//! before the line's first frame or after its last, as outside (skipped: the disk is not yet
//! followed there, or no longer heard; the line ends where its pitch stops rising, see
//! `end_at_stall`), and between them as stray; frames whose two estimators disagree by more than 5 of their sigmas plus a
//! hundredth of the resolution $1/T$, and frames found by the wide search that lie more than
//! 10 % off the median of their four neighbours and out of the order of a rising line among them
//! (above a neighbour after it or below one before it: a short spin's pitch rises by more than
//! a tenth from one frame to the next), as stray; frames without a line, as silent; the last frame before a silence
//! (the disk may settle inside it), as smeared.

use crate::error::ExperimentError;
use crate::sound_analysis::mains::hum::{hum_lines, subtract_hum};
use crate::sound_analysis::spectrum::{Analyser, Estimate};
use crate::trace::Trace;
use motion::add_motion;
use rising::{rises, LineEnd};
use serde::{Deserialize, Serialize};
use std::borrow::Cow;
use std::f64::consts::PI;
use still::still_line;

/// How the track is made.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TrackSettings {
    /// Frame length (s) while searching for the line.
    pub search: f64,
    /// Longest frame (s).
    pub max_frame: f64,
    /// Largest pitch motion across a frame, in frequency resolutions: $\dot f T^2$.
    pub kappa: f64,
    /// Fewest periods of the fundamental in a frame.
    pub cycles: f64,
    /// A harmonic counts when its power stands this many times above the noise per bin.
    pub min_snr: f64,
}

impl Default for TrackSettings {
    fn default() -> Self {
        Self {
            search: 0.5,
            max_frame: 0.25,
            kappa: 0.5,
            cycles: 3.0,
            min_snr: 30.0,
        }
    }
}

/// One frame of the track.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TrackPoint {
    /// Frame start (s).
    pub a: f64,
    /// Frame end (s).
    pub b: f64,
    /// The fundamental, $\Omega$ (rad/s), by reassignment.
    pub omega: f64,
    /// Its standard uncertainty (rad/s): the noise's and the motion's in quadrature.
    pub sigma: f64,
    /// The fundamental by parabolic interpolation (rad/s), the cross-check.
    pub check: f64,
    /// The harmonics' power over the noise's per bin.
    pub snr: f64,
}

/// The track.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrequencyTrack {
    /// Sample rate (S/s).
    pub sample_rate: f64,
    /// The shortest and longest frame analysed (s).
    pub frame_span: (f64, f64),
    /// Frames analysed.
    pub frames: usize,
    /// Frames kept, in time order.
    pub points: Vec<TrackPoint>,
    /// Frames left out as silent, stray or smeared.
    pub silent: usize,
    /// (see `silent`)
    pub stray: usize,
    /// (see `silent`)
    pub smeared: usize,
    /// Frames that hold a tone off the line before the line is first held or after it ends:
    /// sound other than the disk's (a lead-in's bumps, the shudder after $t_0$) or the disk's
    /// line where it cannot yet be followed; skipped, not counted as stray.
    pub outside: usize,
    /// Mains lines subtracted (Hz).
    pub hum: Vec<f64>,
}

impl FrequencyTrack {
    /// The track as CSV: frame start and end (s), $\Omega$ (rad/s), its standard uncertainty
    /// (rad/s), the cross-check's $\Omega$ (rad/s), signal-to-noise.
    pub fn csv(&self) -> String {
        let mut s = String::from("t_start_s,t_end_s,omega_rad_s,sigma_rad_s,check_rad_s,snr\n");
        for p in &self.points {
            s.push_str(&format!(
                "{},{},{},{},{},{}\n",
                p.a, p.b, p.omega, p.sigma, p.check, p.snr
            ));
        }
        s
    }
}

/// A frame as analysed: its span and what it held.
#[derive(Clone, Copy)]
struct Frame {
    a: f64,
    b: f64,
    est: Option<Estimate>,
    /// Searched over the whole band (no line held before it).
    searched: bool,
    /// Searched about the line's predicted pitch but found more than [`JUMP`] off it: not on
    /// the line, and not used to predict the next frame.
    jumped: bool,
    /// One of the frames of a line held still ([`still_line`]): not the disk's line, and on
    /// none where a line of the others rises.
    still: bool,
}

/// The pitch track of a uniformly sampled sound recording.
pub fn frequency_track(
    trace: &Trace,
    s: &TrackSettings,
) -> Result<FrequencyTrack, ExperimentError> {
    let file = trace.source.clone();
    let dt = trace.sample_interval();
    if dt.is_nan() || dt <= 0.0 {
        return Err(ExperimentError::Setting(format!(
            "{file}: the samples have no positive interval"
        )));
    }
    let fs = 1.0 / dt;
    let span = trace.v.len() as f64 * dt;
    if span < 4.0 * s.search {
        return Err(ExperimentError::TooFewPeaks {
            file,
            what: "seconds of sound".into(),
            found: span as usize,
            needed: (4.0 * s.search).ceil() as usize,
            hint: format!(
                "record at least {:.1} s: start the recording before the disk is spun",
                4.0 * s.search
            ),
        });
    }
    // The record is copied only where it has hum to subtract.
    let hum = hum_lines(&trace.v, fs);
    let v: Cow<'_, [f64]> = if hum.is_empty() {
        Cow::Borrowed(&trace.v)
    } else {
        let mut v = trace.v.clone();
        subtract_hum(&mut v, fs, &hum);
        Cow::Owned(v)
    };
    let (frames, smeared_end) = march(&v, trace.t[0], fs, s, &hum);
    let lens: Vec<f64> = frames.iter().map(|f| f.b - f.a).collect();
    let frame_span = (
        lens.iter().copied().fold(f64::INFINITY, f64::min),
        lens.iter().copied().fold(0.0, f64::max),
    );
    let silent = frames.iter().filter(|f| f.est.is_none()).count();
    let line = the_line(&frames);
    let first = line.iter().position(|&l| l).unwrap_or(0);
    let last = line.iter().rposition(|&l| l).unwrap_or(0);
    let (mut kept, mut stray, mut smeared) = (Vec::<(TrackPoint, bool)>::new(), 0, smeared_end);
    let mut outside = 0;
    for (k, fr) in frames.iter().enumerate() {
        let Some(e) = fr.est else { continue };
        if !line[k] {
            if k < first || k > last {
                outside += 1;
            } else {
                stray += 1;
            }
            continue;
        }
        if k + 1 < frames.len() && frames[k + 1].est.is_none() {
            smeared += 1;
            continue;
        }
        let tol = 5.0 * e.sigma + 0.01 / (fr.b - fr.a);
        if (e.f - e.check).abs() > tol {
            stray += 1;
            continue;
        }
        let p = TrackPoint {
            a: fr.a,
            b: fr.b,
            omega: 2.0 * PI * e.f,
            sigma: 2.0 * PI * e.sigma,
            check: 2.0 * PI * e.check,
            snr: e.snr,
        };
        kept.push((p, fr.searched));
    }
    let mut points = Vec::with_capacity(kept.len());
    for (k, (p, searched)) in kept.iter().enumerate() {
        let mut nb: Vec<f64> = (k.saturating_sub(2)..(k + 3).min(kept.len()))
            .filter(|&j| j != k)
            .map(|j| kept[j].0.omega)
            .collect();
        if *searched && nb.len() >= 2 {
            let before = kept[k.saturating_sub(2)..k].iter().map(|q| q.0.omega);
            let after = kept[k + 1..(k + 3).min(kept.len())]
                .iter()
                .map(|q| q.0.omega);
            let in_order = before.fold(f64::MIN, f64::max) <= p.omega
                && p.omega <= after.fold(f64::MAX, f64::min);
            let m = nb.len() / 2;
            let med = *nb.select_nth_unstable_by(m, f64::total_cmp).1;
            if (p.omega / med - 1.0).abs() > 0.1 && !in_order {
                stray += 1;
                continue;
            }
        }
        points.push(*p);
    }
    add_motion(&mut points);
    Ok(FrequencyTrack {
        sample_rate: fs,
        frame_span,
        frames: frames.len(),
        points,
        silent,
        stray,
        smeared,
        outside,
        hum,
    })
}

/// Which frames lie on the line the track follows: the frames holding a fundamental are cut into
/// runs wherever a searched frame's fundamental lies more than [`STEP`] from the last one held
/// (silent frames between do not cut a run); the run of most frames is the line (the earliest
/// of equal runs), of those that rise as a disk's does ([`rising`]) where any does: a line that
/// holds still (a ring after $t_0$, a mains line) is not the disk's. The frames of a line the
/// march held still ([`still_line`]) are on no run, unless no run of the others rises: the
/// track then holds the longest run of all, and its refusal says what it heard.
fn the_line(frames: &[Frame]) -> Vec<bool> {
    let mut line = match longest_run(frames, false) {
        (line, true) => line,
        _ => longest_run(frames, true).0,
    };
    end_at_stall(frames, &mut line);
    line
}

/// The frames of [`the_line`]'s longest run (of those that rise, where any does), the frames of
/// lines held still among them when `with_still`, and whether it rises.
fn longest_run(frames: &[Frame], with_still: bool) -> (Vec<bool>, bool) {
    let mut run = vec![usize::MAX; frames.len()];
    let (mut id, mut last): (usize, Option<f64>) = (0, None);
    for (k, fr) in frames.iter().enumerate() {
        let Some(e) = fr.est.filter(|_| !fr.jumped && (with_still || !fr.still)) else {
            continue;
        };
        if let Some(p) = last {
            if fr.searched && (e.f / p).max(p / e.f) > STEP {
                id += 1;
            }
        }
        last = Some(e.f);
        run[k] = id;
    }
    let count = |i: usize| run.iter().filter(|&&r| r == i).count();
    let span = frames.last().map_or(0.0, |l| l.b) - frames.first().map_or(0.0, |f| f.a);
    let end = |k: Option<usize>| {
        let fr = &frames[k?];
        fr.est.map(|e| LineEnd {
            t: 0.5 * (fr.a + fr.b),
            f: e.f,
            sigma: e.sigma,
        })
    };
    let rising = |i: usize| {
        let first = end(run.iter().position(|&r| r == i));
        let last = end(run.iter().rposition(|&r| r == i));
        first.zip(last).is_some_and(|(a, b)| rises(a, b, span))
    };
    // The longest run that rises as a disk's does, else the longest.
    let any_rising = (0..=id).any(rising);
    let best = (0..=id)
        .rev()
        .filter(|&i| !any_rising || rising(i))
        .max_by_key(|&i| count(i))
        .unwrap_or(0);
    (run.iter().map(|&r| r == best).collect(), any_rising)
}

/// Ends `line` where the pitch stops rising: eq 79's rate rises ever faster toward $t_0$, so
/// after two frames of the line $(t_1, f_1)$, $(t_2, f_2)$ whose pitch rose by more than three
/// of their sigmas, $t_1$ the latest frame at least half the line's span so far before $t_2$ (a
/// long chord, so that one frame pulled a few per cent off, by a bump or a hum line it
/// crosses, does not steepen it), the pitch at a later $t$ is at least
/// $$f_2 + \tfrac12\,\frac{f_2 - f_1}{t_2 - t_1}\,(t - t_2)$$
/// (half the chord's slope, a margin for the slope's noise). A frame more than three sigmas
/// below that, after which no frame of the line comes back above it, is where the disk's line
/// ended (at $t_0$, or where it was no longer heard): a tone held on after it (a mains line the
/// disk's line ran into, the shudder's ring) lies outside the line. A single frame below it with
/// the line going on is left to the stray frames' tests.
fn end_at_stall(frames: &[Frame], line: &mut [bool]) {
    let held: Vec<(usize, f64, Estimate)> = (0..frames.len())
        .filter(|&k| line[k])
        .filter_map(|k| {
            frames[k]
                .est
                .map(|e| (k, 0.5 * (frames[k].a + frames[k].b), e))
        })
        .collect();
    let Some(&(_, t_first, _)) = held.first() else {
        return;
    };
    for i in 2..held.len() {
        let (_, t2, e2) = held[i - 1];
        let j = (0..i - 1)
            .rev()
            .find(|&j| t2 - held[j].1 >= 0.5 * (t2 - t_first))
            .unwrap_or(0);
        let (_, t1, e1) = held[j];
        let rise = e2.f - e1.f;
        if rise <= 3.0 * e1.sigma.hypot(e2.sigma) {
            continue;
        }
        let least = |t: f64| e2.f + 0.5 * rise / (t2 - t1) * (t - t2);
        let below =
            |&(_, t, e): &(usize, f64, Estimate)| e.f < least(t) - 3.0 * e.sigma.hypot(e2.sigma);
        if below(&held[i]) && held[i..].iter().all(below) {
            for &(k, _, _) in &held[i..] {
                line[k] = false;
            }
            return;
        }
    }
}

/// Walks the record frame by frame (see the module's documentation); returns the frames and 1
/// when the track ended because the line moved too fast for a frame (counted as one smeared
/// frame), else 0.
fn march(v: &[f64], t0: f64, fs: f64, s: &TrackSettings, hum: &[f64]) -> (Vec<Frame>, usize) {
    let mut an = Analyser::new(fs);
    an.mask(hum);
    let span = v.len() as f64 / fs;
    let mut masked = hum.to_vec();
    let mut frames: Vec<Frame> = Vec::new();
    let mut pos = 0usize;
    let mut smeared = 0;
    // The frames the line's motion is predicted from: all but those that jumped off it.
    let mut held: Vec<Frame> = Vec::new();
    loop {
        // A line held still is not the disk's: it is masked as the hum is, and the disk's line
        // searched for anew.
        if let Some((from, f)) = still_line(&held, span) {
            let last: Vec<f64> = held[from..].iter().map(|h| h.a).collect();
            for fr in frames.iter_mut().filter(|fr| last.contains(&fr.a)) {
                fr.still = true;
            }
            masked.push(f);
            an.mask(&masked);
            held.clear();
        }
        let mut predicted = None;
        let (len_s, lo, hi) = match predict(&held, t0 + pos as f64 / fs) {
            Some(motion) => {
                // T and the pitch at the frame's middle, each from the other (two rounds).
                let mut t = s.max_frame;
                let mut f_mid = motion.f;
                let limit = s.max_frame.min(0.5 * motion.remaining());
                let mut allowed = t;
                for _ in 0..3 {
                    f_mid = motion.pitch(motion.end + 0.5 * t);
                    let fdot = motion.slope(f_mid);
                    allowed = (s.kappa / fdot.max(f64::MIN_POSITIVE)).sqrt();
                    t = allowed.min(limit);
                }
                let n = held.len();
                // A line too low for `cycles` periods in the longest frame, or whose end three
                // frames predict too near, but slow enough for a frame that holds them, is
                // followed in that frame: only its motion ends the track.
                let need = s.cycles / f_mid;
                let mut holds = t * f_mid >= s.cycles;
                if !holds && need <= allowed && need <= LOW_FRAME.max(s.search) {
                    (t, holds) = (need, true);
                }
                if holds {
                    predicted = Some((f_mid, (f_mid - motion.f).abs()));
                    (t, 0.8 * f_mid, 1.2 * f_mid)
                } else if n >= 4 && one_line(&held[n - 4..]) {
                    smeared = 1;
                    break;
                } else {
                    (s.search, 0.0, 2000.0)
                }
            }
            None => (s.search, 0.0, 2000.0),
        };
        let len = ((len_s * fs).round() as usize).max(16);
        if pos + len > v.len() {
            break;
        }
        let band = (lo.max(5.0).max(2.5 / len_s), hi.min(2000.0));
        let searched = lo == 0.0;
        let est = an.fundamental(&v[pos..pos + len], band, s.min_snr, searched);
        // A frame that jumps off the predicted pitch (a bump, a hum line's subharmonic) is
        // left out, and the line is looked for again about the prediction; after
        // [`LOST_AFTER`] in a row the line is lost, and searched for anew over the whole band.
        let jumped = match (predicted, est) {
            (Some((f, moved)), Some(e)) => {
                let off = (e.f - f).abs();
                off > JUMP * f && off > 2.0 * moved
            }
            _ => false,
        };
        let in_a_row = frames.iter().rev().take_while(|f| f.jumped).count();
        if jumped && in_a_row + 1 >= LOST_AFTER {
            held.clear();
        }
        let frame = Frame {
            a: t0 + pos as f64 / fs,
            b: t0 + (pos + len) as f64 / fs,
            est,
            searched,
            jumped,
            still: false,
        };
        if !jumped {
            held.push(frame);
        }
        frames.push(frame);
        pos += len;
    }
    (frames, smeared)
}

/// The line's motion at the end of the frames held: the last pitch $f$ at time $t$, its rate
/// $\dot f$, and the exponent $q$ of $\dot f \propto f^q$ (from the last three frames, 0 with two).
struct Motion {
    f: f64,
    t: f64,
    fdot: f64,
    q: f64,
    end: f64,
}

impl Motion {
    /// $\dot f$ at pitch `f`.
    fn slope(&self, f: f64) -> f64 {
        self.fdot.abs() * (f / self.f).powf(self.q)
    }

    /// The time from the last frame's end to the singularity of $\dot f \propto f^q$ (for
    /// $q > 1$, $t_0 - t = f/((q-1)\dot f)$); infinite for $q \le 1$.
    fn remaining(&self) -> f64 {
        if self.q > 1.0 && self.fdot > 0.0 {
            self.f / ((self.q - 1.0) * self.fdot) - (self.end - self.t)
        } else {
            f64::INFINITY
        }
    }

    /// The pitch at time `t`, by two midpoint steps of $\dot f(f)$.
    fn pitch(&self, t: f64) -> f64 {
        let h = 0.5 * (t - self.t);
        let mut f = self.f;
        for _ in 0..2 {
            let mid = f + 0.5 * h * self.slope(f);
            f += h * self.slope(mid);
        }
        f
    }
}

/// Largest ratio of consecutive frames' fundamentals on one line.
pub const STEP: f64 = 1.25;

/// Largest relative distance of a frame searched about the line's predicted pitch from that
/// prediction: a frame moves the pitch by at most `kappa / cycles` (a sixth at the defaults) of
/// itself, which the prediction from the last three frames follows to a few per cent; a frame
/// further off, and off by more than twice the motion predicted since the last frame held (near
/// $t_0$ the prediction lags a pitch that runs away), heard something else.
pub const JUMP: f64 = 0.1;

/// Frames in a row off the predicted pitch (see [`JUMP`]) after which the line is lost.
pub const LOST_AFTER: usize = 3;

/// Longest frame (s) that follows a line too low for `cycles` periods in the longest frame
/// (down to 3 Hz at the defaults): such a line moves slowly, and is followed, not cut.
pub const LOW_FRAME: f64 = 1.0;

/// Whether `frames` all hold a fundamental on one line: each frame searched over the whole band
/// within [`STEP`] of the one before (a frame searched about the line's predicted pitch is on
/// it by its band).
fn one_line(frames: &[Frame]) -> bool {
    frames.iter().all(|f| f.est.is_some())
        && frames.windows(2).all(|w| match (w[0].est, w[1].est) {
            (Some(p), Some(q)) => !w[1].searched || (q.f / p.f).max(p.f / q.f) <= STEP,
            _ => false,
        })
}

/// The line's motion from the last frames when the last three held it, for a frame that
/// starts at `start` (s).
fn predict(frames: &[Frame], start: f64) -> Option<Motion> {
    let mid = |f: &Frame| 0.5 * (f.a + f.b);
    let n = frames.len();
    if n < 3 || !one_line(&frames[n - 3..]) {
        return None;
    }
    let (p, q) = (&frames[n - 2], &frames[n - 1]);
    let (e, g) = (p.est?, q.est?);
    let fdot = (g.f - e.f) / (mid(q) - mid(p));
    let exponent = match frames[n - 3].est.map(|d| (&frames[n - 3], d)) {
        Some((o, d)) => {
            let fdot0 = (e.f - d.f) / (mid(p) - mid(o));
            let r = (fdot / fdot0).ln() / (0.5 * (g.f + e.f) / (0.5 * (e.f + d.f))).ln();
            if r.is_finite() {
                r.clamp(0.0, 8.0)
            } else {
                0.0
            }
        }
        None => 0.0,
    };
    Some(Motion {
        f: g.f,
        t: mid(q),
        fdot,
        q: exponent,
        end: start,
    })
}

#[cfg(test)]
mod diagnosis;
mod motion;
pub mod rising;
mod still;
