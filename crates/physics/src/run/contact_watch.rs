//! Where a sampled run looks for a loss of contact: at its steps' ends, and at the rows only
//! of the steps next to a negative normal force.

use crate::model::Model;
use crate::solve::State;
use std::cell::Cell;

/// Where a sampled run looks for a loss of contact: in a step whose start or end has a negative
/// normal force (the start of the first step is the run's start), as [`crate::solve`]'s events
/// are seen at the steps' ends. Those steps' rows are each checked, so the loss found is the
/// first row with $F_z < 0$ of those steps: the one a check of every row finds, unless the force
/// dips below zero and back within one step.
pub(super) struct ContactWatch {
    /// The force at the end of the last step (at the start before the first) is negative.
    last_negative: Cell<bool>,
    /// The rows of the current step are checked.
    armed: Cell<bool>,
    /// The loss of contact is found: nothing more to look for.
    found: Cell<bool>,
}

impl ContactWatch {
    pub(super) fn new<M: Model<N>, const N: usize>(model: &M, y0: &State<N>) -> Self {
        let negative = negative_force(model, y0, &mut Vec::new());
        Self {
            last_negative: Cell::new(negative),
            armed: Cell::new(negative),
            found: Cell::new(false),
        }
    }

    /// The end of the next accepted step, before its rows.
    pub(super) fn step_end<M: Model<N>, const N: usize>(
        &self,
        model: &M,
        y: &State<N>,
        scratch: &mut Vec<f64>,
    ) {
        if self.found.get() {
            return;
        }
        let negative = negative_force(model, y, scratch);
        self.armed.set(negative || self.last_negative.get());
        self.last_negative.set(negative);
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

/// Whether the model's normal force in state `y` is negative (false for a model without one).
fn negative_force<M: Model<N>, const N: usize>(
    model: &M,
    y: &State<N>,
    scratch: &mut Vec<f64>,
) -> bool {
    scratch.clear();
    let shared = model.record_row(y, &[], true, scratch);
    shared.normal_force.is_some_and(|f| f < 0.0)
}

#[cfg(test)]
mod tests;
