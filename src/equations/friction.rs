//! Checks of the paper's equations: see the registry in `super`.

use super::Equation;

/// The checks of this part of the paper.
pub const EQUATIONS: &[Equation] = &[];
