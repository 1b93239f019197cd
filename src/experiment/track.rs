//! A frequency-vs-time track from a sound recording, by short-time spectra (`rustfft`).
//!
//! **Which line is followed.** The sound of a spinning disk is at the contact point's rate,
//! $\Omega/2\pi$, with harmonics at $h\Omega/2\pi$ (see [`sound`](crate::experiment::sound)).
//! Each frame's fundamental is the frequency $f$ that maximises the harmonic sum
//! $S(f) = \sum_{h=1}^{3} \tilde M(hf)$ of the cleaned magnitude spectrum: at the true
//! fundamental all three harmonics add, at half of it only one does, at twice it only the even
//! ones. So the track follows $\Omega$ itself, not a harmonic, even where the second harmonic is
//! the loudest.
//!
//! **Hum.** $\tilde M_k$ is the magnitude with the bins within 4 Hz of the mains lines (50 and
//! 60 Hz and their harmonics) set to zero: the track is never drawn to hum, and where the disk's
//! line crosses a mains line those frames fall out as stray or silent. (A median background
//! over frames was tried first: it also removed the disk's own line early in the record, where
//! the rate changes slowly.) Each frame's mean is removed (drift); clipped or dropped samples
//! only broaden the lines.
//!
//! **Precision.** Frames of $L$ samples (a power of two, at least 0.2 s: four cycles of the
//! slowest rate, 100 rad/s), Hann-windowed,
//! zero-padded four times, not overlapping (so their errors are independent). Each harmonic's
//! peak is placed by a parabola through the log-magnitudes of its three highest bins, and the
//! fundamental is their weighted mean $\sum_h w_h f_h/h / \sum_h w_h$, $w_h = (h M_h)^2$.
//!
//! **Where the track stops.** Frames whose rate changes by more than `max_change` of itself
//! across the frame are left out with all later ones (near $t_0$ the line smears over many
//! bins), as are frames whose peak is not `min_snr` times the frame's median magnitude
//! (silence after the disk settles, and the last frame before a silence, in which the disk may
//! settle) and frames more than 10 % off the median of their four
//! neighbours (a stray line).

use crate::experiment::error::ExperimentError;
use crate::experiment::trace::Trace;
use rustfft::num_complex::Complex;
use rustfft::FftPlanner;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// How the track is made.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct TrackSettings {
    /// Frame length (s), rounded up to a power of two samples.
    pub frame: f64,
    /// Largest relative change of the rate across a frame.
    pub max_change: f64,
    /// A frame's peak must exceed its median magnitude this many times.
    pub min_snr: f64,
}

