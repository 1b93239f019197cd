//! Cleaning a recorded signal before its peaks are timed: isolated glitches and mains hum out.
//!
//! A glitch is one sample far off the line through its two neighbours while the neighbours
//! agree with each other: $|v_j - \tfrac12(v_{j-1} + v_{j+1})| > \max(8\sigma_v,\ 4|v_{j+1} - v_{j-1}|)$,
//! with $\sigma_v$ the noise. It is replaced by the mean of its neighbours. On a monotonic edge
//! the neighbours differ by more than the sample departs, so edges (and the half-height
//! crossings timed on them) are never touched; at a sharp pulse top the top may be lowered,
//! which moves both crossings of the pulse alike and leaves their mean, the peak time, in place.
//! (A stricter rule, neighbours agreeing within $4\sigma_v$, missed glitches on pulse edges and
//! let a trace with two glitches a second be refused.)
//!
//! **Hum.** Mains hum is a sum of lines at $h f_m$ ($f_m$ = 50 or 60 Hz, $h = 1, 2, 3$). Where the
//! pulses are shallow (near $t_0$, and after it when the disk lies flat) it would be timed as
//! pulses of its own. In each block of 1 s the baseline samples (within four robust deviations
//! of the block's median, so not the pulses) are fitted by least squares (nalgebra's SVD) with
//! an offset, a slope and the six sines and cosines of each mains family; the fitted lines
//! are subtracted from the whole block when the family is coherent across blocks (see
//! [`remove_hum`]), so that a clean trace is left alone.
//!
//! Baseline drift and clipping are handled by the peak timing itself (a running half-height
//! level, the mean of a rising and a falling crossing).

/// Replaces isolated one-sample glitches of `v` (noise `sigma_v`); returns how many.
pub fn remove_glitches(v: &mut [f64], sigma_v: f64) -> usize {
    let n = v.len();
    let mut count = 0;
    for j in 1..n.saturating_sub(1) {
        let (a, b) = (v[j - 1], v[j + 1]);
        let d = (v[j] - 0.5 * (a + b)).abs();
        if d > (8.0 * sigma_v).max(4.0 * (b - a).abs()) {
            v[j] = 0.5 * (a + b);
            count += 1;
        }
    }
    count
}

/// The design row of the hum fit at time `t` (block middle `t_mid`): offset, slope, then
/// cos and sin of $2\pi h f t$ for $f$ = 50, 60 Hz and $h$ = 1, 2, 3.
fn hum_row(t: f64, t_mid: f64) -> [f64; 14] {
    use std::f64::consts::TAU;
    let mut r = [0.0; 14];
    r[0] = 1.0;
    r[1] = t - t_mid;
    let mut k = 2;
    for f in [50.0, 60.0] {
        for h in 1..=3 {
            let (s, c) = (TAU * f * h as f64 * t).sin_cos();
            r[k] = c;
            r[k + 1] = s;
            k += 2;
        }
    }
    r
}

