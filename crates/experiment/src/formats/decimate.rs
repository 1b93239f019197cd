//! A long recording's one channel low-passed and decimated as it is read, so that its length
//! costs memory at the rate the analysis needs, not at the file's.
//!
//! **The band kept.** The analysis uses the disk's harmonics below $f_b$ = [`BAND_HZ`] = 3.5 kHz
//! (the pitch's harmonic family, [`MAX_HARMONIC_HZ`], and the phase's harmonics,
//! [`MAX_HZ`](crate::sound_analysis::phase_blocks::MAX_HZ)), each only where it lies below
//! $0.45 f_s$. A recording at $f_s$ is decimated by the largest whole factor
//! $$q = \left\lfloor \frac{0.45\, f_s}{f_b} \right\rfloor$$
//! (6 at 48 kS/s, 4 at 32 kS/s and 12 at 96 kS/s, each to 8 kS/s; 5 at 44.1 kS/s to 8.82 kS/s), so that
//! every harmonic used at the file's rate is used at the decimated rate $f_s/q$ too.
//!
//! **The filter** is a windowed sinc cut at $f_s/(2q)$,
//! $$h_m = \frac{w_m}{q}\,\mathrm{sinc}\frac{m}{q}, \qquad m = -M..M,$$
//! $w$ the four-term Blackman-Harris window over the $2M+1$ taps, scaled to a gain of 1 at
//! 0 Hz, and output $k$ is $y_k = \sum_m h_m x_{kq+m}$ (samples before the first and after the
//! last taken as 0). Its transition, $\pm 4 f_s/(2M)$ about the cut (the window's main lobe),
//! lies within $f_s/(2q) - f_b$ of it: the band below $f_b$ is passed whole, and nothing from
//! above the decimated Nyquist folds below $f_b$ by more than the window's side lobes
//! (-92 dB). At 48 kS/s that is $M = 192$ (8 ms). The filter is symmetric, so output $k$ is
//! the low-passed signal at input sample $kq$ exactly: time, which the analysis measures, is
//! kept. (`rubato`'s sinc resampler is not used: with whole-factor decimation it places its
//! output a few samples from where its stated delay says, by an amount that changes with the
//! rate, 7 output samples late at 48 kS/s and 13 early at 22.05 kS/s.)

use crate::error::ExperimentError;
use crate::sound_analysis::spectrum::MAX_HARMONIC_HZ;
use std::f64::consts::PI;

/// The highest frequency kept (Hz): the highest harmonic the analysis uses.
pub const BAND_HZ: f64 = MAX_HARMONIC_HZ;

/// The decimation factor for a recording at `rate` S/s: the largest whole $q$ with
/// $0.45\,\mathrm{rate}/q \ge$ [`BAND_HZ`], at least 1.
pub fn factor(rate: u32) -> usize {
    ((0.45 * f64::from(rate) / BAND_HZ).floor() as usize).max(1)
}

/// The filter's taps $h_{-M..M}$ for decimation by `q` from `rate` S/s.
fn taps(rate: u32, q: usize) -> Vec<f64> {
    let fs = f64::from(rate);
    let half = 0.5 * fs / q as f64 - BAND_HZ;
    let m = (2.0 * fs / half).ceil() as usize;
    let l = 2.0 * m as f64;
    let h: Vec<f64> = (0..=2 * m)
        .map(|j| {
            let x = 2.0 * PI * j as f64 / l;
            let w =
                0.35875 - 0.48829 * x.cos() + 0.14128 * (2.0 * x).cos() - 0.01168 * (3.0 * x).cos();
            let u = (j as f64 - m as f64) / q as f64;
            let sinc = if u == 0.0 {
                1.0
            } else {
                (PI * u).sin() / (PI * u)
            };
            w * sinc
        })
        .collect();
    let sum: f64 = h.iter().sum();
    h.iter().map(|x| x / sum).collect()
}

/// A low-pass and decimation by a whole factor, fed sample by sample.
pub struct Decimator {
    q: usize,
    h: Vec<f64>,
    /// Input samples from index `base` on (the first `M` are the zeros before the record).
    buf: Vec<f64>,
    base: usize,
    out: Vec<f64>,
    fed: usize,
}

impl Decimator {
    /// A decimator from `rate` S/s by [`factor`]`(rate)`; `capacity` output samples reserved.
    pub fn new(rate: u32, capacity: usize) -> Result<Self, ExperimentError> {
        let q = factor(rate);
        let mut out = Vec::new();
        out.try_reserve_exact(capacity).map_err(|_| {
            ExperimentError::Setting(format!(
                "{capacity} decimated samples cannot be held in memory"
            ))
        })?;
        let h = if q == 1 { vec![1.0] } else { taps(rate, q) };
        let m = h.len() / 2;
        Ok(Self {
            q,
            buf: vec![0.0; m],
            h,
            base: 0,
            out,
            fed: 0,
        })
    }

    /// The decimation factor.
    pub fn factor(&self) -> usize {
        self.q
    }

