//! This tool's sliding model against stored runs of an independent program, M. Batista's Euler
//! disk simulation (Fortran 90, Hairer's DOP853), under `tests/reference/peer/<scene>/`: the
//! scene, the response file `rolling-disk peer export` wrote for it, the peer's `result.txt`
//! (subsampled) and `report.txt`, and `provenance.txt` (commit, compiler, date). A subfolder
//! `eps-1e-7/` holds the same scene run by the peer with its slip regularization speed set to
//! $10^{-7}$ m/s instead of its source's $10^{-3}$ m/s (`scripts/peer_run.sh`,
//! `PEER_SLIP_REGULARIZATION`).
//!
//! Both run at rtol = atol = 1e-10; the peer prints 7 decimals, so $5\times10^{-8}$ is the finest
//! difference its records can show.

use physics::scene::Scene;
use std::path::{Path, PathBuf};
use studies::peer::compare::PeerComparison;
use studies::peer::compare_file;
use studies::peer::result::{parse, switches};

fn dir(scene: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/reference/peer")
        .join(scene)
}

/// The scene compared with its stored peer run (`variant` "" or "eps-1e-7").
fn compared(scene: &str, variant: &str) -> PeerComparison {
    let d = dir(scene);
    let s = Scene::load(d.join("scene.yaml").to_str().unwrap()).unwrap();
    let c = compare_file(&s, &d.join(variant).join("result.txt")).unwrap();
    println!("{scene} {variant}\n{c}");
    c
}

/// Where the two programs model the same thing, they agree to what the peer's records show:
/// falls on a frictionless table (thin and thick), fast slides (with and without rolling and
/// boring resistance) and a launch near the vertical that relocks, with the peer's slip
/// regularization at $10^{-7}$ m/s where a slip ends.
#[test]
fn where_both_model_the_same_they_agree_to_the_printed_digits() {
    for (scene, variant) in [
        ("thin-fall", ""),
        ("thick-fall", ""),
        ("thick-sliding-resisted", "eps-1e-7"),
        ("thick-sliding", "eps-1e-7"),
        ("thick-near-vertical", "eps-1e-7"),
    ] {
        let c = compared(scene, variant);
        assert!(c.rows >= 30, "{scene}: {} rows", c.rows);
        // Within 3 print steps of the end of the shorter record.
        assert!(
            c.until >= c.peer_end.min(c.tool_end.0) - 3e-3,
            "{scene}: {c}"
        );
        assert!(c.tilt.value < 1e-7, "{scene}: tilt {:e}", c.tilt.value);
        assert!(
            c.heading.value < 1e-7,
            "{scene}: heading {:e}",
            c.heading.value
        );
        assert!(
            c.centre.value < 1.5e-7,
            "{scene}: centre {:e}",
            c.centre.value
        );
        assert!(c.spin.value < 1e-6, "{scene}: spin {:e}", c.spin.value);
        assert_eq!(c.switch_counts.0, c.switch_counts.1, "{scene}");
    }
}

/// Tightening both tolerances does not close the gap on a fast slide while the peer regularizes
/// its friction at $\varepsilon = 10^{-3}$ m/s: the difference stays at about $1.5\times10^{-6}$
/// rad (measured: the same at rtol 1e-9, 1e-11 and 1e-13, $3\times10^{-6}$ at 1e-7). With
/// $\varepsilon = 10^{-7}$ m/s it falls to the printed digits: the plateau is the regularization's
/// $1 - \varepsilon^2/2v_s^2$ on the friction, not an error of either integrator.
#[test]
fn the_slip_regularization_is_the_plateau_of_a_fast_slide() {
    let regularized = compared("thick-sliding", "");
    let sharp = compared("thick-sliding", "eps-1e-7");
    assert!(regularized.tilt.value > 10.0 * sharp.tilt.value);
    assert!(regularized.tilt.value < 1e-5);
    let resisted = compared("thick-sliding-resisted", "");
    assert!(
        resisted.heading.value > 3.0 * compared("thick-sliding-resisted", "eps-1e-7").heading.value
    );
    for c in [compared("thin-sliding", ""), regularized, resisted] {
        assert!(
            c.tilt.value < 1e-5 && c.heading.value < 1e-5 && c.spin.value < 1e-5,
            "{c}"
        );
    }
}

