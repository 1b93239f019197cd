//! Speed against accuracy, measured; numerical stability at the extremes.
//!
//! Users trade speed for accuracy, so this module measures the trade instead of hiding it.
//!
//! - [`reference`]: a tight reference solution of a scene (DOP853 at `rtol` = 1e-14), and how it
//!   was validated: its agreement with independent integrations (DOP853 one decade looser,
//!   Dormand-Prince 5(4) at the same tolerance, classical RK4 with a tiny fixed step) and its own
//!   energy drift.
//! - [`study`]: the work-precision diagram: for RK4 over a sweep of step sizes and for DOPRI5 and
//!   DOP853 over `rtol` from 1e-3 to 1e-13 (with `atol` = 1e-2 `rtol`), the error at the final
//!   time and over the trajectory against right-hand-side evaluations and wall time, the observed
//!   order against the nominal one, and the cheapest settings reaching a requested accuracy.
//! - [`preset`]: `--accuracy fast|standard|high` and the accuracy each one actually reaches.
//! - [`cost`]: the cost of one right-hand-side evaluation, the solver's overhead over it and the
//!   growth of the energy drift over long runs.
//! - [`stable`]: numerically stable forms of eqs 29 and 54 where the printed forms lose precision
//!   (near $\alpha_0 = \pi/2$ and near eq 30's bound).
//!
//! The error of a state $y$ against the reference $y^{\rm ref}$ is measured component by
//! component, each relative to the largest magnitude that component reaches on the reference,
//! $$ e(y) = \max_i \frac{|y_i - y_i^{\rm ref}|}{\max_t |y_i^{\rm ref}(t)|}, $$
//! so that a component passing through zero ($\dot\alpha$) is not divided by zero and one with a
//! large range (the heading) is not over-weighted. When a run ends at a stop event, the relative
//! error of the event time, $|t - t^{\rm ref}| / t^{\rm ref}$, joins the maximum.

pub mod cost;
pub mod drift;
pub mod measure;
pub mod preset;
pub mod reference;
pub mod stable;
pub mod study;

pub use cost::{energy_drift, rhs_latency_nanoseconds, rhs_nanoseconds, Drift};
pub use drift::{long_time_drift, DriftRow, DriftTable};
pub use measure::{trace_with, Timing, Trace};
pub use preset::{measure_preset, Accuracy, PresetMeasurement};
pub use reference::{Agreement, Reference, ReferenceOptions};
pub use study::{
    benchmark_study, cheapest, study, study_with_progress, Cost, Point, Series, Study, StudyOptions,
};

use physics::scene::ModelKind;
use physics::solve::SettingsError;
use thiserror::Error;

/// Why a measurement could not be made.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum PrecisionError {
    /// The solver refused the settings.
    #[error(transparent)]
    Settings(#[from] SettingsError),
    /// Energy drift is only meaningful where energy is conserved.
    #[error(
        "energy is not conserved by the {0} model, so its drift measures nothing: use a rolling or frictionless scene"
    )]
    NotConservative(ModelKind),
    /// A run counted in precession periods needs a precession.
    #[error("the scene starts with no precession (Omega = 0), so a number of precession periods means nothing: give a time instead")]
    NoPrecession,
}
