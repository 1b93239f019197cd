//! Where a sampled run looks for a loss of contact: at its steps' ends, and at the rows only
//! of the steps next to a negative normal force.

use crate::model::Model;
use crate::solve::State;
use std::cell::Cell;

/// Where a sampled run looks for a loss of contact: in a step whose start or end has a negative
/// normal force (the start of the first step is the run's start), as [`crate::solve`]'s events
/// are seen at the steps' ends. Where the integrator hands on the right-hand side at a step's
/// end, the force there is taken from it ([`Model::normal_force_from_rates`]: no accelerations
/// solved again), and the step is watched when the force is below the round-off bound that
/// comes with it, so that a step the rows' own $F_z$ would watch is never passed over. Those steps' rows are each checked, so the loss found is the
/// first row with $F_z < 0$ of those steps: the one a check of every row finds, unless the force
/// dips below zero and back within one step. A step shorter than two sampling intervals holds
/// at most two rows, which are checked outright rather than its ends (its end's force is
/// computed only if the next step needs it as its start's), so that a run never computes the
/// force more often than once a row or twice a step.
pub(super) struct ContactWatch<const N: usize> {
    /// The sampling interval (s).
    dt: f64,
    /// The time of the last step's end (the run's start before the first step).
    last_t: Cell<f64>,
    /// The last step's end: whether its force is negative, or the state (and the right-hand
    /// side, when handed on) there when that is not computed yet.
    last_end: Cell<End<N>>,
    /// The rows of the current step are checked.
    armed: Cell<bool>,
    /// The loss of contact is found: nothing more to look for.
    found: Cell<bool>,
}

/// A step's end as the next step's start: its force's sign, or the state to compute it from.
#[derive(Clone, Copy)]
enum End<const N: usize> {
    Negative(bool),
    At(State<N>, Option<State<N>>),
}

impl<const N: usize> ContactWatch<N> {
    /// A watch over a run that starts at `(t0, y0)` and samples every `dt`.
    pub(super) fn new<M: Model<N>>(model: &M, t0: f64, y0: &State<N>, dt: f64) -> Self {
        let negative = negative_force(model, y0, None, &mut Vec::new());
        Self {
            dt,
            last_t: Cell::new(t0),
            last_end: Cell::new(End::Negative(negative)),
            armed: Cell::new(negative),
            found: Cell::new(false),
        }
    }

    /// The end `(t, y)` of the next accepted step, before its rows, with the right-hand side
    /// `dy` there when the integrator has it.
    pub(super) fn step_end<M: Model<N>>(
        &self,
        model: &M,
        t: f64,
        y: &State<N>,
        dy: Option<&State<N>>,
        scratch: &mut Vec<f64>,
    ) {
        if self.found.get() {
            return;
        }
        let h = t - self.last_t.replace(t);
        if h < 2.0 * self.dt {
            self.armed.set(true);
            self.last_end.set(End::At(*y, dy.copied()));
            return;
        }
        let start = match self.last_end.get() {
            End::Negative(negative) => negative,
            End::At(y_a, dy_a) => negative_force(model, &y_a, dy_a.as_ref(), scratch),
        };
        let end = negative_force(model, y, dy, scratch);
        self.armed.set(start || end);
        self.last_end.set(End::Negative(end));
    }

    /// Whether the rows of the current step are to be checked.
    pub(super) fn armed(&self) -> bool {
        self.armed.get()
    }

    /// The loss of contact is found.
    pub(super) fn mark_found(&self) {
        self.found.set(true);
    }
}

/// Whether the model's normal force in state `y` is negative (false for a model without one):
/// from the right-hand side `dy` where it is given and the model can, below its round-off
/// bound; otherwise as a row computes it, below zero.
fn negative_force<M: Model<N>, const N: usize>(
    model: &M,
    y: &State<N>,
    dy: Option<&State<N>>,
    scratch: &mut Vec<f64>,
) -> bool {
    if let Some((fz, bound)) = dy.and_then(|dy| model.normal_force_from_rates(y, dy)) {
        return fz < bound;
    }
    scratch.clear();
    let shared = model.record_row(y, &[], true, scratch);
    shared.normal_force.is_some_and(|f| f < 0.0)
}

#[cfg(test)]
mod tests;
