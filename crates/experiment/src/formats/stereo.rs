//! Several microphones mixed with their delays: each channel's delay behind the first is
//! measured and taken out before the channels are averaged.
//!
//! Two microphones a few centimetres apart hear the disk at times that differ by up to a
//! millisecond or so. Their plain mean is the sound through a comb filter,
//! $\tfrac12\left(1 + e^{-2\pi i f d}\right)$, which cancels the lines near $f = 1/(2d)$ (333 Hz
//! at $d = 1.5$ ms, where the disk's harmonics are near $t_0$).
//!
//! **The delay** $d_c$ of channel $c$ behind channel 1 is the lag of the largest generalised
//! cross-correlation with the phase transform (GCC-PHAT),
//! $$R(\tau) = \sum_f \frac{\overline{X_1(f)}\,X_c(f)}{\left|\overline{X_1(f)}\,X_c(f)\right|}
//!   e^{2\pi i f\tau},$$
//! its cross-spectrum summed over blocks of [`BLOCK`] samples (at most [`MAX_BLOCKS`] of them,
//! spread evenly, so that neither memory nor time grows with the recording), searched within $\pm$ [`MAX_DELAY`]. The phase transform weighs
//! every frequency alike, so that a loud low line common to both channels at no delay (mains
//! hum picked up by the phone's wiring) or a room's low rumble does not pull the lag to zero.
//! The delay is taken in whole samples: the half-sample left is at most $1/(2 f_s)$, a phase
//! of $\pi f/f_s$, under $0.7$ rad at the highest harmonic used (3.5 kHz) and the lowest rate
//! read at 16 kS/s.
//!
//! **A delay is used only when it is clear**: its peak stands [`CLEAR`] times above the
//! correlation's rms over the lags searched; otherwise the channel is mixed as it is (a delay
//! of 0), as it is for channels that hold the same samples.

use rustfft::num_complex::Complex;
use rustfft::FftPlanner;

/// Samples per block of the cross-spectrum.
pub const BLOCK: usize = 1 << 14;

/// The most blocks summed, spread evenly over the recording (32 blocks of [`BLOCK`] are 11 s at
/// 48 kS/s), so that the cost does not grow with the recording's length.
pub const MAX_BLOCKS: usize = 32;

/// The largest delay looked for (s): 5 ms, the sound's travel over 1.7 m, far more than two
/// microphones of one phone or recorder are apart.
pub const MAX_DELAY: f64 = 5e-3;

/// How far the correlation's peak must stand above its rms over the lags searched.
pub const CLEAR: f64 = 6.0;

/// Each channel's delay behind channel 1 (samples; 0 for channel 1 and where none is clear) of
/// `n_ch` interleaved channels at `rate` S/s.
pub fn delays(interleaved: &[f64], n_ch: usize, rate: u32) -> Vec<isize> {
    let n = interleaved.len() / n_ch.max(1);
    delays_of(n, n_ch, rate, &|j, c| interleaved[j * n_ch + c])
}

/// The frames `[start, end)` of each block [`delays`] reads in a recording of `n` frames at
/// `rate` S/s (none where the recording is too short for a delay to be measured): a recording
/// read in pieces keeps these, and only these, for [`delays_of`].
pub fn blocks_read(n: usize, rate: u32) -> Vec<(usize, usize)> {
    let max_lag = max_lag(rate);
    if n < 4 * max_lag.max(1) {
        return Vec::new();
    }
    let len = BLOCK.min(n.next_power_of_two());
    let blocks = n.div_ceil(len);
    (0..blocks.min(MAX_BLOCKS))
        .map(|k| k * blocks / blocks.min(MAX_BLOCKS) * len)
        .filter(|start| start + max_lag < n)
        .map(|start| (start, (start + len).min(n)))
        .collect()
}

/// The largest lag searched (samples) at `rate` S/s.
fn max_lag(rate: u32) -> usize {
    ((MAX_DELAY * f64::from(rate)).round() as usize).min(BLOCK / 4)
}

