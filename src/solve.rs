//! The one door to `ode_solvers`.
//!
//! Every integration in the crate goes through [`solve`]. It offers the three methods of
//! `ode_solvers` (classical fixed-step RK4, Dormand-Prince 5(4) and 8(5,3)), their tolerances,
//! stop events located in time, sampling at fixed intervals, and the solver's statistics.
//!
//! Two facts about `ode_solvers` 0.6.2 shape this module:
//! - Its DOP853 tableau has $c_{12} = c_{13} = 0$ where Hairer's has 1, so any right-hand side
//!   that reads the time is integrated wrongly. [`Dynamics`] therefore has no time argument:
//!   every system here is autonomous, and a problem that depends on time carries it as a state
//!   ([`WithTime`] does that for you).
//! - It can only stop after an accepted step. A stop event is detected on the step ends and then
//!   located by bisection on re-integrations from the start of the step that crossed it.

use crate::budget::{self, Deadline};
use nalgebra::SVector;
use ode_solvers::dop_shared::IntegrationError;
use ode_solvers::{Dop853, Dopri5, OutputType, Rk4, System};
use serde::{Deserialize, Serialize};
use std::fmt;
use thiserror::Error;

/// A state vector of `N` components, on the stack.
pub type State<const N: usize> = SVector<f64, N>;

/// An autonomous system $\dot y = f(y)$. Implementations must not allocate.
pub trait Dynamics<const N: usize> {
    /// Writes $f(y)$ into `dy`.
    fn rhs(&self, y: &State<N>, dy: &mut State<N>);
}

/// The integration method.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Method {
    /// Classical Runge-Kutta of order 4 with a fixed step.
    Rk4,
    /// Dormand-Prince 5(4), adaptive.
    Dopri5,
    /// Dormand-Prince 8(5,3), adaptive.
    Dop853,
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Method::Rk4 => "rk4",
            Method::Dopri5 => "dopri5",
            Method::Dop853 => "dop853",
        })
    }
}

/// How to integrate.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Settings {
    /// The method.
    pub method: Method,
    /// Relative tolerance (adaptive methods).
    pub rtol: f64,
    /// Absolute tolerance (adaptive methods).
    pub atol: f64,
    /// Step for RK4 (shortened so that a whole number of steps fits the interval).
    pub step: f64,
    /// Most steps one run may take before it ends with [`Ending::TooManySteps`].
    pub max_steps: u32,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            method: Method::Dop853,
            rtol: 1e-10,
            atol: 1e-12,
            step: 1e-3,
            max_steps: 2_000_000,
        }
    }
}

