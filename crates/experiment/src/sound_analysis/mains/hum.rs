//! Mains hum found and subtracted from a sound recording before its pitch is tracked.
//!
//! Hum is nearly stationary: lines at $k f_m$ ($f_m$ near 50 or 60 Hz, $k = 1..10$) whose
//! amplitude holds for seconds and whose frequency wanders slowly with the grid's load, while
//! the disk's line sweeps. The mains frequency is the
//! maximum of the whole record's power $|\sum_j x_j e^{-2\pi i f t_j}|^2$ summed over the first
//! three harmonics, searched within $\pm 0.3$ Hz of 50 and of 60 Hz (steps of a quarter of
//! $1/T_{rec}$, then a parabola). A harmonic counts as hum when its power stands
//! [`HUM_RATIO`] times above the median of its neighbours at $\pm 2 .. 20$ resolutions in the
//! quieter half of the Hann-windowed blocks of [`BLOCK_S`] seconds (the disk's sweeping line,
//! a handling bump or the shudder covers a mains line's neighbours in some blocks, hum is in
//! all; see [`stands_out`]); each such line is then fitted by least
//! squares (a cosine and a sine) in blocks of [`BLOCK_S`] seconds and subtracted. Once the disk's pitch is known, the
//! lines are fitted again where the disk keeps clear of them, their phase followed as the grid's
//! frequency wanders ([`remove_hum_clear`]).

use crate::sound_analysis::mains::drift::{phasors, reach, HOP_S};
use crate::sound_analysis::mains::line_power::{hann, power};
use crate::sound_analysis::mains::phase::mains_phase;
use crate::sound_analysis::mains::stands_out::stands_out;
use rayon::prelude::*;
use rustfft::num_complex::Complex;
use std::f64::consts::TAU;

/// A line counts as hum this many times above its neighbours' median power.
pub const HUM_RATIO: f64 = 10.0;

/// Length of the blocks in which each hum line's amplitude and phase are fitted (s).
pub const BLOCK_S: f64 = 2.0;

/// The longest stretch of record (s) whose power the mains search sums coherently: a record
/// longer than this is searched on the sum of its pieces' powers, so that the search's grid
/// (a quarter of the pieces' resolution) and each of its points' cost do not both grow with
/// the record (which would make an hour's search 900 times a minute's, not 60).
pub const SEARCH_S: f64 = 120.0;

/// Subtracts mains hum from `v` (sampled at `fs`); returns the frequencies removed (Hz): the
/// lines [`hum_lines`] finds, subtracted by [`subtract_hum`].
pub fn remove_hum(v: &mut [f64], fs: f64) -> Vec<f64> {
    let lines = hum_lines(v, fs);
    subtract_hum(v, fs, &lines);
    lines
}

/// Subtracts each of the mains lines `lines` (Hz) from `v` (sampled at `fs`), in turn, as the
/// least-squares sinusoid of its frequency in blocks of [`BLOCK_S`] seconds.
pub fn subtract_hum(v: &mut [f64], fs: f64, lines: &[f64]) {
    for &f in lines {
        subtract(v, fs, f);
    }
}

