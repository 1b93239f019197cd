//! Handling bumps and clicks found in a sound recording, so that the pitch track's frames step
//! over them.
//!
//! A bump (the phone knocked, the table struck) is a transient far louder than the disk that
//! starts within milliseconds and dies within a fraction of a second; the disk's sound rises
//! and falls over seconds. In blocks of [`BLOCK_S`] seconds, with $e_k$ the block's mean square
//! about the record's mean, a bump starts at block $k$ where
//! $$e_k > R_{on}\,\tilde e_k, \qquad \tilde e_k = \operatorname{median}(e_{k-20}, \ldots, e_{k-1}),$$
//! the median of the 0.2 s before it ([`ONSET`]), and ends at the first block after it whose
//! $e_j$ is back below [`BACK`] times $\tilde e_k$. A rise that is not back within [`LONGEST_S`]
//! is not a bump (a sound that starts and holds, as the disk's own start may) and is kept.
//! One block on each side is added to the span, for the transient's own onset and tail.

/// Length of the blocks whose energies are compared (s).
pub const BLOCK_S: f64 = 0.01;

/// How many times the median energy of the 0.2 s before it a block must exceed to start a
/// bump: 9 dB. The disk's level rises at most a few per cent per block (its rate rises
/// steadily, the level as a power of the rate), so only a transient jumps this far.
pub const ONSET: f64 = 8.0;

/// How many times that median energy a bump's blocks stay above until it ends: 3 dB.
pub const BACK: f64 = 2.0;

/// The longest a bump lasts (s): a damped thump of tens of milliseconds with the room's
/// reverberation over it.
pub const LONGEST_S: f64 = 0.5;

/// Blocks before a block whose median energy is its baseline (0.2 s).
const BASELINE_BLOCKS: usize = 20;

/// The bumps of `v` sampled at `fs`: each as the samples' span `[start, end)`, in time order.
pub fn find_bumps(v: &[f64], fs: f64) -> Vec<(usize, usize)> {
    let block = ((BLOCK_S * fs).round() as usize).max(1);
    if v.len() < block * (BASELINE_BLOCKS + 2) {
        return Vec::new();
    }
    let mean = v.iter().sum::<f64>() / v.len() as f64;
    let e: Vec<f64> = v
        .chunks_exact(block)
        .map(|c| c.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / block as f64)
        .collect();
    let longest = (LONGEST_S / BLOCK_S).round() as usize;
    let mut out = Vec::new();
    let mut k = BASELINE_BLOCKS;
    while k < e.len() {
        let mut before = e[k - BASELINE_BLOCKS..k].to_vec();
        let m = before.len() / 2;
        let base = *before.select_nth_unstable_by(m, f64::total_cmp).1;
        if !(base > 0.0 && e[k] > ONSET * base) {
            k += 1;
            continue;
        }
        match (k + 1..e.len().min(k + longest)).find(|&j| e[j] < BACK * base) {
            Some(end) => {
                let first = (k - 1) * block;
                let last = ((end + 1) * block).min(v.len());
                out.push((first, last));
                k = end + 1;
            }
            None => k += longest,
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::TAU;

    /// A steady 20 Hz tone whose level rises fourfold over 4 s, with a 40 Hz thump ten times
    /// louder at 2 s (decaying in 30 ms): the thump is found, within 0.3 s of 2 s, and nothing
    /// else; the tone alone, starting from silence at 0.5 s and holding, has no bump.
    #[test]
    fn a_thump_is_a_bump_and_a_rising_tone_is_not() {
        let fs = 8000.0;
        let tone = |t: f64| {
            if t < 0.5 {
                1e-4 * (TAU * 313.0 * t).sin()
            } else {
                0.05 * (1.0 + 0.75 * t) * (TAU * 20.0 * t * (1.0 + 0.02 * t)).sin()
            }
        };
        let thump = |t: f64| {
            let s = t - 2.0;
            if (0.0..0.3).contains(&s) {
                0.8 * (-s / 0.03).exp() * (TAU * 40.0 * s).sin()
            } else {
                0.0
            }
        };
        let x: Vec<f64> = (0..32_000)
            .map(|j| {
                let t = j as f64 / fs;
                tone(t) + thump(t)
            })
            .collect();
        let found = find_bumps(&x, fs);
        assert_eq!(found.len(), 1, "{found:?}");
        let (a, b) = (found[0].0 as f64 / fs, found[0].1 as f64 / fs);
        assert!(a > 1.98 && a <= 2.0 && b > 2.05 && b < 2.3, "{a} .. {b}");
        let plain: Vec<f64> = (0..32_000).map(|j| tone(j as f64 / fs)).collect();
        assert_eq!(find_bumps(&plain, fs), Vec::new());
    }
}
