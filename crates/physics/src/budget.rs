//! Budgets on what a user controls: the memory a trajectory may take, the number of samples and
//! steps, and the wall time of one integration. Each limit is far above what an honest scene
//! needs (the built-in scenes use at most a few percent of each) and each is checked *before*
//! anything is allocated from a user's number, so that a hostile scene is refused at once with
//! a sentence instead of exhausting the machine.
//!
//! The wall-time budget is process-wide: the command line sets it once (`--max-seconds`) and
//! every integration started afterwards, including those run inside `check` and `report`, ends
//! with [`crate::solve::Ending::WallTime`] when it overruns.

use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{Duration, Instant};

/// Bytes the stored steps of one integration may take (times, states and the copy
/// `ode_solvers` hands back): 512 MiB.
pub const TRAJECTORY_BYTES: u64 = 512 << 20;

/// Most rows one run held in memory may record (samples, or accepted steps without `sample`):
/// the runs of `check`, `report` and the studies. A million rows of a scene's columns is about
/// 150 MB in memory; the built-in scenes record at most about 120,000 rows (`spin-down` sampled
/// every 0.5 ms over 60 s). A run that streams its rows (`simulate`) holds none and is bounded
/// by [`ROWS_PER_SECOND`] and the disk instead.
pub const MAX_ROWS: u64 = 1_000_000;

/// More rows than one second of wall time can make: a streamed run that samples more than this
/// many rows for each second of its wall-time budget cannot finish within it, and is refused
/// before integrating. A recorded row costs a polynomial evaluation per state and the recorded
/// quantities, 0.3 to 1 us (`cargo bench --bench benches -- sampling`), so this is a bound no run reaches.
pub const ROWS_PER_SECOND: u64 = 10_000_000;

/// The most rows a streamed run may sample within the current wall-time budget.
pub fn streamed_rows() -> u64 {
    (wall_seconds() * ROWS_PER_SECOND as f64) as u64
}

/// The largest `max_steps` a scene may ask for, whatever its number of states.
pub const MAX_STEPS_LIMIT: u64 = 50_000_000;

/// Most entries a scene's `mechanisms` list may hold. Every right-hand-side evaluation sums
/// them all; the paper's mechanisms are a handful, so a longer list is a mistake, refused before
/// anything is computed.
pub const MAX_MECHANISMS: usize = 64;

/// `x` rounded up to three significant digits: a least value to suggest in a message, so that
/// the number printed (with `{:.3e}`) is itself within the limit it was computed from.
pub fn round_up_3(x: f64) -> f64 {
    if !(x.is_finite() && x > 0.0) {
        return x;
    }
    let unit = 10f64.powf(x.log10().floor() - 2.0);
    let up = (x / unit).ceil() * unit;
    // The product may round below x; one more unit keeps it above.
    if up < x {
        up + unit
    } else {
        up
    }
}

/// A budget the user asked for that cannot be set.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum BudgetError {
    /// `--max-seconds` out of its range.
    #[error("--max-seconds must be a positive number of seconds up to 86400 (a day), got {0}")]
    WallSeconds(f64),
}

/// Default wall-time budget of one integration, in seconds.
pub const DEFAULT_WALL_SECONDS: f64 = 600.0;

/// The wall-time budget of each integration, in nanoseconds (0 is never stored: see
/// [`set_wall_seconds`]).
static WALL_BUDGET_NANOS: AtomicU64 = AtomicU64::new((DEFAULT_WALL_SECONDS * 1e9) as u64);

/// The first integration of this process that ran past its budget: the budget, and the stage
/// it ran in ([`in_stage`]), if one was named.
static OVERRUN: std::sync::Mutex<Option<Overrun>> = std::sync::Mutex::new(None);

thread_local! {
    /// The stage the integrations of this thread run in, for [`Overrun`].
    static STAGE: std::cell::RefCell<Option<String>> = const { std::cell::RefCell::new(None) };
}

/// An integration that ran past the wall-time budget: whatever it was computing is cut short,
/// so a command must not report it as a result.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{} ran past the wall-time budget of {seconds} s (--max-seconds), so what it computed is cut short: give a larger budget, such as the default --max-seconds {DEFAULT_WALL_SECONDS}", stage.as_deref().unwrap_or("an integration"))]
pub struct Overrun {
    /// The budget, in seconds.
    pub seconds: f64,
    /// The stage, such as "the check of eq 65", where known.
    pub stage: Option<String>,
}

/// Runs `f` with its integrations (on this thread) attributed to `stage`.
pub fn in_stage<T>(stage: &str, f: impl FnOnce() -> T) -> T {
    let before = STAGE.with(|s| s.replace(Some(stage.to_string())));
    let out = f();
    STAGE.with(|s| *s.borrow_mut() = before);
    out
}

/// The first integration of this process that ran past its budget, if any did.
pub fn overrun() -> Option<Overrun> {
    OVERRUN.lock().ok().and_then(|o| o.clone())
}

/// Records that an integration with `seconds` of budget ran past it.
fn record_overrun(seconds: f64) {
    if let Ok(mut o) = OVERRUN.lock() {
        if o.is_none() {
            let stage = STAGE.with(|s| s.borrow().clone());
            *o = Some(Overrun { seconds, stage });
        }
    }
}

