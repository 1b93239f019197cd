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

use crate::equations::{row, Row};
use crate::finding::{Finding, Method, Tolerance, Worst};
use crate::harness::{
    add_threshold, printed_relations, printed_threshold, solve_printed, solve_printed_with, Bench,
};
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
pub const EQUATIONS: &[Row] = &[
    row(27, eq27),
    row(28, eq28),
    row(29, eq29),
    row(30, eq30),
    row(31, eq31),
    row(32, eq32),
    row(33, eq33),
    row(34, eq34),
    row(35, eq35),
    row(36, eq36),
    row(37, eq37),
    row(38, eq38),
    row(39, eq39),
    row(40, eq40),
];

fn at(k: f64, alpha0: f64, rho: f64) -> String {
    format!("$k = {k}$, $\\alpha_0 = {alpha0}$, $b/a = {rho:.4}$")
}

// ------------------------------------------------------------------------------------------
// Section 4
// ------------------------------------------------------------------------------------------
