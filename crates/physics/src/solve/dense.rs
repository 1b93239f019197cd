//! DOP853's dense output of one accepted step (Hairer's `contd8`), at one time or over a batch
//! of times; the batch's loops in the baseline build and, where the processor has it, in AVX2
//! ([`numerics::wider`]), the same operations in both.

use super::batch::{Batch, BATCH, LANES};
use super::State;

/// The dense output of one accepted step: a polynomial of degree 7 in
/// $\theta = (t - t_{\mathrm{old}})/h$ (Hairer's `contd8`).
#[derive(Debug, Clone)]
pub(super) struct Dense<const N: usize> {
    /// The start of the step.
    pub(super) t_old: f64,
    /// The step.
    pub(super) h: f64,
    /// The polynomial's coefficients (Hairer's `rcont1` .. `rcont8`).
    pub(super) r: [State<N>; 8],
}

impl<const N: usize> Dense<N> {
    /// The interpolated state at `t` (meant for `t` within the step).
    pub(super) fn at(&self, t: f64) -> State<N> {
        let s = (t - self.t_old) / self.h;
        let s1 = 1.0 - s;
        let r = &self.r;
        // Horner's scheme in s and 1 - s alternately (Hairer's `contd8`), on whole states so
        // that the components are evaluated side by side.
        let mut p = r[6] + r[7] * s;
        p = r[5] + p * s1;
        p = r[4] + p * s;
        p = r[3] + p * s1;
        p = r[2] + p * s;
        p = r[1] + p * s1;
        r[0] + p * s
    }

    /// The interpolated states at `times` (at most [`BATCH`], within the step) written into
    /// `batch`, each to the bit the state [`Dense::at`] gives: the same Horner scheme, one
    /// component at a time over all the rows, so that the rows are evaluated side by side.
    pub(super) fn fill(&self, times: &[f64], batch: &mut Batch<N>) {
        #[cfg(target_arch = "x86_64")]
        if numerics::wider::avx512() {
            // SAFETY: the processor has AVX-512F, checked just above.
            unsafe { self.fill_avx512(times, batch) };
            return;
        }
        #[cfg(target_arch = "x86_64")]
        if numerics::wider::avx2() {
            // SAFETY: the processor has AVX2, checked just above.
            unsafe { self.fill_avx2(times, batch) };
            return;
        }
        self.fill_rows(times, batch);
    }

