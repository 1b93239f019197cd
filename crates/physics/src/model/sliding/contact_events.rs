//! The physical changes of the contact in a sliding run: switches between stick, slip and
//! flight, and impacts.

use super::SlidingRun;
use serde::Serialize;

/// One change of the contact in a run: a switch between stick, slip and flight, or an impact.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ContactEvent {
    /// When (s).
    pub t: f64,
    /// Mode before: stick, slip or flight.
    pub from: &'static str,
    /// Mode after.
    pub to: &'static str,
    /// What happened (with the energy an impact took).
    pub what: String,
}

/// The physical contact changes of a run: mode changes and impacts, without the bookkeeping
/// switches of a slip's direction being held or released.
pub fn contact_events(run: &SlidingRun) -> Vec<ContactEvent> {
    run.switches
        .iter()
        .filter(|s| s.from.name() != s.to.name() || s.what.starts_with("impact"))
        .map(|s| ContactEvent {
            t: s.t,
            from: s.from.name(),
            to: s.to.name(),
            what: s.what.clone(),
        })
        .collect()
}
