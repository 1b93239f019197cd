//! What a run of a scene produced: the recorded table, the solver's work, how it ended, and
//! where a contact-only model would need the table to pull.

use crate::model::sliding::contact_events::ContactEvent;
use crate::model::Motion;
use crate::scene::ModelKind;
use crate::solve::{Ending, Stats};
use serde::Serialize;

/// What a run of a scene produced.
#[derive(Debug, Clone, Serialize)]
pub struct Run {
    /// The scene's name.
    pub scene: String,
    /// The model integrated.
    pub model: ModelKind,
    /// How many states were integrated.
    pub states: usize,
    /// Column names, with units; the first is the time.
    pub columns: Vec<String>,
    /// One row per recorded time: the time then the recorded quantities (empty for a run whose
    /// rows were streamed, see [`crate::run::run_streamed`]).
    pub rows: Vec<Vec<f64>>,
    /// How many rows the run recorded.
    #[serde(skip)]
    pub recorded: u64,
    /// The solver's work.
    pub stats: Stats,
    /// Why the run ended.
    pub ending: Ending,
    /// The paper's variables at the end.
    pub last: Motion,
    /// Energy at the start and at the end (J).
    pub energy: (f64, f64),
    /// Largest $|E(t) - E(0)| / |E(0)|$ over the recorded times (a drift for conservative
    /// models, the energy lost for dissipative ones).
    pub energy_change: f64,
    /// The contact's switches, flights and impacts (sliding model; empty otherwise).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub contact_events: Vec<ContactEvent>,
    /// The first recorded time at which a contact-only model's normal force is negative: from
    /// there on the table would have to pull the disk down, and the motion is not physics.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub contact_lost: Option<ContactLost>,
}

/// Where a model that keeps the rim on the table needs the table to pull: $F_z < 0$.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ContactLost {
    /// The time (s).
    pub t: f64,
    /// The normal force there (N).
    pub normal_force: f64,
}

impl std::fmt::Display for ContactLost {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "the normal force is {:.3} N at t = {:.6} s: the rim would leave the table there, \
             which this model (the rim always on the table) cannot follow, so the motion after \
             it is not physics; use model: sliding (with friction: {{ mu, restitution }}), which \
             lets the disk fly and land",
            self.normal_force, self.t
        )
    }
}
