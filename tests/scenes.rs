//! Scene files: the built-in ones, the states they integrate, and every kind of bad file.

use physics::run::run;
use physics::scene::{builtin::BUILTIN, Scene};
use physics::solve::Ending;

const GOOD: &str = "name: t
disk: { radius: 0.0375, k: 0.25, mass: 0.4, g: 9.81 }
model: rolling
start: { steady: { alpha0: 0.3, b: 0.0 } }
stop: { time: 1.0 }
record: [alpha]
";

#[test]
fn every_scene_file_is_built_in_and_every_built_in_scene_runs() {
    let mut files: Vec<String> = std::fs::read_dir("paper/scenes")
        .unwrap()
        .map(|e| {
            e.unwrap()
                .file_name()
                .to_string_lossy()
                .trim_end_matches(".yaml")
                .to_string()
        })
        .collect();
    files.sort();
    let mut names: Vec<String> = BUILTIN.iter().map(|(n, _)| n.to_string()).collect();
    names.sort();
    assert_eq!(files, names, "paper/scenes and the built-in list differ");
    for (name, src) in BUILTIN {
        let scene = Scene::parse(src, name).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(&scene.name, name, "a scene's name is its file name");
        let r = run(&scene, None).unwrap();
        assert!(r.ending.is_complete(), "{name}: {}", r.ending);
    }
}

#[test]
fn a_scene_integrates_only_the_states_it_records() {
    let alpha_only = Scene::parse(GOOD, "t.yaml").unwrap();
    assert_eq!(run(&alpha_only, None).unwrap().states, 4);
    let path = Scene::parse(&GOOD.replace("[alpha]", "[alpha, path]"), "t.yaml").unwrap();
    let r = run(&path, None).unwrap();
    assert_eq!(r.states, 7, "alpha + heading + x + y");
    assert_eq!(r.columns, ["t_s", "alpha_rad", "x_m", "y_m"]);
    let all = Scene::parse(&GOOD.replace("[alpha]", "[alpha, path, face]"), "t.yaml").unwrap();
    assert_eq!(run(&all, None).unwrap().states, 8);
    let lab = GOOD
        .replace("model: rolling", "model: lab-frame")
        .replace("[alpha]", "[alpha, path, face]");
    let r = run(&Scene::parse(&lab, "t.yaml").unwrap(), None).unwrap();
    assert_eq!(
        r.states, 13,
        "the lab frame always integrates its whole rigid-body state"
    );
    let frictionless = GOOD
        .replace("model: rolling", "model: frictionless")
        .replace("[alpha]", "[alpha, lz]");
    let r = run(&Scene::parse(&frictionless, "t.yaml").unwrap(), None).unwrap();
    assert_eq!(r.states, 3, "omega_1 is a parameter without friction");
}

#[test]
fn a_stop_event_in_a_scene_is_located_to_1e_9_s() {
    // A disk falls from near vertical; stop when alpha < 0.6 rad. Independent runs ending at
    // t_e - 1e-9 s and t_e + 1e-9 s (no events) must straddle the bound.
    let src = "name: fall
disk: { radius: 0.0375, k: 0.25, mass: 0.4 }
model: rolling
start: { explicit: { alpha: 1.5, precession: 2.0 } }
stop: { time: 5.0, alpha_below: 0.6 }
record: [alpha]
solver: { rtol: 1.0e-12, atol: 1.0e-14 }
";
    let scene = Scene::parse(src, "fall.yaml").unwrap();
    let r = run(&scene, None).unwrap();
    let Ending::Event { t: t_e, .. } = r.ending else {
        panic!("no event: {:?}", r.ending)
    };
    let alpha_at = |t: f64| {
        let s = Scene::parse(
            &src.replace("time: 5.0, alpha_below: 0.6", &format!("time: {t:.17e}")),
            "x",
        )
        .unwrap();
        run(&s, None).unwrap().last.alpha
    };
    let (before, after) = (alpha_at(t_e - 1e-9), alpha_at(t_e + 1e-9));
    eprintln!(
        "event at {t_e:.12} s; alpha - 0.6 = {:.2e} before, {:.2e} after",
        before - 0.6,
        after - 0.6
    );
    assert!(before > 0.6 && after < 0.6);
}

