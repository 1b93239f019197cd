//! The mains phase followed on all the lines of one grid at once.
//!
//! A grid's hum is a family of lines at $k f_m$ whose phases are locked to the fundamental's:
//! $\Phi_k(t) = k\,\Phi(t) + c_k$, the wander of line $k$ being $k$ times the fundamental's. Where
//! the disk's harmonics cover one line for seconds (a slow sweep near the start of a record can
//! sit on 50 Hz for four), another is clear; and a weak line followed alone loses its phase once
//! the wander is a few tenths of a hertz. So the fundamental's phase $\Phi$ is followed on all
//! the family's lines together, as [`mains_drift`](crate::sound_analysis::mains::drift) follows one line:
//!
//! - **Frequency**, in segments of [`SEGMENT_S`] s every [`HOP_S`] s on a copy averaged to
//!   about 2 kS/s: the maximum over $g$ within [`reach`] of $f_m$ of the family's power
//!   $\sum_k |\sum_j w_{kj} x_j e^{-2\pi i k g t_j}|^2$ ($w_k$ the Hann window times line $k$'s
//!   taper, [`tapered`]; the lines with less than half their window's weight left out), the
//!   maximum-likelihood frequency of harmonics of unknown amplitudes in white noise. The phase is
//!   its integral ([`integrate`]).
//! - **Phase**, [`REFINE`] rounds: in each segment each line's phase against $k\Phi$,
//!   $\psi_k = \arg \sum_j w_{kj} x_j e^{-ik\Phi_j}$, is $k\delta + c_k$ plus noise, $\delta$ the
//!   fundamental's phase error there. The $\delta$ of every segment and the $c_k$ are found by
//!   alternating ([`OFFSET_ROUNDS`]): $c_k$ the circular mean over the segments of
//!   $\psi_k - k\delta$, and $\delta$ the mean over the lines of $(\psi_k - c_k)/k$ (the branch
//!   nearest the previous segment's $\delta$), weighted by $k^2|z_k|^2$, the inverse of its
//!   variance. $\delta$ is then added, linear between the segments' centres ([`add_between`]).

use crate::sound_analysis::mains::drift::{
    add_between, integrate, peak, phasors, reach, tapered, HOP_S, SEGMENT_S,
};
use crate::sound_analysis::mains::line_power::{hann, power};
use crate::sound_analysis::phase_blocks::wrap;
use rayon::prelude::*;
use std::f64::consts::TAU;

/// Rounds in which the phase is corrected by the lines' phases in each segment.
pub const REFINE: usize = 2;

/// Rounds of the alternation between the segments' phase errors and the lines' constants.
pub const OFFSET_ROUNDS: usize = 3;

/// The fundamental's phase $\Phi$ (rad) at every sample of `v` (rate `fs`) of the grid whose
/// fundamental is near `f` Hz, followed on its lines `ks` (harmonic numbers); `clear(j, i)` says
/// whether sample `j` is clear of the disk for line `ks[i]`. Line $k$'s phase is $k\Phi$ plus a
/// constant (see the module's documentation).
pub fn mains_phase(
    v: &[f64],
    fs: f64,
    f: f64,
    ks: &[usize],
    clear: &(dyn Fn(usize, usize) -> bool + Sync),
) -> Vec<f64> {
    let tapers: Vec<Vec<f64>> = (0..ks.len())
        .into_par_iter()
        .map(|i| tapered(v.len(), fs, &|j| clear(j, i)))
        .collect();
    let freq = frequencies(v, fs, f, ks, &tapers);
    let mut phase = integrate(&freq, f, v.len(), fs);
    for _ in 0..REFINE {
        let found = phase_errors(v, fs, f, ks, &phase, &tapers);
        add_between(&mut phase, &found, fs);
    }
    phase
}

