//! Checks of eqs 72-85: dissipation at very small tilt (section 11 of the paper).
//!
//! References: the exact energy of the rolling disk (eq 26's content, differentiated exactly by
//! dual numbers), the full rolling model dissipating by the power law of eq 75 (a torque
//! anti-parallel to the angular velocity, `model::dissipation`), the one-state law of eq 76
//! integrated numerically (for its exact consequences 77-79 and 84), and derivatives of eq 79 by
//! dual numbers (80, 81, 85).
//!
//! Findings against the paper (numbers in each check's doc):
//! - eq 72 drops the rotational kinetic energy $\frac12 k m a^2\dot\alpha^2$;
//! - eq 73's last form, $\frac52 m a g\dot\alpha$, contradicts its own premise $F_z \approx 0$;
//! - eq 76's factor 2/5 should be 2/3 (adiabatic energy balance), so the $C$ of eq 79 is 5/3
//!   times too large for the dissipative disk.

use super::spin_down_reference::{
    descent, energy, law_bindings, slope, steady_precession, time_remaining_on_model, PrintedLaw,
    BETAS, SMALL_ALPHAS,
};
use crate::equations::{row, Row};
use crate::finding::{Finding, Headline, Method, Tolerance, Worst};
use crate::harness::{last_side, printed_relations, solve_printed, Bench};
use num_dual::{Dual2_64, Dual64, DualNum};
use numerics::oscillation::bisect;
use paper::Bindings;
use physics::model::dissipation::PowerLaw;
use physics::model::rolling::Rolling;
use physics::model::steady::steady_motion;
use physics::model::{Extras, Model, Motion};
use physics::solve::{solve, Dynamics, Problem, State};

/// The checks of this part of the paper.
pub const EQUATIONS: &[Row] = &[
    row(72, eq72),
    row(73, eq73),
    row(74, eq74),
    row(75, eq75),
    row(76, eq76),
    row(77, eq77),
    row(78, eq78),
    row(79, eq79),
    row(80, eq80),
    row(81, eq81),
    row(84, eq84),
    row(85, eq85),
];

mod data;
mod energy;
mod lift_off;
mod power;
#[cfg(test)]
mod tests;

pub use data::*;
pub use energy::*;
pub use lift_off::*;
pub use power::*;
