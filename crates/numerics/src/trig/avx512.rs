//! [`super::sin_each`] in AVX-512 registers, eight angles at a time.

use super::{sin_beyond_plain, sin_each_avx2, COS, DP1, DP2, DP3, MAGIC, PLAIN_LIMIT};
use super::{SIN, TWO_OVER_PI};

/// [`super::sin_each`] eight angles at a time: [`super::plain_sin`]'s operations one for one, each on
/// eight lanes (the quadrant's choice of polynomial by a lane mask where the AVX2 build blends
/// by a sign bit, the same selection); the last angles (fewer than eight) by the AVX2 build.
#[target_feature(enable = "avx512f")]
pub(super) fn sin_each_avx512(x: &[f64], sin: &mut [f64]) {
    use core::arch::x86_64::*;
    let n = x.len();
    let sin = &mut sin[..n];
    let octets = n - n % 8;
    let f = _mm512_set1_pd;
    let i = _mm512_set1_epi64;
    let bits = _mm512_castpd_si512;
    let double = _mm512_castsi512_pd;
    let magic = f(MAGIC);
    let mut plain_only: __mmask8 = 0xff;
    for k in (0..octets).step_by(8) {
        // SAFETY: k + 7 < octets <= n, the length of `x`; an unaligned load.
        let xv = unsafe { _mm512_loadu_pd(x[k..k + 8].as_ptr()) };
        let xa = double(_mm512_and_si512(bits(xv), i(i64::MAX)));
        plain_only &= _mm512_cmp_pd_mask::<_CMP_LE_OQ>(xa, f(PLAIN_LIMIT));
        let shifted = _mm512_add_pd(_mm512_mul_pd(xa, f(TWO_OVER_PI)), magic);
        let y = _mm512_sub_pd(shifted, magic);
        let q = _mm512_sub_epi64(bits(shifted), bits(magic));
        let r = _mm512_sub_pd(xa, _mm512_mul_pd(y, f(DP1)));
        let r = _mm512_sub_pd(r, _mm512_mul_pd(y, f(DP2)));
        let r = _mm512_sub_pd(r, _mm512_mul_pd(y, f(DP3)));
        let r2 = _mm512_mul_pd(r, r);
        let z2 = _mm512_mul_pd(r2, r2);
        let z4 = _mm512_mul_pd(z2, z2);
        // Set in an odd quadrant: the cosine's polynomial and form.
        let odd = _mm512_test_epi64_mask(q, i(1));
        let c = |k: usize| _mm512_mask_blend_pd(odd, f(SIN[k]), f(COS[k]));
        let term = |a: __m512d, b: __m512d| _mm512_add_pd(_mm512_mul_pd(a, r2), b);
        let low = _mm512_add_pd(_mm512_mul_pd(term(c(5), c(4)), z4), term(c(1), c(0)));
        let poly = _mm512_add_pd(_mm512_mul_pd(term(c(3), c(2)), z2), low);
        let factor = _mm512_mask_blend_pd(odd, _mm512_mul_pd(r, r2), z2);
        let one_less = _mm512_sub_pd(f(1.0), _mm512_mul_pd(r2, f(0.5)));
        let addend = _mm512_mask_blend_pd(odd, r, one_less);
        let v = _mm512_add_pd(_mm512_mul_pd(factor, poly), addend);
        let sign = _mm512_and_si512(
            _mm512_xor_si512(_mm512_slli_epi64::<62>(q), bits(xv)),
            i(i64::MIN),
        );
        let v = double(_mm512_xor_si512(bits(v), sign));
        // SAFETY: k + 7 < octets <= n, the length of `sin`; an unaligned store.
        unsafe { _mm512_storeu_pd(sin[k..k + 8].as_mut_ptr(), v) };
    }
    // AVX-512F implies AVX2.
    sin_each_avx2(&x[octets..], &mut sin[octets..]);
    if plain_only != 0xff {
        sin_beyond_plain(&x[..octets], &mut sin[..octets]);
    }
}