/// Where a slip ends, the peer's regularized friction cannot hold the contact at rest: it creeps
/// at a slip speed between its relock threshold ($10^{-4}$ m/s) and a few $\varepsilon$, and
/// never relocks, while this tool sticks. The differences grow to $10^{-2}$ to $4\times10^{-2}$
/// rad in tilt over two seconds; with $\varepsilon = 10^{-7}$ m/s the peer relocks within a print step of this
/// tool and the differences shrink at least fivefold (measured: thin slide 40x, slip-stick 190x,
/// spin-down 5300x, roll 3300x, the last two on the clock of the peer's run).
#[test]
fn the_peers_creeping_slip_explains_the_rolling_differences() {
    for scene in [
        "thin-slide",
        "thick-slip-stick",
        "thick-roll",
        "thick-spin-down",
    ] {
        let d = dir(scene);
        let text = std::fs::read_to_string(d.join("result.txt")).unwrap();
        let rows = parse(&text, scene).unwrap();
        assert!(switches(&rows)
            .iter()
            .all(|(t, rolling)| !rolling || *t < 0.01));
        let late: Vec<f64> = rows
            .iter()
            .filter(|r| r.t > 0.4 && !r.rolling)
            .map(|r| r.slip_speed)
            .collect();
        assert!(late.len() > 10, "{scene}");
        let (lo, hi) = late
            .iter()
            .fold((f64::MAX, 0f64), |(a, b), v| (a.min(*v), b.max(*v)));
        assert!(
            lo > 1e-4 && hi < 5e-3,
            "{scene}: peer slip speed {lo:e} to {hi:e}"
        );
        let creeping = compared(scene, "");
        let sharp = compared(scene, "eps-1e-7");
        assert!(
            creeping.tilt.value > 5.0 * sharp.tilt.value,
            "{scene}: {:e} vs {:e}",
            creeping.tilt.value,
            sharp.tilt.value
        );
        assert!(creeping.tilt.value > 1e-3, "{scene}");
        if sharp.switch_counts.1 > 0 {
            assert!(
                sharp.switch_time() <= 1e-3,
                "{scene}: {}",
                sharp.switch_time()
            );
        }
    }
}

/// After a relock found at its first print step, which it does not carry out, the peer restarts
/// its clock at 0 from the state one print step on: its record holds two rows at t = 0, the second
/// with $\psi$ advanced by $\dot\psi$ times the print step (1 ms). On the clock of its run the
/// 2 s scenes that start rolling agree to a few $10^{-6}$ rad (on its printed clock, $10^{-3}$ rad).
#[test]
fn the_peers_restart_is_one_print_step_late_on_its_clock() {
    for scene in ["thick-roll", "thick-spin-down", "thick-long-spin-down"] {
        let text = std::fs::read_to_string(dir(scene).join("eps-1e-7/result.txt")).unwrap();
        let rows = parse(&text, scene).unwrap();
        assert_eq!((rows[0].t, rows[1].t), (0.0, 0.0), "{scene}");
        let s = rows[0].state;
        let psi_dot = s.omega[2] / s.theta.cos();
        let step = (rows[1].state.psi - s.psi) / psi_dot;
        assert!((step / 1e-3 - 1.0).abs() < 0.01, "{scene}: {step}");
        // The 2 s runs; the 6 s one below.
        if scene != "thick-long-spin-down" {
            let c = compared(scene, "eps-1e-7");
            assert!(c.tilt.value < 2e-5, "{scene}: {:e}", c.tilt.value);
            assert!(c.centre.value < 2e-5, "{scene}: {:e}", c.centre.value);
        }
    }
}

/// A long spin-down under rolling and boring resistance (6 s; the toy loses a quarter of its
/// energy): on the clock of the peer's run with $\varepsilon = 10^{-7}$ m/s the two agree to
/// $4\times10^{-5}$ rad in tilt over the whole run (measured $3.7\times10^{-5}$, growing with
/// time as a phase difference does); the peer's creep with its source's $\varepsilon$ leaves
/// them $0.4$ rad apart.
#[test]
fn a_long_spin_down_with_resistance_agrees_on_the_peers_clock() {
    let sharp = compared("thick-long-spin-down", "eps-1e-7");
    assert!(sharp.until >= 5.99, "{sharp}");
    assert!(sharp.tilt.value < 1e-4, "{sharp}");
    assert!(sharp.centre.value < 1e-5, "{sharp}");
    let creeping = compared("thick-long-spin-down", "");
    assert!(creeping.tilt.value > 0.1, "{creeping}");
    // This tool rolls throughout; the peer slides only in its start-up (its rows at t = 0),
    // whose mode is its assumption, not a switch.
    assert_eq!(sharp.switch_counts, (0, 0));
}

