//! Checks of the numeric and qualitative claims in the paper's prose (`paper/claims.yaml`).
//!
//! Every check computes the claimed quantity independently (closed forms derived here, roots by
//! bisection, exact Jacobians of the rolling model, integrations) and compares it with the number
//! the paper prints, read through [`Bench::claim`].
//!
//! **Loosely stated numbers** ("about 60 degrees", "roughly pi/3", "of order", "a few
//! degrees", "at most about 0.01 s") are judged by the `rule` their entry in claims.yaml states,
//! which the report shows beside the claim ([`stated`]): to the printed digits (the computed
//! value rounded to the digits the paper printed must equal the printed number), within a
//! relative distance, within a factor, under a bound with a slack, or inside a range. The printed
//! number and its reading are read from the YAML, so an author or a referee who reads "about"
//! differently edits one line and re-runs. The mutation test moves a printed number by 1e-3,
//! or, for a loose reading that holds, beyond the reading (twice the distance, the factor
//! squared, a bound ten times tighter): the check must then fail.
//!
//! Qualitative claims (true/false) get a numeric witness: a boundary, a limit, an exponent, or
//! the paper's own arithmetic that the statement rests on.
//!
//! Claims of `paper/claims.yaml` marked 'not checkable' (observations whose data are not in the
//! paper) are NOT registered here; neither are `nutation-disappears-below-0p1` (the equations
//! give no threshold at 0.1 rad) and `contact-speed-exceeds-sound` (no number; its content is
//! `finite-time-singularity`).
//!
//! "About" and "roughly" on a number the paper did not compute (an observation, an estimate, a
//! tilt read off a figure) have one reading: within 5 % (relative), of the number or of a
//! range's nearer end. A number the paper computed (sqrt(3/5) as 0.77, the sec. 11 numbers
//! from its fitted C) is read to the digits it printed.

use crate::equations::Claim;
use crate::finding::{Finding, Headline, Method, Tolerance, Worst};
use crate::harness::Bench;
use nalgebra::SMatrix;
use num_dual::{second_derivative, Dual64, DualNum};
use numerics::fit::log_log_slope;
use numerics::linearize::eigenvalues;
use numerics::minimize::golden_min;
use numerics::oscillation::bisect;
use physics::disk::Disk;
use physics::model::adiabatic::Adiabatic;
use physics::model::dissipation::PowerLaw;
use physics::model::frictionless::{self as fl, Frictionless};
use physics::model::lab_frame::{Contact, LabFrame};
use physics::model::rolling::{self, Rates, Rolling};
use physics::model::steady::{b_bound, steady_motion, vertical_spin};
use physics::model::{Extras, Model, Motion, Quantity};
use physics::solve::{solve, Dynamics, Event, Problem, State};
use std::f64::consts::{FRAC_PI_2, FRAC_PI_3, PI};

mod catalogued;
mod fall;
mod frictionless;
mod integrals;
mod judge;
mod leaves_table;
mod motion;
mod oscillation;
mod rising;
mod spin_down;
#[cfg(test)]
mod tests;

pub use catalogued::catalogued;
use frictionless::{
    angular_momentum_near_vertical, frictionless_constants, frictionless_threshold_uniform,
    limits_eq55_eq71, rolling_threshold_uniform, thresholds_ratio,
};
use integrals::rolling_extra_integrals;
pub use judge::with_printed_headline;
use leaves_table::disk_leaves_table;
use motion::{
    center_of_motion_constant, face_figure_rate_vanishes, k_rim_disk, k_uniform_disk,
    negative_b_friction_angle, no_steady_motion_beyond_vertical, slip_when_b_large,
};
use oscillation::{
    b_of_order_a_alpha, bracket_negative_angle, coincidence_eq58, negative_b_always_stable,
    positive_b_unstable_large_tilt, ratio_hoop_one, ratio_uniform_disk_077,
    rattling_needs_more_friction, summary_nutation_10_15_deg,
};
use rising::rising_needs_slip;
use spin_down::{
    air_viscosity, contact_loss_omega, contact_loss_time, drag_exponent_linear_force,
    drag_exponent_moffatt, drag_exponent_quadratic_air, eq73_second_approximation_sign,
    finite_time_singularity, larger_t0_lowers_beta, omega_units_hz_vs_rad_per_s,
    one_period_remaining_omega, one_period_remaining_time, summary_contact_lost_few_degrees,
    t0_after_last_peak,
};

