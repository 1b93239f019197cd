//! The Rust side of `scripts/compare` (`scripts/compare.py`): the benchmark scene's reference (with its
//! validation) and the Rust timings over a tolerance sweep, printed as one JSON document on
//! stdout. Not a criterion benchmark (`harness = false`).
//!
//! ```text
//! cargo bench --bench benches -- --scipy-reference            # reference, sweep, presets, overhead
//! cargo bench --bench benches -- --scipy-reference --drift    # also the long energy-drift runs
//! ```
//! Options: `--scene NAME` (default `benchmark`), `--drift` (1e4 precession periods at DOP853
//! rtol 1e-13, and 1e5 periods), `--study` (also the whole work-precision study, RK4
//! included), `--quick` (each point timed once). The document's `sampled` part is the scene run
//! as `simulate` runs it, sampled ([`super::scipy_sampled`]).

use physics::model::rolling::Rolling;
use physics::model::{Extras, Model};
use physics::scene::Scene;
use physics::solve::{Dynamics, Engine, Method, Settings, State};
use serde_json::{json, Value};
use std::cell::Cell;
use std::time::Instant;
use studies::precision::{
    energy_drift, measure_preset, rhs_latency_nanoseconds, rhs_nanoseconds, study,
    study::measure_point_with, Accuracy, Reference, ReferenceOptions, StudyOptions, Timing,
};

pub fn main() {
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
    let rhs_latency_ns = rhs_latency_nanoseconds(&scene);

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
    rust.extend(other_crate(&scene, &reference, &timing, rhs_ns));
    let presets: Vec<Value> = Accuracy::ALL
        .iter()
        .map(|&a| json!(measure_preset(&scene, a, &reference, &timing).expect("preset")))
        .collect();

    let sampled = super::scipy_sampled::sweep(&scene, &timing);

    let mut drift = Vec::new();
    if flag("--drift") {
        let s = Settings::dop853(1e-13, 1e-15);
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
        "rhs_latency_nanoseconds": rhs_latency_ns,
        "rust": rust,
        "presets": presets,
        "sampled": sampled,
        "drift": drift,
        "study": study,
    });
    println!("{}", serde_json::to_string_pretty(&out).expect("json"));
}

/// The benchmark scene's rolling model (eqs 23-25) as the `ivp` crate's system, counting its
/// evaluations: the same right-hand side as the tool's, behind another crate's DOP853.
struct IvpSystem {
    model: Rolling<4>,
    evaluations: Cell<u64>,
}

impl ivp::prelude::FirstOrderSystem for IvpSystem {
    fn derivative(&self, _t: f64, y: &[f64], dydt: &mut [f64]) {
        self.evaluations.set(self.evaluations.get() + 1);
        let mut dy = State::<4>::zeros();
        self.model.rhs(&State::<4>::from_column_slice(y), &mut dy);
        dydt.copy_from_slice(dy.as_slice());
    }
}

/// One other Rust ODE crate, `ivp` (a port of SciPy's `solve_ivp`), on the same scene, the
/// same tolerances (atol = 1e-2 rtol) and the same error measure: its DOP853 over the sweep,
/// timed as the tool's points are (median of runs within the timing budget).
fn other_crate(scene: &Scene, reference: &Reference, timing: &Timing, rhs_ns: f64) -> Vec<Value> {
    use ivp::prelude::{Ivp, Method as IvpMethod};
    let system = IvpSystem {
        model: Rolling::<4>::new(scene.disk, Extras::default(), None),
        evaluations: Cell::new(0),
    };
    let y0: Vec<f64> = system.model.state(&scene.start).iter().copied().collect();
    let mut out = Vec::new();
    for e in 3..=13 {
        let rtol = 10f64.powi(-e);
        let atol = 1e-2 * rtol;
        let once = || {
            system.evaluations.set(0);
            let started = Instant::now();
            let sol = Ivp::first_order(&system, 0.0, scene.stop.time, &y0)
                .method(IvpMethod::DOP853)
                .rtol(rtol)
                .atol(atol)
                .max_steps(10_000_000)
                .solve();
            (started.elapsed().as_secs_f64(), sol)
        };
        let (first, sol) = once();
        let sol = match sol {
            Ok(s) => s,
            Err(e) => {
                out.push(json!({ "method": "ivp dop853", "rtol": rtol, "error": e.to_string() }));
                continue;
            }
        };
        let evaluations = system.evaluations.get();
        let mut times = vec![first];
        let budget = Instant::now();
        while times.len() < timing.max_runs
            && (times.len() < timing.min_runs
                || budget.elapsed().as_secs_f64() < timing.budget_seconds)
        {
            times.push(once().0);
        }
        times.sort_by(f64::total_cmp);
        let wall_seconds = times[times.len() / 2];
        let (Some(&t_final), Some(y_final)) = (sol.t.last(), sol.y.last()) else {
            continue;
        };
        let final_error = if (t_final - scene.stop.time).abs() <= 1e-9 * scene.stop.time {
            reference.state_error(y_final, &reference.trace.y_final)
        } else {
            f64::INFINITY
        };
        out.push(json!({
            "method": "ivp dop853", "rtol": rtol, "atol": atol,
            "evaluations": evaluations, "accepted": sol.naccpt, "rejected": sol.nrejct,
            "wall_seconds": wall_seconds, "final_error": final_error,
            "overhead": wall_seconds / (evaluations as f64 * rhs_ns * 1e-9),
        }));
    }
    out
}
