//! The least contact force over a run: the rolling model with eq 75's drag, started from steady
//! rolling, integrated until the tilt falls to a floor, and the smallest upward contact force
//! $F_z/mg = 1 + (a/g)(\ddot\alpha\cos\alpha - \dot\alpha^2\sin\alpha)$ along it (eq 20's exact
//! contact force). The claim `disk-leaves-table` runs the same function on the toy disk.

use super::{Computed, Kind, Parameter, Quantity, Value, Values, ALPHA0, B_OVER_A, K};
use crate::finding::{Method, Tolerance};
use crate::harness::Bench;
use numerics::minimize::golden_min;
use physics::disk::Disk;
use physics::model::dissipation::{Placement, PowerLaw};
use physics::model::rolling::{self, Rolling};
use physics::model::steady::steady_motion;
use physics::model::{Extras, Model};
use physics::solve::{solve, Event, Problem, Settings, State};

/// The placements of eq 75's torque, as a claim names them.
const PLACEMENTS: &[(&str, Placement)] = &[
    ("against-omega", Placement::AgainstOmega),
    ("contact-diameter", Placement::ContactDiameter),
    ("across-path", Placement::AcrossPath),
];

/// `least-contact-force`.
pub(super) const LEAST_CONTACT_FORCE: Quantity = Quantity {
    name: "least-contact-force",
    means: "the smallest upward contact force F_z / m g along a spin-down in the rolling model \
            with eq 75's drag, from steady rolling at tilt alpha_0 and radius b until the tilt \
            falls below alpha_end (or the time t_end passes); 0 or less means the disk leaves \
            the table",
    unit: "m g",
    method: Method::Integration,
    tolerance: solver,
    how: "integration of the rolling model's eqs 23-25 with eq 75's drag torque (DOP853 at the \
          check's rtol); F_z from the exact contact force (eq 20's premises) at every solver \
          step, the least refined by golden-section search between the steps on either side of \
          it; never eq 79's or eq 80's closed form",
    parameters: &[
        K,
        ALPHA0,
        B_OVER_A,
        Parameter {
            name: "epsilon",
            means: "eq 75's drag constant epsilon, in sqrt(a/g)^(beta-1) (the toy disk's 1.2e-6 \
                    s at beta = 2 is 1.94e-5)",
            kind: Kind::Number {
                unit: "sqrt(a/g)^(beta-1)",
                above: 0.0,
                below: 1.0,
                whole: false,
            },
            default: None,
        },
        Parameter {
            name: "beta",
            means: "eq 75's exponent beta: the power lost is epsilon m a g |Omega|^beta",
            kind: Kind::Number {
                unit: "1",
                above: 0.0,
                below: 10.0,
                whole: false,
            },
            default: Some(Value::Number(2.0)),
        },
        Parameter {
            name: "placement",
            means: "the axis of eq 75's torque, which the paper leaves open: against the angular \
                    velocity, about the contact diameter 3-hat, or about the horizontal axis \
                    across the path",
            kind: Kind::Choice(&["against-omega", "contact-diameter", "across-path"]),
            default: Some(Value::Word("against-omega")),
        },
        Parameter {
            name: "alpha_end",
            means: "the tilt at which the run ends",
            kind: Kind::Number {
                unit: "rad",
                above: 0.0,
                below: std::f64::consts::FRAC_PI_2,
                whole: false,
            },
            default: Some(Value::Number(1e-4)),
        },
        Parameter {
            name: "t_end",
            means: "the longest run, in sqrt(a/g)",
            kind: Kind::Number {
                unit: "sqrt(a/g)",
                above: 0.0,
                below: 1e7,
                whole: false,
            },
            default: Some(Value::Number(1e4)),
        },
    ],
    compute: least,
};

/// The least contact force of one run, and where it was met.
#[derive(Debug, Clone, Copy)]
pub struct LeastContact {
    /// $F_z/mg$ at its least.
    pub fz: f64,
    /// The time of the least, in the disk's time unit.
    pub t: f64,
    /// The tilt there, rad.
    pub alpha: f64,
    /// The tilt where the run ended, rad.
    pub alpha_end: f64,
    /// The time where the run ended.
    pub t_end: f64,
}

