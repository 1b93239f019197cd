//! The real toy's scene keys in the sliding model: a thickness with a fillet, static and kinetic
//! friction, rolling and boring resistance. Bad values are refused with the file, line and key;
//! the thin limit of the thick model is the thin disk; the energy taken by friction and
//! resistance is booked.

use physics::run::run;
use physics::scene::Scene;

const BASE: &str = "name: toy
model: sliding
disk: { radius: 0.0375, mass: 0.4, DISK }
friction: { FRICTION }
RESISTANCE
start: { steady: { alpha0: 0.9, b: 0.05 }, slip: { forward: 0.2, sideways: 0.1 } }
stop: { time: 1.0 }
record: [alpha, energy, dissipated]
sample: 0.001
solver: { rtol: 1e-10, atol: 1e-10 }
";

fn scene(disk: &str, friction: &str, resistance: &str) -> Result<Scene, String> {
    let src = BASE
        .replace("DISK", disk)
        .replace("FRICTION", friction)
        .replace("RESISTANCE", resistance);
    Scene::parse(&src, "toy.yaml").map_err(|e| e.to_string())
}

#[test]
fn bad_toy_values_are_refused_with_their_key_and_a_fix() {
    for (disk, friction, resistance, line, words) in [
        (
            "thickness: 0.01, fillet: 0.008",
            "mu: 0.3",
            "",
            3,
            "fillet must lie between 0",
        ),
        (
            "thickness: -0.01",
            "mu: 0.3",
            "",
            3,
            "thickness must be a positive",
        ),
        ("k: 0.25, thickness: 0.01", "mu: 0.3", "", 3, "remove k"),
        (
            "fillet: 0.001, k: 0.25",
            "mu: 0.3",
            "",
            3,
            "add `thickness`",
        ),
        (
            "thickness: 0.01",
            "static: 0.3, kinetic: 0.4",
            "",
            4,
            "kinetic must lie between 0 and static",
        ),
        (
            "thickness: 0.01",
            "static: 0.3",
            "",
            4,
            "give mu, or both static and kinetic",
        ),
        (
            "thickness: 0.01",
            "mu: 0.3, kinetic: 0.2",
            "",
            4,
            "either mu",
        ),
        (
            "thickness: 0.01",
            "mu: 0.3",
            "resistance: { rolling: -1e-5 }",
            5,
            "lever arm",
        ),
        (
            "thickness: 0.01",
            "mu: 0.3",
            "resistance: { boring: 0.5 }",
            5,
            "below the radius",
        ),
        (
            "k: 0.25",
            "mu: 0.3",
            "resistance: { rolling: 1e-5, spin: 1 }",
            5,
            "spin",
        ),
    ] {
        let e = scene(disk, friction, resistance).unwrap_err();
        assert!(e.starts_with(&format!("toy.yaml:{line}")), "{e}");
        assert!(e.contains(words), "{e}");
    }
    let rolling = BASE
        .replace("model: sliding", "model: rolling")
        .replace("DISK", "thickness: 0.01")
        .replace("friction: { FRICTION }\n", "")
        .replace("RESISTANCE\n", "")
        .replace(", slip: { forward: 0.2, sideways: 0.1 }", "")
        .replace("record: [alpha, energy, dissipated]", "record: [alpha]");
    let e = Scene::parse(&rolling, "toy.yaml").unwrap_err().to_string();
    assert!(e.contains("model: sliding only"), "{e}");
}

/// The thin limit of the solid is the thin disk: a solid of thickness $t$ differs by $t^2/12$ in
/// its moments and by $t/2$ along the axis in its contact, and the largest tilt difference over a
/// second with a slip and a relock falls in proportion to $t$ (measured: 5.9e-4, 5.9e-6 and
/// 5.9e-8 rad for 1e-5, 1e-7 and 1e-9 m), with the same contact events.
#[test]
fn the_thin_limit_of_the_solid_is_the_thin_disk() {
    let thin = run(&scene("k: 0.25", "mu: 0.3", "").unwrap(), None).unwrap();
    let events = |r: &physics::run::Run| r.contact_events.iter().map(|e| e.t).collect::<Vec<_>>();
    let mut worst = Vec::new();
    for t in ["1e-7", "1e-9"] {
        let solid = run(
            &scene(&format!("thickness: {t}"), "mu: 0.3", "").unwrap(),
            None,
        )
        .unwrap();
        assert_eq!(thin.rows.len(), solid.rows.len());
        let w = thin
            .rows
            .iter()
            .zip(&solid.rows)
            .map(|(a, b)| (a[1] - b[1]).abs())
            .fold(0.0, f64::max);
        println!("thickness {t} m: largest tilt difference {w:e} rad");
        let (a, b) = (events(&thin), events(&solid));
        assert!(!a.is_empty());
        assert_eq!(a.len(), b.len());
        for (x, y) in a.iter().zip(&b) {
            assert!((x - y).abs() < 1e-5, "{x} {y}");
        }
        worst.push(w);
    }
    let ratio = worst[0] / worst[1];
    assert!((50.0..200.0).contains(&ratio), "{ratio}");
    assert!(worst[1] < 1e-7, "{:e}", worst[1]);
}

