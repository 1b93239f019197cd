//! `peer export` of the built-in scenes (issue 50 item 6). A built-in sliding scene is mapped to
//! what the peer runs, its gravity (9.8067 m/s² against the scenes' 9.81) and a nominal thickness
//! of 2e-4 m for the thin disk (`studies::peer::builtin`), and each change is said on standard
//! error and in the response file; a scene the peer cannot run is refused with why. The mapping's
//! effect on the comparison is measured here by running this tool on the scene and on its mapped
//! form, and on the slip-stick scene against the peer's own run of the mapped scene
//! (`tests/reference/peer-builtin/slip-stick/`, made by `scripts/peer_run.sh`).

use crate::common::{cli_timed, temp_dir};
use physics::dispatch::sliding_model;
use physics::run::sliding::integrate;
use physics::scene::builtin::BUILTIN;
use physics::scene::Scene;
use std::path::Path;
use studies::peer::along::Along;
use studies::peer::builtin::for_peer;

#[test]
fn every_built_in_scene_is_exported_mapped_or_refused_with_why() {
    let dir = temp_dir("peer-builtin", "export");
    let mut exported = Vec::new();
    for (name, _) in BUILTIN {
        let out = format!("{name}.txt");
        let (ok, _, err, took) = cli_timed(&dir, &["peer", "export", name, "--out", &out]);
        assert!(!err.contains("panicked"), "{name}: {err}");
        assert!(took.as_secs_f64() < 2.0, "{name}: {took:?}");
        if ok {
            let text = std::fs::read_to_string(dir.join(&out)).expect("written");
            for said in [&err, &text] {
                assert!(
                    said.contains("mapped for the peer: g 9.81 -> 9.8067")
                        && said.contains("nominal thickness of 0.0002 m"),
                    "{name}: {said}"
                );
            }
            exported.push(*name);
        } else {
            assert!(err.starts_with(&format!("error: builtin:{name}")), "{err}");
            assert!(!dir.join(&out).exists(), "{name}: a refusal wrote {out}");
        }
    }
    println!("exported for the peer: {exported:?}");
    assert!(exported.contains(&"slip-stick"), "{exported:?}");
}

#[test]
fn the_mapping_changes_only_gravity_and_thickness_and_its_effect_is_measured() {
    let scene = Scene::load("slip-stick").expect("built in");
    let (mapped, notes) = for_peer(&scene).expect("mapped");
    assert_eq!(notes.len(), 2, "{notes:?}");
    assert_eq!(mapped.disk.g, studies::peer::response::PEER_G);
    assert_eq!(mapped.toy.solid.map(|s| s.thickness), Some(2e-4));
    assert_eq!(
        (
            mapped.disk.a,
            mapped.disk.m,
            mapped.stop.time,
            mapped.sample
        ),
        (scene.disk.a, scene.disk.m, scene.stop.time, scene.sample)
    );
    // A scene from a file is never mapped.
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("paper/scenes/slip-stick.yaml");
    let own = Scene::load(file.to_str().expect("utf-8")).expect("reads");
    assert!(for_peer(&own).expect("as it is").1.is_empty());
    // The effect: this tool on both, compared at every print step over the first second.
    let (m0, m1) = (sliding_model(&scene), sliding_model(&mapped));
    let mut short = scene.clone();
    short.stop.time = 1.0;
    let mut short_mapped = mapped.clone();
    short_mapped.stop.time = 1.0;
    let r0 = integrate(&m0, &short, short.sample).expect("runs");
    let r1 = integrate(&m1, &short_mapped, short.sample).expect("runs");
    let a1 = Along {
        model: &m1,
        run: &r1,
    };
    let mut tilt: f64 = 0.0;
    for (t, y) in r0.t.iter().zip(&r0.y) {
        if let Some((y1, _)) = a1.at(*t) {
            let d = m0.snapshot(y).motion().alpha - m1.snapshot(&y1).motion().alpha;
            tilt = tilt.max(d.abs());
        }
    }
    let relock = |r: &physics::model::sliding::SlidingRun| {
        r.switches
            .iter()
            .find(|s| s.what.ends_with("stick"))
            .map_or(f64::NAN, |s| s.t)
    };
    let (t0, t1) = (relock(&r0), relock(&r1));
    println!(
        "slip-stick mapped for the peer: largest tilt difference over 1 s {tilt:.3e} rad; the \
         slip ends at {t0:.6} s, mapped {t1:.6} s ({:+.3e} s)",
        t1 - t0
    );
    assert!(t0.is_finite() && t1.is_finite(), "{t0} {t1}");
    // g lowered by 3.3e-4 of itself slows the spiral's end by about as much: within 1 %.
    assert!(((t1 - t0) / t0).abs() < 1e-2, "{t0} {t1}");
    assert!(tilt > 0.0 && tilt < 1e-2, "{tilt}");
    let docs =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/friction.md"))
            .expect("docs")
            .replace('\n', " ");
    let said = format!("moves the tilt by {tilt:.2e} rad within the first second");
    assert!(docs.contains(&said), "docs/friction.md lacks: {said}");
}

/// The peer's own run of the mapped slip-stick scene (its slip regularization 1e-7 m/s, so that
/// it relocks as this tool does) against this tool's run of the same mapped scene: they agree to
/// the figures in docs/friction.md, far below what the mapping itself moves (the test above).
#[test]
fn the_peers_run_of_the_mapped_slip_stick_agrees_with_this_tools() {
    let d = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reference/peer-builtin/slip-stick");
    let scene = Scene::load("slip-stick").expect("built in");
    let (mapped, _) = for_peer(&scene).expect("mapped");
    // The stored response is this tool's export of the mapped scene, answer for answer.
    let answers = |t: &str| {
        t.lines()
            .filter(|l| !l.starts_with('#'))
            .map(str::to_string)
            .collect::<Vec<_>>()
    };
    let stored = std::fs::read_to_string(d.join("response.txt")).expect("stored");
    let exported = studies::peer::response::response(&mapped).expect("exported");
    assert_eq!(answers(&stored), answers(&exported));
    let c = studies::peer::compare_file(&mapped, &d.join("result.txt")).expect("compared");
    println!("slip-stick mapped, against the peer:\n{c}");
    let docs =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/friction.md"))
            .expect("docs")
            .replace('\n', " ");
    let said = format!("to a tilt of {:.1e} rad over 10 s", c.tilt.value);
    assert!(docs.contains(&said), "docs/friction.md lacks: {said}");
    // The mapping alone moves the tilt by 5.3e-3 rad within the first second (test above).
    assert!(c.tilt.value < 1e-5, "{c}");
}
