//! A batch's rows written from its columns ([`Model::record_rows`](super::Model::record_rows)):
//! row `j` is the `j`-th number of each column in turn, appended to the rows already there.
//!
//! Writing rows from columns is a transpose, so the AVX2 build (where the processor has it,
//! [`numerics::wider`]) moves four rows and four columns at a time through registers (two
//! unpacks and two lane permutes per pair of registers) rather than one number at a time, and
//! writes into the rows' reserved space without zeroing it first. The numbers are only moved,
//! never computed, so both builds write the same bits.

use crate::model::{Layout, Quantity};
use crate::solve::{Batch, BATCH, LANES};

/// The most columns a batch's rows have here (the time and every quantity a model records,
/// once each, is 11).
pub(crate) const MAX_COLUMNS: usize = 16;

/// One or two columns of a quantity over a batch's rows: `None` for a quantity the model does
/// not record (a validated scene never asks for one).
pub(crate) type QuantityColumns<'a> = (Option<&'a [f64; BATCH]>, Option<&'a [f64; BATCH]>);

/// The columns that every model's batch holds alike: $\alpha$, $\dot\alpha$ and $\Omega$ (the
/// state's first three components), the heading and the face angle where the layout has them,
/// and the energy, $L_z$ and the normal force as the model computed them over the rows.
pub(crate) struct SharedColumns<'a, const N: usize> {
    /// The batch's states.
    pub batch: &'a Batch<N>,
    /// Where its optional states sit.
    pub layout: &'a Layout,
    /// The rows' energies.
    pub energy: &'a [f64; BATCH],
    /// The rows' $L_z$ (unspecified where not recorded).
    pub lz: &'a [f64; BATCH],
    /// The rows' normal forces (unspecified where not recorded).
    pub normal_force: &'a [f64; BATCH],
}

impl<'a, const N: usize> SharedColumns<'a, N> {
    /// The columns of `q` when it is one of these; `None` for a quantity the model makes its
    /// own way (the spin, the friction, the path).
    #[inline(always)]
    pub(crate) fn of(&self, q: Quantity) -> Option<QuantityColumns<'a>> {
        let y = |i: usize| self.batch.component_rows(i);
        let state = |i: Option<usize>| i.map(y);
        Some(match q {
            Quantity::Alpha => (Some(y(0)), None),
            Quantity::AlphaDot => (Some(y(1)), None),
            Quantity::Precession => (Some(y(2)), None),
            Quantity::Energy => (Some(self.energy), None),
            Quantity::Lz => (Some(self.lz), None),
            Quantity::NormalForce => (Some(self.normal_force), None),
            Quantity::Heading => (state(self.layout.heading), None),
            Quantity::Face => (state(self.layout.face), None),
            _ => return None,
        })
    }
}