    /// Feeds one input sample.
    pub fn push(&mut self, x: f64) {
        self.fed += 1;
        self.buf.push(x);
        self.drain();
    }

    /// Makes every output whose taps are all in (output $k$ needs padded samples
    /// $kq .. kq + 2M$), and drops the samples no later output needs.
    fn drain(&mut self) {
        let taps = self.h.len();
        while self.out.len() * self.q + taps <= self.base + self.buf.len() {
            let at = self.out.len() * self.q - self.base;
            let y = self.buf[at..at + taps]
                .iter()
                .zip(&self.h)
                .map(|(x, h)| x * h)
                .sum();
            self.out.push(y);
        }
        let need = self.out.len() * self.q;
        if need - self.base > 1 << 16 {
            self.buf.drain(..need - self.base);
            self.base = need;
        }
    }

    /// The decimated signal: output $k$ at input sample $kq$, for every $kq$ fed.
    pub fn finish(mut self) -> Result<Vec<f64>, ExperimentError> {
        let want = self.fed.div_ceil(self.q);
        let m = self.h.len() / 2;
        self.buf.extend(std::iter::repeat_n(0.0, m));
        self.drain();
        self.out.truncate(want);
        Ok(self.out)
    }
}

/// Samples `x` at `fs` S/s brought to the band the analysis uses: low-passed and decimated by
/// [`factor`], output $k$ the low-passed signal at input sample $kq$, with $q$. `None` where
/// the factor is 1 (a rate below $2 f_b/0.45$, 15.6 kS/s) or `fs` is not a whole rate in S/s,
/// which is used as it is.
pub fn to_band(x: &[f64], fs: f64) -> Option<(Vec<f64>, usize)> {
    let rate = fs.round();
    if !(rate >= 1.0 && rate <= f64::from(u32::MAX) && (fs - rate).abs() <= 1e-6 * rate) {
        return None;
    }
    let rate = rate as u32;
    let q = factor(rate);
    if q == 1 {
        return None;
    }
    let mut d = Decimator::new(rate, x.len().div_ceil(q)).ok()?;
    x.iter().for_each(|&v| d.push(v));
    Some((d.finish().ok()?, q))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::TAU;

    fn decimate(v: &[f64], rate: u32) -> Vec<f64> {
        let mut d = Decimator::new(rate, 0).unwrap();
        v.iter().for_each(|&x| d.push(x));
        d.finish().unwrap()
    }

    /// At each rate a phone uses, a line in the band comes out at the input's time and level
    /// (output $k$ is the input at sample $kq$), and a line above the decimated Nyquist that
    /// would fold into the band is gone.
    #[test]
    fn the_band_is_kept_in_time_and_what_would_fold_into_it_is_removed() {
        for rate in [16_000u32, 22_050, 32_000, 44_100, 48_000, 96_000] {
            let q = factor(rate);
            let out_rate = f64::from(rate) / q as f64;
            assert!(0.45 * out_rate >= BAND_HZ, "{rate}");
            let n = 3 * rate as usize + 17;
            for f in [200.0, 1234.5, 3400.0] {
                let v: Vec<f64> = (0..n)
                    .map(|j| (TAU * f * j as f64 / f64::from(rate) + 0.3).sin())
                    .collect();
                let y = decimate(&v, rate);
                assert_eq!(y.len(), n.div_ceil(q), "{rate}");
                // Away from the ends, where the filter sees the whole signal.
                let edge = rate as usize / 10 / q;
                let err = y[edge..y.len() - edge]
                    .iter()
                    .enumerate()
                    .map(|(k, x)| (x - v[(k + edge) * q]).abs())
                    .fold(0.0, f64::max);
                assert!(err < 2e-3, "{rate} S/s, {f} Hz: {err}");
            }
            // A line that folds onto 2 kHz at the decimated rate.
            let f = out_rate - 2000.0;
            let v: Vec<f64> = (0..n)
                .map(|j| (TAU * f * j as f64 / f64::from(rate)).sin())
                .collect();
            let y = decimate(&v, rate);
            let edge = rate as usize / 10 / q;
            let peak = y[edge..y.len() - edge]
                .iter()
                .fold(0.0f64, |m, x| m.max(x.abs()));
            assert!(peak < 1e-3, "{rate} S/s, {f} Hz folds in at {peak}");
        }
        assert_eq!(factor(8000), 1);
        assert_eq!(decimate(&[0.5, 0.25, 0.125], 8000), vec![0.5, 0.25, 0.125]);
    }

    /// A record is brought to the band with its factor (the decimator's own output); one at
    /// 8 kS/s, or at no whole rate (a scope's), is left as it is.
    #[test]
    fn a_record_is_brought_to_the_band_or_left() {
        let v: Vec<f64> = (0..96_000)
            .map(|j| (TAU * 440.0 * f64::from(j) / 48_000.0).sin())
            .collect();
        let (band, q) = to_band(&v, 48_000.0).expect("decimated");
        assert_eq!((q, band), (6, decimate(&v, 48_000)));
        assert!(to_band(&v, 8000.0).is_none());
        assert!(to_band(&v, 48_000.5).is_none());
    }
}