/// The fundamental's frequency (Hz) in each segment clear enough on at least one line, with
/// the segment's centre time (s).
fn frequencies(v: &[f64], fs: f64, f: f64, ks: &[usize], tapers: &[Vec<f64>]) -> Vec<(f64, f64)> {
    let q = ((fs / 2000.0).floor() as usize).max(1);
    let fs_low = fs / q as f64;
    let mean = |c: &[f64]| c.iter().sum::<f64>() / q as f64;
    let low: Vec<f64> = v.chunks_exact(q).map(mean).collect();
    let low_w: Vec<Vec<f64>> = tapers
        .iter()
        .map(|w| w.chunks_exact(q).map(mean).collect())
        .collect();
    let seg = ((SEGMENT_S * fs_low) as usize).max(8);
    let hop = ((HOP_S * fs_low) as usize).max(1);
    let hann = hann(seg);
    let total: f64 = hann.iter().sum();
    let starts: Vec<usize> = (0..)
        .map(|s| s * hop)
        .take_while(|s| s + seg <= low.len())
        .collect();
    starts
        .into_par_iter()
        .filter_map(|start| {
            let part = &low[start..start + seg];
            // The lines clear enough here, and below the copy's limit: (k, weighed samples).
            let lines: Vec<(f64, Vec<f64>)> = ks
                .iter()
                .zip(&low_w)
                .filter(|(k, _)| (**k as f64) * (f + reach(f)) < 0.45 * fs_low)
                .filter_map(|(k, w)| {
                    let w = &w[start..start + seg];
                    let kept: f64 = hann.iter().zip(w).map(|(h, w)| h * w).sum();
                    (kept >= 0.5 * total)
                        .then(|| (*k as f64, part.iter().zip(w).map(|(x, w)| x * w).collect()))
                })
                .collect();
            if lines.is_empty() {
                return None;
            }
            let top = lines.iter().map(|l| l.0).fold(0.0, f64::max);
            let score = |g: f64| -> f64 {
                lines
                    .iter()
                    .map(|(k, x)| power(x, &hann, fs_low, k * g))
                    .sum()
            };
            let g = peak(&score, f, reach(f), 0.25 / (SEGMENT_S * top))?;
            Some(((start as f64 + 0.5 * seg as f64) / fs_low, g))
        })
        .collect()
}

/// One round's phase errors $\delta$ of the fundamental (rad) at the centres (s) of the
/// segments where some line is clear enough, against `phase`.
fn phase_errors(
    v: &[f64],
    fs: f64,
    f: f64,
    ks: &[usize],
    phase: &[f64],
    tapers: &[Vec<f64>],
) -> Vec<(f64, f64)> {
    let seg = ((SEGMENT_S * fs) as usize).max(8);
    let hop = ((HOP_S * fs) as usize).max(1);
    let hann = hann(seg);
    let total: f64 = hann.iter().sum();
    let count = if v.len() >= seg {
        (v.len() - seg) / hop + 1
    } else {
        0
    };
    let top = ks.iter().copied().max().unwrap_or(1);
    // Per segment and line: the sums of w x e^{-ik Phi} and of w.
    let mut sums = vec![vec![(0.0, 0.0, 0.0); ks.len()]; count];
    let mut powers = vec![[1.0, 0.0]; top + 1];
    for (j, (p, x)) in phasors(phase, 1.0, f, fs).zip(v).enumerate() {
        for k in 1..=top {
            let [c, s] = powers[k - 1];
            powers[k] = [c * p[0] - s * p[1], s * p[0] + c * p[1]];
        }
        let first = (j + hop).saturating_sub(seg) / hop;
        for (k_seg, row) in sums.iter_mut().enumerate().take(j / hop + 1).skip(first) {
            let h = hann[j - k_seg * hop];
            for ((sum, &k), taper) in row.iter_mut().zip(ks).zip(tapers) {
                let w = h * taper[j];
                let [c, s] = powers[k];
                sum.0 += w * x * c;
                sum.1 -= w * x * s;
                sum.2 += w;
            }
        }
    }
    // Per segment: each clear line's phase.
    let seen: Vec<Segment> = sums
        .iter()
        .enumerate()
        .map(|(s, row)| Segment {
            t: (s as f64 * hop as f64 + 0.5 * seg as f64) / fs,
            lines: row
                .iter()
                .zip(ks)
                .enumerate()
                .filter(|(_, ((re, im, kept), _))| *kept >= 0.5 * total && re.hypot(*im) > 0.0)
                .map(|(line, ((re, im, _), &k))| {
                    let k = k as f64;
                    LineInSegment {
                        line,
                        k,
                        psi: im.atan2(*re),
                        weight: k * k * (re * re + im * im),
                    }
                })
                .collect(),
        })
        .filter(|s| !s.lines.is_empty())
        .collect();
    let delta = offsets(&seen, ks.len());
    seen.iter().map(|s| s.t).zip(delta).collect()
}