/// How far the mutation test moves the printed number of a claim read by `rule` (relative, two
/// moves) to see its check fail: 1e-3 either way; but a loose reading that `holds` is moved
/// beyond itself (twice its distance, its factor squared, a bound ten times tighter), since a
/// 1e-3 move inside "within 5 %" rightly changes nothing. A failing claim is moved by 1e-3 only:
/// a large move could carry a wrong number into the reading by chance.
pub fn mutation_moves(rule: Option<&paper::Rule>, holds: bool) -> [f64; 2] {
    match rule.filter(|_| holds) {
        // A range that holds is moved past itself and its band: up until its low end is beyond
        // the high end's band, down until its high end is below the low end's.
        Some(r) if r.range.is_some() => {
            let [lo, hi] = r.range.unwrap_or([1.0, 1.0]);
            let w = r.within.unwrap_or_default();
            [
                hi / lo * (1.0 + 2.0 * w) - 1.0,
                lo / hi * (1.0 - 2.0 * w) - 1.0,
            ]
        }
        Some(r) if r.within.is_some() => {
            let w = r.within.unwrap_or_default();
            [2.0 * w, -2.0 * w]
        }
        Some(r) if r.at_most.is_some() => [-0.9, -0.95],
        Some(r) if r.factor.is_some() => {
            let f = r.factor.unwrap_or_default();
            [f * f - 1.0, 1.0 / (f * f) - 1.0]
        }
        _ => [1e-3, -1e-3],
    }
}

/// The claim checks.
pub const CLAIMS: &[Claim] = &[
    Claim {
        id: "k-rim-disk",
        check: k_rim_disk,
    },
    Claim {
        id: "k-uniform-disk",
        check: k_uniform_disk,
    },
    Claim {
        id: "center-of-motion-constant",
        check: center_of_motion_constant,
    },
    Claim {
        id: "no-steady-motion-beyond-vertical",
        check: no_steady_motion_beyond_vertical,
    },
    Claim {
        id: "face-figure-rate-vanishes",
        check: face_figure_rate_vanishes,
    },
    Claim {
        id: "slip-when-b-large",
        check: slip_when_b_large,
    },
    Claim {
        id: "negative-b-friction-angle",
        check: negative_b_friction_angle,
    },
    Claim {
        id: "bracket-negative-angle",
        check: bracket_negative_angle,
    },
    Claim {
        id: "positive-b-unstable-large-tilt",
        check: positive_b_unstable_large_tilt,
    },
    Claim {
        id: "negative-b-always-stable",
        check: negative_b_always_stable,
    },
    Claim {
        id: "ratio-uniform-disk-077",
        check: ratio_uniform_disk_077,
    },
    Claim {
        id: "ratio-hoop-one",
        check: ratio_hoop_one,
    },
    Claim {
        id: "b-of-order-a-alpha",
        check: b_of_order_a_alpha,
    },
    Claim {
        id: "coincidence-eq58",
        check: coincidence_eq58,
    },
    Claim {
        id: "summary-nutation-10-15-deg",
        check: summary_nutation_10_15_deg,
    },
    Claim {
        id: "frictionless-threshold-uniform",
        check: frictionless_threshold_uniform,
    },
    Claim {
        id: "rolling-threshold-uniform",
        check: rolling_threshold_uniform,
    },
    Claim {
        id: "thresholds-ratio",
        check: thresholds_ratio,
    },
    Claim {
        id: "frictionless-constants",
        check: frictionless_constants,
    },
    Claim {
        id: "eq73-second-approximation-sign",
        check: eq73_second_approximation_sign,
    },
    Claim {
        id: "drag-exponent-linear-force",
        check: drag_exponent_linear_force,
    },
    Claim {
        id: "drag-exponent-quadratic-air",
        check: drag_exponent_quadratic_air,
    },
    Claim {
        id: "drag-exponent-moffatt",
        check: drag_exponent_moffatt,
    },
    Claim {
        id: "finite-time-singularity",
        check: finite_time_singularity,
    },
    Claim {
        id: "air-viscosity",
        check: air_viscosity,
    },
    Claim {
        id: "omega-units-hz-vs-rad-per-s",
        check: omega_units_hz_vs_rad_per_s,
    },
    Claim {
        id: "one-period-remaining-omega",
        check: one_period_remaining_omega,
    },
    Claim {
        id: "one-period-remaining-time",
        check: one_period_remaining_time,
    },
    Claim {
        id: "t0-after-last-peak",
        check: t0_after_last_peak,
    },
    Claim {
        id: "disk-leaves-table",
        check: disk_leaves_table,
    },
    Claim {
        id: "contact-loss-time",
        check: contact_loss_time,
    },
    Claim {
        id: "contact-loss-omega",
        check: contact_loss_omega,
    },
    Claim {
        id: "larger-t0-lowers-beta",
        check: larger_t0_lowers_beta,
    },
    Claim {
        id: "rolling-extra-integrals",
        check: rolling_extra_integrals,
    },
    Claim {
        id: "rattling-needs-more-friction",
        check: rattling_needs_more_friction,
    },
    Claim {
        id: "angular-momentum-near-vertical",
        check: angular_momentum_near_vertical,
    },
    Claim {
        id: "limits-eq55-eq71",
        check: limits_eq55_eq71,
    },
    Claim {
        id: "rising-needs-slip",
        check: rising_needs_slip,
    },
    Claim {
        id: "summary-contact-lost-few-degrees",
        check: summary_contact_lost_few_degrees,
    },
];

