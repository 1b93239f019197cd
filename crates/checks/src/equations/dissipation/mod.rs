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
use super::{last_side, printed_relations, solve_printed, Bench, Equation};
use crate::finding::{Finding, Headline, Method, Tolerance, Worst};
use num_dual::{Dual2_64, Dual64, DualNum};
use numerics::oscillation::bisect;
use paper::Bindings;
use physics::model::dissipation::PowerLaw;
use physics::model::rolling::Rolling;
use physics::model::steady::steady_motion;
use physics::model::{Extras, Model, Motion};
use physics::solve::{solve, Dynamics, Problem, State};

/// The checks of this part of the paper.
pub const EQUATIONS: &[Equation] = &[
    Equation {
        number: 72,
        label: "e101",
        check: eq72,
    },
    Equation {
        number: 73,
        label: "e102",
        check: eq73,
    },
    Equation {
        number: 74,
        label: "e103",
        check: eq74,
    },
    Equation {
        number: 75,
        label: "e103a",
        check: eq75,
    },
    Equation {
        number: 76,
        label: "e104",
        check: eq76,
    },
    Equation {
        number: 77,
        label: "e105",
        check: eq77,
    },
    Equation {
        number: 78,
        label: "e106",
        check: eq78,
    },
    Equation {
        number: 79,
        label: "e107",
        check: eq79,
    },
    Equation {
        number: 80,
        label: "e108",
        check: eq80,
    },
    Equation {
        number: 81,
        label: "e109",
        check: eq81,
    },
    Equation {
        number: 84,
        label: "e120",
        check: eq84,
    },
    Equation {
        number: 85,
        label: "e121",
        check: eq85,
    },
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
