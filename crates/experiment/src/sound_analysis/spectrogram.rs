//! The spectrogram of a sound recording: how loud each frequency is at each time, for the eye
//! (the analysis itself follows the pitch in [`track`](crate::sound_analysis::track) and the phase in
//! [`phase_blocks`](crate::sound_analysis::phase_blocks)).
//!
//! Frames of `frame` seconds, Hann-windowed, every `hop` seconds, zero-padded so that every band
//! holds at least two of the transform's bins; each frame's power $|X(f)|^2$ in decibels relative
//! to the loudest cell of the whole spectrogram, averaged into `bins` equal bands up to `f_max`.

use crate::trace::Trace;
use rustfft::num_complex::Complex;
use rustfft::FftPlanner;
use serde::Serialize;
use std::f64::consts::PI;

/// A spectrogram on a regular grid.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Spectrogram {
    /// The frames' middle times (s).
    pub t: Vec<f64>,
    /// The bands' middle frequencies (Hz).
    pub f: Vec<f64>,
    /// The power in decibels relative to the loudest cell, `db[i][k]` at `t[i]`, `f[k]`.
    pub db: Vec<Vec<f64>>,
}

/// The spectrogram of `trace` (see the module's documentation); empty when the record is
/// shorter than a frame.
pub fn spectrogram(trace: &Trace, frame: f64, hop: f64, f_max: f64, bins: usize) -> Spectrogram {
    let dt = trace.sample_interval();
    let empty = Spectrogram {
        t: Vec::new(),
        f: Vec::new(),
        db: Vec::new(),
    };
    if !(dt > 0.0 && frame > 0.0 && hop > 0.0 && f_max > 0.0 && bins > 0) {
        return empty;
    }
    let n = ((frame / dt).round() as usize).max(16);
    let step = ((hop / dt).round() as usize).max(1);
    if trace.v.len() < n {
        return empty;
    }
    let band = f_max / bins as f64;
    let nfft = n
        .max((2.0 / (dt * band)).ceil() as usize)
        .next_power_of_two();
    let fft = FftPlanner::<f64>::new().plan_fft_forward(nfft);
    let window: Vec<f64> = (0..n)
        .map(|j| (PI * (j as f64 + 0.5) / n as f64).sin().powi(2))
        .collect();
    let mut t = Vec::new();
    let mut power: Vec<Vec<f64>> = Vec::new();
    let mut buf = vec![Complex::new(0.0, 0.0); nfft];
    for start in (0..=trace.v.len() - n).step_by(step) {
        let x = &trace.v[start..start + n];
        let mean = x.iter().sum::<f64>() / n as f64;
        buf.fill(Complex::new(0.0, 0.0));
        for (b, (v, w)) in buf.iter_mut().zip(x.iter().zip(&window)) {
            *b = Complex::new((v - mean) * w, 0.0);
        }
        fft.process(&mut buf);
        let mut sum = vec![0.0; bins];
        let mut count = vec![0usize; bins];
        for (k, z) in buf.iter().enumerate().take(nfft / 2) {
            let f = k as f64 / (nfft as f64 * dt);
            let i = (f / band) as usize;
            if i < bins {
                sum[i] += z.norm_sqr();
                count[i] += 1;
            }
        }
        power.push(
            sum.iter()
                .zip(&count)
                .map(|(s, &c)| s / c.max(1) as f64)
                .collect(),
        );
        t.push(trace.t[0] + (start as f64 + 0.5 * n as f64) * dt);
    }
    let top = power
        .iter()
        .flatten()
        .copied()
        .fold(f64::MIN_POSITIVE, f64::max);
    Spectrogram {
        t,
        f: (0..bins).map(|i| (i as f64 + 0.5) * band).collect(),
        db: power
            .iter()
            .map(|row| {
                row.iter()
                    .map(|p| 10.0 * (p.max(1e-30) / top).log10())
                    .collect()
            })
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 100 Hz tone is loudest in the band that holds 100 Hz, in every frame.
    #[test]
    fn a_tone_is_loudest_in_its_band() {
        let fs = 8000.0;
        let t: Vec<f64> = (0..16_000).map(|j| j as f64 / fs).collect();
        let v = t.iter().map(|t| (2.0 * PI * 100.0 * t).sin()).collect();
        let s = spectrogram(
            &Trace {
                source: "tone".into(),
                t,
                v,
                truth: None,
            },
            0.1,
            0.05,
            500.0,
            50,
        );
        assert_eq!(s.f.len(), 50);
        assert!(s.t.len() > 30);
        for row in &s.db {
            let k = (0..50).max_by(|a, b| row[*a].total_cmp(&row[*b])).unwrap();
            assert!((s.f[k] - 100.0).abs() <= 5.0, "{}", s.f[k]);
        }
    }
}
