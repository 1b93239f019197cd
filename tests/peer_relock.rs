//! The residual after the peer's relock, traced to its source on the raw peer runs
//! (`tests/reference/peer-raw/`). Per `model2/solout.f90` and `model2/integ.f90` of the peer:
//! at a print time $t_s$ where its slip speed is below $\max(10^3\,{\rm atol}, 10^{-4})$ m/s and
//! rolling would hold, it places the relock at the least value of the parabola through its last
//! three printed slip speeds, $t^* = t_s - \Delta t + \tau$ with
//! $\tau = -p_1/(2p_2)$, $p_1 = (v_s - v_{s-2})/(2\Delta t)$, $p_2 = (v_s - 2v_{s-1} + v_{s-2})/(2\Delta t^2)$,
//! clamped to $[0, \Delta t]$ ($\tau = \Delta t$ where $p_2 \le 0$), so $t^* \le t_s$. Its DOP853
//! has then already returned the state at the end $t_e \ge t_s$ of the step that holds $t_s$; on
//! a switch to rolling its clock is set back to $t^*$ and that state kept, so every rolling row
//! labelled $L$ carries the state of $L + (t_e - t^*)$, an offset of at least $t_s - t^*$ and,
//! with a step longer than a print step, more than $\Delta t$.
//!
//! The test restarts this tool from the peer's last sliding row (the state it printed at $t_s$,
//! interpolated on its dense output, so on time), so both runs leave the slip from one state.
//! The peer's rolling rows up to its next break are then compared with this tool's run at their
//! labels and at their labels plus the offset that `studies::peer::clock` reads from the peer's
//! own angles (this tool's run plays no part in it).

use physics::dispatch::sliding_model;
use physics::scene::Scene;
use std::f64::consts::PI;
use std::path::Path;
use studies::peer::along::Along;
use studies::peer::clock::on_its_clock;
use studies::peer::compare::peer_snapshot;
use studies::peer::result::{parse, PeerRow};

/// The raw runs (folders of `tests/reference/peer-raw/`).
const RUNS: [&str; 10] = [
    "roll-start",
    "roll-start-tight",
    "thin-slide",
    "thin-slide-tight",
    "slip-stick",
    "small-resisted",
    "large-boring",
    "fall",
    "roll-then-slip",
    "slide-default",
];

fn load(name: &str) -> (Scene, Vec<PeerRow>) {
    let d = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/reference/peer-raw")
        .join(name);
    let scene = Scene::load(d.join("scene.yaml").to_str().expect("a UTF-8 path")).expect("loads");
    let text = std::fs::read_to_string(d.join("result.txt")).expect("reads");
    (scene, parse(&text, name).expect("parses"))
}

/// The relock the peer places from its last three printed slip speeds before row `s` and at it
/// (module documentation): $t^*$ on the peer's labels.
fn located_relock(rows: &[PeerRow], s: usize, dt: f64) -> f64 {
    let (v1, v2, v3) = (
        rows[s - 2].slip_speed,
        rows[s - 1].slip_speed,
        rows[s].slip_speed,
    );
    let p1 = (v3 - v1) / (2.0 * dt);
    let p2 = (v3 - 2.0 * v2 + v1) / (2.0 * dt * dt);
    let tau = if p2 > 0.0 { -p1 / (2.0 * p2) } else { dt };
    rows[s].t + tau.clamp(0.0, dt) - dt
}

/// One relock of the peer measured against this tool restarted from the row before it.
struct Relock {
    /// The last sliding row's label $t_s$ (s).
    last_sliding: f64,
    /// Its slip speed (m/s).
    slip: f64,
    /// $t_s - t^*$ (s).
    located_before: f64,
    /// The offset of the rolling rows' state from their labels, read from the peer's angles
    /// (s).
    offset: f64,
    /// Largest tilt and heading differences (rad): this tool ending the slip itself, at the
    /// rows' labels and at their labels plus the offset; and the peer's relock carried out.
    at_labels: (f64, f64),
    shifted: (f64, f64),
    as_the_peer: (f64, f64),
    /// Rolling rows compared.
    rows: usize,
}

/// The largest tilt and heading differences of `rows` against `run` read at `t - t0`.
fn differences(
    m: &physics::model::sliding::Sliding,
    run: &physics::model::sliding::SlidingRun,
    rows: &[PeerRow],
    t0: f64,
) -> (f64, f64) {
    let along = Along { model: m, run };
    let (mut tilt, mut heading) = (0.0f64, 0.0f64);
    for r in rows {
        let (y, _) = along.at(r.t - t0).expect("inside the run");
        let (mine, theirs) = (m.snapshot(&y), peer_snapshot(m, &r.state));
        tilt = tilt.max((mine.motion().alpha - theirs.motion().alpha).abs());
        let dh = (mine.heading() - theirs.heading() + PI).rem_euclid(2.0 * PI) - PI;
        heading = heading.max(dh.abs());
    }
    (tilt, heading)
}