/// Fits and subtracts 50 Hz and 60 Hz hum (three harmonics each) block by block; returns the
/// largest fitted fundamental amplitude that was subtracted (0 if none).
///
/// A family is subtracted only when its fundamental is *coherent* across the blocks: the
/// blocks' complex amplitudes $c_b$ add up, $|\sum_b c_b| > 0.7\sum_b |c_b|$, over at least three
/// blocks, and exceed five standard errors and twice the noise $\sigma_v$ (a fainter hum
/// disturbs the timing less than the noise does; a clean trace with fast pulses once showed a
/// coherent 1.4 $\sigma_v$ of leakage). The pulses' own leakage into a block's fit has a
/// phase that changes from block to block, as $\Omega$ sweeps past the mains lines, and is left
/// alone.
pub fn remove_hum(t: &[f64], v: &mut [f64], sigma_v: f64) -> f64 {
    use nalgebra::{DMatrix, DVector};
    let n = t.len();
    let mut blocks: Vec<(std::ops::Range<usize>, f64, DVector<f64>, f64)> = Vec::new();
    let mut start = 0;
    while start < n {
        let mut end = start;
        while end < n && t[end] < t[start] + 1.0 {
            end += 1;
        }
        let block = start..end;
        start = end;
        if block.len() < 100 {
            continue;
        }
        let mut sorted: Vec<f64> = v[block.clone()].to_vec();
        sorted.sort_by(f64::total_cmp);
        let med = sorted[sorted.len() / 2];
        let mut dev: Vec<f64> = sorted.iter().map(|x| (x - med).abs()).collect();
        dev.sort_by(f64::total_cmp);
        let mad = 1.4826 * dev[dev.len() / 2];
        let quiet: Vec<usize> = block
            .clone()
            .filter(|&j| (v[j] - med).abs() <= 4.0 * mad + 3.0 * sigma_v)
            .collect();
        if quiet.len() < 4 * 14 {
            continue;
        }
        let t_mid = t[block.start];
        let a = DMatrix::from_fn(quiet.len(), 14, |i, k| hum_row(t[quiet[i]], t_mid)[k]);
        let b = DVector::from_fn(quiet.len(), |i, _| v[quiet[i]]);
        if let Ok(x) = a.svd(true, true).solve(&b, 1e-12) {
            let se = sigma_v.max(mad) * (2.0 / quiet.len() as f64).sqrt();
            blocks.push((block, t_mid, x, se));
        }
    }
    let coherent = |k: usize| -> Option<f64> {
        if blocks.len() < 3 {
            return None;
        }
        let (mut re, mut im, mut sum_abs, mut se) = (0.0, 0.0, 0.0, 0.0);
        for (_, _, x, s) in &blocks {
            re += x[k];
            im += x[k + 1];
            sum_abs += x[k].hypot(x[k + 1]);
            se += s * s;
        }
        let m = blocks.len() as f64;
        let mean_amp = re.hypot(im) / m;
        let se = se.sqrt() / m;
        (re.hypot(im) > 0.7 * sum_abs && mean_amp > (5.0 * se).max(2.0 * sigma_v))
            .then_some(mean_amp)
    };
    let (f50, f60) = (coherent(2), coherent(8));
    // A coherent family is stationary (its phase agrees from block to block), so one set of
    // coefficients is subtracted everywhere: each the median over the blocks. A block's own fit
    // would carry the pulses' leakage where they sweep past the mains line (the last block,
    // where Omega reaches 2 pi x 60 Hz), and subtracting it left a hum of the leakage's size
    // after t0, timed as pulses (t0 +19 ms with 60 Hz hum).
    let median = |k: usize| -> f64 {
        let mut c: Vec<f64> = blocks.iter().map(|(_, _, x, _)| x[k]).collect();
        c.sort_by(f64::total_cmp);
        let m = c.len();
        if m % 2 == 1 {
            c[m / 2]
        } else {
            0.5 * (c[m / 2 - 1] + c[m / 2])
        }
    };
    let global: Vec<f64> = (0..14)
        .map(|k| if k < 2 { 0.0 } else { median(k) })
        .collect();
    for (block, t_mid, _, _) in &blocks {
        for j in block.clone() {
            let r = hum_row(t[j], *t_mid);
            let mut hum = 0.0;
            if f50.is_some() {
                hum += (2..8).map(|k| r[k] * global[k]).sum::<f64>();
            }
            if f60.is_some() {
                hum += (8..14).map(|k| r[k] * global[k]).sum::<f64>();
            }
            v[j] -= hum;
        }
    }
    f50.unwrap_or(0.0).max(f60.unwrap_or(0.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_glitch_is_removed_and_an_edge_is_not() {
        let mut v: Vec<f64> = (0..20).map(|j| 0.1 * j as f64).collect();
        let edge = v.clone();
        assert_eq!(remove_glitches(&mut v, 0.01), 0);
        assert_eq!(v, edge);
        v[7] += 3.0;
        assert_eq!(remove_glitches(&mut v, 0.01), 1);
        assert!((v[7] - 0.7).abs() < 1e-12, "{}", v[7]);
    }
}