/// The mains hum lines in `v` (sampled at `fs`), Hz: the 50 Hz grid's, then the 60 Hz grid's.
///
/// The search runs on the record averaged over blocks of $\lfloor f_s/2000\rfloor$ samples
/// (a 2 kS/s copy, ample for lines up to 600 Hz), over the whole record up to [`SEARCH_S`]
/// and on the summed powers of its pieces of [`SEARCH_S`] beyond; each line is judged on that
/// copy of the record as it was given, so that the lines are found before any is subtracted.
pub fn hum_lines(v: &[f64], fs: f64) -> Vec<f64> {
    let span = v.len() as f64 / fs;
    if span < 2.0 {
        return Vec::new();
    }
    let (low, fs_low) = low_copy(v, fs);
    // The whole record, or pieces of SEARCH_S seconds where it is longer.
    let (piece, res) = if span > SEARCH_S {
        let n = (SEARCH_S * fs_low) as usize;
        (n, fs_low / n as f64)
    } else {
        (low.len(), 1.0 / span)
    };
    let w_low = hann(piece);
    let mut removed = Vec::new();
    for mains in [50.0, 60.0] {
        let score = |f: f64| -> f64 {
            (1..=3)
                .filter(|k| f64::from(*k) * f < 0.45 * fs_low)
                .map(|k| {
                    low.chunks_exact(piece)
                        .map(|x| power(x, &w_low, fs_low, f64::from(k) * f))
                        .sum::<f64>()
                })
                .sum()
        };
        let step = 0.25 * res;
        let steps = (0.3 / step).ceil() as i64;
        let grid = coarse_to_fine(steps, &|i| score(mains + i as f64 * step));
        let grid: Vec<(f64, f64)> = grid
            .iter()
            .enumerate()
            .map(|(k, p)| {
                (
                    mains + (k as i64 - steps) as f64 * step,
                    p.unwrap_or(f64::MIN),
                )
            })
            .collect();
        let Some(best) = (1..grid.len() - 1).max_by(|a, b| grid[*a].1.total_cmp(&grid[*b].1))
        else {
            continue;
        };
        let (l, c, r) = (grid[best - 1].1, grid[best].1, grid[best + 1].1);
        let d = l - 2.0 * c + r;
        let f_m = grid[best].0
            + if d < 0.0 {
                0.5 * (l - r) / d * step
            } else {
                0.0
            };
        for k in 1..=10 {
            let f = f64::from(k) * f_m;
            if f > 0.45 * fs_low {
                break;
            }
            if stands_out(&low, fs_low, f) {
                removed.push(f);
            }
        }
    }
    removed
}

/// The record `v` (sampled at `fs`) averaged over blocks of $\lfloor f_s/2000\rfloor$ samples,
/// and its rate: the copy on which [`hum_lines`] searches and judges the lines.
pub(crate) fn low_copy(v: &[f64], fs: f64) -> (Vec<f64>, f64) {
    let q = ((fs / 2000.0).floor() as usize).max(1);
    let low = v
        .chunks_exact(q)
        .map(|c| c.iter().sum::<f64>() / q as f64)
        .collect();
    (low, fs / q as f64)
}

/// The score at the grid points $i = -s..s$ (steps of a quarter resolution) that the search
/// visits: every fourth (one resolution apart, so that a line's main lobe, two resolutions wide
/// each side under the Hann window, holds at least three), then every point within a resolution
/// of the best of those, and the best's neighbours should it lie at that window's edge. The
/// maximum and its neighbours are then those of the whole grid, at a third of its cost; points
/// not visited are `None`.
fn coarse_to_fine(s: i64, score: &(dyn Fn(i64) -> f64 + Sync)) -> Vec<Option<f64>> {
    let mut grid: Vec<Option<f64>> = vec![None; (2 * s + 1) as usize];
    // Scores at the points `at`, on rayon's threads, into the grid.
    let visit = |grid: &mut Vec<Option<f64>>, at: Vec<i64>| {
        let scores: Vec<f64> = at.par_iter().map(|&i| score(i)).collect();
        for (i, v) in at.into_iter().zip(scores) {
            grid[(i + s) as usize] = Some(v);
        }
    };
    visit(
        &mut grid,
        (-s..=s).filter(|i| i.rem_euclid(4) == 0).collect(),
    );
    let mut best = (f64::MIN, 0);
    for i in (-s..=s).filter(|i| i.rem_euclid(4) == 0) {
        let v = grid[(i + s) as usize].unwrap_or(f64::MIN);
        if v > best.0 {
            best = (v, i);
        }
    }
    let near: Vec<i64> = ((best.1 - 5).max(-s)..=(best.1 + 5).min(s))
        .filter(|i| grid[(i + s) as usize].is_none())
        .collect();
    visit(&mut grid, near);
    // Should the best lie at the window's edge, its neighbours too.
    loop {
        let Some(top) = (0..grid.len())
            .filter(|&k| grid[k].is_some())
            .max_by(|a, b| {
                grid[*a]
                    .unwrap_or(f64::MIN)
                    .total_cmp(&grid[*b].unwrap_or(f64::MIN))
            })
        else {
            return grid;
        };
        let missing: Vec<i64> = [top.wrapping_sub(1), top + 1]
            .into_iter()
            .filter(|&k| k < grid.len() && grid[k].is_none())
            .map(|k| k as i64 - s)
            .collect();
        if missing.is_empty() {
            return grid;
        }
        visit(&mut grid, missing);
    }
}