    /// [`Dense::fill`] in AVX2 registers: [`Dense::fill_rows`]'s operations one for one, on
    /// four rows at a time.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    pub(super) fn fill_avx2(&self, times: &[f64], batch: &mut Batch<N>) {
        use core::arch::x86_64::*;
        let mut s = [0.0; BATCH];
        for (s, t) in s.iter_mut().zip(times) {
            *s = (t - self.t_old) / self.h;
        }
        batch.set_times(times);
        let m = batch.lanes();
        let r = &self.r;
        let (add, mul) = (_mm256_add_pd, _mm256_mul_pd);
        for (i, out) in batch.components_mut().iter_mut().enumerate() {
            let c: [__m256d; 8] = std::array::from_fn(|k| _mm256_set1_pd(r[k][i]));
            for (y, s) in out[..m]
                .chunks_exact_mut(LANES)
                .zip(s[..m].chunks_exact(LANES))
            {
                let s = _mm256_set_pd(s[3], s[2], s[1], s[0]);
                let s1 = _mm256_sub_pd(_mm256_set1_pd(1.0), s);
                let mut p = add(c[6], mul(c[7], s));
                p = add(c[5], mul(p, s1));
                p = add(c[4], mul(p, s));
                p = add(c[3], mul(p, s1));
                p = add(c[2], mul(p, s));
                p = add(c[1], mul(p, s1));
                p = add(c[0], mul(p, s));
                // SAFETY: `y` holds four doubles; an unaligned store.
                unsafe { _mm256_storeu_pd(y.as_mut_ptr(), p) };
            }
        }
    }

    /// [`Dense::fill`] in AVX-512 registers: [`Dense::fill_rows`]'s operations one for one, on
    /// eight rows at a time, and on the last four in AVX2 registers where the batch's rows
    /// are not a multiple of eight.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx512f")]
    pub(super) fn fill_avx512(&self, times: &[f64], batch: &mut Batch<N>) {
        use core::arch::x86_64::*;
        let mut s = [0.0; BATCH];
        for (s, t) in s.iter_mut().zip(times) {
            *s = (t - self.t_old) / self.h;
        }
        batch.set_times(times);
        let m = batch.lanes();
        let octets = m - m % 8;
        let r = &self.r;
        let (add, mul) = (_mm512_add_pd, _mm512_mul_pd);
        for (i, out) in batch.components_mut().iter_mut().enumerate() {
            let c: [__m512d; 8] = std::array::from_fn(|k| _mm512_set1_pd(r[k][i]));
            for (y, s) in out[..octets]
                .chunks_exact_mut(8)
                .zip(s[..octets].chunks_exact(8))
            {
                // SAFETY: `s` holds eight doubles; an unaligned load.
                let s = unsafe { _mm512_loadu_pd(s.as_ptr()) };
                let s1 = _mm512_sub_pd(_mm512_set1_pd(1.0), s);
                let mut p = add(c[6], mul(c[7], s));
                p = add(c[5], mul(p, s1));
                p = add(c[4], mul(p, s));
                p = add(c[3], mul(p, s1));
                p = add(c[2], mul(p, s));
                p = add(c[1], mul(p, s1));
                p = add(c[0], mul(p, s));
                // SAFETY: `y` holds eight doubles; an unaligned store.
                unsafe { _mm512_storeu_pd(y.as_mut_ptr(), p) };
            }
            if octets < m {
                let (add, mul) = (_mm256_add_pd, _mm256_mul_pd);
                let c: [__m256d; 8] = std::array::from_fn(|k| _mm256_set1_pd(r[k][i]));
                // SAFETY: rows `octets..m` are four; an unaligned load.
                let s = unsafe { _mm256_loadu_pd(s[octets..m].as_ptr()) };
                let s1 = _mm256_sub_pd(_mm256_set1_pd(1.0), s);
                let mut p = add(c[6], mul(c[7], s));
                p = add(c[5], mul(p, s1));
                p = add(c[4], mul(p, s));
                p = add(c[3], mul(p, s1));
                p = add(c[2], mul(p, s));
                p = add(c[1], mul(p, s1));
                p = add(c[0], mul(p, s));
                // SAFETY: rows `octets..m` are four; an unaligned store.
                unsafe { _mm256_storeu_pd(out[octets..m].as_mut_ptr(), p) };
            }
        }
    }

    /// [`Dense::fill`]'s loops, in the build this is inlined into (the baseline one when called
    /// directly).
    #[inline(always)]
    pub(super) fn fill_rows(&self, times: &[f64], batch: &mut Batch<N>) {
        let mut s = [0.0; BATCH];
        for (s, t) in s.iter_mut().zip(times) {
            *s = (t - self.t_old) / self.h;
        }
        batch.set_times(times);
        // Four rows at a time, the last four past the samples at s = 0 (no remainder loop).
        let m = batch.lanes();
        let r = &self.r;
        for (i, out) in batch.components_mut().iter_mut().enumerate() {
            let c = [
                r[0][i], r[1][i], r[2][i], r[3][i], r[4][i], r[5][i], r[6][i], r[7][i],
            ];
            let rows = out[..m]
                .chunks_exact_mut(LANES)
                .zip(s[..m].chunks_exact(LANES));
            for (y, s) in rows {
                for (y, &s) in y.iter_mut().zip(s) {
                    let s1 = 1.0 - s;
                    let mut p = c[6] + c[7] * s;
                    p = c[5] + p * s1;
                    p = c[4] + p * s;
                    p = c[3] + p * s1;
                    p = c[2] + p * s;
                    p = c[1] + p * s1;
                    *y = c[0] + p * s;
                }
            }
        }
    }
}
