//! The one door to the integrators.
//!
//! Every integration in the crate goes through [`solve`]. It offers classical fixed-step RK4,
//! Dormand-Prince 5(4) and 8(5,3), their tolerances, stop events located in time, sampling at
//! fixed intervals, and the solver's statistics. One [`Settings`] value says all of it and is
//! serializable, so a report can print what a run actually used.
//!
//! - By default all three go through `ode_solvers` 0.6.2 ([`upstream`]): measured side by side
//!   (`cargo bench --bench benches -- solver_steps`) it takes the same steps as Hairer's DOP853
//!   and spends 80 ns per evaluation against 87-144 ns for the crate's own.
//! - The crate's own DOP853 ([`dop853`], driven by [`driver`]: Hairer's error control and
//!   controller with its order-7 dense output, events located on it at 3 evaluations) is
//!   reachable through [`solve_with`] and [`Engine::Own`], and integrates every sampled or
//!   projected DOP853 problem: its dense output makes a sample a polynomial evaluation. It is
//!   not the default for the other problems: it moves the last digits of several findings
//!   (round-off of a different summation order) and those have not been reviewed.
//!
//! Every system here is autonomous ([`Dynamics`] has no time argument: `ode_solvers`' DOP853
//! tableau has $c_{12} = c_{13} = 0$ where Hairer's has 1); a problem that depends on time
//! carries it as a state ([`WithTime`] does that for you).

pub mod arenstorf;
mod batch;
mod dense;
#[cfg(test)]
mod dense_error;
mod dop853;
mod driver;
mod grid;
mod outcome;
mod projection;
mod settings;
mod tableau;
mod upstream;

pub use batch::{Batch, BatchSink, BATCH, LANES};
pub use outcome::{Ending, Solution, Stats};
pub use projection::{onto_level, Projection};
pub use settings::{Method, Settings, SettingsError};
pub use upstream::RK4_RESOLUTION;

use crate::budget::{self, Deadline};
use nalgebra::SVector;
use serde::Serialize;

/// A state vector of `N` components, on the stack.
pub type State<const N: usize> = SVector<f64, N>;

/// An autonomous system $\dot y = f(y)$. Implementations must not allocate.
pub trait Dynamics<const N: usize> {
    /// Writes $f(y)$ into `dy`.
    fn rhs(&self, y: &State<N>, dy: &mut State<N>);
}

/// A stop condition: the run ends where `value` first goes from positive to zero or below.
pub struct Event<'a, const N: usize> {
    /// A short name for reports ("alpha below 0.01").
    pub name: String,
    /// The event function.
    pub value: Box<dyn Fn(&State<N>) -> f64 + 'a>,
}

impl<'a, const N: usize> Event<'a, N> {
    /// An event from a name and a function.
    pub fn new(name: impl Into<String>, value: impl Fn(&State<N>) -> f64 + 'a) -> Self {
        Self {
            name: name.into(),
            value: Box::new(value),
        }
    }
}

/// Takes each sample of a sampled run as it is made ([`Problem::on_sample`]).
pub type Sink<'a, const N: usize> = &'a mut dyn FnMut(f64, &State<N>);

/// Takes the end of each accepted step of a sampled run ([`Problem::on_step`]): its time, its
/// state and, where the engine has it, the right-hand side there.
pub type StepSink<'a, const N: usize> = &'a mut dyn FnMut(f64, &State<N>, Option<&State<N>>);

/// Moves a state back onto an invariant ([`Problem::project`]).
pub type Projector<'a, const N: usize> = Box<dyn Fn(&mut State<N>) + 'a>;

/// An event's time is located to this many seconds (absolute) at least.
pub const EVENT_TIME_TOLERANCE: f64 = 1e-12;