/// Subtracts the mains lines `lines` (Hz) from `v` (sampled at `fs`), grid by grid
/// ([`families`]). Each line $k$ of a grid is fitted over the whole record as
/// $(a + a'\tau)\cos\Phi_k + (b + b'\tau)\sin\Phi_k$ ($\tau$ the time from the record's middle
/// over its length, so that the line's amplitude may drift slowly) by least squares on the
/// samples `clear(j, f)` says are free of the disk (its harmonics far from the line), and
/// subtracted, one line after the other. The phases are either all steady, $\Phi_k = 2\pi f'_k t$
/// at each line's frequency refined on the record ([`steady_frequency`]), or all followed as the
/// grid's frequency wanders, $\Phi_k = k\Phi$ ([`mains_phase`]).
///
/// **Which.** The followed phase has about one more parameter, $p$ in all, per [`HOP_S`] of
/// record, shared by the grid's lines, and always fits the clear samples a little better, partly
/// by following their noise and the disk's leak. It is taken where the grid's lines together
/// say so by the Bayesian information criterion: $\sum_k \Delta S_k/\hat\sigma_k^2 > p \ln n$,
/// $\Delta S_k$ the drop in line $k$'s residual sum of squares, $\hat\sigma_k^2$ its steady fit's
/// residual variance, $n$ the most samples a line uses. On six exact-law phone sounds in a quiet
/// room (0.003) with 2 % of steady hum, the followed phase chosen by the smaller sum alone moved
/// $\beta$ by up to 6.7 of its sigmas from the same sounds without hum
/// (`steady_hum_in_a_quiet_room_leaves_beta_alone`). Chosen line by line, a line whose clear
/// samples say little may stay steady while its grid wanders, and its phase is then wrong where
/// the disk covers it, which is where the disk's phase is read.
///
/// **Why the whole record.** The disk's line sweeping through a mains line is then not taken for
/// hum: fitted in short blocks, the part of the sweep just outside the guard leaks into the
/// block's fit, always with the disk's phase, and the subtraction biases the disk's phase near
/// the crossing (on twelve exact-law phone sounds with 2 % hum, against the same sounds without
/// it, $t_0$ moved by +33 us on average, half its sigma, with the lines fitted in 2 s blocks; by
/// +8 us fitted thus). A line with fewer than a quarter of the samples clear is left.
pub fn remove_hum_clear(
    v: &mut [f64],
    fs: f64,
    lines: &[f64],
    clear: &(dyn Fn(usize, f64) -> bool + Sync),
) {
    let n = v.len();
    if n < 2 {
        return;
    }
    let masks: Vec<Vec<bool>> = lines
        .par_iter()
        .map(|&f| (0..n).map(|j| clear(j, f)).collect())
        .collect();
    for (mains, members) in families(lines) {
        let ks: Vec<usize> = members.iter().map(|m| m.1).collect();
        let followed = mains_phase(v, fs, mains, &ks, &|j, i| masks[members[i].0][j]);
        // The record with the grid's lines subtracted steady, and followed; the evidence.
        let (mut by_steady, mut by_followed) = (v.to_vec(), v.to_vec());
        let (mut evidence, mut most) = (0.0, 1usize);
        for &(i, k) in &members {
            let mask = &masks[i];
            let refined = steady_frequency(&by_steady, fs, lines[i], mask);
            let fits = rayon::join(
                || line_fit(&by_steady, steady(n, fs, refined), mask),
                || line_fit(&by_followed, phasors(&followed, k as f64, mains, fs), mask),
            );
            let (Some((steady_coef, steady_rss, used)), Some((coef, rss, _))) = fits else {
                continue;
            };
            subtract_line(&mut by_steady, steady(n, fs, refined), &steady_coef);
            subtract_line(
                &mut by_followed,
                phasors(&followed, k as f64, mains, fs),
                &coef,
            );
            evidence += (steady_rss - rss) / (steady_rss / used as f64);
            most = most.max(used);
        }
        // The followed phase's extra parameters: about one frequency per hop of its segments.
        let extra = (n as f64 / fs / HOP_S).round().max(1.0);
        let chosen = if evidence > extra * (most as f64).ln() {
            by_followed
        } else {
            by_steady
        };
        v.copy_from_slice(&chosen);
    }
}

