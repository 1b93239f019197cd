//! A peer run against this tool's run of the same scene, row by row on the clock of the peer's
//! motion ([`super::clock`]): the largest differences of the tilt $\alpha$, the spin
//! $\boldsymbol\omega\cdot\hat{\mathbf 1}$, the heading of $\hat{\mathbf 2}$, the centre on the
//! table, the normal and friction forces over the weight, the slip speed and the energy; the
//! rows whose modes differ; and the changes between rolling and sliding paired by direction
//! and time ([`super::pairing`]).
//!
//! This tool's run is read at each row's time ([`super::along`]). The peer's start-up, the rows
//! printed at $t = 0$, is compared in its state only: its mode there is an assumption
//! (sliding, whose regularized friction vanishes at the start's zero slip) and its slip the
//! seed it adds, not a finding, so its modes, slip, forces and energy are compared from its
//! first row labelled after $t = 0$ on, and its mode changes counted from there.

use super::along::Along;
use super::clock::{on_its_clock, Break};
use super::mapping::PeerState;
use super::pairing::{pair, Pairing, PeerSwitch};
use super::result::PeerRow;
use super::PeerError;
use physics::dispatch::sliding_model;
use physics::model::lab_frame::Snapshot;
use physics::model::sliding::contact_events::contact_events;
use physics::model::sliding::{Flow, Mode, Sliding};
use physics::run::sliding::integrate;
use physics::scene::Scene;
use serde::Serialize;
use std::f64::consts::PI;

/// The largest difference of one quantity and when it happens.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Largest {
    /// $\max|x_{\rm tool} - x_{\rm peer}|$.
    pub value: f64,
    /// When (s).
    pub at: f64,
}

impl Largest {
    const NONE: Largest = Largest {
        value: 0.0,
        at: 0.0,
    };

    fn see(&mut self, d: f64, t: f64) {
        if d > self.value {
            *self = Largest { value: d, at: t };
        }
    }
}

/// The rows whose modes differ (from the peer's first row after $t = 0$ on).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ModesDiffer {
    /// Rows whose modes differ, of `of`.
    pub rows: usize,
    /// Rows whose modes were compared.
    pub of: usize,
    /// The first and last time they differ (s).
    pub between: (f64, f64),
    /// Rows where the peer slides while this tool rolls, and its largest slip speed there (m/s).
    pub peer_creeps: (usize, f64),
}

impl ModesDiffer {
    /// True when the modes differ in every row compared: the runs are in different modes
    /// throughout, whatever their switch counts say.
    pub fn whole_run(&self) -> bool {
        self.of > 0 && self.rows == self.of
    }
}

/// How a peer run and this tool's run of a scene differ.
#[derive(Debug, Clone, Serialize)]
pub struct PeerComparison {
    /// Rows compared (those whose time this tool's run reaches).
    pub rows: usize,
    /// The last time compared (s).
    pub until: f64,
    /// Where the peer's record ends, on the clock of its motion (s).
    pub peer_end: f64,
    /// Where this tool's run ends (s), and why.
    pub tool_end: (f64, String),
    /// Tilt $\alpha$ (rad).
    pub tilt: Largest,
    /// Spin about the symmetry axis (rad/s).
    pub spin: Largest,
    /// Heading of $\hat{\mathbf 2}$ (rad).
    pub heading: Largest,
    /// Centre on the table (m).
    pub centre: Largest,
    /// Normal force over the weight, $F_z/mg$.
    pub normal: Largest,
    /// Friction force over the weight, $|\mathbf F_t|/mg$.
    pub friction: Largest,
    /// Slip speed of the contact point (m/s).
    pub slip: Largest,
    /// Energy $\frac12 m|\mathbf v|^2 + \frac12\boldsymbol\omega\cdot I\boldsymbol\omega + mgz$ (J).
    pub energy: Largest,
    /// The rows whose modes differ.
    pub modes: ModesDiffer,
    /// The breaks of the peer's clock ([`super::clock`]).
    pub clock: Vec<Break>,
    /// The switches paired by direction and time.
    pub pairing: Pairing,
    /// The paired switches as (peer, tool) times (s): the peer's the end of its interval.
    pub switches: Vec<(f64, f64)>,
    /// Switch counts: (peer, tool) before the end of the comparison.
    pub switch_counts: (usize, usize),
    /// At each compared row: $(t, \alpha_{\rm tool}, \alpha_{\rm peer})$ (s, rad).
    #[serde(skip)]
    pub tilts: Vec<[f64; 3]>,
}

impl PeerComparison {
    /// The largest difference of the paired (peer, tool) times of [`PeerComparison::switches`]
    /// (s), 0 without a pair; how far they lie outside the peer's intervals is
    /// [`Pairing::largest_outside`].
    pub fn switch_time(&self) -> f64 {
        self.switches
            .iter()
            .map(|(p, t)| (p - t).abs())
            .fold(0.0, f64::max)
    }
}

/// The geometry of a peer state as this tool reads it.
pub fn peer_snapshot(model: &Sliding, p: &PeerState) -> Snapshot {
    model.snapshot(&p.lab_state())
}

