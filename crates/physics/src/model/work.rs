//! The rolling model with the work of its dissipation integrated beside it.

use crate::model::rolling::Rolling;
use crate::solve::{Dynamics, State};

/// The rolling model with the work its eq 75 dissipation does, $W = \int P\,dt$ with
/// $P = -\epsilon m a g|\Omega|^\beta$, carried as a fifth state (J): along a run,
/// $E(t) - E(0) = W(t)$ is the energy balance. Without dissipation $W$ stays zero.
#[derive(Debug, Clone)]
pub struct WithWork {
    /// The rolling model, with its dissipation.
    pub model: Rolling<4>,
}

impl Dynamics<5> for WithWork {
    fn rhs(&self, y: &State<5>, dy: &mut State<5>) {
        let core = State::<4>::new(y[0], y[1], y[2], y[3]);
        let mut d = State::<4>::zeros();
        self.model.rhs(&core, &mut d);
        dy.fixed_rows_mut::<4>(0).copy_from(&d);
        dy[4] = self
            .model
            .dissipation
            .map_or(0.0, |law| law.power(&self.model.disk, y[2]));
    }
}
