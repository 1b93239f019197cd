//! A mains line's phase followed over a record, as the grid's frequency wanders.
//!
//! A grid's frequency follows its load: $f(t) = k f_m + \delta(t)$, $\delta$ a slow wander of
//! hundredths to tenths of a hertz. The line's frequency is measured in segments of
//! [`SEGMENT_S`] seconds every [`HOP_S`] seconds: the maximum of the segment's power
//! $|\sum_j w_j x_j e^{-2\pi i g t_j}|^2$ ($w$ the Hann window times the samples the caller says
//! are clear of the disk) over $g$ within [`reach`] of the line (steps of a quarter of
//! $1/T_{seg}$, then a parabola), on a copy averaged to about 2 kS/s; the samples near the disk
//! weigh nothing, and their neighbours less ([`TAPER_S`]). Segments of less than half their
//! window's weight are left out; the phase is then refined by the line's own phase in each
//! segment ([`REFINE`] rounds). Between the segments' centres $f(t)$ is linear (and extended so beyond
//! the first and last, within the search's reach), and the phase is its integral,
//! $$\Phi(t_j) = 2\pi \sum_{i < j} f\!\left(t_i + \tfrac{\Delta t}{2}\right)\Delta t .$$
//! A steady line gives $\Phi = 2\pi f t$, its frequency measured to the segments' precision.

use std::f64::consts::TAU;

/// Length of the segments in which the line's frequency is measured (s).
pub const SEGMENT_S: f64 = 2.0;

/// Time between the segments' starts (s).
pub const HOP_S: f64 = 1.0;

/// How far (Hz) from its nominal frequency `f` a line is searched for: 0.3 Hz at the mains
/// fundamental, in proportion above it (a harmonic's wander is $k$ times the fundamental's).
pub fn reach(f: f64) -> f64 {
    0.3f64.max(0.006 * f)
}

/// The phase (rad) at every sample of `v` (rate `fs`) of the line near `f` Hz, its frequency
/// followed segment by segment on the samples `clear(j)` admits (see the module's documentation).
pub fn line_phase(v: &[f64], fs: f64, f: f64, clear: &dyn Fn(usize) -> bool) -> Vec<f64> {
    let taper = tapered(v.len(), fs, clear);
    let q = ((fs / 2000.0).floor() as usize).max(1);
    let fs_low = fs / q as f64;
    let low: Vec<(f64, f64)> = v
        .chunks_exact(q)
        .zip(taper.chunks_exact(q))
        .map(|(c, w)| {
            (
                c.iter().sum::<f64>() / q as f64,
                w.iter().sum::<f64>() / q as f64,
            )
        })
        .collect();
    let seg = ((SEGMENT_S * fs_low) as usize).max(8);
    let hop = ((HOP_S * fs_low) as usize).max(1);
    let hann = hann(seg);
    // (centre time, frequency) of each segment clear enough.
    let mut found: Vec<(f64, f64)> = Vec::new();
    let mut start = 0;
    while start + seg <= low.len() {
        let part = &low[start..start + seg];
        let total: f64 = hann.iter().sum();
        let kept: f64 = hann.iter().zip(part).map(|(w, p)| w * p.1).sum();
        if kept >= 0.5 * total {
            let t0 = start as f64 / fs_low;
            let power = |g: f64| -> f64 {
                let (mut re, mut im) = (0.0, 0.0);
                for (i, (w, &(x, ok))) in hann.iter().zip(part).enumerate() {
                    if ok > 0.0 {
                        let (s, c) = (TAU * g * (t0 + i as f64 / fs_low)).sin_cos();
                        re += w * ok * x * c;
                        im -= w * ok * x * s;
                    }
                }
                re * re + im * im
            };
            if let Some(g) = peak(&power, f, reach(f), 0.25 / SEGMENT_S) {
                found.push((t0 + 0.5 * seg as f64 / fs_low, g));
            }
        }
        start += hop;
    }
    let freq = found;
    let dt = 1.0 / fs;
    let m = freq.len();
    // The segment pair about time t, found by walking forward as t grows.
    let mut i = 1;
    let mut at = |t: f64| -> f64 {
        if m < 2 {
            return freq.first().map_or(f, |p| p.1);
        }
        while i < m - 1 && freq[i].0 <= t {
            i += 1;
        }
        let ((a, fa), (b, fb)) = (freq[i - 1], freq[i]);
        (fa + (fb - fa) * (t - a) / (b - a)).clamp(f - reach(f), f + reach(f))
    };
    let mut phase = Vec::with_capacity(v.len());
    let mut acc = 0.0;
    for j in 0..v.len() {
        phase.push(acc);
        acc += TAU * at((j as f64 + 0.5) * dt) * dt;
    }
    for _ in 0..REFINE {
        refine(v, fs, &mut phase, &taper);
    }
    phase
}

/// How long (s) the weight of the samples takes to rise from a sample the disk is near to a
/// clear one.
pub const TAPER_S: f64 = 0.4;