/// $E(t) + W(t) = E(0)$ with a thick disk, two coefficients and both resistances: every joule
/// the friction and the contact moments take is booked.
#[test]
fn friction_and_resistance_work_is_booked() {
    let s = scene(
        "thickness: 0.0128, fillet: 0.002",
        "static: 0.3, kinetic: 0.2",
        "resistance: { rolling: 3.75e-5, boring: 3.75e-4 }",
    )
    .unwrap();
    let r = run(&s, None).unwrap();
    let e0 = r.rows[0][2];
    let worst = r
        .rows
        .iter()
        .map(|row| (row[2] + row[3] - e0).abs() / e0)
        .fold(0.0, f64::max);
    let lost = r.rows.last().unwrap()[3];
    println!(
        "{} contact events, {lost:e} J dissipated, balance {worst:e}",
        r.contact_events.len()
    );
    assert!(lost > 1e-4 * e0, "{lost}");
    assert!(worst < 1e-7, "{worst:e}");
}

/// A thick disk's `steady` start is the solid's steady rolling: its tilt stays put; a `b` on the
/// wrong side of the solid's edge is refused with the line, the edge and the fix, and the edge
/// named is where the refusals stop.
#[test]
fn a_thick_disks_steady_start_is_steady_and_its_edge_is_named() {
    let src = |alpha0: f64, b: f64| {
        format!(
            "name: toy-steady
model: sliding
disk: {{ radius: 0.0375, mass: 0.4, thickness: 0.0128, fillet: 0.002 }}
friction: {{ mu: 1.0 }}
start: {{ steady: {{ alpha0: {alpha0}, b: {b} }} }}
stop: {{ time: 0.5 }}
record: [alpha]
sample: 0.001
solver: {{ rtol: 1e-11, atol: 1e-13 }}
"
        )
    };
    for (alpha0, b) in [(0.3, 0.0), (1.2, 0.01), (1.2, -0.0005)] {
        let s = Scene::parse(&src(alpha0, b), "toy-steady.yaml").unwrap();
        let r = run(&s, None).unwrap();
        assert!(r.contact_events.is_empty(), "{alpha0} {b}");
        let drift = r
            .rows
            .iter()
            .map(|x| (x[1] - alpha0).abs())
            .fold(0.0, f64::max);
        println!("alpha0 {alpha0}, b {b} m: tilt drifts {drift:e} rad over 0.5 s");
        assert!(drift < 1e-8, "{drift:e}");
    }
    let e = Scene::parse(&src(1.4, 0.0), "toy-steady.yaml")
        .unwrap_err()
        .to_string();
    println!("{e}");
    assert!(
        e.starts_with("toy-steady.yaml:5:") && e.contains("raise b"),
        "{e}"
    );
    let edge: f64 = e
        .split("needs b > ")
        .nth(1)
        .and_then(|t| t.split(' ').next())
        .and_then(|t| t.parse().ok())
        .expect("the edge in the message");
    assert!(Scene::parse(&src(1.4, edge * 0.99), "toy-steady.yaml").is_err());
    assert!(Scene::parse(&src(1.4, edge * 1.01), "toy-steady.yaml").is_ok());
}

/// A thick disk started upright (rolling straight, or spinning about a vertical diameter) is
/// refused with the start's line and a tilt that works; the tilted start runs.
#[test]
fn a_thick_disk_started_upright_is_refused_with_a_tilt_that_works() {
    let src = |start: &str| {
        format!(
            "name: toy-upright
model: sliding
disk: {{ radius: 0.0375, mass: 0.4, thickness: 0.0128, fillet: 0.002 }}
friction: {{ mu: 1.0 }}
start: {{ {start} }}
stop: {{ time: 0.05 }}
"
        )
    };
    for start in [
        "rolling_straight: { spin: 5.0 }",
        "vertical_spin: { precession: 30.0 }",
    ] {
        let e = Scene::parse(&src(start), "toy-upright.yaml")
            .unwrap_err()
            .to_string();
        println!("{e}");
        assert!(e.starts_with("toy-upright.yaml:5:"), "{e}");
        let fix = e
            .split("add ")
            .nth(1)
            .expect("the fix in the message")
            .trim_end_matches('.');
        let fixed = format!("{start}, {fix}");
        let r = run(
            &Scene::parse(&src(&fixed), "toy-upright.yaml").unwrap(),
            None,
        )
        .unwrap();
        assert!(
            r.ending.is_complete() && r.rows.last().is_some_and(|x| x[0] > 0.04),
            "{start}: {}",
            r.ending
        );
    }
}