// ------------------------------------------------------------------------------ helpers

/// Bisections here narrow their bracket to this relative width.
const WIDTH: f64 = 1e-12;

/// A dimensionless disk: $a = g = m = 1$, so rates are in units of $\sqrt{g/a}$.
fn unit_disk(k: f64) -> Disk {
    Disk::new(1.0, k, 1.0, 1.0).expect("a valid disk")
}

/// The exact Jacobian of eqs 23-25 at a state.
fn rolling_jacobian(disk: &Disk, m: &Motion) -> SMatrix<f64, 4, 4> {
    rolling::jacobian(disk, &[m.alpha, m.alpha_dot, m.precession, m.spin])
}

/// The squared small-oscillation frequency at an equilibrium whose Jacobian has one pair of
/// non-zero eigenvalues $\pm i\varpi$ (the others zero): $\varpi^2 = -\mathrm{tr}(J^2)/2$.
fn varpi2<const N: usize>(j: &SMatrix<f64, N, N>) -> f64 {
    -(j * j).trace() / 2.0
}

/// $(k+1)\varpi^2/\Omega_0^2$ from the linearized eqs 23-25 at the steady motion $(\alpha_0, b = \beta a)$:
/// the quantity the right side of eq 54 claims, measured independently of it; NaN where there is
/// no such steady motion (a $b/a$ that is not a number, drawn from a printed form that cannot be
/// evaluated).
fn q_linearized(k: f64, alpha0: f64, beta: f64) -> f64 {
    let disk = unit_disk(k);
    let Ok(m) = steady_motion(&disk, alpha0, beta) else {
        return f64::NAN;
    };
    let j = rolling_jacobian(&disk, &m);
    (k + 1.0) * varpi2(&j) / (m.precession * m.precession)
}

/// The right side of eq 54 (the paper's claim) at $b = \beta a$, evaluated from the paper's
/// LaTeX ([`paper::Paper::right_side`]); NaN if it cannot be evaluated.
fn q_eq54(b: &Bench, k: f64, alpha0: f64, beta: f64) -> f64 {
    let bind = paper::Bindings::new()
        .scalar("k", k)
        .scalar("alpha_0", alpha0)
        .scalar("a", 1.0)
        .scalar("b", beta);
    b.paper.right_side(54, &bind).unwrap_or(f64::NAN)
}

