//! The Rust side of `scripts/compare` (`scripts/compare.py`): the benchmark scene's reference (with its
//! validation) and the Rust timings over a tolerance sweep, printed as one JSON document on
//! stdout. Not a criterion benchmark (`harness = false`).
//!
//! ```text
//! cargo bench --bench scipy_reference              # reference, sweep, presets, overhead
//! cargo bench --bench scipy_reference -- --drift   # also the long energy-drift runs
//! ```
//! Options: `--scene NAME` (default `benchmark`), `--drift` (1e4 precession periods at DOP853
//! rtol 1e-13, and 1e5 periods), `--study` (also the whole work-precision study, RK4
//! included), `--quick` (each point timed once).

use rolling_disk::precision::{
    energy_drift, measure_preset, rhs_nanoseconds, study, study::measure_point_with, Accuracy,
    Reference, ReferenceOptions, StudyOptions, Timing,
};
use rolling_disk::scene::Scene;
use rolling_disk::solve::{Engine, Method, Settings};
use serde_json::{json, Value};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let flag = |f: &str| args.iter().any(|a| a == f);
    let scene_name = args
        .iter()
        .position(|a| a == "--scene")
        .and_then(|i| args.get(i + 1))
        .map_or("benchmark", String::as_str);
    let scene = Scene::load(scene_name).unwrap_or_else(|e| panic!("{e}"));
    let timing = if flag("--quick") {
        Timing::ONCE
    } else {
        Timing {
            min_runs: 5,
            max_runs: 51,
            budget_seconds: 0.5,
        }
    };

    let reference = Reference::compute(&scene, &ReferenceOptions::default()).expect("reference");
    let rhs_ns = rhs_nanoseconds(&scene);

    let mut rust = Vec::new();
    let engines = [
        (Method::Dop853, Engine::Own, "dop853"),
        (Method::Dop853, Engine::OdeSolvers, "ode_solvers dop853"),
        (Method::Dopri5, Engine::Own, "dopri5"),
    ];
    for (method, engine, name) in engines {
        for e in 3..=13 {
            let rtol = 10f64.powi(-e);
            let s = Settings {
                method,
                rtol,
                atol: 1e-2 * rtol,
                ..Settings::default()
            };
            let p = measure_point_with(&scene, &s, &reference, &timing, engine).expect("point");
            let overhead = p.wall_seconds / (p.evaluations as f64 * rhs_ns * 1e-9);
            rust.push(json!({
                "method": name, "rtol": rtol, "atol": s.atol,
                "evaluations": p.evaluations, "accepted": p.accepted, "rejected": p.rejected,
                "wall_seconds": p.wall_seconds, "final_error": p.final_error,
                "trajectory_error": p.trajectory_error, "energy_change": p.energy_change,
                "overhead": overhead,
            }));
        }
    }
    let presets: Vec<Value> = Accuracy::ALL
        .iter()
        .map(|&a| json!(measure_preset(&scene, a, &reference, &timing).expect("preset")))
        .collect();

    let mut drift = Vec::new();
    if flag("--drift") {
        let s = Settings {
            method: Method::Dop853,
            rtol: 1e-13,
            atol: 1e-15,
            ..Settings::default()
        };
        for (periods, checkpoints) in [(1e4, 40), (1e5, 100)] {
            match energy_drift(&scene, &s, periods, checkpoints) {
                Ok(d) => drift.push(json!({ "periods": periods, "drift": d })),
                Err(e) => drift.push(json!({ "periods": periods, "error": e.to_string() })),
            }
        }
    }

    let study = flag("--study").then(|| {
        let opts = StudyOptions {
            timing,
            ..StudyOptions::default()
        };
        study(&scene, &opts).expect("study")
    });

    let out = json!({
        "scene": scene.name,
        "disk": scene.disk,
        "start": scene.start,
        "t_end": scene.stop.time,
        "state_order": ["alpha", "alpha_dot", "precession", "spin"],
        "atol_per_rtol": 1e-2,
        "reference": {
            "settings": reference.trace.settings,
            "y_final": reference.trace.y_final,
            "t_final": reference.trace.t_final,
            "evaluations": reference.trace.stats.evaluations,
            "energy_change": reference.trace.energy_change,
            "scale": reference.scale,
            "agreements": reference.agreements,
            "uncertainty": reference.uncertainty,
        },
        "rhs_nanoseconds": rhs_ns,
        "rust": rust,
        "presets": presets,
        "drift": drift,
        "study": study,
    });
    println!("{}", serde_json::to_string_pretty(&out).expect("json"));
}
