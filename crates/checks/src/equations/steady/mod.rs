//! Steady motion, sections 4-5 of the paper (eqs 27-40).
//!
//! The references here never use the paper's steady-motion formulas (nor `model::steady`, which
//! implements eqs 28-30 and is therefore a claim): a steady motion is found by solving the
//! model's equation of motion (eq 24, `model::rolling::rates`) for $\ddot\alpha = 0$ with
//! Newton's method (exact derivatives by dual numbers), at a tilt $\alpha_0$ and a ratio
//! $\rho = \omega_{10}/\Omega_0$; the radius $b$ of the centre of mass's circle and the radius
//! $r$ of the contact point's circle are then MEASURED on an integration of the rolling model
//! that carries the heading and the centre of mass in the plane (the circle's centre is the mean
//! of the path sampled evenly over one precession period).
//!
//! Section 5's vector relations (eqs 33-37) are checked against the independent lab-frame
//! Newton-Euler model (`model::lab_frame`): the $b = 0$ steady state found as above is started in
//! the lab model, integrated over one precession period (its steadiness measured there), and
//! $\mathbf L$, $d\mathbf L/dt$, the contact torque, $\boldsymbol\omega$, the precession and
//! relative-spin rates are all computed or measured in the lab.
//!
//! The steady motions themselves come from `steady_reference.rs`, shared with `slippage.rs` and
//! `oscillation.rs`.

use super::{
    add_threshold, printed_relations, printed_threshold, solve_printed, solve_printed_with, Bench,
    Equation,
};
use crate::finding::{Finding, Method, Tolerance, Worst};
use nalgebra::Vector3;
use paper::Bindings;
use physics::disk::Disk;
use physics::model::lab_frame::{Contact, LabFrame, Snapshot};
use physics::model::rolling::{contact_force, rates, Rolling};
use physics::model::{Extras, Model, Motion};
use physics::solve::{solve, Problem, State};
use std::f64::consts::PI;

mod circles;
mod lab;
#[cfg(test)]
mod tests;

use circles::{eq27, eq28, eq29, eq30, eq31, eq32, eq38, eq39, eq40};
use lab::{eq33, eq34, eq35, eq36, eq37};

/// The checks of this part of the paper.
pub const EQUATIONS: &[Equation] = &[
    Equation {
        number: 27,
        label: "e21",
        check: eq27,
    },
    Equation {
        number: 28,
        label: "e22",
        check: eq28,
    },
    Equation {
        number: 29,
        label: "e23",
        check: eq29,
    },
    Equation {
        number: 30,
        label: "e23a",
        check: eq30,
    },
    Equation {
        number: 31,
        label: "e24",
        check: eq31,
    },
    Equation {
        number: 32,
        label: "e25",
        check: eq32,
    },
    Equation {
        number: 33,
        label: "e26",
        check: eq33,
    },
    Equation {
        number: 34,
        label: "e27",
        check: eq34,
    },
    Equation {
        number: 35,
        label: "e28",
        check: eq35,
    },
    Equation {
        number: 36,
        label: "e29",
        check: eq36,
    },
    Equation {
        number: 37,
        label: "e30",
        check: eq37,
    },
    Equation {
        number: 38,
        label: "e31",
        check: eq38,
    },
    Equation {
        number: 39,
        label: "e32",
        check: eq39,
    },
    Equation {
        number: 40,
        label: "e33",
        check: eq40,
    },
];

fn at(k: f64, alpha0: f64, rho: f64) -> String {
    format!("k = {k}, alpha0 = {alpha0}, b/a = {rho:.4}")
}

// ------------------------------------------------------------------------------------------
// Section 4
// ------------------------------------------------------------------------------------------
