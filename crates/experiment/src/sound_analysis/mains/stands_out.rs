//! Whether a mains line stands out as hum in a sound recording ([`stands_out`]), judged block
//! by block ([`block_ratios`]) for [`hum_lines`](crate::sound_analysis::mains::hum::hum_lines).

use crate::sound_analysis::mains::hum::{steady, BLOCK_S, HUM_RATIO};
use crate::sound_analysis::mains::line_power::hann;
use rayon::prelude::*;
use rustfft::num_complex::Complex;

/// Whether a line at `f` stands [`HUM_RATIO`] times above its neighbours at $\pm 2 .. 20$
/// resolutions in the quieter half of its blocks of [`BLOCK_S`] seconds ([`block_ratios`]): the
/// blocks whose neighbours' median power is lowest, and there in the median block. Hum is in
/// every block at the same power; what raises a block's neighbours is broad or moves, and in a
/// recording of a few seconds it covers most blocks about the mains fundamental, so that the
/// median of all the blocks would miss the hum there. A line of the disk's held in one block
/// stands out in that block only, not in the median of the quieter half of a recording of more
/// than two blocks; room noise alone stands out at that ratio in about one block in a thousand
/// ($2^{-10}$: an exponential variate's median is $\ln 2$ of its mean).
pub fn stands_out(v: &[f64], fs: f64, f: f64) -> bool {
    let block = ((BLOCK_S * fs) as usize).max(1);
    let mut blocks = block_ratios(v, fs, f, block);
    if blocks.is_empty() {
        return false;
    }
    blocks.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut quiet: Vec<f64> = blocks[..blocks.len().div_ceil(2)]
        .iter()
        .map(|b| b.1)
        .collect();
    let m = quiet.len() / 2;
    *quiet.select_nth_unstable_by(m, f64::total_cmp).1 > HUM_RATIO
}

/// Each block's neighbours' median power and the line's power over it, for a line at `f` in
/// `v` (sampled at `fs`): blocks of `block` samples, Hann-windowed, starting every half block,
/// and one more ending at the record's end, so that the record's last second (the tail after
/// $t_0$) is judged too; the neighbours are the powers at $\pm 2 .. 20$ resolutions (the
/// block's $f_s/$`block`) of `f`. None where the record is shorter than a block or a block
/// too short for the neighbours.
pub(crate) fn block_ratios(v: &[f64], fs: f64, f: f64, block: usize) -> Vec<(f64, f64)> {
    if v.len() < block || block < 41 {
        return Vec::new();
    }
    let mut starts: Vec<usize> = (0..=v.len() - block).step_by(block / 2).collect();
    if starts.last() != Some(&(v.len() - block)) {
        starts.push(v.len() - block);
    }
    let w = hann(block);
    let fft = rustfft::FftPlanner::<f64>::new().plan_fft_forward(block);
    // One resolution is one bin of the block's transform: shifted down by f, the block's bins
    // k and block - k are the powers at f + k res and f - k res.
    starts
        .par_iter()
        .map(|&s| {
            let b = &v[s..s + block];
            let mut buf = vec![Complex::new(0.0, 0.0); block];
            for (z, ((x, w), [c, sn])) in buf
                .iter_mut()
                .zip(b.iter().zip(&w).zip(steady(block, fs, f)))
            {
                *z = Complex::new(c, -sn) * (x * w);
            }
            fft.process(&mut buf);
            let power = |k: usize| buf[k % block].norm_sqr();
            let mut around: Vec<f64> = (2..=20)
                .flat_map(|i| [power(i), power(block - i)])
                .collect();
            let m = around.len() / 2;
            let floor = *around.select_nth_unstable_by(m, f64::total_cmp).1;
            (floor, power(0) / floor.max(f64::MIN_POSITIVE))
        })
        .collect()
}