/// Settings that cannot be used.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SettingsError {
    /// rtol must lie strictly between 0 and 1: at 1 or above the error control accepts any step,
    /// so the numbers would mean nothing.
    #[error("rtol must lie strictly between 0 and 1 (for example 1e-10; at 1 or above any step is accepted and the result means nothing), got {0}")]
    Rtol(f64),
    /// atol must be zero or positive, and finite.
    #[error("atol must be zero or a positive number (for example 1e-12), got {0}")]
    Atol(f64),
    /// max_steps must be at least 1 and at most [`budget::MAX_STEPS_LIMIT`].
    #[error("max_steps must lie between 1 and {limit}, got {steps}")]
    MaxSteps {
        /// The value asked for.
        steps: u64,
        /// The limit.
        limit: u64,
    },
    /// The steps the solver might store would take more memory than the budget.
    #[error("max_steps = {steps} lets the solver store up to {mib} MiB of steps of {states} states, more than the budget of {limit_mib} MiB: lower max_steps to {fits} or less")]
    Memory {
        /// Steps asked for (max_steps, or the rk4 steps needed).
        steps: u64,
        /// States of the system.
        states: usize,
        /// MiB those steps take.
        mib: u64,
        /// The budget in MiB.
        limit_mib: u64,
        /// The most steps that fit the budget.
        fits: u64,
    },
    /// A run without `sample` took more steps than rows may be recorded.
    #[error("the run took {rows} steps, each recorded as a row, more than the limit of {limit} rows: add sample: {suggest:.3e} (seconds between rows) to the scene")]
    Rows {
        /// Rows the run produced.
        rows: u64,
        /// The limit.
        limit: u64,
        /// A sampling interval that records about a tenth of the limit.
        suggest: f64,
    },
    /// Sampling would record more rows than allowed.
    #[error("sampling every {sample} s over {span} s records {rows:.0} rows, more than the limit of {limit}: raise sample to at least {least:.3e} s")]
    Samples {
        /// The sampling interval.
        sample: f64,
        /// The time span.
        span: f64,
        /// Rows it would record.
        rows: f64,
        /// The limit.
        limit: u64,
        /// The smallest interval within the limit.
        least: f64,
    },
    /// The RK4 step must be positive and finite.
    #[error("the rk4 step must be a positive number of seconds (for example 1e-4), got {0}")]
    Step(f64),
    /// The time span must be positive and finite.
    #[error("the time to integrate over must be a positive number of seconds, got {0}")]
    Span(f64),
    /// The sampling interval must be positive and finite.
    #[error("the sampling interval must be a positive number of seconds, got {0}")]
    Sample(f64),
    /// RK4 would need more steps than allowed.
    #[error("rk4 with step {step} s needs {needed} steps, more than the limit of {limit}: use a larger step or dop853")]
    TooManyRk4Steps {
        /// The step asked for.
        step: f64,
        /// Steps it would take.
        needed: f64,
        /// The limit.
        limit: u32,
    },
    /// The start state holds a NaN or an infinity.
    #[error("the start state is not finite: {0:?}")]
    Start(Vec<f64>),
}

impl Settings {
    /// Checks that the settings can be used: rtol in (0, 1), atol >= 0, a positive finite rk4
    /// step, and max_steps between 1 and [`budget::MAX_STEPS_LIMIT`]. The memory the steps may
    /// take depends on the number of states and is checked by [`solve`].
    pub fn validate(&self) -> Result<(), SettingsError> {
        let ok = |x: f64| x.is_finite() && x > 0.0;
        let steps = u64::from(self.max_steps);
        if steps == 0 || steps > budget::MAX_STEPS_LIMIT {
            return Err(SettingsError::MaxSteps {
                steps,
                limit: budget::MAX_STEPS_LIMIT,
            });
        }
        match self.method {
            Method::Rk4 if !ok(self.step) => Err(SettingsError::Step(self.step)),
            Method::Dopri5 | Method::Dop853 if !(ok(self.rtol) && self.rtol < 1.0) => {
                Err(SettingsError::Rtol(self.rtol))
            }
            Method::Dopri5 | Method::Dop853 if !(self.atol.is_finite() && self.atol >= 0.0) => {
                Err(SettingsError::Atol(self.atol))
            }
            _ => Ok(()),
        }
    }

