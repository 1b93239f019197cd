//! The window over a block's $N$ whole turns with which the harmonics are demodulated
//! ([`phase_blocks`](crate::sound_analysis::phase_blocks)): blind to the other harmonics, to
//! the negative-frequency images and to a level that changes linearly across the block.
//!
//! In the heading $\theta \in [0, 2\pi N)$ (from the block's start) the sound is a sum of lines
//! at whole numbers of cycles per turn, $x(\theta) = \sum_k A_k(\theta) e^{ik\theta}$, $k = \pm1,
//! \pm2, \ldots$, each with its slowly changing amplitude $A_k$ (the level rises as the pitch
//! does, and a phone's gain control moves it). Demodulated at harmonic $h$ with a window $w$,
//! line $k$ leaks $\int w\,A_k\,e^{im\theta}\,d\theta$, $m = k - h \neq 0$ a whole number. With
//! $A_k = a_k(1 + \epsilon_k s)$ linear in the block's position $s = \theta/(\pi N) - 1 \in
//! [-1, 1]$, that vanishes for every such $m$ when
//! $$\int_0^{2\pi N} w\,e^{im\theta}\,d\theta = 0 \quad\text{and}\quad
//!   \int_0^{2\pi N} s\,w\,e^{im\theta}\,d\theta = 0,$$
//! i.e. when $w$ and $s\,w$, folded onto one turn ($\sum_j$ over the turns $j$ at the same
//! heading $\varphi = \theta \bmod 2\pi$), are constant. A flat window meets the first but not
//! the second: a level rising by a fraction $\epsilon$ across the block moves the phase of $z_h$
//! by about $(a_k/a_h)\,\epsilon/(\pi N m)$, which grows toward $t_0$ (where the level changes
//! fastest per turn) and so reads as a filter whose lead changes with the pitch.
//!
//! Of the windows that meet both, the one with the least noise (the least $\int w^2$ for a
//! given $\int w$) is, at each $\varphi$, linear in the turns' positions $s_j$: with
//! $S_1 = \sum_j s_j$ and $S_2 = \sum_j s_j^2$ over the $N$ turns at $\varphi$,
//! $$w = N\,\frac{S_2 - S_1\,s}{N S_2 - S_1^2},$$
//! whose folded sum is $N$ (mean 1) and folded first moment 0. For $N = 2$ it is the triangle
//! over the two turns; its noise costs $N^2/(N^2 - 1)$ of a flat window's variance (4/3 at
//! $N = 2$, 16/15 at 4).

use std::f64::consts::TAU;

/// The window's weight at heading `theta` (rad) from the start of a block of `turns` whole
/// turns (see the module's documentation); 0 outside the block.
pub fn weight(theta: f64, turns: usize) -> f64 {
    let n = turns as f64;
    let x = theta / TAU;
    if !(x >= 0.0 && x <= n) || turns == 0 {
        return 0.0;
    }
    if turns == 1 {
        return 1.0;
    }
    // The turn's fraction, with the block's end taken as the last turn's.
    let f = (x - x.floor()).max(if x >= n { 1.0 } else { 0.0 });
    let s = 2.0 * x / n - 1.0;
    let s1 = 2.0 * f - 1.0;
    // S2 = sum_j (a + j d)^2, a = 2f/N - 1, d = 2/N.
    let (a, d) = (2.0 * f / n - 1.0, 2.0 / n);
    let s2 = n * a * a + a * d * n * (n - 1.0) + d * d * (n - 1.0) * n * (2.0 * n - 1.0) / 6.0;
    n * (s2 - s1 * s) / (n * s2 - s1 * s1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rustfft::num_complex::Complex;

    /// The window's sums over `turns` turns, sampled finely: $\int w\,s^a\,e^{im\theta}$ over
    /// $\int w$.
    fn moment(turns: usize, a: i32, m: f64) -> Complex<f64> {
        let per = 4000;
        let n = turns * per;
        let (mut acc, mut sw) = (Complex::new(0.0, 0.0), 0.0);
        for j in 0..n {
            let theta = TAU * (j as f64 + 0.5) / per as f64;
            let s = theta / (std::f64::consts::PI * turns as f64) - 1.0;
            let w = weight(theta, turns);
            acc += Complex::from_polar(w * s.powi(a), m * theta);
            sw += w;
        }
        acc / sw
    }

    /// At every whole offset the window leaks nothing from a line of constant or linearly
    /// changing amplitude, where a flat window leaks the linear change by $1/(\pi N m)$.
    #[test]
    fn blind_to_whole_offsets_and_a_linear_level() {
        for turns in [2, 4, 6, 10] {
            for m in [-7.0, -3.0, -2.0, -1.0, 1.0, 2.0, 5.0] {
                assert!(moment(turns, 0, m).norm() < 1e-9, "{turns} {m}");
                assert!(moment(turns, 1, m).norm() < 1e-9, "{turns} {m}");
            }
        }
        // The flat window's leak of the linear change, for comparison: 1/(pi N m) (N = 2, m = 1).
        let per = 4000;
        let mut acc = Complex::new(0.0, 0.0);
        for j in 0..2 * per {
            let theta = TAU * (j as f64 + 0.5) / per as f64;
            acc += Complex::from_polar(theta / std::f64::consts::PI / 2.0 - 1.0, theta);
        }
        let flat = (acc / (2 * per) as f64).norm();
        assert!(
            (flat - 1.0 / std::f64::consts::PI / 2.0).abs() < 1e-3,
            "{flat}"
        );
    }

    /// Mean 1 over the block, positive, the triangle at two turns; its noise costs
    /// $N^2/(N^2 - 1)$ of a flat window's variance.
    #[test]
    fn its_shape_and_its_noise() {
        for turns in [2, 4, 6] {
            let per = 4000;
            let n = turns * per;
            let w: Vec<f64> = (0..n)
                .map(|j| weight(TAU * (j as f64 + 0.5) / per as f64, turns))
                .collect();
            let mean = w.iter().sum::<f64>() / n as f64;
            let power = w.iter().map(|v| v * v).sum::<f64>() / n as f64;
            assert!((mean - 1.0).abs() < 1e-9, "{turns}: {mean}");
            assert!(w.iter().all(|&v| v > 0.0), "{turns}");
            let nn = (turns * turns) as f64;
            let want = nn / (nn - 1.0);
            assert!((power - want).abs() < 1e-6, "{turns}: {power}");
        }
        for x in [0.1, 0.5, 0.9, 1.2, 1.7] {
            let tri = if x < 1.0 { 2.0 * x } else { 2.0 * (2.0 - x) };
            assert!((weight(TAU * x, 2) - tri).abs() < 1e-12, "{x}");
        }
        assert_eq!(weight(-0.1, 2), 0.0);
        assert_eq!(weight(TAU * 2.01, 2), 0.0);
    }
}