impl Default for TrackSettings {
    fn default() -> Self {
        Self {
            frame: 0.2,
            max_change: 0.12,
            min_snr: 10.0,
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
    /// The fundamental, $\Omega$ (rad/s).
    pub omega: f64,
    /// The fundamental's magnitude over the frame's median.
    pub snr: f64,
}

/// The track.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrequencyTrack {
    /// Sample rate (S/s).
    pub sample_rate: f64,
    /// Frame length (samples).
    pub frame: usize,
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
}

/// The parabola's vertex offset through three log-magnitudes around a local maximum.
fn vertex(l: f64, c: f64, r: f64) -> f64 {
    let d = l - 2.0 * c + r;
    if d < 0.0 {
        (0.5 * (l - r) / d).clamp(-0.5, 0.5)
    } else {
        0.0
    }
}

/// The frequency track of a uniformly sampled sound recording.
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
    let len = ((s.frame * fs).ceil() as usize).next_power_of_two().max(64);
    let nfft = 4 * len;
    let frames = trace.v.len() / len;
    if frames < 8 {
        return Err(ExperimentError::TooFewPeaks {
            file,
            what: "spectral frames".into(),
            found: frames,
            needed: 8,
            hint: format!("record at least {:.2} s of sound", 8.0 * len as f64 / fs),
        });
    }
    let half = nfft / 2;
    let fft = FftPlanner::<f64>::new().plan_fft_forward(nfft);
    let window: Vec<f64> = (0..len)
        .map(|j| (PI * (j as f64 + 0.5) / len as f64).sin().powi(2))
        .collect();
    let mut mags: Vec<Vec<f64>> = Vec::with_capacity(frames);
    let mut buf = vec![Complex::new(0.0, 0.0); nfft];
    for k in 0..frames {
        let x = &trace.v[k * len..(k + 1) * len];
        let mean = x.iter().sum::<f64>() / len as f64;
        for (j, c) in buf.iter_mut().enumerate() {
            *c = if j < len {
                Complex::new((x[j] - mean) * window[j], 0.0)
            } else {
                Complex::new(0.0, 0.0)
            };
        }
        fft.process(&mut buf);
        mags.push(buf[..=half].iter().map(|c| c.norm()).collect());
    }
    let median = |v: &mut Vec<f64>| {
        let m = v.len() / 2;
        *v.select_nth_unstable_by(m, f64::total_cmp).1
    };
    // Bins within 4 Hz of a mains line (50, 60 Hz and harmonics up to 1 kHz) are not followed.
    let bin_hz = fs / nfft as f64;
    let mains: Vec<bool> = (0..=half)
        .map(|b| {
            let f = b as f64 * bin_hz;
            [50.0, 60.0].iter().any(|m: &f64| {
                let h = (f / m).round();
                (1.0..=20.0).contains(&h) && (f - h * m).abs() < 4.0
            })
        })
        .collect();
    let b_lo = ((5.0 / bin_hz).ceil() as usize).max(2);
    let b_hi = half / 3 - 2;
    let mut raw: Vec<Option<TrackPoint>> = Vec::with_capacity(frames);
    let mut silent = 0;
    for (k, m) in mags.iter().enumerate() {
        let clean: Vec<f64> = m
            .iter()
            .zip(&mains)
            .map(|(x, hum)| if *hum { 0.0 } else { *x })
            .collect();
        let best = (b_lo..b_hi)
            .map(|b| (b, clean[b] + clean[2 * b] + clean[3 * b]))
            .max_by(|x, y| x.1.total_cmp(&y.1));
        let floor = median(&mut m.clone()).max(f64::MIN_POSITIVE);
        let Some((b0, _)) = best else {
            silent += 1;
            raw.push(None);
            continue;
        };
        // The local maximum of harmonic h near h b0, and its refined frequency.
        let refine = |h: usize| -> (f64, f64) {
            let c = h * b0;
            let lo = c.saturating_sub(2).max(1);
            let hi = (c + 2).min(half - 1);
            let p = (lo..=hi)
                .max_by(|x, y| m[*x].total_cmp(&m[*y]))
                .unwrap_or(c);
            let ln = |b: usize| m[b].max(f64::MIN_POSITIVE).ln();
            let d = vertex(ln(p - 1), ln(p), ln(p + 1));
            ((p as f64 + d) * fs / nfft as f64, m[p])
        };
        let (f1, m1) = refine(1);
        if m1 < s.min_snr * floor {
            silent += 1;
            raw.push(None);
            continue;
        }
        let (mut num, mut den) = (0.0, 0.0);
        for h in 1..=3usize {
            let (f, mh) = if h == 1 { (f1, m1) } else { refine(h) };
            if mh >= s.min_snr * floor {
                let w = (h as f64 * mh).powi(2);
                num += w * f / h as f64;
                den += w;
            }
        }
        let a = trace.t[k * len];
        raw.push(Some(TrackPoint {
            a,
            b: a + len as f64 * dt,
            omega: 2.0 * PI * num / den,
            snr: m1 / floor,
        }));
    }
    // Stray lines: off the median of their four neighbours by more than 10 %.
    let mut smeared = 0;
    let om: Vec<Option<f64>> = raw.iter().map(|p| p.map(|p| p.omega)).collect();
    let mut stray = 0;
    let mut kept: Vec<TrackPoint> = Vec::new();
    for (k, p) in raw.iter().enumerate() {
        let Some(p) = p else { continue };
        if k + 1 < frames && raw[k + 1].is_none() {
            // The last sound before a silence: the disk may settle inside this frame.
            smeared += 1;
            continue;
        }
        let mut nb: Vec<f64> = (k.saturating_sub(2)..(k + 3).min(frames))
            .filter(|&j| j != k)
            .filter_map(|j| om[j])
            .collect();
        if nb.len() >= 2 {
            let m = median(&mut nb);
            if (p.omega / m - 1.0).abs() > 0.1 {
                stray += 1;
                continue;
            }
        }
        kept.push(*p);
    }
    // Smeared: from the first frame across which the rate changes too much.
    if kept.len() >= 3 {
        let cut = (1..kept.len() - 1).find(|&k| {
            let span = kept[k + 1].a - kept[k - 1].a;
            let change = (kept[k + 1].omega - kept[k - 1].omega) / kept[k].omega;
            change * (kept[k].b - kept[k].a) / span > s.max_change
        });
        if let Some(c) = cut {
            smeared = kept.len() - c;
            kept.truncate(c);
        }
    }
    Ok(FrequencyTrack {
        sample_rate: fs,
        frame: len,
        frames,
        points: kept,
        silent,
        stray,
        smeared,
    })
}