    /// Checks that `steps` stored steps of an `n`-state system fit the memory budget.
    fn check_memory(steps: u64, n: usize) -> Result<(), SettingsError> {
        let bytes = budget::trajectory_bytes(steps, n);
        if bytes <= budget::TRAJECTORY_BYTES {
            return Ok(());
        }
        Err(SettingsError::Memory {
            steps,
            states: n,
            mib: bytes >> 20,
            limit_mib: budget::TRAJECTORY_BYTES >> 20,
            fits: budget::TRAJECTORY_BYTES / budget::trajectory_bytes(1, n),
        })
    }
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

/// Why a run ended.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Ending {
    /// It reached the end time.
    TimeReached,
    /// A stop event happened at time `t` (located to [`EVENT_TIME_TOLERANCE`]).
    Event {
        /// Which event (its index in the list given).
        index: usize,
        /// Its name.
        name: String,
        /// When.
        t: f64,
    },
    /// The step size fell below what floating point can resolve at time `t`: the solution is
    /// most likely running into a singularity there.
    StepCollapse {
        /// Where the step collapsed.
        t: f64,
    },
    /// The step limit was reached at time `t`.
    TooManySteps {
        /// Where.
        t: f64,
        /// The limit.
        steps: u32,
    },
    /// The solver's stiffness test fired at time `t`.
    Stiff {
        /// Where.
        t: f64,
    },
    /// The state became NaN or infinite at time `t`.
    NonFinite {
        /// Where.
        t: f64,
    },
    /// A hybrid run ([`crate::events`]) could not go on at time `t`, for the reason given.
    Halted {
        /// Where.
        t: f64,
        /// Why, in a sentence.
        reason: String,
    },
    /// A fixed-step (rk4) run went unstable in the step ending at `t`: the step's terms beyond
    /// first order were `ratio` times its first-order (Euler) term, so the step is beyond what
    /// the method resolves (see [`RK4_RESOLUTION`]); the state there is discarded.
    Unstable {
        /// The end of the first unresolved step.
        t: f64,
        /// Higher-order over first-order part of that step.
        ratio: f64,
        /// The step.
        step: f64,
    },
    /// The wall-time budget of the integration ran out at simulated time `t`.
    WallTime {
        /// Where.
        t: f64,
        /// The budget, in seconds.
        seconds: f64,
    },
}

impl Ending {
    /// True when the run went as far as it was asked to (end time or a stop event).
    pub fn is_complete(&self) -> bool {
        matches!(self, Ending::TimeReached | Ending::Event { .. })
    }
}

impl fmt::Display for Ending {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Ending::TimeReached => write!(f, "reached the end time"),
            Ending::Event { name, t, .. } => write!(f, "stopped: {name} at t = {t:.12} s"),
            Ending::StepCollapse { t } => write!(
                f,
                "the step size collapsed at t = {t:.12} s (the motion runs into a singularity: \
                 stop earlier, e.g. with stop: {{ alpha_below: ... }})"
            ),
            Ending::TooManySteps { t, steps } => write!(
                f,
                "gave up after {steps} steps at t = {t:.9} s (raise solver.max_steps, loosen \
                 solver.rtol or lower stop.time)"
            ),
            Ending::Unstable { t, ratio, step } => write!(
                f,
                "rk4 went unstable at t = {t:.9} s: its step of {step:.3e} s is beyond what it \
                 resolves there (the step's higher-order part is {ratio:.3e} times its \
                 first-order part), so no number of this run can be trusted: lower solver.step \
                 or use method: dop853"
            ),
            Ending::WallTime { t, seconds } => write!(
                f,
                "the wall-time budget of {seconds} s ran out at t = {t:.9} s (raise --max-seconds \
                 or lower stop.time)"
            ),
            Ending::Stiff { t } => write!(f, "the problem became stiff at t = {t:.9} s"),
            Ending::NonFinite { t } => {
                write!(f, "the state became NaN or infinite at t = {t:.9} s")
            }
            Ending::Halted { t, reason } => write!(f, "halted at t = {t:.9} s: {reason}"),
        }
    }
}

/// Work done by the solver.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize)]
pub struct Stats {
    /// Right-hand-side evaluations of the main pass.
    pub evaluations: u64,
    /// Accepted steps.
    pub accepted: u64,
    /// Rejected steps.
    pub rejected: u64,
    /// Evaluations spent after the main pass: locating events and sampling.
    pub extra_evaluations: u64,
}

impl Stats {
    /// All right-hand-side evaluations.
    pub fn total_evaluations(&self) -> u64 {
        self.evaluations + self.extra_evaluations
    }
}

