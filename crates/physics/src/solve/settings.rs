//! How to integrate: the method, its tolerances and limits ([`Settings`]), and why settings
//! cannot be used ([`SettingsError`]).

use crate::budget;
use serde::{Deserialize, Serialize};
use std::fmt;
use thiserror::Error;

/// The integration method.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
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

impl Settings {
    /// DOP853 at relative tolerance `rtol` and absolute tolerance `atol`, the rest default.
    pub fn dop853(rtol: f64, atol: f64) -> Self {
        Settings {
            method: Method::Dop853,
            rtol,
            atol,
            ..Settings::default()
        }
    }
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
    /// rtol below [`RTOL_LEAST`] asks for more than double precision holds.
    #[error("rtol {0:e} asks for more than double precision holds (numbers are stored to 2.2e-16 relative, and rounding adds up over the steps): use rtol 1e-14 or more")]
    RtolBelowPrecision(f64),
    /// atol must be finite and at least [`ATOL_LEAST`]: with no absolute floor, a state that
    /// passes through zero must be computed to a relative accuracy of its own rounding and the
    /// step collapses there.
    #[error("atol must be a number of at least 1e-30 (for example 1e-12): with a smaller floor a state that passes through zero must be computed exactly and the step collapses there, got {0:e}")]
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
    #[error("sampling every {sample} s over {span} s records {rows:.0} rows, more than the limit of {limit} a run held in memory may record: raise sample to at least {least:.3e} s (rolling-disk simulate --csv FILE streams any number of rows)")]
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
    /// A projection onto an invariant needs the crate's own DOP853 step loop.
    #[error("a projection onto an invariant (solver: {{ project: energy }}) needs method dop853, got {0}")]
    Projection(Method),
    /// The start state holds a NaN or an infinity.
    #[error("the start state is not finite: {0:?}")]
    Start(Vec<f64>),
}

/// The smallest rtol accepted: ten times double precision's spacing (2.2e-16); a step can
/// meet no tighter one, and the step size collapses instead.
pub const RTOL_LEAST: f64 = 1e-15;

/// The smallest atol accepted. The error of a state that passes through zero is held to atol
/// alone; far below the states' scale (1 rad, 1 rad/s) that asks for a vanishing error, and the
/// step size collapses (at 0 on the sliding and bouncing scenes). Above this floor a scene may
/// still need a larger atol (at rtol 1e-10 the scene wheel-thrown-sliding runs at 1e-16 and gives
/// up at 1e-20); a run that gives up on its steps names a tiny atol among its remedies.
pub const ATOL_LEAST: f64 = 1e-30;

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
            Method::Dopri5 | Method::Dop853 if self.rtol < RTOL_LEAST => {
                Err(SettingsError::RtolBelowPrecision(self.rtol))
            }
            Method::Dopri5 | Method::Dop853
                if !(self.atol.is_finite() && self.atol >= ATOL_LEAST) =>
            {
                Err(SettingsError::Atol(self.atol))
            }
            _ => Ok(()),
        }
    }

    /// Checks that `steps` steps of an `n`-state system, stored with the start point, fit the
    /// memory budget.
    pub(super) fn check_memory(steps: u64, n: usize) -> Result<(), SettingsError> {
        let bytes = budget::trajectory_bytes(steps.saturating_add(1), n);
        if bytes <= budget::TRAJECTORY_BYTES {
            return Ok(());
        }
        Err(SettingsError::Memory {
            steps,
            states: n,
            mib: bytes >> 20,
            limit_mib: budget::TRAJECTORY_BYTES >> 20,
            fits: budget::TRAJECTORY_BYTES / budget::trajectory_bytes(1, n) - 1,
        })
    }
}