/// The columns of a batch's rows as [`write_rows`] takes them: `time` first, then the one or
/// two columns `columns_of` gives for each of `quantities` in turn; with how many there are.
/// The batch's width must be at most [`MAX_COLUMNS`].
#[inline(always)]
pub(crate) fn gather_columns<'a>(
    time: &'a [f64; BATCH],
    quantities: &[Quantity],
    mut columns_of: impl FnMut(Quantity) -> QuantityColumns<'a>,
) -> ([&'a [f64; BATCH]; MAX_COLUMNS], usize) {
    let mut columns = [time; MAX_COLUMNS];
    let mut c = 1;
    for &q in quantities {
        let (first, second) = columns_of(q);
        debug_assert!(
            first.is_some(),
            "validated scenes only record what the model provides"
        );
        for column in [first, second].into_iter().flatten() {
            columns[c] = column;
            c += 1;
        }
    }
    (columns, c)
}

/// Appends rows `0..n` (`n` at most [`BATCH`]) of `columns` to `out`, row after row: row `j` is
/// `columns[c][j]` for each `c`.
#[inline(always)]
pub(crate) fn write_rows(columns: &[&[f64; BATCH]], n: usize, out: &mut Vec<f64>) {
    #[cfg(target_arch = "x86_64")]
    if numerics::wider::avx2() {
        // SAFETY: the processor has AVX2, checked just above.
        unsafe { write_rows_avx2(columns, n, out) };
        return;
    }
    write_rows_plain(columns, n, out);
}

/// [`write_rows`] one number at a time, in the build it is inlined into; the usual widths
/// with the width known to the compiler.
#[inline(always)]
fn write_rows_plain(columns: &[&[f64; BATCH]], n: usize, out: &mut Vec<f64>) {
    let n = n.min(BATCH);
    match columns {
        [a, b] => write_fixed(&[*a, *b], n, out),
        [a, b, c] => write_fixed(&[*a, *b, *c], n, out),
        [a, b, c, d] => write_fixed(&[*a, *b, *c, *d], n, out),
        [a, b, c, d, e] => write_fixed(&[*a, *b, *c, *d, *e], n, out),
        [a, b, c, d, e, f] => write_fixed(&[*a, *b, *c, *d, *e, *f], n, out),
        [a, b, c, d, e, f, g] => write_fixed(&[*a, *b, *c, *d, *e, *f, *g], n, out),
        [a, b, c, d, e, f, g, h] => write_fixed(&[*a, *b, *c, *d, *e, *f, *g, *h], n, out),
        _ => {
            for j in 0..n {
                out.extend(columns.iter().map(|c| c[j]));
            }
        }
    }
}

/// [`write_rows_plain`] for `W` columns.
#[inline(always)]
fn write_fixed<const W: usize>(columns: &[&[f64; BATCH]; W], n: usize, out: &mut Vec<f64>) {
    let start = out.len();
    out.resize(start + n * W, 0.0);
    let (rows, _) = out[start..].as_chunks_mut::<W>();
    for (row, j) in rows.iter_mut().zip(0..BATCH) {
        for (v, c) in row.iter_mut().zip(columns) {
            *v = c[j];
        }
    }
}

/// [`write_rows`] in AVX2 registers, the usual widths with the width known to the compiler.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn write_rows_avx2(columns: &[&[f64; BATCH]], n: usize, out: &mut Vec<f64>) {
    match columns {
        [a, b] => write_fixed_avx2(&[*a, *b], n, out),
        [a, b, c] => write_fixed_avx2(&[*a, *b, *c], n, out),
        [a, b, c, d] => write_fixed_avx2(&[*a, *b, *c, *d], n, out),
        [a, b, c, d, e] => write_fixed_avx2(&[*a, *b, *c, *d, *e], n, out),
        [a, b, c, d, e, f] => write_fixed_avx2(&[*a, *b, *c, *d, *e, *f], n, out),
        [a, b, c, d, e, f, g] => write_fixed_avx2(&[*a, *b, *c, *d, *e, *f, *g], n, out),
        [a, b, c, d, e, f, g, h] => write_fixed_avx2(&[*a, *b, *c, *d, *e, *f, *g, *h], n, out),
        _ => write_any_avx2(columns, n, out),
    }
}

/// [`write_rows_avx2`] for `W` columns: each block of four rows (the last one's rows past `n`
/// written into the reserved space and left out of the length), four columns at a time by a
/// 4x4 transpose, then two, then one.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn write_fixed_avx2<const W: usize>(columns: &[&[f64; BATCH]; W], n: usize, out: &mut Vec<f64>) {
    use core::arch::x86_64::*;
    let n = n.min(BATCH);
    let blocks = n.div_ceil(LANES);
    out.reserve(blocks * LANES * W);
    let start = out.len();
    let cols: [*const f64; W] = std::array::from_fn(|c| columns[c].as_ptr());
    // SAFETY: as in `write_any_avx2`; the loads read numbers `j .. j + 4` of arrays of
    // `BATCH`, with `j + 4 <= blocks * LANES <= BATCH`.
    unsafe {
        let base = out.as_mut_ptr().add(start);
        for b in 0..blocks {
            let j = b * LANES;
            let row = base.add(j * W);
            let at = |r: usize, c: usize| row.add(r * W + c);
            let load = |c: usize| _mm256_loadu_pd(cols[c].add(j));
            let mut c = 0;
            while c + 4 <= W {
                let (a0, a1, a2, a3) = (load(c), load(c + 1), load(c + 2), load(c + 3));
                let t0 = _mm256_unpacklo_pd(a0, a1);
                let t1 = _mm256_unpackhi_pd(a0, a1);
                let t2 = _mm256_unpacklo_pd(a2, a3);
                let t3 = _mm256_unpackhi_pd(a2, a3);
                _mm256_storeu_pd(at(0, c), _mm256_permute2f128_pd::<0x20>(t0, t2));
                _mm256_storeu_pd(at(1, c), _mm256_permute2f128_pd::<0x20>(t1, t3));
                _mm256_storeu_pd(at(2, c), _mm256_permute2f128_pd::<0x31>(t0, t2));
                _mm256_storeu_pd(at(3, c), _mm256_permute2f128_pd::<0x31>(t1, t3));
                c += 4;
            }
            if c + 2 <= W {
                let (a0, a1) = (load(c), load(c + 1));
                let t0 = _mm256_unpacklo_pd(a0, a1);
                let t1 = _mm256_unpackhi_pd(a0, a1);
                _mm_storeu_pd(at(0, c), _mm256_castpd256_pd128(t0));
                _mm_storeu_pd(at(1, c), _mm256_castpd256_pd128(t1));
                _mm_storeu_pd(at(2, c), _mm256_extractf128_pd::<1>(t0));
                _mm_storeu_pd(at(3, c), _mm256_extractf128_pd::<1>(t1));
                c += 2;
            }
            if c < W {
                for r in 0..LANES {
                    at(r, c).write(*cols[c].add(j + r));
                }
            }
        }
        out.set_len(start + n * W);
    }
}

