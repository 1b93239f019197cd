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
