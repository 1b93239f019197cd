//! This tool's run read at any time inside it: between two of its points, in the mode of the
//! segment they belong to, the cubic Hermite interpolant
//! $$ y(t_j + sh) = (2s^3 - 3s^2 + 1)\,y_j + (s^3 - 2s^2 + s)\,h f_j +
//!    (-2s^3 + 3s^2)\,y_{j+1} + (s^3 - s^2)\,h f_{j+1},\qquad f = \dot y \text{ of the mode's flow}, $$
//! whose error is $h^4 \max|y^{(4)}|/384$, and the orientation's quaternion set back to unit
//! length. The peer's rows whose state is later than their label are read this way.

use physics::model::sliding::{Flow, Mode, Sliding, SlidingRun};
use physics::solve::{Dynamics, State};

/// A run and its model, read at any time of the run.
pub struct Along<'a> {
    /// The model.
    pub model: &'a Sliding,
    /// The run.
    pub run: &'a SlidingRun,
}

impl Along<'_> {
    /// The state and mode at `t`, `None` outside the run.
    pub fn at(&self, t: f64) -> Option<(State<14>, Mode)> {
        let ts = &self.run.t;
        let (first, last) = (*ts.first()?, *ts.last()?);
        // A row's time, its label (7 decimals) plus the offset read from its angles, may pass
        // the run's ends by their rounding: within a microsecond it is read at the end.
        let t = if (t - last).abs() < 1e-6 {
            last
        } else if (t - first).abs() < 1e-6 {
            first
        } else {
            t
        };
        if t < first || t > last {
            return None;
        }
        let j = ts.partition_point(|&x| x <= t) - 1;
        let mode = self.run.mode[j];
        if j + 1 == ts.len() || ts[j] == t {
            return Some((self.run.y[j], mode));
        }
        let (y0, y1) = (&self.run.y[j], &self.run.y[j + 1]);
        let h = ts[j + 1] - ts[j];
        let flow = Flow {
            model: self.model,
            mode,
        };
        let (mut f0, mut f1) = (State::<14>::zeros(), State::<14>::zeros());
        flow.rhs(y0, &mut f0);
        flow.rhs(y1, &mut f1);
        let s = (t - ts[j]) / h;
        let (s2, s3) = (s * s, s * s * s);
        let mut y = y0 * (2.0 * s3 - 3.0 * s2 + 1.0)
            + f0 * (h * (s3 - 2.0 * s2 + s))
            + y1 * (-2.0 * s3 + 3.0 * s2)
            + f1 * (h * (s3 - s2));
        let norm = (0..4).map(|i| y[i] * y[i]).sum::<f64>().sqrt();
        for i in 0..4 {
            y[i] /= norm;
        }
        Some((y, mode))
    }
}