/// The mains lines `lines` (Hz) grouped by grid: each family's fundamental (Hz) and its
/// members' (index in `lines`, harmonic number). A line is $k f_m$ for the first family whose
/// fundamental it is a whole multiple of (to $10^{-9}$); else it starts a family whose fundamental
/// is the line over the harmonic number that puts it within [`reach`] of 50 or 60 Hz (the line
/// itself where neither does).
fn families(lines: &[f64]) -> Vec<(f64, Vec<(usize, usize)>)> {
    let mut out: Vec<(f64, Vec<(usize, usize)>)> = Vec::new();
    for (i, &f) in lines.iter().enumerate() {
        let member = out.iter_mut().find_map(|(m, members)| {
            let k = (f / *m).round();
            ((f - k * *m).abs() <= 1e-9 * f && k >= 1.0).then_some((members, k as usize))
        });
        if let Some((members, k)) = member {
            members.push((i, k));
            continue;
        }
        let k = [50.0, 60.0]
            .into_iter()
            .map(|nominal: f64| (f / nominal).round().max(1.0))
            .find(|k| {
                let m = f / k;
                (m - 50.0).abs() <= reach(50.0) || (m - 60.0).abs() <= reach(60.0)
            })
            .unwrap_or(1.0);
        out.push((f / k, vec![(i, k as usize)]));
    }
    out
}

/// Subtracts the line $(a + a'\tau)\cos\Phi + (b + b'\tau)\sin\Phi$, `coef` = $(a, b, a', b')$,
/// of phasors `phase`, from `v`.
fn subtract_line(
    v: &mut [f64],
    phase: impl Iterator<Item = [f64; 2]>,
    coef: &nalgebra::Vector4<f64>,
) {
    let n = v.len();
    for (j, (x, p)) in v.iter_mut().zip(phase).enumerate() {
        let b = basis(p, j, n);
        *x -= (0..4).map(|k| coef[k] * b[k]).sum::<f64>();
    }
}

/// Gauss-Newton steps on a steady line's frequency in [`steady_frequency`].
pub const FREQUENCY_STEPS: usize = 2;

/// The phasors of the steady phase $2\pi f j/f_s$ at `n` samples of rate `fs`, each the last
/// turned by $2\pi f/f_s$ and set afresh from the phase every [`RESYNC`] samples, so that the
/// rounding of the product cannot build up (a sine saved per sample, line and pass).
pub(crate) fn steady(n: usize, fs: f64, f: f64) -> impl Iterator<Item = [f64; 2]> {
    let (ws, wc) = (TAU * f / fs).sin_cos();
    let mut p = [1.0, 0.0];
    (0..n).map(move |j| {
        if j % RESYNC == 0 {
            let (s, c) = (TAU * f * j as f64 / fs).sin_cos();
            p = [c, s];
        }
        let out = p;
        p = [p[0] * wc - p[1] * ws, p[1] * wc + p[0] * ws];
        out
    })
}

/// Samples between the steady phasors' fresh starts.
const RESYNC: usize = 1024;

/// The frequency $f'$ of the steady line found near `f` Hz, refined on the samples `mask`
/// admits. A line whose frequency is $f + \delta f$, fitted at $f$ as
/// $(a + a'\tau)\cos\Phi + (b + b'\tau)\sin\Phi$ ([`line_fit`]), has the complex amplitude
/// $(a + a'\tau) - i(b + b'\tau) \propto e^{2\pi i\,\delta f\,t}$, so
/// $$\delta f \approx \frac{1}{2\pi T}\,\mathrm{Im}\,\frac{a' - ib'}{a - ib},$$
/// $T$ the record's length ($t = T\tau$). The mains frequency found from the whole record's
/// spectrum is off by up to a hundredth of a hertz where the disk's harmonics sweep past it,
/// which over ten seconds turns a line's phase by a radian at 150 Hz: more than the fit's
/// linear amplitude terms absorb. A step larger than [`reach`](crate::sound_analysis::mains::drift::reach)
/// is not taken.
fn steady_frequency(v: &[f64], fs: f64, f: f64, mask: &[bool]) -> f64 {
    let n = v.len();
    let mut line = f;
    for _ in 0..FREQUENCY_STEPS {
        let Some((c, _, _)) = line_fit(v, steady(n, fs, line), mask) else {
            break;
        };
        let z = Complex::new(c[0], -c[1]);
        let dz = Complex::new(c[2], -c[3]);
        let step = (dz / z).im / (TAU * n as f64 / fs);
        if !(step.is_finite() && (line + step - f).abs() <= reach(f)) {
            break;
        }
        line += step;
    }
    line
}