/// [`delays`] of a recording of `n` frames whose sample `j` of channel `c` (from 0) is
/// `sample(j, c)`; only the frames of [`blocks_read`] are asked for.
pub fn delays_of(
    n: usize,
    n_ch: usize,
    rate: u32,
    sample: &dyn Fn(usize, usize) -> f64,
) -> Vec<isize> {
    let mut out = vec![0isize; n_ch];
    let max_lag = max_lag(rate);
    let blocks = blocks_read(n, rate);
    if n_ch < 2 || blocks.is_empty() {
        return out;
    }
    let len = BLOCK.min(n.next_power_of_two());
    let nfft = 2 * len;
    let mut planner = FftPlanner::<f64>::new();
    let (fwd, inv) = (
        planner.plan_fft_forward(nfft),
        planner.plan_fft_inverse(nfft),
    );
    let spectrum = |c: usize, (start, end): (usize, usize), fft: &dyn rustfft::Fft<f64>| {
        let mut buf: Vec<Complex<f64>> = (start..end)
            .map(|j| Complex::new(sample(j, c), 0.0))
            .collect();
        let m = buf.iter().map(|z| z.re).sum::<f64>() / buf.len().max(1) as f64;
        buf.iter_mut().for_each(|z| z.re -= m);
        buf.resize(nfft, Complex::new(0.0, 0.0));
        fft.process(&mut buf);
        buf
    };
    for (c, d) in out.iter_mut().enumerate().skip(1) {
        let mut cross = vec![Complex::new(0.0, 0.0); nfft];
        for &block in &blocks {
            let a = spectrum(0, block, fwd.as_ref());
            let b = spectrum(c, block, fwd.as_ref());
            for (s, (x, y)) in cross.iter_mut().zip(a.iter().zip(&b)) {
                *s += x.conj() * y;
            }
        }
        for s in cross.iter_mut() {
            let m = s.norm();
            *s = if m > 0.0 {
                *s / m
            } else {
                Complex::new(0.0, 0.0)
            };
        }
        inv.process(&mut cross);
        let r = |lag: isize| cross[lag.rem_euclid(nfft as isize) as usize].re;
        let lags = -(max_lag as isize)..=max_lag as isize;
        let rms =
            (lags.clone().map(|l| r(l).powi(2)).sum::<f64>() / (2 * max_lag + 1) as f64).sqrt();
        let best = lags.max_by(|p, q| r(*p).total_cmp(&r(*q))).unwrap_or(0);
        if rms > 0.0 && r(best) > CLEAR * rms {
            *d = best;
        }
    }
    out
}

/// The channels' mean with each channel advanced by its delay (`delays`), the first channel's
/// time kept; where a channel's advanced samples run past the end, the others' mean stands.
pub fn aligned_mean(interleaved: &[f64], n_ch: usize, delays: &[isize]) -> Vec<f64> {
    let n = interleaved.len() / n_ch.max(1);
    (0..n)
        .map(|j| {
            let (s, k) = (0..n_ch).fold((0.0, 0usize), |(s, k), c| {
                let i = j as isize + delays[c];
                if (0..n as isize).contains(&i) {
                    (s + interleaved[i as usize * n_ch + c], k + 1)
                } else {
                    (s, k)
                }
            });
            s / k.max(1) as f64
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two microphones hearing noise-like sound, the second 37 samples later and under a common
    /// 50 Hz hum at no delay: the delay is found and the aligned mean is the sound at the first
    /// channel's time (the hum, not delayed, is shifted in the second channel instead).
    #[test]
    fn the_second_microphones_delay_is_found_and_taken_out() {
        let (rate, n, d) = (48_000u32, 100_000usize, 37usize);
        let mut state = 12345u64;
        let sound: Vec<f64> = (0..n + d)
            .map(|_| {
                state = state.wrapping_mul(6364136223846793005).wrapping_add(1);
                ((state >> 33) as f64 / (1u64 << 31) as f64) - 0.5
            })
            .collect();
        let hum = |j: usize| 0.5 * (std::f64::consts::TAU * 50.0 * j as f64 / 48_000.0).sin();
        let mut x = Vec::with_capacity(2 * n);
        for j in 0..n {
            x.push(sound[j + d] + hum(j));
            x.push(0.8 * sound[j] + hum(j));
        }
        assert_eq!(delays(&x, 2, rate), vec![0, d as isize]);
        let m = aligned_mean(&x, 2, &[0, d as isize]);
        let err = (0..n - d)
            .map(|j| (m[j] - (0.9 * sound[j + d] + 0.5 * (hum(j) + hum(j + d)))).abs())
            .fold(0.0, f64::max);
        assert!(err < 1e-12, "{err}");
        // Channels of independent noise have no clear delay.
        let z: Vec<f64> = (0..n)
            .flat_map(|j| [sound[j], sound[(j * 7919) % n]])
            .collect();
        assert_eq!(delays(&z, 2, rate), vec![0, 0]);
    }
}
