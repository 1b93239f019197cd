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

use crate::line_power::{hann, power};
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
    let total: f64 = hann.iter().sum();
    // (centre time, frequency) of each segment clear enough.
    let mut found: Vec<(f64, f64)> = Vec::new();
    let mut start = 0;
    while start + seg <= low.len() {
        let part = &low[start..start + seg];
        let kept: f64 = hann.iter().zip(part).map(|(w, p)| w * p.1).sum();
        if kept >= 0.5 * total {
            let weighed: Vec<f64> = part.iter().map(|(x, ok)| x * ok).collect();
            let at = |g: f64| power(&weighed, &hann, fs_low, g);
            if let Some(g) = peak(&at, f, reach(f), 0.25 / SEGMENT_S) {
                let t0 = start as f64 / fs_low;
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
        refine(v, fs, f, &mut phase, &taper);
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
    // sin^2 at the whole sample distances below d, once.
    let rise: Vec<f64> = (0..d.ceil() as usize)
        .map(|x| (0.5 * std::f64::consts::PI * x as f64 / d).sin().powi(2))
        .collect();
    for x in dist.iter_mut() {
        *x = if *x >= d { 1.0 } else { rise[*x as usize] };
    }
    dist
}

/// Rounds in which the phase is corrected by the line's own phase in each segment.
pub const REFINE: usize = 2;

/// Corrects `phase` by the line's phase against it in each segment, $\arg\sum_j w_j x_j
/// e^{-i\Phi_j}$ ($w$ the Hann window on the clear samples; the weighted mean of the phase's error
/// over the segment, referred to its centre), unwrapped from segment to segment and linear
/// between the centres (extended so beyond the first and last), `f` the line's nominal
/// frequency (Hz). A segment measures the mean of
/// the frequency over it, which differs from the frequency at its centre where the wander
/// curves; the phase measures what the frequency left.
fn refine(v: &[f64], fs: f64, f: f64, phase: &mut [f64], taper: &[f64]) {
    let seg = ((SEGMENT_S * fs) as usize).max(8);
    let hop = ((HOP_S * fs) as usize).max(1);
    let hann = hann(seg);
    let total: f64 = hann.iter().sum();
    // Each segment's sums, the samples streamed once: sample j lies in the segments that
    // start at k hop for k hop <= j < k hop + seg.
    let count = if v.len() >= seg {
        (v.len() - seg) / hop + 1
    } else {
        0
    };
    let mut sums = vec![(0.0, 0.0, 0.0); count];
    for (j, ([c, s], (x, w))) in phasors(phase, f, fs).zip(v.iter().zip(taper)).enumerate() {
        let (re, im) = (w * x * c, -w * x * s);
        let first = (j + hop).saturating_sub(seg) / hop;
        for (k, sum) in sums.iter_mut().enumerate().take(j / hop + 1).skip(first) {
            let h = hann[j - k * hop];
            sum.0 += h * re;
            sum.1 += h * im;
            sum.2 += h * w;
        }
    }
    let mut found: Vec<(f64, f64)> = Vec::new();
    for (k, &(re, im, kept)) in sums.iter().enumerate() {
        if kept >= 0.5 * total && re.hypot(im) > 0.0 {
            let centre = (k as f64 * hop as f64 + 0.5 * seg as f64) / fs;
            let mut psi = im.atan2(re);
            if let Some(&(_, last)) = found.last() {
                psi = last + crate::phase_blocks::wrap(psi - last);
            }
            found.push((centre, psi));
        }
    }
    let n = found.len();
    if n < 2 {
        return;
    }
    // Each pair of centres' line: its start, value there and slope.
    let lines: Vec<(f64, f64, f64)> = found
        .windows(2)
        .map(|w| (w[0].0, w[0].1, (w[1].1 - w[0].1) / (w[1].0 - w[0].0)))
        .collect();
    let mut i = 0;
    for (j, p) in phase.iter_mut().enumerate() {
        let t = (j as f64 + 0.5) / fs;
        while i + 2 < n && found[i + 1].0 <= t {
            i += 1;
        }
        let (a, pa, slope) = lines[i];
        *p += pa + slope * (t - a);
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

/// Samples between the exact phasors of [`phasors`].
const ANCHOR: usize = 16;

/// The phasors $(\cos\Phi_j, \sin\Phi_j)$ of a followed phase `phase` (rad) of a line near
/// `f` Hz, sampled at `fs`. Every [`ANCHOR`]-th is exact; between, the phase is the anchor's
/// $\Phi_k$ plus the steady line's $2\pi f (j - k)/f_s$ (a table of [`ANCHOR`] phasors) plus the
/// wander's small remainder $\epsilon = \Phi_j - \Phi_k - 2\pi f (j - k)/f_s$, whose phasor is
/// its Taylor series to $\epsilon^6$ (error below $\epsilon^7/5040$, $10^{-13}$ at the largest
/// $|\epsilon|$ it is used for, [`SMALL`]; a larger remainder takes its sine and cosine). The
/// wander is a few hertz at most, so over [`ANCHOR`] samples $\epsilon$ stays below
/// a hundredth of a radian at 8 kS/s, and a sine and a cosine per sample become one per anchor.
pub fn phasors(phase: &[f64], f: f64, fs: f64) -> impl Iterator<Item = [f64; 2]> + '_ {
    let w = TAU * f / fs;
    let table: [(f64, f64); ANCHOR] = std::array::from_fn(|m| (w * m as f64).sin_cos());
    let mut anchor = (0.0, [1.0, 0.0]);
    phase.iter().enumerate().map(move |(j, &p)| {
        let m = j % ANCHOR;
        if m == 0 {
            let (s, c) = p.sin_cos();
            anchor = (p, [c, s]);
            return [c, s];
        }
        let e = p - anchor.0 - w * m as f64;
        let (es, ec) = if e.abs() <= SMALL {
            let e2 = e * e;
            (
                e * (1.0 - e2 / 6.0 * (1.0 - e2 / 20.0)),
                1.0 - e2 / 2.0 * (1.0 - e2 / 12.0 * (1.0 - e2 / 30.0)),
            )
        } else {
            e.sin_cos()
        };
        let (ts, tc) = table[m];
        // The anchor's phasor turned by the steady step, then by the remainder.
        let [ac, as_] = anchor.1;
        let (c1, s1) = (ac * tc - as_ * ts, as_ * tc + ac * ts);
        [c1 * ec - s1 * es, s1 * ec + c1 * es]
    })
}

/// The largest remainder (rad) whose phasor [`phasors`] takes from its Taylor series.
const SMALL: f64 = 0.05;