/// A solution: the accepted step ends (or the samples asked for), the statistics and why it ended.
#[derive(Debug, Clone)]
pub struct Solution<const N: usize> {
    /// Times.
    pub t: Vec<f64>,
    /// States at those times.
    pub y: Vec<State<N>>,
    /// Work done.
    pub stats: Stats,
    /// Why it ended.
    pub ending: Ending,
}

impl<const N: usize> Solution<N> {
    /// The last time and state.
    pub fn last(&self) -> (f64, State<N>) {
        let i = self.t.len() - 1;
        (self.t[i], self.y[i])
    }
}

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
    /// Called with the current time now and then, for progress bars.
    pub progress: Option<&'a dyn Fn(f64)>,
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
            progress: None,
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

/// A fixed step is taken as unresolved, and the run as unstable, when the part of the step
/// beyond first order exceeds this multiple of its first-order (Euler) part.
///
/// The first-order part is taken as the largest of the recent steps' (a maximum that decays by
/// 1 % a step, so over about a hundred steps): at the turning points of a nutation the slope
/// passes near zero while the curvature does not, and the step's own Euler part would make the
/// ratio spike there without any instability.
///
/// For a linear mode $\dot y = \lambda y$ the RK4 step multiplies $y$ by
/// $R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24$ with $z = h\lambda$, so the ratio is
/// $|z/2 + z^2/6 + z^3/24|$. It reaches 1 at $z = -2.785$, exactly RK4's stability limit on the
/// negative real axis, and at $|z| \approx 2.1$ on the imaginary axis (the limit there is
/// $2\sqrt 2$, where the phase is already wrong by a large fraction of a turn). The ratio needs no
/// extra evaluation: `ode_solvers` hands the step's first slope $f(y_n)$ to the step-end callback.
pub const RK4_RESOLUTION: f64 = 1.0;

/// Bridges a [`Dynamics`] to `ode_solvers`: ignores the time it is passed, watches the events,
/// the finiteness of the state, the wall-time budget and (for RK4) the resolution of each step.
struct Bridge<'p, 'a, D, const N: usize> {
    dynamics: &'a D,
    events: &'p [Event<'a, N>],
    progress: Option<&'a dyn Fn(f64)>,
    /// The last accepted step end at which no event had happened.
    prev: (f64, State<N>),
    /// The last accepted step end, whatever happened there.
    last: (f64, State<N>),
    crossed: bool,
    non_finite: Option<f64>,
    steps: u64,
    /// Watch each fixed step's resolution (RK4 only).
    fixed_step: bool,
    unstable: Option<(f64, f64, f64)>,
    /// The decaying maximum of the recent steps' Euler parts.
    scale: f64,
    deadline: Option<Deadline>,
    timed_out: Option<f64>,
}

impl<'p, 'a, D: Dynamics<N>, const N: usize> Bridge<'p, 'a, D, N> {
    fn new(dynamics: &'a D, events: &'p [Event<'a, N>], t0: f64, y0: State<N>) -> Self {
        Self {
            dynamics,
            events,
            progress: None,
            prev: (t0, y0),
            last: (t0, y0),
            crossed: false,
            non_finite: None,
            steps: 0,
            fixed_step: false,
            unstable: None,
            scale: 0.0,
            deadline: None,
            timed_out: None,
        }
    }

    /// The step from `self.last` to `(t, y)` with first slope `dy`: `Some((ratio, h))` when its
    /// higher-order part exceeds [`RK4_RESOLUTION`] times the recent Euler parts, or the size
    /// of the state itself (a step that jumps). A floor of 1e-6 of the state's size keeps
    /// round-off in a motion at rest from counting.
    fn unresolved(&mut self, t: f64, y: &State<N>, dy: &State<N>) -> Option<(f64, f64)> {
        let (t_a, y_a) = &self.last;
        let h = t - t_a;
        let euler = dy * h;
        self.scale = euler.norm().max(0.99 * self.scale);
        let rest = (y - y_a - euler).norm();
        let floor = 1e-6 * (1.0 + y_a.norm());
        let unresolved = rest > RK4_RESOLUTION * self.scale && rest > floor;
        let jump = rest > y_a.norm() + euler.norm();
        (unresolved || jump).then(|| (rest / self.scale.max(f64::MIN_POSITIVE), h))
    }
}

impl<D: Dynamics<N>, const N: usize> System<f64, State<N>> for &mut Bridge<'_, '_, D, N> {
    fn system(&self, _t: f64, y: &State<N>, dy: &mut State<N>) {
        self.dynamics.rhs(y, dy);
    }