/// Sets the wall-time budget of every integration started from now on. Returns an error
/// sentence when `seconds` is not a positive finite number of at most a day.
pub fn set_wall_seconds(seconds: f64) -> Result<(), BudgetError> {
    if !(seconds.is_finite() && seconds > 0.0 && seconds <= 86_400.0) {
        return Err(BudgetError::WallSeconds(seconds));
    }
    let nanos = (seconds * 1e9).ceil().max(1.0) as u64;
    WALL_BUDGET_NANOS.store(nanos, Ordering::Relaxed);
    Ok(())
}

/// The wall-time budget of one integration, in seconds.
pub fn wall_seconds() -> f64 {
    WALL_BUDGET_NANOS.load(Ordering::Relaxed) as f64 / 1e9
}

/// A deadline for one integration, started now with the current budget.
#[derive(Debug, Clone, Copy)]
pub struct Deadline {
    end: Instant,
    seconds: f64,
}

impl Deadline {
    /// Starts the clock of one integration.
    pub fn start() -> Self {
        let seconds = wall_seconds();
        Self {
            end: Instant::now() + Duration::from_secs_f64(seconds),
            seconds,
        }
    }

    /// True once the budget is spent; the first time in the process, the overrun is recorded
    /// ([`overrun`]).
    pub fn passed(&self) -> bool {
        let passed = Instant::now() >= self.end;
        if passed {
            record_overrun(self.seconds);
        }
        passed
    }

    /// The budget, in seconds.
    pub fn seconds(&self) -> f64 {
        self.seconds
    }
}

/// Work that is not an integration (reading, cleaning and analysing a recording; simulating its
/// artifacts) under the same wall-time budget as an integration: each stage it starts first
/// checks the clock, and tells `progress` its name.
pub struct Work<'a> {
    what: String,
    deadline: Deadline,
    progress: Option<&'a dyn Fn(&str)>,
}

/// Work that ran past the wall-time budget.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{what} ran past the wall-time budget of {seconds} s (before {stage}): raise the budget with --max-seconds SECONDS (at most 86400)")]
pub struct OverBudget {
    /// The work, e.g. "the analysis of run.csv".
    pub what: String,
    /// The stage that was to start.
    pub stage: String,
    /// The budget, in seconds.
    pub seconds: f64,
}

impl<'a> Work<'a> {
    /// Starts the clock of `what` with the current budget.
    pub fn start(what: impl Into<String>) -> Self {
        Self {
            what: what.into(),
            deadline: Deadline::start(),
            progress: None,
        }
    }

    /// The same work, telling `progress` each stage it starts.
    pub fn with_progress(self, progress: &'a dyn Fn(&str)) -> Self {
        Self {
            progress: Some(progress),
            ..self
        }
    }

    /// Starts `stage`: an error once the budget is spent.
    pub fn stage(&self, stage: &str) -> Result<(), OverBudget> {
        // Said by the error returned, which names the work and the stage: not an overrun of an
        // integration.
        if Instant::now() >= self.deadline.end {
            return Err(OverBudget {
                what: self.what.clone(),
                stage: stage.into(),
                seconds: self.deadline.seconds(),
            });
        }
        if let Some(p) = self.progress {
            p(stage);
        }
        Ok(())
    }
}

/// Bytes that `steps` stored steps of an `n`-state system take in the solver (a time and a
/// state each, twice: the solver's own vectors and the copy handed back).
pub fn trajectory_bytes(steps: u64, n: usize) -> u64 {
    steps.saturating_mul(2 * (8 + 8 * n as u64))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn work_past_its_budget_names_the_budget_and_the_option() {
        let said = std::cell::RefCell::new(Vec::new());
        let note = |s: &str| said.borrow_mut().push(s.to_string());
        let work = Work {
            what: "the analysis of x.csv".into(),
            deadline: Deadline {
                end: Instant::now() + Duration::from_secs(60),
                seconds: 60.0,
            },
            progress: None,
        }
        .with_progress(&note);
        assert_eq!(work.stage("cleaning"), Ok(()));
        assert_eq!(*said.borrow(), ["cleaning"]);
        let spent = Work {
            deadline: Deadline {
                end: Instant::now(),
                seconds: 0.001,
            },
            ..work
        };
        let e = spent.stage("fitting").unwrap_err().to_string();
        assert_eq!(
            e,
            "the analysis of x.csv ran past the wall-time budget of 0.001 s (before fitting): \
             raise the budget with --max-seconds SECONDS (at most 86400)"
        );
        assert_eq!(said.borrow().len(), 1, "no progress for a stage refused");
    }

    #[test]
    fn a_suggested_least_value_prints_at_or_above_the_limit() {
        for x in [5.000_010_000_02e-6, 1e-3, 0.123_456_7, 7.0, 9.999_9e10] {
            let up = round_up_3(x);
            let printed: f64 = format!("{up:.3e}").parse().unwrap_or(0.0);
            assert!(printed >= x, "{x} -> {up} printed {printed}");
            assert!(up <= x * 1.01 + 1e-300, "{x} -> {up}");
        }
    }

    #[test]
    fn the_budget_refuses_nonsense_and_keeps_the_last_good_value() {
        let before = wall_seconds();
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY, 1e9] {
            assert!(set_wall_seconds(bad).is_err(), "{bad} accepted");
        }
        assert_eq!(wall_seconds(), before);
    }

    #[test]
    fn the_default_step_limit_fits_the_memory_budget_for_every_model() {
        // The lab-frame model has the most states (13).
        let default = u64::from(crate::solve::Settings::default().max_steps);
        assert!(trajectory_bytes(default, 13) <= TRAJECTORY_BYTES);
        assert!(trajectory_bytes(MAX_STEPS_LIMIT, 4) > TRAJECTORY_BYTES);
    }
}