/// The stored runs the report compares (built into the tool) are every folder here.
#[test]
fn the_report_compares_every_stored_run() {
    let mut folders: Vec<String> = std::fs::read_dir(dir(""))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    folders.sort();
    let mut built: Vec<String> = studies::peer::stored::STORED
        .iter()
        .map(|s| s.name.to_string())
        .collect();
    built.sort();
    assert_eq!(folders, built);
    for s in &studies::peer::stored::STORED {
        let d = dir(s.name);
        assert_eq!(
            std::fs::read_to_string(d.join("scene.yaml")).unwrap(),
            s.scene
        );
        assert_eq!(
            std::fs::read_to_string(d.join("result.txt")).unwrap(),
            s.result
        );
        assert_eq!(
            std::fs::read_to_string(d.join("eps-1e-7/result.txt"))
                .ok()
                .as_deref(),
            s.sharp,
            "{}",
            s.name
        );
    }
}

/// The launch near the vertical (3 degrees off, outside the peer's smoothing band of 0.02 rad)
/// relocks in both; with $\varepsilon = 10^{-3}$ m/s the peer's seeded and creeping slip before
/// its relock leaves $2.7\times10^{-4}$ rad after a second.
#[test]
fn a_launch_near_the_vertical_relocks_in_both() {
    let c = compared("thick-near-vertical", "");
    assert_eq!(c.switch_counts, (1, 1));
    // The peer finds a relock at its print steps (1 ms) on a quadratic through three of them.
    assert!(c.switch_time() < 2e-3, "{}", c.switch_time());
    assert!(
        c.tilt.value < 1e-3 && c.tilt.value > 1e-5,
        "{:e}",
        c.tilt.value
    );
}

/// The stored response files are what `peer export` writes for the stored scenes today.
#[test]
fn stored_responses_are_the_exports_of_the_stored_scenes() {
    for entry in std::fs::read_dir(dir("")).unwrap() {
        let d = entry.unwrap().path();
        let scene_path = d.join("scene.yaml");
        let s = Scene::load(scene_path.to_str().unwrap()).unwrap();
        let text = studies::peer::response::response(&s).unwrap();
        let stored = std::fs::read_to_string(d.join("response.txt")).unwrap();
        // The comment names the scene's path, which depends on where it was loaded from.
        let body = |t: &str| t.lines().skip(2).collect::<Vec<_>>().join("\n");
        assert_eq!(body(&text), body(&stored), "{}", d.display());
        let prov = std::fs::read_to_string(d.join("provenance.txt")).unwrap();
        assert!(prov.contains("commit: 82427e918ee08b2a5216807f2a0ec4851b3175ed"));
    }
}

/// A scene the peer cannot run is refused with the reason and a fix.
#[test]
fn scenes_the_peer_cannot_run_are_refused_with_a_fix() {
    let d = dir("thick-roll");
    let src = std::fs::read_to_string(d.join("scene.yaml")).unwrap();
    for (from, to, words) in [
        (
            ", thickness: 0.0128, fillet: 0.002",
            ", k: 0.25",
            "add disk: { thickness: 2e-4 }",
        ),
        (", g: 9.8067", "", "set disk: { g: 9.8067 }"),
        ("sample: 0.001\n", "", "add sample"),
        ("mu: 1.0", "mu: 1.0, restitution: 0.5", "no flight"),
        (
            "model: sliding",
            "model: sliding\ndissipation: { epsilon: 1e-6, beta: 2 }",
            "no drag",
        ),
    ] {
        assert!(src.contains(from), "{from}");
        let s = Scene::parse(&src.replace(from, to), "x.yaml").unwrap();
        let e = studies::peer::response::response(&s)
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("x.yaml: ") && e.contains(words), "{e}");
    }
}