/// What to integrate: a system from `y0` at `t0` to `t_end`, with stop events and an optional
/// sampling interval (without one, the solution holds every accepted step).
pub struct Problem<'a, D, const N: usize> {
    /// The system.
    pub dynamics: &'a D,
    /// Start time.
    pub t0: f64,
    /// Start state.
    pub y0: State<N>,
    /// End time (the run may stop earlier at an event).
    pub t_end: f64,
    /// Stop events.
    pub events: Vec<Event<'a, N>>,
    /// Sample the solution every `sample` seconds instead of at the steps.
    pub sample: Option<f64>,
    /// The origin $t_g$ of the sample grid $t_g + n\,\Delta t$ (`None`: the start time), so
    /// that the runs of a hybrid system's segments sample one grid.
    pub sample_origin: Option<f64>,
    /// Takes the samples of a sampled run as they are made, so that none is held: the
    /// [`Solution`] then holds only the last point (the end time or the event), which is not
    /// passed to the sink.
    pub on_sample: Option<Sink<'a, N>>,
    /// Takes the end of every accepted step of a sampled run, each before the samples that
    /// lie in that step go to [`Problem::on_sample`] (a step's samples are those after its
    /// start and up to its end), so that a recorder can watch a quantity at the steps and
    /// look closer only in the steps where it changes sign. The tool's own DOP853 hands on the
    /// right-hand side at the step's end too (its last stage, which the next step starts
    /// from); re-integrated samples and a located event do not. A run stopped by an event
    /// passes the located event's time and state as the end of its last step.
    pub on_step: Option<StepSink<'a, N>>,
    /// Takes the samples of a sampled run a step's worth at a time (at most [`BATCH`] in one
    /// call), in place of [`Problem::on_sample`] when both are given: the samples of DOP853's
    /// dense output are then evaluated side by side. Each [`Problem::on_step`] call comes
    /// before the batches of its step's samples.
    pub on_batch: Option<BatchSink<'a, N>>,
    /// Take DOP853's samples from its dense output (a polynomial evaluation each; the default)
    /// instead of re-integrating each from the step before it. Such a run integrates at the
    /// tightened tolerances of [`driver::dense_tolerances`], so that its samples are as
    /// accurate as the settings ask (within a few tolerances: `dense_error`).
    pub dense_samples: bool,
    /// Called with the current time now and then, for progress bars.
    pub progress: Option<&'a dyn Fn(f64)>,
    /// Applied to the state after every accepted step ([`projection`]): moves it back onto an
    /// invariant. Only the crate's own DOP853 can apply it, so a problem that has one is
    /// integrated by it (and refused with another method).
    pub project: Option<Projector<'a, N>>,
}

impl<'a, D: Dynamics<N>, const N: usize> Problem<'a, D, N> {
    /// A problem with no events, no sampling and no progress report.
    pub fn new(dynamics: &'a D, t0: f64, y0: State<N>, t_end: f64) -> Self {
        Self {
            dynamics,
            t0,
            y0,
            t_end,
            events: Vec::new(),
            sample: None,
            sample_origin: None,
            on_sample: None,
            on_step: None,
            on_batch: None,
            dense_samples: true,
            progress: None,
            project: None,
        }
    }

    /// Adds a stop event.
    pub fn stop_when(mut self, event: Event<'a, N>) -> Self {
        self.events.push(event);
        self
    }

    /// Samples the solution at a fixed interval.
    pub fn sampled(mut self, every: f64) -> Self {
        self.sample = Some(every);
        self
    }
}

/// Which implementation integrates a DOP853 run (RK4 and DOPRI5 always go through
/// `ode_solvers`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Engine {
    /// The crate's own DOP853 ([`dop853`]): events on its dense output, projections.
    Own,
    /// `ode_solvers` 0.6.2's DOP853: the default.
    OdeSolvers,
}

/// Integrates a problem with the default engine ([`Engine::OdeSolvers`]). Settings are checked first;
/// everything that can go wrong during the run (a singularity, too many steps, NaN) is reported
/// in [`Solution::ending`], never a panic.
pub fn solve<D: Dynamics<N>, const N: usize>(
    problem: Problem<'_, D, N>,
    settings: &Settings,
) -> Result<Solution<N>, SettingsError> {
    solve_with(problem, settings, Engine::OdeSolvers)
}