/// One line's phase in one segment.
struct LineInSegment {
    /// Its index among the grid's lines.
    line: usize,
    /// Its harmonic number $k$.
    k: f64,
    /// $\psi_k$ (rad).
    psi: f64,
    /// $k^2|z_k|^2$, the inverse of the variance of $\psi_k/k$ but for the noise's level.
    weight: f64,
}

/// A segment's centre time (s) and the phases of its clear lines.
struct Segment {
    t: f64,
    lines: Vec<LineInSegment>,
}

/// The fundamental's phase error $\delta$ in each segment of `seen`, with the constants $c_k$
/// of the grid's `lines` lines, by alternating (see the module's documentation).
fn offsets(seen: &[Segment], lines: usize) -> Vec<f64> {
    let mut delta = vec![0.0; seen.len()];
    for _ in 0..OFFSET_ROUNDS {
        // Each line's constant: the circular mean of psi - k delta, weighted.
        let mut acc = vec![(0.0, 0.0); lines];
        for (s, d) in seen.iter().zip(&delta) {
            for l in &s.lines {
                let a = &mut acc[l.line];
                a.0 += l.weight * (l.psi - l.k * d).cos();
                a.1 += l.weight * (l.psi - l.k * d).sin();
            }
        }
        let c: Vec<f64> = acc.iter().map(|(re, im)| im.atan2(*re)).collect();
        // Each segment's delta: the weighted mean of the lines' branches nearest the previous.
        let mut previous = delta.first().copied().unwrap_or(0.0);
        for (s, d) in seen.iter().zip(delta.iter_mut()) {
            let (mut num, mut den) = (0.0, 0.0);
            for l in &s.lines {
                let step = TAU / l.k;
                let raw = wrap(l.psi - c[l.line]) / l.k;
                let branch = raw + step * ((previous - raw) / step).round();
                num += l.weight * branch;
                den += l.weight;
            }
            *d = num / den;
            previous = *d;
        }
    }
    delta
}

#[cfg(test)]
mod tests {
    use super::mains_phase;
    use std::f64::consts::TAU;

    /// A grid at 50 Hz whose frequency wanders by 0.2 Hz (period 12 s), its lines 1, 2 and 3
    /// (2, 1 and 0.5 % of full scale) in white noise, 12 s at 4 kS/s; for the first 4 s a louder
    /// tone at 51 Hz covers the fundamental, whose samples there are not clear. The followed phase
    /// is within 0.05 rad of the grid's throughout, the covered stretch included (the
    /// fundamental's phase there comes from the other lines).
    #[test]
    fn a_covered_fundamental_is_followed_on_the_other_lines() {
        let fs = 4000.0;
        let n = 48_000;
        let truth = |t: f64| TAU * 50.0 * t + 0.2 * 12.0 * (1.0 - (TAU * t / 12.0).cos());
        let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
        let x: Vec<f64> = (0..n)
            .map(|j| {
                let t = j as f64 / fs;
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                let u = (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
                let p = truth(t);
                let cover = if t < 4.0 {
                    0.2 * (TAU * 51.0 * t).sin()
                } else {
                    0.0
                };
                0.02 * p.sin()
                    + 0.01 * (2.0 * p + 0.4).sin()
                    + 0.005 * (3.0 * p + 1.1).sin()
                    + 0.01 * u
                    + cover
            })
            .collect();
        let clear = |j: usize, i: usize| i != 0 || j as f64 / fs >= 4.0;
        let phase = mains_phase(&x, fs, 50.0, &[1, 2, 3], &clear);
        let err: Vec<f64> = (0..n).map(|j| phase[j] - truth(j as f64 / fs)).collect();
        let mean = err.iter().sum::<f64>() / n as f64;
        let worst = err
            .iter()
            .skip(2000)
            .take(n - 4000)
            .map(|e| (e - mean).abs())
            .fold(0.0, f64::max);
        assert!(worst < 0.05, "phase off by up to {worst:.3} rad");
    }
}