/// [`write_rows_avx2`] for any width, as [`write_fixed_avx2`] does it.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn write_any_avx2(columns: &[&[f64; BATCH]], n: usize, out: &mut Vec<f64>) {
    use core::arch::x86_64::*;
    let n = n.min(BATCH);
    let w = columns.len();
    let blocks = n.div_ceil(LANES);
    out.reserve(blocks * LANES * w);
    let start = out.len();
    // SAFETY: `out` has room for `blocks * LANES` rows of `w` numbers past `start` (reserved
    // just above), so every pointer below stays within its allocation; the numbers past the
    // `n` rows are written but not counted, and every one of the first `n` rows is written
    // before the length covers it.
    unsafe {
        let base = out.as_mut_ptr().add(start);
        for b in 0..blocks {
            let j = b * LANES;
            let row = |r: usize| base.add((j + r) * w);
            let load = |c: usize| _mm256_loadu_pd(columns[c][j..j + LANES].as_ptr());
            let mut c = 0;
            while c + 4 <= w {
                let (a0, a1, a2, a3) = (load(c), load(c + 1), load(c + 2), load(c + 3));
                // Rows 0 and 2, then 1 and 3, of columns c, c + 1 and of c + 2, c + 3.
                let t0 = _mm256_unpacklo_pd(a0, a1);
                let t1 = _mm256_unpackhi_pd(a0, a1);
                let t2 = _mm256_unpacklo_pd(a2, a3);
                let t3 = _mm256_unpackhi_pd(a2, a3);
                _mm256_storeu_pd(row(0).add(c), _mm256_permute2f128_pd::<0x20>(t0, t2));
                _mm256_storeu_pd(row(1).add(c), _mm256_permute2f128_pd::<0x20>(t1, t3));
                _mm256_storeu_pd(row(2).add(c), _mm256_permute2f128_pd::<0x31>(t0, t2));
                _mm256_storeu_pd(row(3).add(c), _mm256_permute2f128_pd::<0x31>(t1, t3));
                c += 4;
            }
            if c + 2 <= w {
                let (a0, a1) = (load(c), load(c + 1));
                let t0 = _mm256_unpacklo_pd(a0, a1);
                let t1 = _mm256_unpackhi_pd(a0, a1);
                _mm_storeu_pd(row(0).add(c), _mm256_castpd256_pd128(t0));
                _mm_storeu_pd(row(1).add(c), _mm256_castpd256_pd128(t1));
                _mm_storeu_pd(row(2).add(c), _mm256_extractf128_pd::<1>(t0));
                _mm_storeu_pd(row(3).add(c), _mm256_extractf128_pd::<1>(t1));
                c += 2;
            }
            if c < w {
                for r in 0..LANES {
                    row(r).add(c).write(columns[c][j + r]);
                }
            }
        }
        out.set_len(start + n * w);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every width up to [`MAX_COLUMNS`] and every number of rows up to [`BATCH`], appended to
    /// rows already there: the rows of the columns, number for number, in both builds.
    #[test]
    fn the_rows_are_the_columns_transposed_in_both_builds() {
        let columns: Vec<[f64; BATCH]> = (0..MAX_COLUMNS)
            .map(|c| std::array::from_fn(|j| (100 * c + j) as f64 + 0.5))
            .collect();
        for w in 1..=MAX_COLUMNS {
            let cols: Vec<&[f64; BATCH]> = columns[..w].iter().collect();
            for n in 0..=BATCH {
                let mut expected = vec![-1.0, -2.0];
                for j in 0..n {
                    expected.extend((0..w).map(|c| (100 * c + j) as f64 + 0.5));
                }
                let mut out = vec![-1.0, -2.0];
                write_rows(&cols, n, &mut out);
                assert_eq!(out, expected, "{w} columns, {n} rows");
                let mut plain = vec![-1.0, -2.0];
                write_rows_plain(&cols, n, &mut plain);
                assert_eq!(plain, expected, "{w} columns, {n} rows, baseline");
            }
        }
    }
}