/// Runs `scene` in the sliding model, sampled at the peer's print step, and compares it with
/// the peer's `rows` (from [`super::result::parse`]) on the clock of the peer's motion.
pub fn compare(scene: &Scene, rows: &[PeerRow]) -> Result<PeerComparison, PeerError> {
    let m = sliding_model(scene);
    same_start(&m, scene, rows)?;
    let dt = scene
        .sample
        .unwrap_or(rows.get(1).map_or(1e-3, |r| r.t - rows[0].t));
    // The start-up: every row printed at t = 0.
    let start_up = rows.iter().take_while(|r| r.t == 0.0).count().max(1);
    let (rows, clock) = on_its_clock(rows);
    let run = integrate(&m, scene, Some(dt)).map_err(PeerError::Settings)?;
    let along = Along {
        model: &m,
        run: &run,
    };
    let tool_end = *run.t.last().unwrap_or(&0.0);
    let weight = m.disk.m * m.disk.g;
    let mut out = PeerComparison {
        rows: 0,
        until: 0.0,
        peer_end: rows.last().map_or(0.0, |r| r.t),
        tool_end: (tool_end, run.ending.to_string()),
        tilt: Largest::NONE,
        spin: Largest::NONE,
        heading: Largest::NONE,
        centre: Largest::NONE,
        normal: Largest::NONE,
        friction: Largest::NONE,
        slip: Largest::NONE,
        energy: Largest::NONE,
        modes: ModesDiffer {
            rows: 0,
            of: 0,
            between: (0.0, 0.0),
            peer_creeps: (0, 0.0),
        },
        clock,
        pairing: Pairing::default(),
        switches: Vec::new(),
        switch_counts: (0, 0),
        tilts: Vec::new(),
    };
    for (i, r) in rows.iter().enumerate() {
        let Some((y, mode)) = along.at(r.t) else {
            break;
        };
        let mine = m.snapshot(&y);
        let theirs = peer_snapshot(&m, &r.state);
        let (a, b) = (mine.motion(), theirs.motion());
        out.tilt.see((a.alpha - b.alpha).abs(), r.t);
        out.spin.see((a.spin - b.spin).abs(), r.t);
        let dh = (mine.heading() - theirs.heading() + PI).rem_euclid(2.0 * PI) - PI;
        out.heading.see(dh.abs(), r.t);
        out.centre
            .see((mine.centre - theirs.centre).xy().norm(), r.t);
        out.tilts.push([r.t, a.alpha, b.alpha]);
        out.rows += 1;
        out.until = r.t;
        if i < start_up {
            continue;
        }
        let f = Flow { model: &m, mode }.force(&y);
        out.normal.see((f.z / weight - r.normal).abs(), r.t);
        out.friction
            .see((f.xy().norm() / weight - r.tangential).abs(), r.t);
        let slip = mine.contact_velocity.xy().norm();
        out.slip.see((slip - r.slip_speed).abs(), r.t);
        let e = (m.energy(&y) - m.energy(&r.state.lab_state())).abs();
        out.energy.see(e, r.t);
        see_modes(&mut out.modes, matches!(mode, Mode::Stick), r);
    }
    let peer = peer_switches(&rows[start_up.min(rows.len())..], dt, out.until);
    let tool: Vec<(bool, f64)> = contact_events(&run)
        .into_iter()
        .filter(|e| e.from != "flight" && e.to != "flight" && e.from != e.to && e.t <= out.until)
        .map(|e| (e.to == "stick", e.t))
        .collect();
    out.switch_counts = (peer.len(), tool.len());
    out.pairing = pair(&peer, &tool, dt);
    out.switches = out
        .pairing
        .paired
        .iter()
        .map(|p| (p.peer.within.1, p.tool))
        .collect();
    Ok(out)
}

/// Counts a row whose modes differ: `rolling` this tool's.
fn see_modes(d: &mut ModesDiffer, rolling: bool, r: &PeerRow) {
    d.of += 1;
    if rolling == r.rolling {
        return;
    }
    if d.rows == 0 {
        d.between.0 = r.t;
    }
    d.rows += 1;
    d.between.1 = r.t;
    if rolling {
        d.peer_creeps.0 += 1;
        d.peer_creeps.1 = d.peer_creeps.1.max(r.slip_speed);
    }
}

/// The peer's mode changes in `rows` (after its start-up) up to `until`, each with the
/// interval its located switch lies in ([`super::pairing`]).
fn peer_switches(rows: &[PeerRow], dt: f64, until: f64) -> Vec<PeerSwitch> {
    rows.windows(2)
        .filter(|w| w[0].rolling != w[1].rolling && w[1].t <= until)
        .map(|w| {
            let end = if w[1].rolling { w[0].t } else { w[1].t };
            PeerSwitch {
                to_rolling: w[1].rolling,
                within: (end - dt, end),
            }
        })
        .collect()
}

/// Refuses a record that does not start where the scene starts: its first row's centre height,
/// tilt, spin and precession must be the scene's to the peer's printed digits (with room for
/// their rounding).
fn same_start(m: &Sliding, scene: &Scene, rows: &[PeerRow]) -> Result<(), PeerError> {
    let Some(first) = rows.first() else {
        return Ok(());
    };
    let (sa, sb) = (
        m.snapshot(&m.start_state(&scene.start)),
        peer_snapshot(m, &first.state),
    );
    let (a, b) = (sa.motion(), sb.motion());
    let off = [
        ("the centre's height", sa.centre.z - sb.centre.z),
        ("tilt", a.alpha - b.alpha),
        ("spin", a.spin - b.spin),
        ("precession", a.precession - b.precession),
    ];
    for (what, d) in off {
        if d.abs() > 1e-6 * (1.0 + a.spin.abs() + a.precession.abs()) || first.t != 0.0 {
            return Err(PeerError::Scene(
                scene.source.clone(),
                format!(
                    "the peer's record does not start where this scene starts ({what} differs by \
                     {d:.3e} at t = {}): run the peer on this scene's `peer export`",
                    first.t
                ),
            ));
        }
    }
    Ok(())
}
