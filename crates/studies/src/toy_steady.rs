//! Eqs 29-30 for the Euler's Disk toy: its steady motions and the condition on $b$, from the
//! closed form of [`physics::model::steady_solid`], each checked on the sliding model's own
//! equations (Newton-Euler with the rolling constraint on the rounded rim), which the closed form
//! does not use.
//!
//! At each tilt of [`TILTS_DEG`]:
//! - **the edge** $b_*$ of the toy beside eq 30's for the thin disk, and which side of it the
//!   toy's steady motions are on;
//! - **existence, both sides of the edge.** At $b_\pm = b_* \pm$ [`OFFSET`]$\,a$ the model is
//!   started rolling at $(\alpha_0, \dot\alpha = 0, \Omega, \omega_1 = \Omega(b - p\sin\alpha_0)/q)$
//!   for 80 values of $\Omega$ from 0.05 to 200 $\sqrt{g/a}$ (log-spaced), and the sign of
//!   $\alpha(\tau) - \alpha_0$ after $\tau$ = 1 ms is read. A steady motion is a sign change;
//!   on the allowed side there must be exactly one, on the other none;
//! - **the steady $\Omega_0$ shot on the model**: the sign change refined by bisection (60
//!   halvings), against the closed form;
//! - **the closed form's start held**: the largest $|\alpha - \alpha_0|$ over [`HOLD`] s from
//!   the closed-form start, against the same with $\Omega$ and $\omega_1$ raised by 0.1 %.
//!
//! The model is integrated in its rolling mode alone (the contact force is whatever rolling
//! needs), so a start near the edge, whose precession is high, is not cut short by a friction
//! coefficient.

use crate::thickness::{Shape, TOY};
use crate::StudyError;
use numerics::oscillation::{bisect, try_bisect};
use physics::dispatch::sliding_model;
use physics::model::sliding::{Flow, Mode, Sliding};
use physics::model::steady_solid::Side;
use physics::model::Motion;
use physics::solve::{solve, Problem, Settings};
use serde::{Deserialize, Serialize};

/// The tilts compared (deg).
pub const TILTS_DEG: [f64; 9] = [10.0, 30.0, 50.0, 70.0, 75.0, 78.0, 80.0, 82.0, 85.0];
/// How far from the edge the two sides are tried, in units of $a$.
pub const OFFSET: f64 = 0.05;
/// How long the closed form's start is followed (s).
pub const HOLD: f64 = 0.1;
/// The time after which the tilt's change is read in the scan (s).
const TAU: f64 = 1e-3;

/// One tilt: the thin disk's eq 30 and 29 beside the toy's, and the model's checks.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
pub struct EdgeRow {
    /// $\alpha_0$ (deg).
    pub alpha0_deg: f64,
    /// Eq 30's edge for the thin disk, $b_*/a$.
    pub thin_edge: f64,
    /// The toy's edge $b_*/a$.
    pub toy_edge: f64,
    /// True when the toy's steady motions have $b > b_*$, false when $b < b_*$.
    pub toy_above: bool,
    /// Eq 29's $\Omega_0$ at $b = 0$ for the thin disk (rad/s).
    pub thin_b0: f64,
    /// The toy's $\Omega_0$ at $b = 0$ (rad/s); `None` where it has no such motion.
    pub toy_b0: Option<f64>,
    /// Sign changes of $\alpha(\tau) - \alpha_0$ over the scan on the allowed side.
    pub roots_allowed: usize,
    /// The same on the other side.
    pub roots_forbidden: usize,
    /// $b/a$ on the allowed side, and the closed form's $\Omega_0$ there (rad/s).
    pub allowed: (f64, f64),
    /// The model's steady $\Omega_0$ there over the closed form's, minus 1.
    pub shot_error: f64,
    /// The largest $|\alpha - \alpha_0|$ over [`HOLD`] s from the closed-form start (rad).
    pub held: f64,
    /// The same with $\Omega$ and $\omega_1$ 0.1 % higher (rad).
    pub missed: f64,
}

/// The rolling model of `shape` and the rolling start of a motion.
fn model_and_start(
    shape: Shape,
    m: Motion,
) -> Result<(Sliding, physics::solve::State<14>), StudyError> {
    let s = crate::thickness::scene(shape, m.alpha, 0.0, m.precession, m.spin, HOLD, HOLD, "")?;
    let model = sliding_model(&s);
    let y0 = model.start_state(&s.start);
    Ok((model, y0))
}

/// $\alpha(t) - \alpha_0$ at each sample of a rolling run of `shape` from `m` (`every` s apart,
/// to `until` s).
fn tilt_changes(shape: Shape, m: Motion, until: f64, every: f64) -> Result<Vec<f64>, StudyError> {
    let (model, y0) = model_and_start(shape, m)?;
    let flow = Flow {
        model: &model,
        mode: Mode::Stick,
    };
    let run = solve(
        Problem::new(&flow, 0.0, y0, until).sampled(every),
        &Settings::dop853(1e-12, 1e-15),
    )?;
    if !run.ending.is_complete() {
        return Err(format!("the rolling run from {m:?} ended early: {:?}", run.ending).into());
    }
    Ok(run
        .y
        .iter()
        .map(|y| model.snapshot(y).motion().alpha - m.alpha)
        .collect())
}

/// $\alpha(\tau) - \alpha_0$ from the start at precession `omega` with the spin of radius `b`.
fn drift(shape: Shape, alpha0: f64, b: f64, omega: f64) -> Result<f64, StudyError> {
    let spin = shape.rolling().spin_ratio(alpha0, b) * omega;
    let m = Motion {
        alpha: alpha0,
        alpha_dot: 0.0,
        precession: omega,
        spin,
    };
    Ok(*tilt_changes(shape, m, TAU, TAU)?
        .last()
        .ok_or("an empty run")?)
}