    fn solout(&mut self, t: f64, y: &State<N>, dy: &State<N>) -> bool {
        self.steps += 1;
        if self.steps.is_multiple_of(256) {
            if let Some(p) = self.progress {
                p(t);
            }
        }
        if self.steps.is_multiple_of(64) && self.deadline.is_some_and(|d| d.passed()) {
            self.timed_out = Some(t);
            return true;
        }
        if !y.iter().all(|v| v.is_finite()) {
            self.non_finite = Some(t);
            return true;
        }
        if self.fixed_step {
            if let Some((ratio, h)) = self.unresolved(t, y, dy) {
                self.unstable = Some((t, ratio, h));
                return true;
            }
            self.last = (t, *y);
        }
        if self.events.iter().any(|e| (e.value)(y) <= 0.0) {
            self.crossed = true;
            return true;
        }
        self.prev = (t, *y);
        false
    }
}

type Raw<const N: usize> = (
    Result<ode_solvers::dop_shared::Stats, IntegrationError>,
    Vec<f64>,
    Vec<State<N>>,
);

/// One run of an `ode_solvers` integrator from `t0` to `t_end`, keeping every accepted step.
/// `first_step` = 0 lets the adaptive methods choose it.
fn raw_run<D: Dynamics<N>, const N: usize>(
    bridge: &mut Bridge<'_, '_, D, N>,
    settings: &Settings,
    t0: f64,
    y0: State<N>,
    t_end: f64,
    first_step: f64,
) -> Raw<N> {
    let span = t_end - t0;
    let n_max = settings.max_steps;
    macro_rules! finish {
        ($s:ident) => {{
            let r = $s.integrate();
            let (t, y) = $s.results().get();
            (r, t.clone(), y.clone())
        }};
    }
    match settings.method {
        Method::Dop853 => {
            let mut s = Dop853::from_param(
                bridge,
                t0,
                t_end,
                span,
                y0,
                settings.rtol,
                settings.atol,
                0.9,
                0.0,
                0.333,
                6.0,
                span,
                first_step,
                n_max,
                1000,
                OutputType::Sparse,
            );
            finish!(s)
        }
        Method::Dopri5 => {
            let mut s = Dopri5::from_param(
                bridge,
                t0,
                t_end,
                span,
                y0,
                settings.rtol,
                settings.atol,
                0.9,
                0.04,
                0.2,
                10.0,
                span,
                first_step,
                n_max,
                1000,
                OutputType::Sparse,
            );
            finish!(s)
        }
        Method::Rk4 => {
            // ode_solvers takes ceil(span / step) steps of the full step and so overshoots
            // t_end: shorten the step so that a whole number of steps ends exactly there.
            let h = if first_step > 0.0 {
                first_step
            } else {
                settings.step
            };
            let n = (span / h).ceil().max(1.0);
            let mut s = Rk4::new(bridge, t0, y0, t_end, span / n);
            finish!(s)
        }
    }
}

/// The state at `t0 + tau` re-integrated from `(t0, y0)` with the same method and tolerances:
/// one RK4 step, or an adaptive run that first tries the whole interval in one step.
fn advance<D: Dynamics<N>, const N: usize>(
    dynamics: &D,
    settings: &Settings,
    t0: f64,
    y0: State<N>,
    tau: f64,
    stats: &mut Stats,
) -> State<N> {
    if tau <= 0.0 {
        return y0;
    }
    let mut bridge = Bridge::new(dynamics, &[], t0, y0);
    let (r, _, y) = raw_run(&mut bridge, settings, t0, y0, t0 + tau, tau);
    if let Ok(s) = r {
        stats.extra_evaluations += u64::from(s.num_eval);
    }
    *y.last().unwrap_or(&y0)
}

/// Integrates a problem. Settings are checked first; everything that can go wrong during the
/// run (a singularity, too many steps, NaN) is reported in [`Solution::ending`], never a panic.
pub fn solve<D: Dynamics<N>, const N: usize>(
    problem: Problem<'_, D, N>,
    settings: &Settings,
) -> Result<Solution<N>, SettingsError> {
    settings.validate()?;
    let span = problem.t_end - problem.t0;
    if !(span.is_finite() && span > 0.0) {
        return Err(SettingsError::Span(span));
    }
    if let Some(dt) = problem.sample {
        if !(dt.is_finite() && dt > 0.0) {
            return Err(SettingsError::Sample(dt));
        }
        let rows = (span / dt).floor() + 2.0;
        if rows > budget::MAX_ROWS as f64 {
            return Err(SettingsError::Samples {
                sample: dt,
                span,
                rows,
                limit: budget::MAX_ROWS,
                least: span / (budget::MAX_ROWS as f64 - 2.0),
            });
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
        needed as u64 + 1
    } else {
        u64::from(settings.max_steps) + 1
    };
    Settings::check_memory(stored, N)?;
    let (t0, y0) = (problem.t0, problem.y0);
    let deadline = Deadline::start();
    let mut stats = Stats::default();

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

    let mut bridge = Bridge::new(problem.dynamics, &problem.events, t0, y0);
    bridge.progress = problem.progress;
    bridge.fixed_step = settings.method == Method::Rk4;
    bridge.deadline = Some(deadline);
    let (result, mut ts, mut ys) = raw_run(&mut bridge, settings, t0, y0, problem.t_end, 0.0);
    let (crossed, non_finite, prev) = (bridge.crossed, bridge.non_finite, bridge.prev);
    let (unstable, timed_out) = (bridge.unstable, bridge.timed_out);
    let mut ending = Ending::TimeReached;
    match result {
        Ok(s) => {
            stats.evaluations = u64::from(s.num_eval);
            stats.accepted = u64::from(s.accepted_steps);
            stats.rejected = u64::from(s.rejected_steps);
        }
        Err(e) => {
            ending = match e {
                IntegrationError::StepSizeUnderflow { x } => Ending::StepCollapse { t: x },
                IntegrationError::MaxNumStepReached { x, n_step } => Ending::TooManySteps {
                    t: x,
                    steps: n_step,
                },
                IntegrationError::StiffnessDetected { x } => Ending::Stiff { t: x },
            };
            stats.accepted = ts.len().saturating_sub(1) as u64;
        }
    }
    if let Some(t) = non_finite {
        ending = Ending::NonFinite { t };
        ts.pop();
        ys.pop();
    } else if let Some((t, ratio, step)) = unstable {
        ending = Ending::Unstable { t, ratio, step };
        ts.pop();
        ys.pop();
    } else if let Some(t) = timed_out {
        ending = Ending::WallTime {
            t,
            seconds: deadline.seconds(),
        };
    } else if crossed {
        let (t_a, y_a) = prev;
        let t_b = ts.last().copied().unwrap_or(t0);
        let (index, t_e, y_e) = locate(
            problem.dynamics,
            settings,
            &problem.events,
            t_a,
            y_a,
            t_b,
            &mut stats,
        );
        ts.pop();
        ys.pop();
        ts.push(t_e);
        ys.push(y_e);
        ending = Ending::Event {
            index,
            name: problem.events[index].name.clone(),
            t: t_e,
        };
    }
    if let Some(p) = problem.progress {
        p(*ts.last().unwrap_or(&t0));
    }

    let (t, y) = match problem.sample {
        None => (ts, ys),
        Some(dt) => {
            let (t, y, complete) = resample(
                problem.dynamics,
                settings,
                &ts,
                &ys,
                t0,
                dt,
                &deadline,
                &mut stats,
            );
            if !complete && ending.is_complete() {
                ending = Ending::WallTime {
                    t: *t.last().unwrap_or(&t0),
                    seconds: deadline.seconds(),
                };
            }
            (t, y)
        }
    };
    Ok(Solution {
        t,
        y,
        stats,
        ending,
    })
}

/// The earliest event that crossed in the step from `(t_a, y_a)` to `t_b`, located by bisection
/// on the re-integrated state. Returns its index, time and the state there (where it holds).
fn locate<D: Dynamics<N>, const N: usize>(
    dynamics: &D,
    settings: &Settings,
    events: &[Event<'_, N>],
    t_a: f64,
    y_a: State<N>,
    t_b: f64,
    stats: &mut Stats,
) -> (usize, f64, State<N>) {
    let mut best: Option<(usize, f64, State<N>)> = None;
    let y_b = advance(dynamics, settings, t_a, y_a, t_b - t_a, stats);
    for (i, e) in events.iter().enumerate() {
        if (e.value)(&y_b) > 0.0 {
            continue;
        }
        let (mut lo, mut hi) = (0.0, t_b - t_a);
        let mut y_hi = y_b;
        while hi - lo > EVENT_TIME_TOLERANCE * 0.5 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            let y_mid = advance(dynamics, settings, t_a, y_a, mid, stats);
            if (e.value)(&y_mid) <= 0.0 {
                hi = mid;
                y_hi = y_mid;
            } else {
                lo = mid;
            }
        }
        if best.as_ref().is_none_or(|b| t_a + hi < b.1) {
            best = Some((i, t_a + hi, y_hi));
        }
    }
    // The step ends showed a crossing, so at least one event fires at t_b or before.
    best.unwrap_or((0, t_b, y_b))
}

/// Samples a solution every `dt` seconds from `t0`, each sample re-integrated from the last
/// accepted step before it. The final point (end time or event) is kept as the last sample.
/// The flag is false when the wall-time budget ran out first (the samples then stop there).
#[allow(clippy::too_many_arguments)]
fn resample<const N: usize, D: Dynamics<N>>(
    dynamics: &D,
    settings: &Settings,
    ts: &[f64],
    ys: &[State<N>],
    t0: f64,
    dt: f64,
    deadline: &Deadline,
    stats: &mut Stats,
) -> (Vec<f64>, Vec<State<N>>, bool) {
    let Some((&t_last, &y_last)) = ts.last().zip(ys.last()) else {
        return (Vec::new(), Vec::new(), true);
    };
    let mut out_t = Vec::new();
    let mut out_y = Vec::new();
    let mut j = 0;
    let mut n: u64 = 0;
    loop {
        let t = t0 + dt * n as f64;
        if t >= t_last - 1e-12 * dt.max(t_last.abs()) {
            break;
        }
        if n.is_multiple_of(64) && deadline.passed() {
            out_t.push(t_last);
            out_y.push(y_last);
            return (out_t, out_y, false);
        }
        while j + 1 < ts.len() && ts[j + 1] <= t {
            j += 1;
        }
        out_t.push(t);
        out_y.push(advance(dynamics, settings, ts[j], ys[j], t - ts[j], stats));
        n += 1;
    }
    out_t.push(t_last);
    out_y.push(y_last);
    (out_t, out_y, true)
}

/// Makes a time-dependent system $\dot y = f(t, y)$ autonomous by carrying $t$ as the last of
/// `M` = `N` + 1 states, so that `ode_solvers`' defective DOP853 nodes never see the time.
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