/// The largest real part of the eigenvalues of eqs 23-25 linearized at a steady motion; NaN
/// where there is no such steady motion.
fn max_growth(k: f64, alpha0: f64, beta: f64) -> f64 {
    let disk = unit_disk(k);
    let Ok(m) = steady_motion(&disk, alpha0, beta) else {
        return f64::NAN;
    };
    eigenvalues(&rolling_jacobian(&disk, &m))
        .iter()
        .map(|z| z.re)
        .fold(f64::NEG_INFINITY, f64::max)
}

/// The required friction coefficient $|F_{horizontal}|/F_z$ of a steady motion, from the exact
/// contact force of eq 20 (the model's [`rolling::contact_force`]); NaN where there is no such
/// steady motion.
fn mu_required(k: f64, alpha0: f64, beta: f64) -> f64 {
    let disk = unit_disk(k);
    let Ok(m) = steady_motion(&disk, alpha0, beta) else {
        return f64::NAN;
    };
    let r = rolling::rates(&disk, &m, [0.0; 3]);
    let [fz, fr, f2] = rolling::contact_force(&disk, &m, &r);
    fr.hypot(f2) / fz
}

/// The stability threshold of a disk spinning about a vertical diameter, in $\sqrt{g/a}$, from
/// the linearized eqs 23-25 (rolling) at $\alpha = \pi/2$, $\omega_1 = 0$.
fn rolling_vertical_threshold(k: f64) -> (f64, f64) {
    let disk = unit_disk(k);
    let stable = |om: f64| varpi2(&rolling_jacobian(&disk, &vertical_spin(om))) > 0.0;
    bisect(0.1, 10.0, WIDTH, stable)
}

/// The same threshold without friction, from the linearized eqs 61-62 ($\omega_1 = 0$).
fn frictionless_vertical_threshold(k: f64) -> (f64, f64) {
    let disk = unit_disk(k);
    let stable = |om: f64| {
        let j = fl::spinless_jacobian(&disk, &[FRAC_PI_2, 0.0, om]);
        varpi2(&j) > 0.0
    };
    bisect(0.1, 10.0, WIDTH, stable)
}

fn mid((lo, hi): (f64, f64)) -> f64 {
    0.5 * (lo + hi)
}

/// $C$ of the experimental fit (s^-3), from paper/claims.yaml ([`paper::Fit`]).
fn c_fit(b: &Bench) -> f64 {
    b.paper.fit.c()
}

/// The precession rate at which one period remains, $t_0 - t = 2\pi/\Omega$ on eq 79 with
/// $\beta = 2$ ($t_0 - t = C/\Omega^4$), by bisection.
fn one_period_omega(b: &Bench) -> f64 {
    let (c, n) = (c_fit(b), b.paper.fit.beta + 2.0);
    mid(bisect(10.0, 1e4, WIDTH, |om| {
        c / om.powf(n) < 2.0 * PI / om
    }))
}

/// Remaining time $t_0 - t$ at which $d^2(1/\Omega^2)/dt^2 = -k$ on eq 79 ($\beta = 2$, $k = 1/4$),
/// i.e. the vertical contact force vanishes (sec. 11's premise), by bisection with exact second
/// derivatives.
fn contact_loss_remaining(b: &Bench) -> f64 {
    let fit = b.paper.fit;
    let (c, k, beta) = (fit.c(), 0.25, fit.beta);
    let inv_omega2 = |tau: f64| {
        let (_, _, d2) = second_derivative(
            |t: num_dual::Dual2_64| (t * (1.0 / c)).powf(2.0 / (beta + 2.0)),
            tau,
        );
        d2
    };
    mid(bisect(1e-7, 1.0, WIDTH, |tau| inv_omega2(tau) > -k))
}
