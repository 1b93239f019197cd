//! The sine and cosine of many angles at once: Agner Fog's vector class library algorithm
//! (Cody-Waite reduction by $\pi/2$ in three parts, then minimax polynomials of degree 13 and 12
//! on $[-\pi/4, \pi/4]$), as `wide`'s `f64x2` `sin_cos` computes it, to the bit.
//!
//! For $|x| \le 10^{15}$ the reduction's quotient $q = \mathrm{round}(2|x|/\pi) < 2^{52}$ is read
//! from the bits of $2|x|/\pi + 2^{52}$ (the sum `wide` rounds with), so the whole computation is
//! multiplies, adds and bit operations on plain doubles, which the compiler vectorizes: two angles
//! to a register in the baseline build (SSE2), four in the AVX2 build chosen at run time
//! ([`crate::wider`]). Larger angles, infinities and `NaN` go to `wide` itself. The value of one
//! angle does not depend on the others, so [`sin_cos`] (one angle) and [`sin_cos_each`] (a
//! slice) give the same bits for the same angle; code that records a row alone and rows in a
//! batch uses them for the same numbers.
//!
//! Accuracy, measured against the C library's `sin` and `cos` (`tests` below, a million angles
//! drawn on each of $[-\pi/2, \pi/2]$, $[-8\pi, 8\pi]$ and $[-10^6, 10^6]$): within 2 ulp; `NaN`
//! and $\pm\infty$ give `NaN`. The same tests find the bits of `wide`'s `f64x2` `sin_cos` for every
//! angle in both builds. The build's baseline (SSE2) has no fused multiply-add, and neither
//! build fuses, so the bits are the same on every x86-64 machine running this build.

use wide::f64x2;

#[cfg(target_arch = "x86_64")]
mod avx512;

/// The largest $|x|$ taken by the plain-double path: $2|x|/\pi$ stays below $2^{52}$.
const PLAIN_LIMIT: f64 = 1e15;

/// True for an angle the plain path takes ($|x| \le$ [`PLAIN_LIMIT`]); false for larger ones,
/// the infinities and `NaN`.
#[inline(always)]
fn on_plain_path(x: f64) -> bool {
    x.abs() <= PLAIN_LIMIT
}

/// The polynomials' coefficients, $c_0 .. c_5$ (Agner Fog's, as `wide` has them): the sine's
/// of $x^3$ and the cosine's of $x^4$ in $x^2$. The digits are the published ones, more than a
/// double holds; each rounds to the double `wide` uses.
#[allow(clippy::excessive_precision)]
const SIN: [f64; 6] = [
    -1.666_666_666_666_663_072_95E-1,
    8.333_333_333_322_118_588_78E-3,
    -1.984_126_982_958_953_859_96E-4,
    2.755_731_362_138_572_452_13E-6,
    -2.505_074_776_285_780_728_66E-8,
    1.589_623_015_765_465_680_60E-10,
];
#[allow(clippy::excessive_precision)]
const COS: [f64; 6] = [
    4.166_666_666_666_659_292_18E-2,
    -1.388_888_888_887_305_641_16E-3,
    2.480_158_728_885_170_453_48E-5,
    -2.755_731_417_929_673_881_12E-7,
    2.087_570_084_197_473_167_78E-9,
    -1.135_853_652_138_768_173_00E-11,
];
/// $\pi/2$ in three parts (Cody and Waite), with the published digits as well.
#[allow(clippy::excessive_precision)]
const DP1: f64 = 7.853_981_554_508_209_228_515_625E-1 * 2.;
#[allow(clippy::excessive_precision)]
const DP2: f64 = 7.946_627_356_147_928_367_14E-9 * 2.;
#[allow(clippy::excessive_precision)]
const DP3: f64 = 3.061_616_997_868_382_943_07E-17 * 2.;
const TWO_OVER_PI: f64 = 2.0 / core::f64::consts::PI;
/// $2^{52}$: adding it rounds a non-negative double below $2^{52}$ to an integer, held in the
/// low bits of the sum's mantissa.
const MAGIC: f64 = 4_503_599_627_370_496.0;
const SIGN: u64 = 1 << 63;

