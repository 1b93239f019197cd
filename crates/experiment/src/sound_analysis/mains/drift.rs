//! The pieces with which a mains line's phase is followed as the grid's frequency wanders
//! ([`mains_phase`](crate::sound_analysis::mains::phase) follows a grid's lines together with them).
//!
//! A grid's frequency follows its load: $f(t) = k f_m + \delta(t)$, $\delta$ a slow wander of
//! hundredths to tenths of a hertz. It is measured in segments of [`SEGMENT_S`] seconds every
//! [`HOP_S`] seconds, within [`reach`] of the line, the maximum of a power ([`peak`]) on the
//! samples clear of the disk, weighed by a taper ([`tapered`]); the phase is its integral
//! ([`integrate`]), corrected by the phase measured in the segments ([`add_between`]); and the
//! line's phasors follow from the phase ([`phasors`]). A steady line gives $\Phi = 2\pi f t$,
//! its frequency measured to the segments' precision.

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

/// The phase (rad) at `n` samples of rate `fs` of a line whose frequency is `freq` (segment
/// centre time (s), frequency (Hz)), linear between the centres and extended so beyond the first
/// and last, within [`reach`] of `f`: $\Phi(t_j) = 2\pi \sum_{i < j} f(t_i + \Delta t/2)\,\Delta t$.
pub(crate) fn integrate(freq: &[(f64, f64)], f: f64, n: usize, fs: f64) -> Vec<f64> {
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
    let mut phase = Vec::with_capacity(n);
    let mut acc = 0.0;
    for j in 0..n {
        phase.push(acc);
        acc += TAU * at((j as f64 + 0.5) * dt) * dt;
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
pub(crate) fn tapered(n: usize, fs: f64, clear: &dyn Fn(usize) -> bool) -> Vec<f64> {
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

/// Adds to `phase` (samples at rate `fs`) the corrections `found` (segment centre time (s),
/// phase (rad)), linear between the centres and extended so beyond the first and last; nothing
/// with fewer than two.
pub(crate) fn add_between(phase: &mut [f64], found: &[(f64, f64)], fs: f64) {
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
pub(crate) fn peak(power: &dyn Fn(f64) -> f64, f: f64, reach: f64, step: f64) -> Option<f64> {
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

/// The phasors $(\cos k\Phi_j, \sin k\Phi_j)$ of $k$ times a followed phase `phase` (rad) of a
/// line near `f` Hz, sampled at `fs`. Every [`ANCHOR`]-th is exact; between, the phase is the
/// anchor's $k\Phi_a$ plus the steady line's $2\pi k f (j - a)/f_s$ (a table of [`ANCHOR`]
/// phasors) plus the wander's small remainder $\epsilon = k(\Phi_j - \Phi_a) - 2\pi k f (j -
/// a)/f_s$, whose phasor is its Taylor series to $\epsilon^6$ (error below $\epsilon^7/5040$,
/// $10^{-13}$ at the largest $|\epsilon|$ it is used for, [`SMALL`]; a larger remainder takes its
/// sine and cosine). A line's wander stays within [`reach`] (3 Hz at 500 Hz), so over [`ANCHOR`]
/// samples $\epsilon$ stays below 0.04 rad at 8 kS/s, and a sine and a cosine per sample become
/// one per anchor.
pub fn phasors(phase: &[f64], k: f64, f: f64, fs: f64) -> impl Iterator<Item = [f64; 2]> + '_ {
    let w = TAU * k * f / fs;
    let table: [(f64, f64); ANCHOR] = std::array::from_fn(|m| (w * m as f64).sin_cos());
    let mut anchor = (0.0, [1.0, 0.0]);
    phase.iter().enumerate().map(move |(j, &p)| {
        let m = j % ANCHOR;
        if m == 0 {
            let (s, c) = (k * p).sin_cos();
            anchor = (p, [c, s]);
            return [c, s];
        }
        let e = k * (p - anchor.0) - w * m as f64;
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
