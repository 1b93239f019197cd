//! Hostile inputs of issue 48's second round, each through the binary: a scene argument that
//! is not UTF-8 is refused naming the argument, and the name fixed as the message says runs;
//! `peer export` warns where the peer's fixed floors shape its run, and only there. None may
//! take over 2 s.

use super::sandbox::cli_timed;
use crate::common::temp_dir;
use std::ffi::OsString;
use std::os::unix::ffi::OsStringExt;
use std::process::Command;
use std::time::{Duration, Instant};

const QUICK: Duration = Duration::from_secs(2);

#[test]
fn a_scene_argument_not_utf8_is_refused_naming_it_and_the_fix_works() {
    let dir = temp_dir("hostile2", "utf8");
    let scene = include_str!("../reference/peer-raw/fall/scene.yaml");
    let bad = OsString::from_vec(b"sc\xffene.yaml".to_vec());
    std::fs::write(dir.join(&bad), scene).unwrap();
    for (command, argument) in [
        (&["simulate"][..], "<SCENE>"),
        (&["peer", "export"], "<SCENE>"),
        (&["precision"], "[SCENE]"),
    ] {
        let start = Instant::now();
        let out = Command::new(env!("CARGO_BIN_EXE_rolling-disk"))
            .args(command)
            .arg(&bad)
            .current_dir(&dir)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{command:?}: {err}");
        assert!(start.elapsed() < QUICK, "{command:?}");
        assert!(
            err.contains(argument) && err.contains("not valid UTF-8") && err.contains("rename"),
            "{command:?}: {err}"
        );
    }
    // The fix: renamed with UTF-8 characters, it runs.
    std::fs::rename(dir.join(&bad), dir.join("scene.yaml")).unwrap();
    let (ok, _, err, took) = cli_timed(&dir, &["simulate", "scene.yaml"]);
    assert!(ok && took < QUICK, "{err}");
}

/// A no-slip start exported for the peer is warned about its seed slip and its creep; a fast
/// slide with a sharp end is not warned about a creep; a scene that spins down below the peer's
/// energy stop is warned where.
#[test]
fn peer_export_warns_where_the_peers_floors_shape_its_run() {
    let dir = temp_dir("hostile2", "floors");
    let raw = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/reference/peer-raw");
    let (ok, _, err, took) = cli_timed(
        &dir,
        &[
            "peer",
            "export",
            &format!("{raw}/roll-start/scene.yaml"),
            "--out",
            "r.txt",
        ],
    );
    assert!(ok, "{err} ({took:?})");
    assert!(err.contains("seed slip of 5e-3 m/s"), "{err}");
    assert!(err.contains("creeps there instead of rolling"), "{err}");
    assert!(!err.contains("energy"), "{err}");
    let (ok, _, err, _) = cli_timed(
        &dir,
        &[
            "peer",
            "export",
            &format!("{raw}/large-boring/scene.yaml"),
            "--out",
            "b.txt",
        ],
    );
    assert!(ok, "{err}");
    assert!(
        !err.contains("seed slip") && !err.contains("creeps"),
        "{err}"
    );
    // A small, slow disk: its energy above lying flat is below the peer's stop at once.
    let small = "name: small\nmodel: sliding\n\
        disk: { radius: 0.01, mass: 0.01, thickness: 0.004, fillet: 0.001, g: 9.8067 }\n\
        friction: { mu: 0.5 }\n\
        start: { explicit: { alpha: 0.3, alpha_dot: 0.0, precession: 1.0, spin: 1.0 } }\n\
        stop: { time: 0.05 }\nsample: 0.001\n";
    std::fs::write(dir.join("small.yaml"), small).unwrap();
    let (ok, _, err, _) = cli_timed(&dir, &["peer", "export", "small.yaml", "--out", "s.txt"]);
    assert!(ok, "{err}");
    assert!(
        err.contains("energy above lying flat falls to 3e-4 J"),
        "{err}"
    );
}

/// A numeric option given a negative, zero or huge value is refused by its own range, naming
/// the option, the value in the user's digits and the range; never with clap's "unexpected
/// argument" and its tip `-- -1`, which would not run. The range's end, given instead, runs.
#[test]
fn numeric_options_out_of_range_name_the_option_and_the_range_and_its_end_runs() {
    let dir = temp_dir("hostile2", "ranges");
    let simulate = ["experiment", "simulate", "spin-down", "--csv", "out.csv"];
    // (the option, a value outside, what the message says, a value inside)
    let cases: [(&str, &str, &str, &str); 8] = [
        ("--max-seconds", "-1", "above 0, at most 86400", "86400"),
        ("--max-seconds", "1e300", "1e300 is outside", "86400"),
        ("--drift", "-0.1", "from 0 to 1", "0"),
        ("--clip", "-1", "above 0, at most 1", "1"),
        ("--glitches", "1e300", "1e300 is outside", "1000"),
        ("--dropped", "-0.1", "from 0 to below 0.5", "0"),
        ("--mains", "-50", "from 10 to 1000", "10"),
        ("--rate", "-5", "1000..=384000", "1000"),
    ];
    for (option, outside, says, inside) in cases {
        let mut args: Vec<&str> = simulate.to_vec();
        args.extend([option, outside]);
        let (ok, _, err, took) = cli_timed(&dir, &args);
        assert!(!ok && took < QUICK, "{option} {outside}: {err}");
        assert!(
            err.contains(option) && err.contains(says) && !err.contains("unexpected argument"),
            "{option} {outside}: {err}"
        );
        assert!(!dir.join("out.csv").exists(), "{option} {outside} wrote");
        let fixed: Vec<&str> = args[..args.len() - 1]
            .iter()
            .copied()
            .chain([inside, "--seed", "2"])
            .collect();
        let (ok, _, err, _) = cli_timed(&dir, &fixed);
        assert!(ok, "{option} {inside}: {err}");
        std::fs::remove_file(dir.join("out.csv")).unwrap();
    }
    // A negative seed and target name their option too.
    for args in [
        &[
            "experiment",
            "simulate",
            "spin-down",
            "--csv",
            "s.csv",
            "--seed",
            "-1",
        ][..],
        &["precision", "--quick", "--target", "-1"],
    ] {
        let (ok, _, err, took) = cli_timed(&dir, args);
        let option = args[args.len() - 2];
        assert!(!ok && took < QUICK, "{args:?}: {err}");
        assert!(
            err.contains(option) && !err.contains("unexpected argument"),
            "{args:?}: {err}"
        );
    }
}