/// $(\sin x, \cos x)$.
#[inline]
pub fn sin_cos(x: f64) -> (f64, f64) {
    if x.abs() <= PLAIN_LIMIT {
        plain(x)
    } else {
        by_wide(x)
    }
}

/// `wide`'s `f64x2` `sin_cos` of one angle.
fn by_wide(x: f64) -> (f64, f64) {
    let (s, c) = f64x2::splat(x).sin_cos();
    (s.to_array()[0], c.to_array()[0])
}

/// `wide`'s `f64x2` `sin_cos` for $|x| \le$ [`PLAIN_LIMIT`], written on plain doubles: the same
/// operations in the same order (`wide` without `fma` multiplies, then adds).
#[inline(always)]
fn plain(x: f64) -> (f64, f64) {
    let xa = x.abs();
    let shifted = xa * TWO_OVER_PI + MAGIC;
    let y = shifted - MAGIC;
    let q = shifted.to_bits().wrapping_sub(MAGIC.to_bits());
    let r = xa - y * DP1;
    let r = r - y * DP2;
    let r = r - y * DP3;
    let r2 = r * r;
    let poly = |c: [f64; 6]| {
        let (z2, z4) = (r2 * r2, (r2 * r2) * (r2 * r2));
        (c[3] * r2 + c[2]) * z2 + ((c[5] * r2 + c[4]) * z4 + (c[1] * r2 + c[0]))
    };
    let s = (r * r2) * poly(SIN) + r;
    let c = (r2 * r2) * poly(COS) + (1.0 - r2 * 0.5);
    // All ones when the quadrant is odd: sine and cosine trade places.
    let swap = 0u64.wrapping_sub(q & 1);
    let (sb, cb) = (s.to_bits(), c.to_bits());
    let sin = (cb & swap) | (sb & !swap);
    let cos = (sb & swap) | (cb & !swap);
    let sin_sign = ((q << 62) ^ x.to_bits()) & SIGN;
    let cos_sign = (q.wrapping_add(1) & 2) << 62;
    (
        f64::from_bits(sin ^ sin_sign),
        f64::from_bits(cos ^ cos_sign),
    )
}

/// Writes $\sin x_i$ to `sin[i]` and $\cos x_i$ to `cos[i]` for every angle of `x`, each the
/// bits [`sin_cos`] gives for it. `sin` and `cos` must be at least as long as `x`.
pub fn sin_cos_each(x: &[f64], sin: &mut [f64], cos: &mut [f64]) {
    #[cfg(target_arch = "x86_64")]
    if crate::wider::avx2() {
        // SAFETY: the processor has AVX2, checked just above.
        unsafe { each_avx2(x, sin, cos) };
        return;
    }
    each(x, sin, cos);
}

