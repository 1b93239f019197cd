//! A scope trace: sample times and signal, and, for a synthetic one, the truth it was made from.

use serde::Serialize;

/// What a synthetic trace was made from, so that an analysis can be scored against it.
///
/// **How $t_0$ is defined.** Eq 79 (the law $\Omega = (C/(t_0 - t))^{1/(\beta+2)}$) has a
/// finite-time singularity at $t_0$. The dissipative (or sliding) model is integrated until $\alpha$ falls to
/// a floor $\alpha_{min}$ (the scene's `stop.alpha_below`; or until lift-off if the scene asks),
/// at time `t_stop`. Near the end the model follows
/// $\alpha \propto (t_0 - t)^{2/(\beta+2)}$, so the time still missing to the singularity is
/// $$\tau_{rem} = \frac{2\,\alpha}{(\beta + 2)\,|\dot\alpha|}\Big|_{t_{stop}},$$
/// and the truth is $t_0 = t_{stop} + \tau_{rem}$. With $\alpha_{min}$ small (1e-4 or less),
/// $\tau_{rem}$ is far below one sample period for $\beta \ge 1$; it is reported so that this
/// can be seen. Times are record times (the first sample at 0).
///
/// A model is not eq 79 exactly, so eq 84 fitted even to its exact motion finds another $t_0$
/// (20 ms earlier over the built-in record; [`crate::fit::motion_law`] computes it and
/// tells the law's part of an analysis's error from the analysis's own).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Truth {
    /// The dissipation exponent $\beta$ of eq 75 that made the trace.
    pub beta: f64,
    /// The singular time $t_0$ of eq 79 in record time (s).
    pub t0: f64,
    /// When the integration stopped (record time, s).
    pub t_stop: f64,
    /// $t_0 - t_{stop}$ (s).
    pub tau_rem: f64,
    /// $C$ of eq 79 when known exactly (law traces); `None` for the model, whose constant is not
    /// the paper's.
    pub c: Option<f64>,
    /// Where the truth came from.
    pub origin: String,
}

impl Truth {
    /// The truth of a spin-down integrated until record time `t_stop`, where the tilt is
    /// `alpha` and falls at `alpha_dot`: $t_0 = t_{stop} + \tau_{rem}$ with
    /// $\tau_{rem} = 2\alpha/((\beta+2)|\dot\alpha|)$ (zero once the disk is flat).
    pub fn at_stop(beta: f64, t_stop: f64, alpha: f64, alpha_dot: f64, origin: String) -> Self {
        let tau_rem = if alpha > 0.0 {
            2.0 * alpha / ((beta + 2.0) * alpha_dot.abs().max(f64::MIN_POSITIVE))
        } else {
            0.0
        };
        Self {
            beta,
            t0: t_stop + tau_rem,
            t_stop,
            tau_rem,
            c: None,
            origin,
        }
    }
}

/// A recorded (or simulated) light signal.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Trace {
    /// Where it came from: a file path or a description; errors name it.
    pub source: String,
    /// Sample times (s), strictly increasing.
    pub t: Vec<f64>,
    /// Signal (V).
    pub v: Vec<f64>,
    /// The truth, for synthetic traces.
    pub truth: Option<Truth>,
}

impl Trace {
    /// The number of samples.
    pub fn len(&self) -> usize {
        self.t.len()
    }

    /// True when there are no samples.
    pub fn is_empty(&self) -> bool {
        self.t.is_empty()
    }

    /// The median sample interval (s); 0 with fewer than two samples.
    ///
    /// A uniformly sampled trace's intervals take a few values (the rounding of $t_j$), so
    /// they are counted value by value, without a copy of the record; a trace whose intervals
    /// take more than [`FEW_INTERVALS`] values is sorted for its median. Both give the same
    /// interval.
    pub fn sample_interval(&self) -> f64 {
        if self.t.len() < 2 {
            return 0.0;
        }
        let mid = (self.t.len() - 1) / 2;
        let mut counts: Vec<(f64, usize)> = Vec::new();
        for w in self.t.windows(2) {
            let d = w[1] - w[0];
            match counts.iter().position(|c| c.0.to_bits() == d.to_bits()) {
                Some(i) => counts[i].1 += 1,
                None if counts.len() < FEW_INTERVALS => counts.push((d, 1)),
                None => {
                    let mut d: Vec<f64> = self.t.windows(2).map(|w| w[1] - w[0]).collect();
                    let (_, m, _) = d.select_nth_unstable_by(mid, f64::total_cmp);
                    return *m;
                }
            }
        }
        counts.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut below = 0;
        for (d, k) in counts {
            below += k;
            if below > mid {
                return d;
            }
        }
        0.0
    }
}

/// The most distinct intervals [`Trace::sample_interval`] counts before it sorts them.
pub const FEW_INTERVALS: usize = 64;

/// The sampled motion of a spin-down: tilt and heading at the record's times, NaN after the
/// spin-down ends (the disk lies flat), and the truth.
#[derive(Debug, Clone, PartialEq)]
pub struct Motion {
    /// Record times (s), the first at 0.
    pub t: Vec<f64>,
    /// $\alpha$ (rad), NaN once flat.
    pub alpha: Vec<f64>,
    /// The heading $\psi$, $\dot\psi = \Omega$ (rad), NaN once flat.
    pub heading: Vec<f64>,
    /// The truth.
    pub truth: Truth,
}

#[cfg(test)]
mod tests {
    use super::Trace;

    fn median_by_sorting(t: &[f64]) -> f64 {
        let mut d: Vec<f64> = t.windows(2).map(|w| w[1] - w[0]).collect();
        d.sort_by(f64::total_cmp);
        d[(t.len() - 1) / 2]
    }

    /// The median interval counted value by value is the sorted intervals' median: on a
    /// uniform record (its intervals a few roundings of 1/48000 s), on a record with a gap,
    /// and on a jittered one (every interval its own value, so sorted).
    #[test]
    fn the_median_interval_is_the_sorted_intervals_median() {
        let trace = |t: Vec<f64>| Trace {
            source: "x".into(),
            v: vec![0.0; t.len()],
            t,
            truth: None,
        };
        let uniform: Vec<f64> = (0..200_001).map(|j| 3.5 + j as f64 / 48_000.0).collect();
        let mut gap = uniform.clone();
        gap.iter_mut().skip(1000).for_each(|t| *t += 0.25);
        let mut state = 11u64;
        let jitter: Vec<f64> = (0..5_000)
            .map(|j| {
                state = state.wrapping_mul(6364136223846793005).wrapping_add(1);
                j as f64 * 1e-3 + 1e-5 * ((state >> 11) as f64 / (1u64 << 53) as f64)
            })
            .collect();
        for t in [uniform, gap, jitter, vec![0.0, 2.0], vec![0.0, 1.0, 3.0]] {
            let want = median_by_sorting(&t);
            assert_eq!(trace(t).sample_interval().to_bits(), want.to_bits());
        }
        assert_eq!(trace(vec![1.0]).sample_interval(), 0.0);
    }
}