/// Each sample's weight: 0 where `clear` says the disk is near the line, rising as
/// $\sin^2(\pi d/2D)$ with the time $d$ to the nearest such sample, $D$ = [`TAPER_S`], to 1: a
/// segment's sums then have no sharp edge through which the disk's line, a few hertz off, would
/// leak.
fn tapered(n: usize, fs: f64, clear: &dyn Fn(usize) -> bool) -> Vec<f64> {
    let d = (TAPER_S * fs).max(1.0);
    let mut dist = vec![f64::INFINITY; n];
    let mut last = f64::NEG_INFINITY;
    for (j, x) in dist.iter_mut().enumerate() {
        if !clear(j) {
            last = j as f64;
        }
        *x = j as f64 - last;
    }
    let mut next = f64::INFINITY;
    for (j, x) in dist.iter_mut().enumerate().rev() {
        if *x == 0.0 {
            next = j as f64;
        }
        *x = x.min(next - j as f64);
    }
    dist.iter()
        .map(|&x| {
            if x >= d {
                1.0
            } else {
                (0.5 * std::f64::consts::PI * x / d).sin().powi(2)
            }
        })
        .collect()
}

/// Rounds in which the phase is corrected by the line's own phase in each segment.
pub const REFINE: usize = 2;

/// Corrects `phase` by the line's phase against it in each segment, $\arg\sum_j w_j x_j
/// e^{-i\Phi_j}$ ($w$ the Hann window on the clear samples; the weighted mean of the phase's error
/// over the segment, referred to its centre), unwrapped from segment to segment and linear
/// between the centres (extended so beyond the first and last). A segment measures the mean of
/// the frequency over it, which differs from the frequency at its centre where the wander
/// curves; the phase measures what the frequency left.
fn refine(v: &[f64], fs: f64, phase: &mut [f64], taper: &[f64]) {
    let seg = ((SEGMENT_S * fs) as usize).max(8);
    let hop = ((HOP_S * fs) as usize).max(1);
    let hann = hann(seg);
    let total: f64 = hann.iter().sum();
    // Each sample's weighted value against the phase, once for the overlapping segments.
    let against: Vec<(f64, f64)> = (0..v.len())
        .map(|j| {
            if taper[j] > 0.0 {
                let (s, c) = phase[j].sin_cos();
                (v[j] * c, -v[j] * s)
            } else {
                (0.0, 0.0)
            }
        })
        .collect();
    let mut found: Vec<(f64, f64)> = Vec::new();
    let mut start = 0;
    while start + seg <= v.len() {
        let (mut re, mut im, mut kept) = (0.0, 0.0, 0.0);
        for (i, h) in hann.iter().enumerate() {
            let j = start + i;
            let w = h * taper[j];
            if w > 0.0 {
                re += w * against[j].0;
                im += w * against[j].1;
                kept += w;
            }
        }
        if kept >= 0.5 * total && re.hypot(im) > 0.0 {
            let centre = (start as f64 + 0.5 * seg as f64) / fs;
            let mut psi = im.atan2(re);
            if let Some(&(_, last)) = found.last() {
                psi = last + crate::phase_blocks::wrap(psi - last);
            }
            found.push((centre, psi));
        }
        start += hop;
    }
    let n = found.len();
    if n < 2 {
        return;
    }
    let mut i = 1;
    for (j, p) in phase.iter_mut().enumerate() {
        let t = (j as f64 + 0.5) / fs;
        while i + 1 < n && found[i].0 <= t {
            i += 1;
        }
        let ((a, pa), (b, pb)) = (found[i - 1], found[i]);
        *p += pa + (pb - pa) * (t - a) / (b - a);
    }
}

/// The maximum of `power` within `reach` of `f` (steps `step`, then a parabola); `None` when it
/// lies on the search's edge (no line there).
fn peak(power: &dyn Fn(f64) -> f64, f: f64, reach: f64, step: f64) -> Option<f64> {
    let n = (reach / step).ceil() as i64;
    let grid: Vec<(f64, f64)> = (-n..=n)
        .map(|i| {
            let g = f + i as f64 * step;
            (g, power(g))
        })
        .collect();
    let best = (0..grid.len()).max_by(|a, b| grid[*a].1.total_cmp(&grid[*b].1))?;
    if best == 0 || best + 1 == grid.len() {
        return None;
    }
    let (l, c, r) = (grid[best - 1].1, grid[best].1, grid[best + 1].1);
    let d = l - 2.0 * c + r;
    let off = if d < 0.0 { 0.5 * (l - r) / d } else { 0.0 };
    Some(grid[best].0 + off.clamp(-0.5, 0.5) * step)
}

/// The Hann window of `n` points.
pub(crate) fn hann(n: usize) -> Vec<f64> {
    (0..n)
        .map(|j| {
            (std::f64::consts::PI * (j as f64 + 0.5) / n as f64)
                .sin()
                .powi(2)
        })
        .collect()
}
