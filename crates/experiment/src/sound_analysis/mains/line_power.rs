//! A line's power under a window: what the mains search ([`hum`](crate::sound_analysis::mains::hum)) and the
//! follower of a line's wander ([`mains_drift`](crate::sound_analysis::mains::drift)) both maximise.
//!
//! The power at one frequency is summed directly rather than read from an FFT because the
//! searches want it on a grid finer than the record's resolution, at a few dozen frequencies.

use std::f64::consts::TAU;

/// The (unnormalised) power at `f` Hz of `v` weighted by the window `w` (as long as `v`).
pub fn power(v: &[f64], w: &[f64], fs: f64, f: f64) -> f64 {
    let (s, c) = (TAU * f / fs).sin_cos();
    let rot = (c, -s);
    let (mut re, mut im) = (0.0, 0.0);
    let (mut pr, mut pi) = (1.0, 0.0);
    for (j, (x, w)) in v.iter().zip(w).enumerate() {
        re += x * w * pr;
        im += x * w * pi;
        let nr = pr * rot.0 - pi * rot.1;
        pi = pr * rot.1 + pi * rot.0;
        pr = nr;
        if j % 4096 == 4095 {
            let m = (pr * pr + pi * pi).sqrt();
            pr /= m;
            pi /= m;
        }
    }
    re * re + im * im
}

/// The Hann window of `n` points.
pub fn hann(n: usize) -> Vec<f64> {
    (0..n)
        .map(|j| {
            (std::f64::consts::PI * (j as f64 + 0.5) / n as f64)
                .sin()
                .powi(2)
        })
        .collect()
}
