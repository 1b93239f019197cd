//! `peer compare` on ten raw peer runs (every row the peer wrote, spaces squeezed) under
//! `tests/reference/peer-raw/<scene>/`: the scene, the response file `rolling-disk peer export`
//! wrote, the peer's `result.txt` and `report.txt`, and `provenance.txt` (commit, compiler, its
//! slip regularization, date), run by `scripts/peer_run.sh` with `PEER_SQUEEZE=1`. Thin and
//! thick disks of 10 to 100 mm, friction 0.05 to 1, static and kinetic, rolling and boring
//! resistance; starts with and without slip; rtol 1e-10 and 1e-12.
//!
//! The comparison's alignment (the peer's clock read back from its angles, `studies::peer::clock`)
//! is held against an independent one written here: the peer's rows cut into segments wherever
//! its label repeats or its mode changes, and each segment moved by the one constant time
//! shift, within two print steps, that brings the tilt and heading of its first five rows
//! closest to this tool's run (the rest of the segment then shows how the runs drift apart).

use physics::dispatch::sliding_model;
use physics::run::sliding::integrate;
use physics::scene::Scene;
use std::f64::consts::PI;
use std::path::{Path, PathBuf};
use studies::peer::along::Along;
use studies::peer::clock::{on_its_clock, trapezoid};
use studies::peer::compare::{compare, peer_snapshot, PeerComparison};
use studies::peer::result::{parse, PeerRow};

/// The ten runs: (folder, the peer's slip regularization in m/s).
const RUNS: [(&str, f64); 10] = [
    ("roll-start", 1e-3),
    ("roll-start-tight", 1e-9),
    ("thin-slide", 1e-7),
    ("thin-slide-tight", 1e-9),
    ("slip-stick", 1e-7),
    ("small-resisted", 1e-9),
    ("large-boring", 1e-7),
    ("fall", 1e-9),
    ("roll-then-slip", 1e-7),
    ("slide-default", 1e-3),
];

fn dir(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/reference/peer-raw")
        .join(name)
}

fn load(name: &str) -> (Scene, Vec<PeerRow>) {
    let d = dir(name);
    let scene = Scene::load(d.join("scene.yaml").to_str().unwrap()).unwrap();
    let text = std::fs::read_to_string(d.join("result.txt")).unwrap();
    (scene, parse(&text, name).unwrap())
}

/// The largest tilt and heading differences (rad) under the independent alignment.
fn independent(scene: &Scene, rows: &[PeerRow]) -> (f64, f64) {
    let m = sliding_model(scene);
    let dt = scene.sample.unwrap();
    let run = integrate(&m, scene, Some(dt)).unwrap();
    let along = Along {
        model: &m,
        run: &run,
    };
    // Segments: a new one where the label does not advance or the mode changes.
    let mut segments: Vec<&[PeerRow]> = Vec::new();
    let mut from = 0;
    for i in 1..=rows.len() {
        if i == rows.len() || rows[i].t <= rows[i - 1].t || rows[i].rolling != rows[i - 1].rolling {
            segments.push(&rows[from..i]);
            from = i;
        }
    }
    // The largest (tilt, heading) differences of a segment moved by `s`; None past the run.
    let moved = |seg: &[PeerRow], s: f64| -> Option<(f64, f64)> {
        let (mut tilt, mut heading) = (0.0f64, 0.0f64);
        for r in seg {
            let (y, _) = along.at(r.t + s)?;
            let (mine, theirs) = (m.snapshot(&y), peer_snapshot(&m, &r.state));
            tilt = tilt.max((mine.motion().alpha - theirs.motion().alpha).abs());
            let dh = (mine.heading() - theirs.heading() + PI).rem_euclid(2.0 * PI) - PI;
            heading = heading.max(dh.abs());
        }
        Some((tilt, heading))
    };
    let (mut tilt, mut heading) = (0.0f64, 0.0f64);
    for seg in segments {
        let head = &seg[..seg.len().min(5)];
        let score = |s: f64| moved(head, s).map(|(a, h)| a + h);
        // A coarse scan over two print steps either way, then a fine one round its best.
        let best_in = |lo: f64, hi: f64, n: usize| {
            (0..=n)
                .map(|k| lo + (hi - lo) * k as f64 / n as f64)
                .filter_map(|s| score(s).map(|v| (s, v)))
                .min_by(|a, b| a.1.total_cmp(&b.1))
        };
        let lo = if seg[0].t == 0.0 { 0.0 } else { -2.0 * dt };
        let Some((coarse, _)) = best_in(lo, 2.0 * dt, 80) else {
            continue;
        };
        let step = 4.0 * dt / 80.0;
        let (s, _) = best_in((coarse - step).max(lo), coarse + step, 100).unwrap();
        let (a, h) = moved(seg, s).unwrap();
        tilt = tilt.max(a);
        heading = heading.max(h);
    }
    (tilt, heading)
}