/// Every relock of `name` inside the run: a row rolling after three sliding rows a print step
/// apart (the start's restarts at $t = 0$ are not relocks of a slip).
fn relocks(name: &str) -> Vec<Relock> {
    let (scene, rows) = load(name);
    let dt = scene.sample.expect("a print step");
    let m = sliding_model(&scene);
    let breaks = on_its_clock(&rows).1;
    let no_stops = || Vec::new();
    let run_from = |y: &physics::solve::State<14>, span: f64| {
        let run = m
            .run(y, span, &scene.settings, Some(dt / 10.0), &no_stops)
            .expect("runs");
        assert!(run.ending.is_complete(), "{name}: {}", run.ending);
        run
    };
    let mut found = Vec::new();
    for k in 3..rows.len() {
        let s = k - 1;
        let slid = (s - 2..=s).all(|j| !rows[j].rolling)
            && (s - 1..=s).all(|j| (rows[j].t - rows[j - 1].t - dt).abs() < 1e-9);
        if !(rows[k].rolling && slid) {
            continue;
        }
        let Some(b) = breaks.iter().find(|b| b.row == k) else {
            continue;
        };
        let before = breaks
            .iter()
            .rev()
            .find(|b| b.row < k)
            .map_or(0.0, |b| b.offset);
        let offset = b.offset - before;
        let t_s = rows[s].t;
        let t_star = located_relock(&rows, s, dt);
        // The rolling rows up to the peer's next break.
        let end = (k + 1..rows.len())
            .find(|&j| rows[j].t <= rows[j - 1].t || !rows[j].rolling)
            .unwrap_or(rows.len());
        let rolling = &rows[k..end];
        let span = rows[end - 1].t - t_s + 2.0 * dt;
        // This tool from the peer's last sliding row, ending the slip under its friction.
        let y_s = rows[s].state.lab_state();
        let own = run_from(&y_s, span);
        // The peer's relock carried out: slid on to the end of its step, t* + offset, where
        // its slip is dropped (the centre's velocity set to rolling's, the rotation kept),
        // then rolled on its clock from t*.
        let slid_on = run_from(&y_s, t_star + offset - t_s);
        let mut y_e = *slid_on.y.last().expect("a state");
        let contact = m.snapshot(&y_e).contact_velocity;
        for i in 0..3 {
            y_e[10 + i] -= contact[i];
        }
        let peer_way = run_from(&y_e, span);
        found.push(Relock {
            last_sliding: t_s,
            slip: rows[s].slip_speed,
            located_before: t_s - t_star,
            offset,
            at_labels: differences(&m, &own, rolling, t_s),
            shifted: differences(&m, &own, rolling, t_s - offset),
            as_the_peer: differences(&m, &peer_way, rolling, t_star),
            rows: end - k,
        });
    }
    found
}

/// On every raw run that relocks inside its run: the peer's rolling rows carry a state later
/// than their label by at least the time from its located relock to the print that found it;
/// and their difference from this tool is the slip the peer drops at its relock: this tool,
/// restarted from the peer's last sliding row, differs from them where it ends the slip under
/// friction, at their labels and at their labels plus the offset alike, and agrees with them
/// to many times less where the peer's relock is carried out on it.
#[test]
fn the_peers_relock_drops_its_slip_and_keeps_the_state_of_the_end_of_its_step() {
    let mut wrong = Vec::new();
    let mut seen = 0;
    let mut said = Vec::new();
    for name in RUNS {
        for r in relocks(name) {
            seen += 1;
            println!(
                "{name}: last sliding row {:.4} s slipping at {:.2e} m/s, located relock {:.3e} s \
                 before it, offset {:.3e} s; {} rolling rows, tilt / heading (rad): at labels \
                 {:.2e} / {:.2e}, shifted {:.2e} / {:.2e}, the peer's relock {:.2e} / {:.2e}",
                r.last_sliding,
                r.slip,
                r.located_before,
                r.offset,
                r.rows,
                r.at_labels.0,
                r.at_labels.1,
                r.shifted.0,
                r.shifted.1,
                r.as_the_peer.0,
                r.as_the_peer.1
            );
            if name == "thin-slide" {
                said.push((name, format!(
                    "(slipping at {:.2e} m/s there) by {:.2e} rad in tilt at their labels and {:.2e} rad at \
                     their labels plus the offset read from the peer's angles ({:.3e} s); with the peer's \
                     relock carried out on it (slid to the end of the step, the slip dropped, rolled \
                     from t*) by {:.2e} rad",
                    r.slip, r.at_labels.0, r.shifted.0, r.offset, r.as_the_peer.0
                )));
            }
            if name == "slip-stick" {
                said.push((name, format!(
                    "On `slip-stick` the same three are {:.2e}, {:.2e} (offset {:.3e} s) and {:.2e} rad",
                    r.at_labels.0, r.shifted.0, r.offset, r.as_the_peer.0
                )));
            }
            // The state is from the end of the step holding the print that found the relock.
            // The offset is read from angles printed to 7 decimals: a microsecond's reading.
            if r.offset < r.located_before - 1e-6 {
                wrong.push(format!(
                    "{name} at {}: offset {:e} below {:e}",
                    r.last_sliding, r.offset, r.located_before
                ));
            }
            let sum = |(a, b): (f64, f64)| a + b;
            let best_own = sum(r.at_labels).min(sum(r.shifted));
            if sum(r.as_the_peer) * 10.0 > best_own {
                wrong.push(format!(
                    "{name} at {}: the peer's relock {:?} against {:?} and {:?}",
                    r.last_sliding, r.as_the_peer, r.at_labels, r.shifted
                ));
            }
        }
    }
    assert!(seen >= 3, "only {seen} relocks in the raw runs");
    // docs/friction.md gives the figures of two of them.
    let docs =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/friction.md"))
            .expect("the docs")
            .replace('\n', " ");
    for (name, said) in said {
        assert!(
            docs.contains(&said),
            "docs/friction.md lacks, for {name}: {said}"
        );
    }
    assert!(wrong.is_empty(), "{wrong:#?}");
}
