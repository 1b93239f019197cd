//! A scope trace: sample times and signal, and, for a synthetic one, the truth it was made from.

use serde::Serialize;

/// What a synthetic trace was made from, so that an analysis can be scored against it.
///
/// **How $t_0$ is defined.** Eq 79 (the law $\Omega = (C/(t_0 - t))^{1/(\beta+2)}$) has a
/// finite-time singularity at $t_0$. The dissipative model is integrated until $\alpha$ falls to
/// a floor $\alpha_{min}$ (the scene's `stop.alpha_below`; or until lift-off if the scene asks),
/// at time `t_stop`. Near the end the model follows
/// $\alpha \propto (t_0 - t)^{2/(\beta+2)}$, so the time still missing to the singularity is
/// $$\tau_{rem} = \frac{2\,\alpha}{(\beta + 2)\,|\dot\alpha|}\Big|_{t_{stop}},$$
/// and the truth is $t_0 = t_{stop} + \tau_{rem}$. With $\alpha_{min}$ small (1e-4 or less),
/// $\tau_{rem}$ is far below one sample period for $\beta \ge 1$; it is reported so that this
/// can be seen. Times are record times (the first sample at 0).
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
    pub fn sample_interval(&self) -> f64 {
        if self.t.len() < 2 {
            return 0.0;
        }
        let mut d: Vec<f64> = self.t.windows(2).map(|w| w[1] - w[0]).collect();
        let mid = d.len() / 2;
        let (_, m, _) = d.select_nth_unstable_by(mid, f64::total_cmp);
        *m
    }
}