/// A spin-down of `disk` in the rolling model with `law`'s drag along `placement`, from the
/// steady motion at tilt `alpha0` and radius `b` (in units of $a$) until the tilt falls below
/// `floor` or `t_end` passes: the least $F_z/mg$ over the solver's steps, refined by
/// golden-section search between the steps on either side of it (each point of the search an
/// integration from the step before, with the same settings). An error says why where the run
/// could not be made.
#[allow(clippy::too_many_arguments)]
pub fn least_contact_force(
    disk: &Disk,
    law: PowerLaw,
    placement: Placement,
    alpha0: f64,
    b: f64,
    floor: f64,
    t_end: f64,
    settings: &Settings,
) -> Result<LeastContact, String> {
    let model = Rolling::<4>::new(*disk, Extras::default(), Some(law)).with_placement(placement);
    let start = steady_motion(disk, alpha0, b * disk.a).map_err(|e| {
        format!("no steady rolling motion at $\\alpha_0 = {alpha0}$ rad, $b/a = {b}$: {e}")
    })?;
    let stop = Event::new(
        format!("the tilt falls below {floor:e} rad"),
        move |y: &State<4>| y[0] - floor,
    );
    let sol = solve(
        Problem::new(&model, 0.0, model.state(&start), t_end).stop_when(stop),
        settings,
    )
    .map_err(|e| format!("the run failed: {e}"))?;
    let fz = |y: &State<4>| {
        rolling::contact_force(disk, &model.motion(y), &model.rates(y))[0] / (disk.m * disk.g)
    };
    let i = (0..sol.y.len())
        .min_by(|&i, &j| fz(&sol.y[i]).total_cmp(&fz(&sol.y[j])))
        .ok_or("the run recorded no step")?;
    let (lo, hi) = (i.saturating_sub(1), (i + 1).min(sol.y.len() - 1));
    let at = |t: f64| -> Option<State<4>> {
        if t <= sol.t[lo] {
            return Some(sol.y[lo]);
        }
        let p = Problem::new(&model, sol.t[lo], sol.y[lo], t);
        solve(p, settings).ok().and_then(|s| s.y.last().copied())
    };
    let (t, least) = golden_min(sol.t[lo], sol.t[hi], 1e-13, |t| {
        at(t).map_or(f64::INFINITY, |y| fz(&y))
    });
    // The search is kept only where it improves on the steps themselves.
    let (t, least, alpha) = match at(t) {
        Some(y) if least < fz(&sol.y[i]) => (t, least, y[0]),
        _ => (sol.t[i], fz(&sol.y[i]), sol.y[i][0]),
    };
    Ok(LeastContact {
        fz: least,
        t,
        alpha,
        alpha_end: sol.y.last().map_or(f64::NAN, |y| y[0]),
        t_end: sol.t.last().copied().unwrap_or(f64::NAN),
    })
}

/// [`LEAST_CONTACT_FORCE`] for the disk $a = g = m = 1$.
fn least(v: &Values, b: &Bench) -> Computed {
    let (k, alpha0, b_over_a) = (v.number("k"), v.number("alpha0"), v.number("b_over_a"));
    let law = PowerLaw {
        epsilon: v.number("epsilon"),
        beta: v.number("beta"),
    };
    let placement = PLACEMENTS
        .iter()
        .find(|(w, _)| *w == v.word("placement"))
        .map_or(Placement::AgainstOmega, |(_, p)| *p);
    let Ok(disk) = Disk::new(1.0, k, 1.0, 1.0) else {
        return super::threshold::not_located(format!("no disk with $k = {k}$"));
    };
    let (floor, t_end) = (v.number("alpha_end"), v.number("t_end"));
    match least_contact_force(
        &disk,
        law,
        placement,
        alpha0,
        b_over_a,
        floor,
        t_end,
        &b.settings(),
    ) {
        Ok(r) => Computed::value(
            r.fz,
            format!(
                "{}: smallest $F_z = {:.9} m g$ at $t = {:.6} \\sqrt{{a/g}}$, $\\alpha = {:.3e}$ rad (the run \
                 ends at $\\alpha = {:.1e}$ rad, $t = {:.3} \\sqrt{{a/g}}$)",
                v.describe(),
                r.fz,
                r.t,
                r.alpha,
                r.alpha_end,
                r.t_end
            ),
        ),
        Err(why) => super::threshold::not_located(why),
    }
}

/// The tolerance of an integration at the check's rtol.
fn solver(b: &Bench) -> Tolerance {
    Tolerance::solver(b.rtol)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// F_z/mg is dimensionless: the toy disk (a = 37.5 mm, g = 9.81) with epsilon = 1.2e-6 s
    /// and the disk a = g = 1 with epsilon in units of sqrt(a/g) give the same least force.
    #[test]
    fn the_least_force_does_not_depend_on_the_units() {
        let settings = Bench::default().settings();
        let toy = Disk {
            a: 0.0375,
            k: 0.25,
            m: 0.4,
            g: 9.81,
        };
        let unit = Disk::new(1.0, 0.25, 1.0, 1.0).expect("a disk");
        let time = (toy.a / toy.g).sqrt();
        let law = |eps: f64| PowerLaw {
            epsilon: eps,
            beta: 2.0,
        };
        let a = least_contact_force(
            &toy,
            law(1.2e-6),
            Placement::AgainstOmega,
            0.15,
            0.0,
            1e-4,
            120.0,
            &settings,
        )
        .expect("runs");
        let u = least_contact_force(
            &unit,
            law(1.2e-6 / time),
            Placement::AgainstOmega,
            0.15,
            0.0,
            1e-4,
            120.0 / time,
            &settings,
        )
        .expect("runs");
        assert!((a.fz - u.fz).abs() < 1e-6, "{} {}", a.fz, u.fz);
        assert!(
            (a.t / time - u.t).abs() < 1e-6 * u.t,
            "{} {}",
            a.t / time,
            u.t
        );
        assert!(a.fz > 0.5 && a.fz < 1.0, "{}", a.fz);
    }
}