/// Integrates a problem with the engine given (see [`solve`]).
pub fn solve_with<D: Dynamics<N>, const N: usize>(
    problem: Problem<'_, D, N>,
    settings: &Settings,
    engine: Engine,
) -> Result<Solution<N>, SettingsError> {
    settings.validate()?;
    if problem.project.is_some() && settings.method != Method::Dop853 {
        return Err(SettingsError::Projection(settings.method));
    }
    let span = problem.t_end - problem.t0;
    if !(span.is_finite() && span > 0.0) {
        return Err(SettingsError::Span(span));
    }
    if let Some(dt) = problem.sample {
        if !(dt.is_finite() && dt > 0.0) {
            return Err(SettingsError::Sample(dt));
        }
        if problem.on_sample.is_none() && problem.on_batch.is_none() {
            held_samples(span, dt)?;
        }
    }
    if !problem.y0.iter().all(|v| v.is_finite()) {
        return Err(SettingsError::Start(problem.y0.iter().copied().collect()));
    }
    // Never allocate from a user's number unchecked: ode_solvers' RK4 reserves room for all
    // ceil(span / step) steps at once, and the adaptive methods keep every accepted step.
    let stored = if settings.method == Method::Rk4 {
        let needed = (span / settings.step).ceil();
        if needed > f64::from(settings.max_steps) {
            return Err(SettingsError::TooManyRk4Steps {
                step: settings.step,
                needed,
                limit: settings.max_steps,
            });
        }
        needed as u64
    } else {
        u64::from(settings.max_steps)
    };
    Settings::check_memory(stored, N)?;
    let (t0, y0) = (problem.t0, problem.y0);
    let deadline = Deadline::start();
    let stats = Stats::default();

    // An event that already holds at the start ends the run there.
    if let Some(i) = problem.events.iter().position(|e| (e.value)(&y0) <= 0.0) {
        return Ok(Solution {
            t: vec![t0],
            y: vec![y0],
            stats,
            ending: Ending::Event {
                index: i,
                name: problem.events[i].name.clone(),
                t: t0,
            },
        });
    }
    Ok(match (settings.method, engine) {
        (Method::Dop853, Engine::Own) => driver::run(problem, settings, deadline),
        // Only the own engine's step loop can project, and only its dense output samples at
        // the price of a polynomial.
        (Method::Dop853, _)
            if problem.project.is_some() || (problem.sample.is_some() && problem.dense_samples) =>
        {
            driver::run(problem, settings, deadline)
        }
        _ => upstream::run(problem, settings, deadline),
    })
}

/// Refuses a sampled run whose samples, held in memory, would be more than
/// [`budget::MAX_ROWS`] (a run that streams its samples to a sink holds none).
pub fn held_samples(span: f64, dt: f64) -> Result<(), SettingsError> {
    let rows = (span / dt).floor() + 2.0;
    if rows > budget::MAX_ROWS as f64 {
        return Err(SettingsError::Samples {
            sample: dt,
            span,
            rows,
            limit: budget::MAX_ROWS,
            least: budget::round_up_3(span / (budget::MAX_ROWS as f64 - 2.0)),
        });
    }
    Ok(())
}

/// Makes a time-dependent system $\dot y = f(t, y)$ autonomous by carrying $t$ as the last of
/// `M` = `N` + 1 states, so that the integrators never need the time argument.
pub struct WithTime<F, const N: usize> {
    /// $f(t, y)$.
    pub f: F,
}

impl<F, const N: usize, const M: usize> Dynamics<M> for WithTime<F, N>
where
    F: Fn(f64, &[f64], &mut [f64]),
{
    fn rhs(&self, y: &State<M>, dy: &mut State<M>) {
        debug_assert_eq!(M, N + 1);
        let t = y[N];
        (self.f)(t, &y.as_slice()[..N], &mut dy.as_mut_slice()[..N]);
        dy[N] = 1.0;
    }
}