/// The line's basis at sample `j` of `n`, its phasor `[c, s]`: $\cos\Phi$, $\sin\Phi$ and both
/// times $\tau$.
fn basis([c, s]: [f64; 2], j: usize, n: usize) -> [f64; 4] {
    let tau = (j as f64 - 0.5 * (n - 1) as f64) / n as f64;
    [c, s, c * tau, s * tau]
}

/// The least-squares coefficients of [`basis`] on the samples `mask` admits, the line's
/// phasors `phase`, the residual sum of squares there and the samples used; `None` with fewer
/// than a quarter of the samples clear.
fn line_fit(
    v: &[f64],
    phase: impl Iterator<Item = [f64; 2]>,
    mask: &[bool],
) -> Option<(nalgebra::Vector4<f64>, f64, usize)> {
    let n = v.len();
    let mut a = nalgebra::Matrix4::<f64>::zeros();
    let mut r = nalgebra::Vector4::<f64>::zeros();
    let (mut used, mut xx) = (0, 0.0);
    for (j, (x, p)) in v.iter().zip(phase).enumerate() {
        if !mask[j] {
            continue;
        }
        let b = basis(p, j, n);
        // The normal matrix's upper triangle; the lower is its mirror.
        for row in 0..4 {
            for col in row..4 {
                a[(row, col)] += b[row] * b[col];
            }
            r[row] += b[row] * *x;
        }
        xx += x * x;
        used += 1;
    }
    if 4 * used < v.len() {
        return None;
    }
    a.fill_lower_triangle_with_upper_triangle();
    let coef = a.lu().solve(&r)?;
    Some((coef, xx - coef.dot(&r), used))
}

/// Subtracts the least-squares sinusoid of frequency `f` from `v`, block by block.
fn subtract(v: &mut [f64], fs: f64, f: f64) {
    let block = ((BLOCK_S * fs) as usize).max(1);
    let w = TAU * f / fs;
    let (sw, cw) = w.sin_cos();
    v.par_chunks_mut(block).enumerate().for_each(|(b, chunk)| {
        let phasors = || {
            let (s0, c0) = (w * (b * block) as f64).sin_cos();
            std::iter::successors(Some((c0, s0)), move |&(c, s)| {
                Some((c * cw - s * sw, s * cw + c * sw))
            })
        };
        let (mut cc, mut ss, mut cs, mut xc, mut xs) = (0.0, 0.0, 0.0, 0.0, 0.0);
        for (x, (c, s)) in chunk.iter().zip(phasors()) {
            cc += c * c;
            ss += s * s;
            cs += c * s;
            xc += x * c;
            xs += x * s;
        }
        let det = cc * ss - cs * cs;
        if det.abs() < 1e-12 * cc * ss {
            return;
        }
        let a = (xc * ss - xs * cs) / det;
        let bb = (xs * cc - xc * cs) / det;
        for (x, (c, s)) in chunk.iter_mut().zip(phasors()) {
            *x -= a * c + bb * s;
        }
    });
}

#[cfg(test)]
mod tests {
    use super::{coarse_to_fine, families, remove_hum};
    use crate::sound_analysis::mains::line_power::{hann, power};
    use std::f64::consts::TAU;

