//! What a run produced: the solution, the solver's work and why the run ended.

use super::State;
use serde::Serialize;
use std::fmt;

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
        /// The steps that would reach the end at the pace so far ([`Ending::pace`]).
        needs: Option<u64>,
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
    /// The steps that reach `t_end` from `t0` at the pace of `steps` steps up to `t`, with a
    /// tenth more (for [`Ending::TooManySteps`]); `None` where no time passed or fewer than 100
    /// steps were taken (the first steps, still growing from the solver's first guess, tell
    /// nothing of its pace).
    pub fn pace(steps: u64, t0: f64, t: f64, t_end: f64) -> Option<u64> {
        let done = t - t0;
        (steps >= 100 && done > 0.0 && t_end > t0).then(|| {
            let n = (steps as f64 * (t_end - t0) / done * 1.1).ceil();
            if n >= u64::MAX as f64 {
                u64::MAX
            } else {
                n as u64
            }
        })
    }

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
            Ending::TooManySteps {
                t,
                steps,
                needs: Some(n),
            } if *n <= crate::budget::MAX_STEPS_LIMIT => write!(
                f,
                "gave up after {steps} steps at t = {t:.9} s; at its pace so far about {n} steps \
                 reach the end: set solver: {{ max_steps: {n} }} (or loosen solver.rtol, raise a tiny \
                 solver.atol, or lower stop.time)"
            ),
            Ending::TooManySteps {
                t,
                steps,
                needs: Some(n),
            } => write!(
                f,
                "gave up after {steps} steps at t = {t:.9} s; at its pace so far about {n:.2e} \
                 steps reach the end, more than the {:.0e} solver.max_steps allows: loosen \
                 solver.rtol, raise a tiny solver.atol, or lower stop.time",
                crate::budget::MAX_STEPS_LIMIT as f64
            ),
            Ending::TooManySteps { t, steps, .. } => write!(
                f,
                "gave up after {steps} steps at t = {t:.9} s (raise solver.max_steps, loosen \
                 solver.rtol, raise a tiny solver.atol, or lower stop.time)"
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
