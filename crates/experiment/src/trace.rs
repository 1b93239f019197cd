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