/// The peer's printed digits in tilt: 7 decimals, so differences below about 1e-7 rad are its
/// rounding.
const PRINTED_TILT: f64 = 1e-7;
/// The same in heading, which turns at up to 35 rad/s in these runs: the peer's clock, read back
/// from its angles at each break, is uncertain by their rounding over their rates (about
/// 1e-7 / 20 rad/s = 5e-9 s a break, 2e-7 rad of heading over the two breaks of a start-up
/// relock at 10-35 rad/s), so differences below 3e-7 rad are its rounding.
const PRINTED_HEADING: f64 = 3e-7;

/// Within a factor 2 of the independent alignment's difference, or both at the printed digits.
fn within_twice(reported: f64, independent: f64, printed: f64) -> bool {
    let (a, b) = (reported.max(printed), independent.max(printed));
    a <= 2.0 * b && b <= 2.0 * a
}

fn compared(name: &str) -> (PeerComparison, (f64, f64)) {
    let (scene, rows) = load(name);
    let c = compare(&scene, &rows).unwrap();
    let ind = independent(&scene, &rows);
    println!(
        "{name}: independent tilt {:.3e}, heading {:.3e}\n{c}",
        ind.0, ind.1
    );
    (c, ind)
}

/// Every raw run: the reported tilt and heading differences are within 2x of the independent
/// alignment's, and every mode change is paired, or, where one run switches and the other does
/// not (the peer creeping where this tool relocks), the comparison reports the rows whose modes
/// differ from that switch on.
#[test]
fn raw_runs_are_aligned_and_every_mode_change_paired() {
    let mut wrong = Vec::new();
    for (name, _) in RUNS {
        let (c, (tilt, heading)) = compared(name);
        if c.rows < 290 {
            wrong.push(format!("{name}: {} rows", c.rows));
        }
        let aligned = within_twice(c.tilt.value, tilt, PRINTED_TILT)
            && within_twice(c.heading.value, heading, PRINTED_HEADING);
        if !aligned {
            wrong.push(format!(
                "{name}: tilt {:e} vs {tilt:e}, heading {:e} vs {heading:e}",
                c.tilt.value, c.heading.value
            ));
        }
        let dt = 1e-3;
        let unpaired = c
            .pairing
            .tool_only
            .iter()
            .map(|(_, t)| *t)
            .chain(c.pairing.peer_only.iter().map(|p| p.within.1));
        for t in unpaired {
            let reported = c.modes.rows > 0 && (c.modes.between.0 - t).abs() <= 2.0 * dt;
            if !reported && !c.modes.whole_run() {
                wrong.push(format!(
                    "{name}: the switch at {t} s unpaired and not reported"
                ));
            }
        }
    }
    assert!(wrong.is_empty(), "{wrong:#?}");
}

/// The numbers after `key` on the lines of the peer's `report.txt` that hold it.
fn reported(report: &str, key: &str) -> Vec<f64> {
    report
        .lines()
        .filter_map(|l| l.split_once(key))
        .filter_map(|(_, rest)| rest.split_whitespace().next()?.parse().ok())
        .collect()
}

/// `small-resisted`'s start-up, as the peer's own report tells it: it restarted sliding from
/// the start with its clock set back a print step ("change mode at -0.001"), so its row
/// labelled 0 after the restart carries the state one print step on; it relocked there
/// ("change mode at 0.000") and kept the state at the end of the step its DOP853 stopped at
/// (`EXIT OF DOP853 AT X=`, on the clock set back), so from its row labelled 1 ms on its state
/// is that much more later than its label. The clock read from the peer's angles holds both
/// within 1e-8 s; the trapezoid over the two print steps misreads the second by more than 5e-8 s
/// (the 10 mm disk nutates fast), which is what the comparison used to show.
#[test]
fn small_resisted_start_up_is_read_as_the_peers_report_says() {
    let d = dir("small-resisted");
    let report = std::fs::read_to_string(d.join("report.txt")).unwrap();
    let changes = reported(&report, "change mode at");
    let stops = reported(&report, "EXIT OF DOP853 AT X=");
    assert_eq!(changes, [0.0, -0.001, 0.0], "{report}");
    assert_eq!(stops.len(), 3, "{report}");
    let set_back = -changes[1];
    let kept = set_back + stops[2] - changes[2];
    let (_, rows) = load("small-resisted");
    let breaks = on_its_clock(&rows).1;
    let offset = |row: usize| {
        breaks
            .iter()
            .find(|b| b.row == row)
            .map(|b| b.offset)
            .unwrap()
    };
    println!(
        "small-resisted: offsets read {:.6e}, {:.6e} s; the report's {set_back:.6e}, {kept:.6e} s",
        offset(2),
        offset(3)
    );
    assert!((offset(2) - set_back).abs() < 1e-8, "{breaks:?}");
    assert!((offset(3) - kept).abs() < 1e-8, "{breaks:?}");
    let by_trapezoid =
        trapezoid(&rows[1], &rows[2]).unwrap() + trapezoid(&rows[2], &rows[3]).unwrap() - rows[3].t;
    println!("small-resisted: by the trapezoid {by_trapezoid:.6e} s");
    assert!((by_trapezoid - kept).abs() > 5e-8, "{by_trapezoid:e}");
    let docs =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/friction.md"))
            .unwrap()
            .replace('\n', " ");
    let said = format!("{:.3e} s past its print time", stops[2]);
    assert!(docs.contains(&said), "docs/friction.md lacks: {said}");
}
