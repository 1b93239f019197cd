//! What a relock at a print step leaves: a peer run whose slip ends is split at the peer's
//! relock, the first row it prints rolling again. Before it, the two runs are compared as they
//! are; after it, this tool is restarted from the peer's own printed state there
//! ([`super::mapping::PeerState::lab_state`]) and compared with the peer's later rows. A
//! difference that is small on both sides, and large over the whole run, comes from the
//! interval between the slip's end in this tool and the peer's relock, not from either
//! program's motion before or after it.

use super::clock::on_its_clock;
use super::compare::{compare, peer_snapshot};
use super::result::{switches, PeerRow};
use super::PeerError;
use physics::dispatch::sliding_model;
use physics::scene::Scene;
use serde::{Deserialize, Serialize};

/// The run split at the peer's first relock.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
pub struct RelockSplit {
    /// The peer's relock: its first row rolling after sliding (s).
    pub relock: f64,
    /// Largest $|\Delta\alpha|$ over the print times before this tool's slip ends (rad).
    pub before: f64,
    /// Largest $|\Delta\alpha|$ after the relock, this tool restarted from the peer's state
    /// there (rad).
    pub after: f64,
    /// Largest $|\Delta\alpha|$ over the whole run, compared as it is (rad).
    pub whole: f64,
}

/// The split of `rows` (a peer record of `scene`), or `None` when the peer never relocks.
pub fn split(scene: &Scene, raw: &[PeerRow]) -> Result<Option<RelockSplit>, PeerError> {
    let dt = scene.sample.unwrap_or(1e-3);
    let rows = on_its_clock(raw).0;
    let Some(&(relock, _)) = switches(&rows).iter().find(|(_, rolling)| *rolling) else {
        return Ok(None);
    };
    let whole = compare(scene, raw)?;
    let slip_end = whole
        .switches
        .first()
        .map_or(relock, |&(_, tool)| tool.min(relock));
    let before = whole
        .tilts
        .iter()
        .filter(|r| r[0] < slip_end)
        .map(|r| (r[1] - r[2]).abs())
        .fold(0.0, f64::max);
    let m = sliding_model(scene);
    let start = rows
        .iter()
        .position(|r| r.t == relock)
        .ok_or_else(|| PeerError::Scene(scene.source.clone(), "no row at the relock".into()))?;
    let y0 = rows[start].state.lab_state();
    let rest = &rows[start..];
    let span = rest.last().map_or(0.0, |r| r.t) - relock;
    let no_stops = || Vec::new();
    let run = m
        .run(&y0, span, &scene.settings, Some(dt), &no_stops)
        .map_err(PeerError::Settings)?;
    if !run.ending.is_complete() {
        return Err(PeerError::Scene(
            scene.source.clone(),
            format!(
                "the run restarted at the peer's relock ended early: {}",
                run.ending
            ),
        ));
    }
    let mut after: f64 = 0.0;
    let mut j = 0;
    for r in rest {
        let t = r.t - relock;
        while j < run.t.len() && run.t[j] < t - 1e-6 {
            j += 1;
        }
        if j == run.t.len() {
            break;
        }
        if (run.t[j] - t).abs() > 1e-6 {
            continue;
        }
        let mine = m.snapshot(&run.y[j]).motion().alpha;
        let theirs = peer_snapshot(&m, &r.state).motion().alpha;
        after = after.max((mine - theirs).abs());
    }
    Ok(Some(RelockSplit {
        relock,
        before,
        after,
        whole: whole.tilt.value,
    }))
}