/// [`sin_cos_each`] in AVX2 registers, four angles at a time: [`plain`]'s operations one for
/// one, each on four lanes; the last angles (fewer than four) and those beyond the plain path
/// as [`each`] takes them.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn each_avx2(x: &[f64], sin: &mut [f64], cos: &mut [f64]) {
    use core::arch::x86_64::*;
    let n = x.len();
    let (sin, cos) = (&mut sin[..n], &mut cos[..n]);
    let quads = n - n % 4;
    let f = _mm256_set1_pd;
    let i = _mm256_set1_epi64x;
    let magic = f(4_503_599_627_370_496.0);
    let mut plain_only = _mm256_castsi256_pd(i(-1));
    for k in (0..quads).step_by(4) {
        let xv = _mm256_set_pd(x[k + 3], x[k + 2], x[k + 1], x[k]);
        let xa = _mm256_and_pd(xv, _mm256_castsi256_pd(i(i64::MAX)));
        plain_only = _mm256_and_pd(plain_only, _mm256_cmp_pd::<_CMP_LE_OQ>(xa, f(PLAIN_LIMIT)));
        let shifted = _mm256_add_pd(_mm256_mul_pd(xa, f(TWO_OVER_PI)), magic);
        let y = _mm256_sub_pd(shifted, magic);
        let q = _mm256_sub_epi64(_mm256_castpd_si256(shifted), _mm256_castpd_si256(magic));
        let r = _mm256_sub_pd(xa, _mm256_mul_pd(y, f(DP1)));
        let r = _mm256_sub_pd(r, _mm256_mul_pd(y, f(DP2)));
        let r = _mm256_sub_pd(r, _mm256_mul_pd(y, f(DP3)));
        let r2 = _mm256_mul_pd(r, r);
        let z2 = _mm256_mul_pd(r2, r2);
        let z4 = _mm256_mul_pd(z2, z2);
        let term = |a: f64, b: f64| _mm256_add_pd(_mm256_mul_pd(f(a), r2), f(b));
        let poly = |c: [f64; 6]| {
            let low = _mm256_add_pd(_mm256_mul_pd(term(c[5], c[4]), z4), term(c[1], c[0]));
            _mm256_add_pd(_mm256_mul_pd(term(c[3], c[2]), z2), low)
        };
        let s = _mm256_add_pd(_mm256_mul_pd(_mm256_mul_pd(r, r2), poly(SIN)), r);
        let one_less = _mm256_sub_pd(f(1.0), _mm256_mul_pd(r2, f(0.5)));
        let c = _mm256_add_pd(_mm256_mul_pd(z2, poly(COS)), one_less);
        let swap = _mm256_castsi256_pd(_mm256_sub_epi64(
            _mm256_setzero_si256(),
            _mm256_and_si256(q, i(1)),
        ));
        let sv = _mm256_or_pd(_mm256_and_pd(c, swap), _mm256_andnot_pd(swap, s));
        let cv = _mm256_or_pd(_mm256_and_pd(s, swap), _mm256_andnot_pd(swap, c));
        let sin_sign = _mm256_and_si256(
            _mm256_xor_si256(_mm256_slli_epi64::<62>(q), _mm256_castpd_si256(xv)),
            i(i64::MIN),
        );
        let cos_sign = _mm256_slli_epi64::<62>(_mm256_and_si256(_mm256_add_epi64(q, i(1)), i(2)));
        let sv = _mm256_xor_pd(sv, _mm256_castsi256_pd(sin_sign));
        let cv = _mm256_xor_pd(cv, _mm256_castsi256_pd(cos_sign));
        // SAFETY: k + 3 < quads <= n, the length of `sin` and `cos`; unaligned stores.
        unsafe {
            _mm256_storeu_pd(sin[k..k + 4].as_mut_ptr(), sv);
            _mm256_storeu_pd(cos[k..k + 4].as_mut_ptr(), cv);
        }
    }
    let all_plain = _mm256_movemask_pd(plain_only) == 0b1111;
    for k in quads..n {
        (sin[k], cos[k]) = plain(x[k]);
    }
    if !all_plain || x[quads..].iter().any(|&x| !on_plain_path(x)) {
        beyond_plain(x, sin, cos);
    }
}

/// Writes $\sin x_i$ to `sin[i]` for every angle of `x`, the bits [`sin_cos`] gives for it,
/// without the cosine: each angle's one polynomial (the sine's in an even quadrant, the
/// cosine's in an odd one, where they trade places) with the same operations as [`plain`]
/// makes for it, so half the polynomial work. `sin` must be at least as long as `x`.
pub fn sin_each(x: &[f64], sin: &mut [f64]) {
    #[cfg(target_arch = "x86_64")]
    if crate::wider::avx512() {
        // SAFETY: the processor has AVX-512F, checked just above.
        unsafe { avx512::sin_each_avx512(x, sin) };
        return;
    }
    #[cfg(target_arch = "x86_64")]
    if crate::wider::avx2() {
        // SAFETY: the processor has AVX2, checked just above.
        unsafe { sin_each_avx2(x, sin) };
        return;
    }
    sin_each_plain(x, sin);
}

