//! The scope record of a disk spun down by ONE dissipation mechanism from its physics
//! ([`physics::model::mechanism`]) instead of eq 75's law: the rolling model (eqs 23-25) with the
//! mechanism's torque, started in steady motion with $b = 0$ at
//! [`START_RATE`](crate::synthetic::mechanisms::START_RATE), integrated until the tilt falls to
//! `alpha_below` or the disk leaves the table ($F_z = 0$), whichever comes first (or
//! [`LONGEST`] passes), and seen through a [`LightModel`] whose scope puts that end at its
//! `end_at`.
//!
//! Such a record has one mechanism by construction, so whatever the experiment's model choice
//! says of it is a statement about the analysis, not about the physics: the calibration of the
//! two-mechanism verdict ([`crate::model_choice`]) is made on these records.

use crate::error::ExperimentError;
use crate::synthetic::light::LightModel;
use crate::synthetic::mechanisms::START_RATE;
use crate::synthetic::scope::Scope;
use crate::synthetic::simulate::trace_of_motion;
use crate::trace::Motion;
use crate::trace::{Trace, Truth};
use physics::disk::Disk;
use physics::model::mechanism::Mechanism;
use physics::model::rolling::Rolling;
use physics::model::steady::{steady_motion, tilt_at_b0};
use physics::model::{Extras, Model, Quantity};
use physics::solve::{solve, Ending, Event, Problem, Settings, Solution, State};

/// The longest spin-down followed (s).
pub const LONGEST: f64 = 60.0;
/// The tilt that ends a spin-down unless the disk leaves the table first (rad), as the
/// built-in `spin-down` scene's `stop.alpha_below`.
pub const ALPHA_BELOW: f64 = 1e-4;

/// The scope record of `disk` spun down by `mech` alone, through `light`; the truth's
/// $\beta$ is the mechanism's small-tilt exponent ([`Mechanism::exponent`]).
pub fn mechanism_trace(
    disk: &Disk,
    mech: &Mechanism,
    light: &LightModel,
    settings: &Settings,
) -> Result<Trace, ExperimentError> {
    light.validate()?;
    let motion = mechanism_motion(disk, mech, &light.scope, settings)?;
    Ok(trace_of_motion(&motion, light, mech.name()))
}

/// The motion of `disk` spun down by `mech` alone, sampled as `scope` records (its end at the
/// scope's `end_at`).
pub fn mechanism_motion(
    disk: &Disk,
    mech: &Mechanism,
    scope: &Scope,
    settings: &Settings,
) -> Result<Motion, ExperimentError> {
    scope.validate()?;
    let fail = |m: String| ExperimentError::Setting(format!("{}: {m}", mech.name()));
    let extras = Extras {
        heading: true,
        path: false,
        face: false,
    };
    let model = Rolling::<5>::new(*disk, extras, None).with_mechanisms(&[*mech]);
    let start = steady_motion(disk, tilt_at_b0(disk, START_RATE), 0.0)
        .map_err(|e| fail(format!("no steady start at {START_RATE} rad/s ({e})")))?;
    let y0 = model.state(&start);
    let stopped = |t0: f64, y: State<5>, t_end: f64, sample: Option<f64>| {
        let mut p = Problem::new(&model, t0, y, t_end)
            .stop_when(Event::new("alpha_below", |y: &State<5>| y[0] - ALPHA_BELOW))
            .stop_when(Event::new("lift-off", |y: &State<5>| {
                let mut f = Vec::with_capacity(1);
                model.record(y, Quantity::NormalForce, &mut f);
                f[0]
            }));
        if let Some(dt) = sample {
            p = p.sampled(dt);
        }
        solve(p, settings).map_err(|e| fail(e.to_string()))
    };
    let end = |s: &Solution<5>| match &s.ending {
        Ending::Event { t, .. } => Ok(*t),
        other => Err(fail(format!(
            "the spin-down did not end within {LONGEST} s ({other})"
        ))),
    };
    let t_stop = end(&stopped(0.0, y0, LONGEST, None)?)?;
    let t_start = t_stop - scope.end_at;
    if t_start <= 0.0 {
        return Err(fail(format!(
            "the spin-down lasts {t_stop:.3} s, less than the record's {} s before its end",
            scope.end_at
        )));
    }
    let to_start =
        solve(Problem::new(&model, 0.0, y0, t_start), settings).map_err(|e| fail(e.to_string()))?;
    let (_, y_start) = to_start.last();
    let run = stopped(t_start, y_start, t_stop + 1.0, Some(scope.dt()))?;
    let t_end = end(&run)?;
    let (_, y_end) = run.last();
    let samples = scope.samples;
    let mut alpha = vec![f64::NAN; samples];
    let mut heading = vec![f64::NAN; samples];
    // The last point of a sampled solution is the event, off the grid: skip it.
    let on_grid = run.t.len().saturating_sub(1);
    for (j, y) in run.y.iter().take(on_grid.min(samples)).enumerate() {
        alpha[j] = y[0];
        heading[j] = y[4];
    }
    Ok(Motion {
        t: scope.times(),
        alpha,
        heading,
        truth: Truth::at_stop(
            mech.exponent(),
            t_end - t_start,
            y_end[0],
            y_end[1],
            format!(
                "rolling model with {} alone ({} = {:e} {})",
                mech.name(),
                mech.key(),
                mech.coefficient(),
                mech.unit()
            ),
        ),
    })
}