/// Parses `src` and returns the error's text; panics if it parses.
fn error_of(src: &str) -> String {
    match Scene::parse(src, "bad.yaml") {
        Ok(_) => panic!("accepted:\n{src}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn every_kind_of_bad_scene_gets_a_located_actionable_error() {
    let cases: Vec<(String, &str, &[&str])> = vec![
        ("name: [unclosed\n".into(), "bad.yaml:1", &[]),
        (
            GOOD.replace("record: [alpha]", "record: [alpha]\ncolour: red"),
            "bad.yaml:7",
            &["unknown key `colour`", "the keys here are"],
        ),
        (
            GOOD.replace("k: 0.25", "k: 0.0"),
            "bad.yaml:2",
            &["inertia factor k must be positive"],
        ),
        (
            GOOD.replace("k: 0.25", "k: -1"),
            "bad.yaml:2",
            &["k must be positive"],
        ),
        (
            GOOD.replace("radius: 0.0375", "radius: -0.0375"),
            "bad.yaml:2",
            &["radius must be a positive"],
        ),
        (
            GOOD.replace("radius: 0.0375", "radius: 0"),
            "bad.yaml:2",
            &["radius"],
        ),
        (
            GOOD.replace("alpha0: 0.3", "alpha0: 1.7"),
            "bad.yaml:4",
            &["0 < alpha0 < pi/2", "vertical_spin"],
        ),
        (
            GOOD.replace("alpha0: 0.3", "alpha0: 0.0"),
            "bad.yaml:4",
            &["does not exist"],
        ),
        (
            GOOD.replace("b: 0.0", "b: -0.01"),
            "bad.yaml:4",
            &["eq 30 needs b >", "-0.005971 m"],
        ),
        (
            GOOD.replace("record: [alpha]", "record: [alpha]\nsolver: { rtol: 0 }"),
            "bad.yaml:7",
            &["rtol must lie strictly between 0 and 1"],
        ),
        (
            GOOD.replace(
                "record: [alpha]",
                "record: [alpha]\nsolver: { rtol: -1e-9 }",
            ),
            "bad.yaml:7",
            &["rtol"],
        ),
        (
            GOOD.replace("stop: { time: 1.0 }", "stop: { alpha_below: 0.1 }"),
            "bad.yaml:5",
            &["time bound", "add `time"],
        ),
        (
            GOOD.replace("model: rolling", "model: skidding"),
            "bad.yaml:3",
            &["`skidding` is not a name", "rolling"],
        ),
        (
            GOOD.replace("record: [alpha]", "record: [alpah]"),
            "bad.yaml:6",
            &["`alpah` is not a name", "did you mean `alpha`?"],
        ),
        (
            GOOD.replace("mass: 0.4, ", ""),
            "bad.yaml:2",
            &["disk needs the key `mass`", "add it"],
        ),
        (
            GOOD.replace(
                "stop: { time: 1.0 }",
                "stop: { time: 1.0, alpha_below: 0.5 }",
            ),
            "bad.yaml:5",
            &["already holds at the start"],
        ),
        (
            GOOD.replace("model: rolling", "model: dissipative"),
            "bad.yaml:3",
            &["needs a dissipation law"],
        ),
        (
            GOOD.replace(
                "start: { steady: { alpha0: 0.3, b: 0.0 } }",
                "start: { perturb: { alpha: 0.1 } }",
            ),
            "bad.yaml:4",
            &["exactly one of"],
        ),
        (
            GOOD.replace("record: [alpha]", "record: [alpha]\nsample: -1"),
            "bad.yaml:7",
            &["sample must be a positive"],
        ),
    ];
    for (src, at, words) in cases {
        let e = error_of(&src);
        assert!(e.starts_with(at), "expected the error at {at}, got: {e}");
        for w in words {
            assert!(e.contains(w), "expected {w:?} in: {e}");
        }
    }
}

#[test]
fn a_disk_that_falls_flat_stops_there_instead_of_passing_through_the_table() {
    let src = "name: fall-flat
disk: { radius: 0.0375, k: 0.25, mass: 0.4 }
model: rolling
start: { explicit: { alpha: 0.01 } }
stop: { time: 10.0 }
record: [alpha]
";
    let r = run(&Scene::parse(src, "fall.yaml").unwrap(), None).unwrap();
    let Ending::Event { name, t, .. } = &r.ending else {
        panic!("{:?}", r.ending)
    };
    assert!(name.contains("fell flat"), "{name}");
    assert!(
        *t < 1.0 && r.last.alpha.abs() < 1e-9,
        "t = {t}, alpha = {}",
        r.last.alpha
    );
}

/// `solver: { project: energy }`: a rolling run keeps its energy at round-off (the run without
/// drifts more), and the scenes where a projection means nothing are refused at the key.
#[test]
fn projection_onto_the_energy_holds_it_and_is_refused_where_it_means_nothing() {
    let base = GOOD
        .replace(
            "start: { steady: { alpha0: 0.3, b: 0.0 } }",
            "start: { explicit: { alpha: 1.2, alpha_dot: 0.5, precession: 10.0, spin: 5.0 } }",
        )
        .replace("stop: { time: 1.0 }", "stop: { time: 20.0 }")
        + "solver: { method: dop853, rtol: 1.0e-6, atol: 1.0e-8 }\n";
    let projected = base.replace("atol: 1.0e-8 }", "atol: 1.0e-8, project: energy }");
    let free = run(&Scene::parse(&base, "free.yaml").unwrap(), None).unwrap();
    let held = run(&Scene::parse(&projected, "held.yaml").unwrap(), None).unwrap();
    eprintln!(
        "energy change: free {:e} ({} evaluations), projected {:e} ({} evaluations)",
        free.energy_change, free.stats.evaluations, held.energy_change, held.stats.evaluations
    );
    assert_eq!(held.ending, Ending::TimeReached);
    assert!(
        held.energy_change < 1e-14,
        "projected: {:e}",
        held.energy_change
    );
    assert!(
        free.energy_change > 100.0 * held.energy_change.max(1e-16),
        "free {:e}, projected {:e}",
        free.energy_change,
        held.energy_change
    );
    let dissipative = projected.replace(
        "model: rolling",
        "model: dissipative\ndissipation: { epsilon: 1.0e-6, beta: 2 }",
    );
    let e = error_of(&dissipative);
    assert!(e.contains("solver.project") || e.contains("project"), "{e}");
    assert!(e.contains("conserves the energy"), "{e}");
    let rk4 = projected.replace("method: dop853", "method: rk4");
    let e = error_of(&rk4);
    assert!(e.contains("needs method: dop853"), "{e}");
    let unknown = projected.replace("project: energy", "project: momentum");
    let e = error_of(&unknown);
    assert!(e.contains("energy"), "{e}");
}

const MECHANISM: &str = "name: viscous
disk: { radius: 0.0375, k: 0.25, mass: 0.4, g: 9.81 }
model: dissipative
mechanisms: [ { viscous_rolling: { time: 2.0e-7 } } ]
start: { steady: { alpha0: 0.15, b: 0.0 } }
stop: { time: 0.02 }
record: [energy]
sample: 1.0e-4
solver: { method: dop853, rtol: 1.0e-12, atol: 1.0e-14 }
";

/// A scene asks for a mechanism by its key: the run loses energy at the mechanism's own rate,
/// $P = -\tau F_z v_p^2/a$ with $v_p = a\Omega\cos\alpha$ the contact point's speed along the
/// table and $F_z = mg$ at steady $b = 0$ (computed here from the steady motion, not by the
/// model), measured as the slope of the recorded energy over the first 20 ms.
#[test]
fn a_scene_asks_for_a_mechanism_by_name_and_loses_energy_at_its_rate() {
    let scene = Scene::parse(MECHANISM, "viscous.yaml").unwrap();
    assert_eq!(scene.mechanisms.len(), 1);
    assert!(scene.dissipation.is_none());
    let r = run(&scene, None).unwrap();
    let (t, e) = (r.column("t_s").unwrap(), r.column("energy_J").unwrap());
    let n = t.len() - 1;
    let slope = (e[n] - e[0]) / (t[n] - t[0]);
    let d = scene.disk;
    let (alpha, omega) = (scene.start.alpha, scene.start.precession);
    let v_p = d.a * omega * alpha.cos();
    let expected = -2.0e-7 * d.m * d.g * v_p * v_p / d.a;
    assert!(
        (slope / expected - 1.0).abs() < 1e-3,
        "slope {slope} W, expected {expected} W"
    );
    // With eq 75's law besides, the two losses add.
    let both = MECHANISM.replace(
        "mechanisms:",
        "dissipation: { epsilon: 1.0e-6, beta: 2.0 }\nmechanisms:",
    );
    let s2 = Scene::parse(&both, "both.yaml").unwrap();
    assert!(s2.dissipation.is_some() && s2.mechanisms.len() == 1);
    let r2 = run(&s2, None).unwrap();
    let e2 = r2.column("energy_J").unwrap();
    assert!(e2[e2.len() - 1] < e[n], "the law adds its own loss");
}

#[test]
fn bad_mechanisms_are_refused_with_the_key_and_the_fix() {
    let cases: Vec<(String, &[&str])> = vec![
        (
            MECHANISM.replace("model: dissipative", "model: rolling"),
            &[
                "bad.yaml:4",
                "the rolling model has no dissipation mechanisms",
                "model: dissipative",
            ],
        ),
        (
            MECHANISM.replace("time: 2.0e-7", "time: -1.0"),
            &[
                "bad.yaml:4",
                "viscous rolling friction",
                "`time` in s",
                "got -1",
            ],
        ),
        (
            MECHANISM.replace("time: 2.0e-7 } }", "time: 2.0e-7 }, air_film: {} }"),
            &["bad.yaml:4", "entry 1 names 2 mechanisms", "its own entry"],
        ),
        (
            MECHANISM.replace("viscous_rolling", "viscous_drag"),
            &["bad.yaml:4", "viscous_drag", "viscous_rolling"],
        ),
        (
            MECHANISM.replace(
                "mechanisms: [ { viscous_rolling: { time: 2.0e-7 } } ]\n",
                "",
            ),
            &["needs a dissipation law", "or a list of `mechanisms`"],
        ),
    ];
    for (src, wanted) in cases {
        let e = error_of(&src);
        for w in wanted {
            assert!(e.contains(w), "`{w}` not in: {e}");
        }
    }
}
