//! A peer run against this tool's run of the same scene: the largest differences over the
//! common print times of the tilt $\alpha$, the spin $\boldsymbol\omega\cdot\hat{\mathbf 1}$, the
//! heading of $\hat{\mathbf 2}$ and the centre on the table, and the times of the changes
//! between rolling and sliding, paired in order.

use super::mapping::PeerState;
use super::result::{retimed, switches, PeerRow};
use super::PeerError;
use physics::dispatch::sliding_model;
use physics::model::lab_frame::Snapshot;
use physics::model::sliding::contact_events::contact_events;
use physics::model::sliding::Sliding;
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
    fn see(&mut self, d: f64, t: f64) {
        if d > self.value {
            *self = Largest { value: d, at: t };
        }
    }
}

/// How a peer run and this tool's run of a scene differ.
#[derive(Debug, Clone, Serialize)]
pub struct PeerComparison {
    /// Print times compared (those both runs reach).
    pub rows: usize,
    /// The last time compared (s).
    pub until: f64,
    /// Where the peer's record ends (s).
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
    /// The changes between rolling and sliding, (peer, tool) times paired in order (s).
    pub switches: Vec<(f64, f64)>,
    /// Switch counts: (peer, tool) before the end of the comparison.
    pub switch_counts: (usize, usize),
    /// At each compared print time: $(t, \alpha_{\rm tool}, \alpha_{\rm peer})$ (s, rad).
    #[serde(skip)]
    pub tilts: Vec<[f64; 3]>,
}

impl PeerComparison {
    /// The largest difference of the paired switch times (s), 0 without switches.
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
/// the peer's `rows` (from [`super::result::parse`]), on the clock of its run
/// ([`super::result::retimed`]).
pub fn compare(scene: &Scene, rows: &[PeerRow]) -> Result<PeerComparison, PeerError> {
    let m = sliding_model(scene);
    same_start(&m, scene, rows)?;
    let dt = scene
        .sample
        .unwrap_or(rows.get(1).map_or(1e-3, |r| r.t - rows[0].t));
    let rows = &retimed(rows, dt)[..];
    let run = integrate(&m, scene, Some(dt)).map_err(PeerError::Settings)?;
    let tool_end = *run.t.last().unwrap_or(&0.0);
    let peer_end = rows.last().map_or(0.0, |r| r.t);
    let mut out = PeerComparison {
        rows: 0,
        until: 0.0,
        peer_end,
        tool_end: (tool_end, run.ending.to_string()),
        tilt: Largest {
            value: 0.0,
            at: 0.0,
        },
        spin: Largest {
            value: 0.0,
            at: 0.0,
        },
        heading: Largest {
            value: 0.0,
            at: 0.0,
        },
        centre: Largest {
            value: 0.0,
            at: 0.0,
        },
        switches: Vec::new(),
        switch_counts: (0, 0),
        tilts: Vec::new(),
    };
    // The peer prints times with 7 decimals.
    let tol = 1e-6;
    let mut j = 0;
    for r in rows {
        while j < run.t.len() && run.t[j] < r.t - tol {
            j += 1;
        }
        if j == run.t.len() {
            break;
        }
        if (run.t[j] - r.t).abs() > tol {
            continue;
        }
        let mine = m.snapshot(&run.y[j]);
        let theirs = peer_snapshot(&m, &r.state);
        let (a, b) = (mine.motion(), theirs.motion());
        out.tilt.see((a.alpha - b.alpha).abs(), r.t);
        out.spin.see((a.spin - b.spin).abs(), r.t);
        let dh = (mine.heading() - theirs.heading() + PI).rem_euclid(2.0 * PI) - PI;
        out.heading.see(dh.abs(), r.t);
        let dc = (mine.centre - theirs.centre).xy().norm();
        out.centre.see(dc, r.t);
        out.tilts.push([r.t, a.alpha, b.alpha]);
        out.rows += 1;
        out.until = r.t;
    }
    let peer: Vec<f64> = switches(rows)
        .into_iter()
        .map(|(t, _)| t)
        .filter(|t| *t <= out.until)
        .collect();
    let tool: Vec<f64> = contact_events(&run)
        .into_iter()
        .filter(|e| e.from != "flight" && e.to != "flight" && e.from != e.to && e.t <= out.until)
        .map(|e| e.t)
        .collect();
    out.switch_counts = (peer.len(), tool.len());
    out.switches = peer.iter().copied().zip(tool.iter().copied()).collect();
    Ok(out)
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

impl std::fmt::Display for PeerComparison {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        writeln!(
            f,
            "compared {} print times up to t = {:.6} s (peer record ends at {:.6} s; this tool's run at {:.6} s: {})",
            self.rows, self.until, self.peer_end, self.tool_end.0, self.tool_end.1
        )?;
        writeln!(f, "largest differences (this tool - peer):")?;
        for (name, l, unit) in [
            ("tilt alpha", self.tilt, "rad"),
            ("spin", self.spin, "rad/s"),
            ("heading", self.heading, "rad"),
            ("centre", self.centre, "m"),
        ] {
            writeln!(
                f,
                "  {name:<11} {:.3e} {unit:<5} at t = {:.6} s",
                l.value, l.at
            )?;
        }
        writeln!(
            f,
            "  rolling/sliding changes: {} in the peer, {} here; largest paired time difference {:.3e} s",
            self.switch_counts.0,
            self.switch_counts.1,
            self.switch_time()
        )?;
        for (p, t) in &self.switches {
            writeln!(f, "    peer {p:.6} s, here {t:.6} s")?;
        }
        Ok(())
    }
}