/// [`sin_each`]'s loop in the build this is inlined into: [`plain_sin`] on every angle, then
/// those beyond the plain path by `wide`.
#[inline(always)]
fn sin_each_plain(x: &[f64], sin: &mut [f64]) {
    let sin = &mut sin[..x.len()];
    let mut plain_only = true;
    for (s, &x) in sin.iter_mut().zip(x) {
        *s = plain_sin(x);
        plain_only &= on_plain_path(x);
    }
    if !plain_only {
        sin_beyond_plain(x, sin);
    }
}

/// [`sin_each`] in AVX2 registers, four angles at a time: [`plain_sin`]'s operations one for
/// one, each on four lanes; the last angles (fewer than four) by [`plain_sin`].
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn sin_each_avx2(x: &[f64], sin: &mut [f64]) {
    use core::arch::x86_64::*;
    let n = x.len();
    let sin = &mut sin[..n];
    let quads = n - n % 4;
    let f = _mm256_set1_pd;
    let i = _mm256_set1_epi64x;
    let magic = f(MAGIC);
    let mut plain_only = _mm256_castsi256_pd(i(-1));
    for k in (0..quads).step_by(4) {
        // SAFETY: k + 3 < quads <= n, the length of `x`; an unaligned load.
        let xv = unsafe { _mm256_loadu_pd(x[k..k + 4].as_ptr()) };
        let xa = _mm256_and_pd(xv, _mm256_castsi256_pd(i(i64::MAX)));
        plain_only = _mm256_and_pd(plain_only, _mm256_cmp_pd::<_CMP_LE_OQ>(xa, f(PLAIN_LIMIT)));
        let shifted = _mm256_add_pd(_mm256_mul_pd(xa, f(TWO_OVER_PI)), magic);
        let y = _mm256_sub_pd(shifted, magic);
        let q = _mm256_sub_epi64(_mm256_castpd_si256(shifted), _mm256_castpd_si256(magic));
        let r = _mm256_sub_pd(xa, _mm256_mul_pd(y, f(DP1)));
        let r = _mm256_sub_pd(r, _mm256_mul_pd(y, f(DP2)));
        let r = _mm256_sub_pd(r, _mm256_mul_pd(y, f(DP3)));
        let r2 = _mm256_mul_pd(r, r);
        let z2 = _mm256_mul_pd(r2, r2);
        let z4 = _mm256_mul_pd(z2, z2);
        // All ones in an odd quadrant: the cosine's polynomial and form.
        let odd = _mm256_castsi256_pd(_mm256_sub_epi64(
            _mm256_setzero_si256(),
            _mm256_and_si256(q, i(1)),
        ));
        let c = |k: usize| _mm256_blendv_pd(f(SIN[k]), f(COS[k]), odd);
        let term = |a: __m256d, b: __m256d| _mm256_add_pd(_mm256_mul_pd(a, r2), b);
        let low = _mm256_add_pd(_mm256_mul_pd(term(c(5), c(4)), z4), term(c(1), c(0)));
        let poly = _mm256_add_pd(_mm256_mul_pd(term(c(3), c(2)), z2), low);
        let factor = _mm256_blendv_pd(_mm256_mul_pd(r, r2), z2, odd);
        let one_less = _mm256_sub_pd(f(1.0), _mm256_mul_pd(r2, f(0.5)));
        let addend = _mm256_blendv_pd(r, one_less, odd);
        let v = _mm256_add_pd(_mm256_mul_pd(factor, poly), addend);
        let sign = _mm256_and_si256(
            _mm256_xor_si256(_mm256_slli_epi64::<62>(q), _mm256_castpd_si256(xv)),
            i(i64::MIN),
        );
        let v = _mm256_xor_pd(v, _mm256_castsi256_pd(sign));
        // SAFETY: k + 3 < quads <= n, the length of `sin`; an unaligned store.
        unsafe { _mm256_storeu_pd(sin[k..k + 4].as_mut_ptr(), v) };
    }
    let all_plain = _mm256_movemask_pd(plain_only) == 0b1111;
    for k in quads..n {
        sin[k] = plain_sin(x[k]);
    }
    if !all_plain || x[quads..].iter().any(|&x| !on_plain_path(x)) {
        sin_beyond_plain(x, sin);
    }
}

