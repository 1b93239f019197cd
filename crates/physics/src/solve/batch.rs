//! The samples of one step handed on together ([`Problem::on_batch`](super::Problem::on_batch)):
//! up to [`BATCH`] times and their states, stored component by component (one array of rows
//! per state), so that whoever takes them can compute a column over all the rows at once.

use super::State;

/// The most samples in one batch.
pub const BATCH: usize = 32;

/// The rows a loop over a batch takes together ([`Batch::lanes`]): four doubles fill an AVX2
/// register, two SSE2 registers.
pub const LANES: usize = 4;

/// Samples of a run, in time order, all from one step.
#[derive(Debug, Clone)]
pub struct Batch<const N: usize> {
    len: usize,
    t: [f64; BATCH],
    y: [[f64; BATCH]; N],
}

/// Takes each batch of samples of a sampled run as it is made ([`super::Problem::on_batch`]).
pub type BatchSink<'a, const N: usize> = &'a mut dyn FnMut(&Batch<N>);

impl<const N: usize> Default for Batch<N> {
    fn default() -> Self {
        Self {
            len: 0,
            t: [0.0; BATCH],
            y: [[0.0; BATCH]; N],
        }
    }
}

impl<const N: usize> Batch<N> {
    /// A batch of the one sample `(t, y)`.
    pub fn one(t: f64, y: &State<N>) -> Self {
        let mut b = Self::default();
        b.push(t, y);
        b
    }

    /// Adds the sample `(t, y)` after the others; false (and nothing added) when the batch is
    /// full.
    pub fn push(&mut self, t: f64, y: &State<N>) -> bool {
        if self.len == BATCH {
            return false;
        }
        self.t[self.len] = t;
        for i in 0..N {
            self.y[i][self.len] = y[i];
        }
        self.len += 1;
        true
    }

    /// The number of samples.
    pub fn len(&self) -> usize {
        self.len
    }

    /// True when the batch holds no sample.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The samples' times.
    pub fn times(&self) -> &[f64] {
        &self.t[..self.len]
    }

    /// Component `i` of every sample's state.
    pub fn component(&self, i: usize) -> &[f64] {
        &self.y[i][..self.len]
    }

    /// The number of rows a loop over the batch four at a time covers: [`Batch::len`] rounded
    /// up to a multiple of 4 (at most [`BATCH`]). The rows past the samples hold numbers left
    /// from earlier batches (or zeros): a loop may compute over them, so as to run without a
    /// remainder, and must not hand them on.
    pub fn lanes(&self) -> usize {
        self.len.next_multiple_of(LANES)
    }

    /// Component `i` of every row of the batch, the [`Batch::lanes`] past the samples too.
    pub fn component_rows(&self, i: usize) -> &[f64; BATCH] {
        &self.y[i]
    }

    /// The times of every row, as [`Batch::component_rows`].
    pub fn time_rows(&self) -> &[f64; BATCH] {
        &self.t
    }

    /// The state of sample `j`.
    pub fn state(&self, j: usize) -> State<N> {
        State::<N>::from_fn(|i, _| self.y[i][j])
    }

    /// Makes the batch the samples at `times` (at most [`BATCH`]), their states still to be
    /// written by [`Batch::components_mut`].
    pub(super) fn set_times(&mut self, times: &[f64]) {
        self.len = times.len();
        self.t[..self.len].copy_from_slice(times);
    }

    /// Every component's rows, to be written.
    pub(super) fn components_mut(&mut self) -> &mut [[f64; BATCH]; N] {
        &mut self.y
    }
}

#[cfg(test)]
mod tests {
    use super::super::arenstorf::{start, Arenstorf, PERIOD};
    use super::super::dop853::{Dop853, Outcome};
    use super::*;

    /// Every step of an orbit, its dense output at up to a full batch of times (and at fewer,
    /// so that a partial batch is seen): each state of the batch is the one `Dense::at` gives,
    /// to the bit, in the build `Dense::fill` chooses (AVX-512 or AVX2 where the processor has
    /// it), in the AVX2 one and in the baseline one.
    #[test]
    fn a_batch_from_the_dense_output_is_each_sample_alone_to_the_bit() {
        let mut s = Dop853::new(&Arenstorf, 1e-9, 1e-9, 0.0, start(), PERIOD);
        let mut steps = 0;
        while s.t < PERIOD {
            let t_a = s.t;
            assert_eq!(s.step(PERIOD), Outcome::Accepted);
            let d = s.dense();
            let n = 1 + steps % BATCH;
            let times: Vec<f64> = (1..=n)
                .map(|j| t_a + (s.t - t_a) * j as f64 / n as f64)
                .collect();
            let mut b = Batch::default();
            d.fill(&times, &mut b);
            // The baseline build's loops, whichever build `fill` chose on this processor.
            let mut baseline = Batch::default();
            d.fill_rows(&times, &mut baseline);
            // The AVX2 build too where `fill` chose the AVX-512 one.
            let mut builds = vec![baseline];
            #[cfg(target_arch = "x86_64")]
            if numerics::wider::avx2() {
                let mut avx2 = Batch::default();
                // SAFETY: the processor has AVX2, checked just above.
                unsafe { d.fill_avx2(&times, &mut avx2) };
                builds.push(avx2);
            }
            assert_eq!(b.len(), n);
            for (j, &t) in times.iter().enumerate() {
                assert_eq!(b.times()[j], t);
                let alone = d.at(t);
                for i in 0..4 {
                    assert_eq!(b.component(i)[j].to_bits(), alone[i].to_bits());
                    for other in &builds {
                        assert_eq!(other.component(i)[j].to_bits(), alone[i].to_bits());
                    }
                }
                assert_eq!(b.state(j), alone);
            }
            steps += 1;
        }
        assert!(steps > 50, "{steps} steps");
    }

    #[test]
    fn a_full_batch_takes_no_more() {
        let mut b = Batch::<2>::default();
        let y = State::<2>::new(1.0, 2.0);
        for k in 0..BATCH {
            assert!(b.push(k as f64, &y));
        }
        assert!(!b.push(0.0, &y));
        assert_eq!(b.len(), BATCH);
        assert_eq!(Batch::one(3.0, &y).state(0), y);
    }
}