/// The accuracy both integrators reach: the fast slide run by both at rtol = atol = 1e-6, 1e-8 and
/// 1e-10 (the peer with $\varepsilon = 10^{-7}$ m/s, so that only the integrators differ). The
/// difference falls with the tolerance until it meets the peer's printed digits: this tool's
/// sampled run integrates at the tightened tolerances of its dense output, so it meets them at
/// rtol 1e-8 already, and 1e-8 and 1e-10 differ from the peer alike.
#[test]
fn tightening_both_tolerances_closes_the_gap_to_the_printed_digits() {
    let d = dir("thick-sliding");
    let mut tilt = Vec::new();
    for (scene, result) in [
        ("rtol-1e-6/scene.yaml", "rtol-1e-6/result.txt"),
        ("rtol-1e-8/scene.yaml", "rtol-1e-8/result.txt"),
        ("scene.yaml", "eps-1e-7/result.txt"),
    ] {
        let s = Scene::load(d.join(scene).to_str().unwrap()).unwrap();
        let c = compare_file(&s, &d.join(result)).unwrap();
        println!(
            "{scene}: tilt {:.3e} rad, spin {:.3e} rad/s, heading {:.3e} rad",
            c.tilt.value, c.spin.value, c.heading.value
        );
        tilt.push(c.tilt.value);
    }
    assert!(
        tilt[0] > 10.0 * tilt[1] && (tilt[1] - tilt[2]).abs() < 0.1 * tilt[2],
        "{tilt:?}"
    );
    assert!(tilt[2] < 1e-7);
}

/// `peer export` and `peer compare` on the command line: the export is the stored response,
/// the comparison prints its figures, and a file that is not the peer's is refused with its line.
#[test]
fn the_peer_commands_export_compare_and_refuse() {
    let exe = env!("CARGO_BIN_EXE_rolling-disk");
    let d = dir("thick-fall");
    let scene = d.join("scene.yaml");
    let out = std::process::Command::new(exe)
        .args(["peer", "export", scene.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    let stored = std::fs::read_to_string(d.join("response.txt")).unwrap();
    let body = |t: &str| t.lines().skip(2).collect::<Vec<_>>().join("\n");
    assert_eq!(body(&text), body(&stored));
    let out = std::process::Command::new(exe)
        .args([
            "peer",
            "compare",
            scene.to_str().unwrap(),
            d.join("result.txt").to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("tilt alpha") && text.contains("rolling/sliding changes"),
        "{text}"
    );
    let out = std::process::Command::new(exe)
        .args([
            "peer",
            "compare",
            scene.to_str().unwrap(),
            d.join("report.txt").to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(
        err.contains("report.txt:1: the first line is not the peer's header"),
        "{err}"
    );
}

/// The runs the peer relocks at a print step (ε = 1e-7 m/s), split there: before this tool's
/// slip ends and after the relock (this tool restarted from the peer's printed state) they agree
/// far closer than over the whole run, so the interval between the two relocks is what differs.
#[test]
fn a_relock_at_a_print_step_is_what_the_slip_stick_runs_differ_by() {
    let mut slip_ends = 0;
    for s in studies::peer::stored::STORED
        .iter()
        .filter(|s| s.sharp.is_some())
    {
        let file = format!("tests/reference/peer/{}/scene.yaml", s.name);
        let scene = Scene::parse(s.scene, &file).unwrap();
        let rows = parse(s.sharp.unwrap(), "eps-1e-7/result.txt").unwrap();
        let Some(split) = studies::peer::relock::split(&scene, &rows).unwrap() else {
            println!("{}: the peer never relocks", s.name);
            continue;
        };
        println!(
            "{}: peer relocks at {} s; tilt difference before the slip ends {:.2e} rad, after the relock (restarted) {:.2e} rad, whole run {:.2e} rad",
            s.name, split.relock, split.before, split.after, split.whole
        );
        // Before the slip ends, the printed digits.
        assert!(split.before < 1e-7, "{}: {split:?}", s.name);
        // After the relock, from the same state, within a few 1e-6 rad over seconds.
        assert!(split.after < 3e-6, "{}: {split:?}", s.name);
        if s.explained_by.contains("relock at a print step") {
            assert!(split.whole > 100.0 * split.after, "{}: {split:?}", s.name);
            slip_ends += 1;
        }
    }
    assert_eq!(slip_ends, 2);
}