/// The brackets of $\Omega$ where the drift changes sign over the scan at (`alpha0`, `b`).
fn brackets(shape: Shape, alpha0: f64, b: f64) -> Result<Vec<(f64, f64)>, StudyError> {
    let unit = (physics::disk::toy_disk().g / TOY.0).sqrt();
    let n = 80;
    let grid: Vec<f64> = (0..n)
        .map(|i| unit * 0.05 * (4000f64).powf(i as f64 / (n - 1) as f64))
        .collect();
    let signs: Vec<bool> = grid
        .iter()
        .map(|&w| Ok(drift(shape, alpha0, b, w)? > 0.0))
        .collect::<Result<_, StudyError>>()?;
    Ok((1..n)
        .filter(|&i| signs[i] != signs[i - 1])
        .map(|i| (grid[i - 1], grid[i]))
        .collect())
}

/// The root of the drift in a bracket, by bisection to the last bit.
fn shoot(shape: Shape, alpha0: f64, b: f64, (lo, hi): (f64, f64)) -> Result<f64, StudyError> {
    let low_sign = drift(shape, alpha0, b, lo)? > 0.0;
    let narrow = |_: f64, _: f64| false;
    let changed = |w: f64| {
        drift(shape, alpha0, b, w)
            .ok()
            .map(|d| (d > 0.0) != low_sign)
    };
    let (lo, hi) = try_bisect(lo, hi, narrow, changed)
        .ok_or_else(|| format!("a rolling run at alpha0 = {alpha0} rad failed in the bisection"))?;
    Ok(0.5 * (lo + hi))
}

/// The largest $|\alpha - \alpha_0|$ over [`HOLD`] s from `m`.
fn largest_change(shape: Shape, m: Motion) -> Result<f64, StudyError> {
    Ok(tilt_changes(shape, m, HOLD, 1e-3)?
        .iter()
        .fold(0.0, |x: f64, d| x.max(d.abs())))
}

/// One tilt's row.
pub fn row(alpha0_deg: f64) -> Result<EdgeRow, StudyError> {
    let alpha0 = alpha0_deg.to_radians();
    let (thin, toy) = (Shape::Thin.rolling(), Shape::Toy.rolling());
    let a = TOY.0;
    let edge = toy.edge(alpha0);
    let toy_above = match edge.side {
        Side::Above => true,
        Side::Below => false,
        Side::Balanced => return Err(format!("the toy balances at {alpha0_deg} deg").into()),
    };
    let step = if toy_above { OFFSET * a } else { -OFFSET * a };
    let (inside, outside) = (edge.b + step, edge.b - step);
    let allowed = toy.steady(alpha0, inside).map_err(|e| e.to_string())?;
    let found = brackets(Shape::Toy, alpha0, inside)?;
    let shot = match found.as_slice() {
        [one] => shoot(Shape::Toy, alpha0, inside, *one)?,
        _ => {
            return Err(format!(
                "{alpha0_deg} deg: {} steady precessions on the allowed side",
                found.len()
            )
            .into())
        }
    };
    let faster = Motion {
        precession: 1.001 * allowed.precession,
        spin: 1.001 * allowed.spin,
        ..allowed
    };
    Ok(EdgeRow {
        alpha0_deg,
        thin_edge: thin.edge(alpha0).b / a,
        toy_edge: edge.b / a,
        toy_above,
        thin_b0: thin
            .steady(alpha0, 0.0)
            .map_err(|e| e.to_string())?
            .precession,
        toy_b0: toy.steady(alpha0, 0.0).ok().map(|m| m.precession),
        roots_allowed: found.len(),
        roots_forbidden: brackets(Shape::Toy, alpha0, outside)?.len(),
        allowed: (inside / a, allowed.precession),
        shot_error: shot / allowed.precession.abs() - 1.0,
        held: largest_change(Shape::Toy, allowed)?,
        missed: largest_change(Shape::Toy, faster)?,
    })
}

/// Eq 30 for the toy: the rows, and the tilts between which it cannot spin in place.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
pub struct ToySteady {
    /// One row per tilt of [`TILTS_DEG`].
    pub rows: Vec<EdgeRow>,
    /// The tilts (deg) where the toy's edge crosses $b = 0$ and where its centre comes above
    /// its contact: between them it has no steady motion with its centre at rest.
    pub no_spin_in_place_deg: (f64, f64),
}

/// The tilt in (`lo`, `hi`) deg where `f` changes sign, by bisection.
fn crossing(f: impl Fn(f64) -> f64, (lo, hi): (f64, f64)) -> f64 {
    let low = f(lo) > 0.0;
    let (lo, hi) = bisect(lo, hi, 0.0, |d| (f(d) > 0.0) != low);
    0.5 * (lo + hi)
}

/// The study.
pub fn compute() -> Result<ToySteady, StudyError> {
    use rayon::prelude::*;
    let toy = Shape::Toy.rolling();
    let rows = TILTS_DEG
        .par_iter()
        .map(|&d| row(d))
        .collect::<Result<Vec<_>, _>>()?;
    let edge_at_zero = crossing(|d| toy.edge(d.to_radians()).b, (45.0, 89.0));
    let balance = crossing(
        |d| {
            let x = toy.edge(d.to_radians());
            if x.side == Side::Above {
                1.0
            } else {
                -1.0
            }
        },
        (45.0, 89.9),
    );
    Ok(ToySteady {
        rows,
        no_spin_in_place_deg: (edge_at_zero, balance),
    })
}