/// [`plain`]'s sine alone: the one polynomial its quadrant takes, by the same operations.
#[inline(always)]
fn plain_sin(x: f64) -> f64 {
    let xa = x.abs();
    let shifted = xa * TWO_OVER_PI + MAGIC;
    let y = shifted - MAGIC;
    let q = shifted.to_bits().wrapping_sub(MAGIC.to_bits());
    let r = xa - y * DP1;
    let r = r - y * DP2;
    let r = r - y * DP3;
    let r2 = r * r;
    let (z2, z4) = (r2 * r2, (r2 * r2) * (r2 * r2));
    let odd = q & 1 == 1;
    let c = if odd { COS } else { SIN };
    let poly = (c[3] * r2 + c[2]) * z2 + ((c[5] * r2 + c[4]) * z4 + (c[1] * r2 + c[0]));
    let v = if odd {
        z2 * poly + (1.0 - r2 * 0.5)
    } else {
        (r * r2) * poly + r
    };
    let sign = ((q << 62) ^ x.to_bits()) & SIGN;
    f64::from_bits(v.to_bits() ^ sign)
}

/// The sines of the angles of `x` beyond the plain path, by `wide`.
#[cold]
fn sin_beyond_plain(x: &[f64], sin: &mut [f64]) {
    for (&x, s) in x.iter().zip(sin.iter_mut()) {
        if !on_plain_path(x) {
            *s = by_wide(x).0;
        }
    }
}

/// [`sin_cos_each`]'s loop: every angle by the plain path, four at a time and then the rest,
/// then those beyond the plain path again by `wide`.
#[inline(always)]
fn each(x: &[f64], sin: &mut [f64], cos: &mut [f64]) {
    const LANES: usize = 4;
    let n = x.len();
    let (sin, cos) = (&mut sin[..n], &mut cos[..n]);
    let mut plain_only = [true; LANES];
    let quads = x
        .chunks_exact(LANES)
        .zip(sin.chunks_exact_mut(LANES))
        .zip(cos.chunks_exact_mut(LANES));
    for ((x, s), c) in quads {
        for l in 0..LANES {
            (s[l], c[l]) = plain(x[l]);
            plain_only[l] &= x[l].abs() <= PLAIN_LIMIT;
        }
    }
    let rest = n - n % LANES;
    for i in rest..n {
        (sin[i], cos[i]) = plain(x[i]);
        plain_only[0] &= x[i].abs() <= PLAIN_LIMIT;
    }
    if plain_only != [true; LANES] {
        beyond_plain(x, sin, cos);
    }
}