    /// A disk's sweeping line in white noise (8 kS/s, 10 s), with and without 2 % of 50 Hz hum
    /// and its second and third harmonics.
    fn sweep(hum: f64) -> Vec<f64> {
        let fs = 8000.0;
        let mut state: u64 = 0x2545_F491_4F6C_DD1D;
        (0..80_000)
            .map(|j| {
                let t = f64::from(j) / fs;
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                let u = (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
                let w = TAU * 50.0 * t;
                0.3 * (TAU * (20.0 * t + 14.0 * t * t)).sin()
                    + 0.01 * u
                    + hum * (w.sin() + 0.5 * (2.0 * w).sin() + 0.25 * (3.0 * w).sin())
            })
            .collect()
    }

    /// Hum is found at its three lines, and nothing where there is none.
    #[test]
    fn hum_is_found_where_it_is_and_only_there() {
        let mut clean = sweep(0.0);
        assert_eq!(remove_hum(&mut clean, 8000.0), Vec::<f64>::new());
        let mut hummed = sweep(0.02);
        let lines = remove_hum(&mut hummed, 8000.0);
        assert_eq!(lines.len(), 3, "{lines:?}");
        for (k, f) in (1..).zip(&lines) {
            assert!(
                (f - 50.0 * f64::from(k)).abs() < 0.01 * f64::from(k),
                "{lines:?}"
            );
        }
    }

    /// On the search's own score (three harmonics' power under the Hann window, 10 s at 2 kS/s)
    /// of mains hum anywhere within the search's reach, with a disk's line sweeping past, the
    /// search finds the whole grid's maximum and both its neighbours.
    #[test]
    fn the_coarse_to_fine_search_finds_the_whole_grids_maximum() {
        let (fs, span): (f64, f64) = (2000.0, 10.0);
        let n = (fs * span) as usize;
        let w = hann(n);
        let step = 0.25 / span;
        let s = (0.3 / step).ceil() as i64;
        for m in 0..60 {
            let mains = 50.0 - 0.3 + 0.6 * f64::from(m) / 59.0;
            let x: Vec<f64> = (0..n)
                .map(|j| {
                    let t = j as f64 / fs;
                    let hum: f64 = (1..=3)
                        .map(|k| (TAU * f64::from(k) * mains * t).sin() / f64::from(k))
                        .sum();
                    // A disk's line sweeping from 20 to 200 Hz.
                    hum + 0.5 * (TAU * (20.0 * t + 9.0 * t * t)).sin()
                })
                .collect();
            let score = |i: i64| -> f64 {
                let f = 50.0 + i as f64 * step;
                (1..=3).map(|k| power(&x, &w, fs, f64::from(k) * f)).sum()
            };
            let grid = coarse_to_fine(s, &score);
            let full: Vec<f64> = (-s..=s).map(score).collect();
            let top = (0..full.len())
                .max_by(|a, b| full[*a].total_cmp(&full[*b]))
                .unwrap();
            let found = (0..grid.len())
                .max_by(|a, b| {
                    grid[*a]
                        .unwrap_or(f64::MIN)
                        .total_cmp(&grid[*b].unwrap_or(f64::MIN))
                })
                .unwrap();
            assert_eq!(found, top, "mains {mains}");
            for k in [top.saturating_sub(1), (top + 1).min(full.len() - 1)] {
                assert_eq!(grid[k], Some(full[k]), "mains {mains}");
            }
        }
    }

    /// Lines of a 50 Hz grid and of a 60 Hz grid (whose fundamental did not stand out) fall
    /// into two families with their harmonic numbers; 300 Hz, a harmonic of both nominal
    /// frequencies, goes to the grid it is a multiple of.
    #[test]
    fn lines_are_grouped_by_grid() {
        let (a, b) = (50.013, 59.987);
        let lines = [a, 2.0 * a, 6.0 * a, 2.0 * b, 3.0 * b, 5.0 * b];
        let got = families(&lines);
        assert_eq!(got.len(), 2, "{got:?}");
        assert!(
            (got[0].0 - a).abs() < 1e-12 && (got[1].0 - b).abs() < 1e-12,
            "{got:?}"
        );
        assert_eq!(got[0].1, vec![(0, 1), (1, 2), (2, 6)]);
        assert_eq!(got[1].1, vec![(3, 2), (4, 3), (5, 5)]);
    }
}