/// The angles of `x` beyond the plain path, by `wide`.
#[cold]
fn beyond_plain(x: &[f64], sin: &mut [f64], cos: &mut [f64]) {
    for ((&x, s), c) in x.iter().zip(sin.iter_mut()).zip(cos.iter_mut()) {
        if !on_plain_path(x) {
            (*s, *c) = by_wide(x);
        }
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

    /// Angles of every kind the plain path takes and a few it leaves to `wide`: uniform on
    /// growing ranges, next to multiples of $\pi/4$ (where the quadrant changes), tiny and
    /// subnormal, near [`PLAIN_LIMIT`], and the special values.
    fn angles(n: usize) -> Vec<f64> {
        use std::f64::consts::FRAC_PI_4;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(6);
        let mut x = Vec::with_capacity(n + 16);
        for i in 0..n {
            let v: f64 = match i % 6 {
                0 => rng.random_range(-1.6..1.6),
                1 => rng.random_range(-30.0..30.0),
                2 => rng.random_range(-1e6..1e6),
                3 => {
                    let k: f64 = rng.random_range(-1000i32..1000).into();
                    f64::from_bits((k * FRAC_PI_4).to_bits() ^ rng.random_range(0..8))
                }
                4 => rng.random_range(-1e15..1e15),
                _ => f64::from_bits(rng.random::<u64>() >> rng.random_range(1..12)),
            };
            x.push(v);
        }
        let special = [
            0.0,
            -0.0,
            f64::MIN_POSITIVE,
            5e-324,
            -5e-324,
            1e-300,
            PLAIN_LIMIT,
            -PLAIN_LIMIT,
            f64::from_bits(PLAIN_LIMIT.to_bits() + 1),
            1e300,
            f64::MAX,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        x.extend_from_slice(&special);
        x
    }

    /// Same bits, or both `NaN`.
    fn same(a: f64, b: f64) -> bool {
        a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
    }

    #[test]
    fn the_plain_path_and_both_builds_give_the_bits_of_wide_for_every_angle() {
        let x = angles(1_200_000);
        let n = x.len();
        let (mut s, mut c) = (vec![0.0; n], vec![0.0; n]);
        each(&x, &mut s, &mut c);
        let mut builds = vec![("baseline", s, c)];
        #[cfg(target_arch = "x86_64")]
        if crate::wider::avx2() {
            let (mut s, mut c) = (vec![0.0; n], vec![0.0; n]);
            // SAFETY: the processor has AVX2, checked just above.
            unsafe { each_avx2(&x, &mut s, &mut c) };
            builds.push(("avx2", s, c));
        }
        for (i, &x) in x.iter().enumerate() {
            let (ws, wc) = by_wide(x);
            let (s1, c1) = sin_cos(x);
            assert!(same(s1, ws) && same(c1, wc), "sin_cos({x:e})");
            for (build, s, c) in &builds {
                assert!(same(s[i], ws) && same(c[i], wc), "{build}: {x:e}");
            }
        }
        // The processor of this machine and of CI has AVX2: both builds were compared.
        eprintln!("compared builds: {}", builds.len());
    }

    #[test]
    fn the_sine_alone_is_the_sine_of_sin_cos_to_the_bit_in_both_builds() {
        let x = angles(1_200_000);
        let n = x.len();
        let mut plain = vec![0.0; n];
        sin_each_plain(&x, &mut plain);
        let mut builds = vec![("baseline", plain)];
        #[cfg(target_arch = "x86_64")]
        if crate::wider::avx2() {
            let mut s = vec![0.0; n];
            // SAFETY: the processor has AVX2, checked just above.
            unsafe { sin_each_avx2(&x, &mut s) };
            builds.push(("avx2", s));
        }
        #[cfg(target_arch = "x86_64")]
        if crate::wider::avx512() {
            let mut s = vec![0.0; n];
            // SAFETY: the processor has AVX-512F, checked just above.
            unsafe { avx512::sin_each_avx512(&x, &mut s) };
            builds.push(("avx512", s));
        }
        for (i, &x) in x.iter().enumerate() {
            let expected = sin_cos(x).0;
            for (build, s) in &builds {
                assert!(same(s[i], expected), "{build}: sin({x:e}) {:e}", s[i]);
            }
        }
        // Slices of every length up to a few quads, so that the remainder is taken too.
        for len in 0..11 {
            let mut s = vec![0.0; len];
            sin_each(&x[..len], &mut s);
            for (&s, &x) in s.iter().zip(&x) {
                assert_eq!(s.to_bits(), sin_cos(x).0.to_bits(), "{len}: sin({x:e})");
            }
        }
        eprintln!("compared builds: {}", builds.len());
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
