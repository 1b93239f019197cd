//! The experiment of section 11: synthetic traces, their analysis, CSV validation, the paper's
//! numbers.

use rolling_disk::experiment::numbers::paper_numbers;
use rolling_disk::experiment::*;
use rolling_disk::scene::Scene;
use rolling_disk::Disk;
use std::f64::consts::PI;

/// A dissipative spin-down with exponent `beta` lasting about 9 s, started in its adiabatic
/// state (steady b = 0 motion plus the drift of alpha that dissipation imposes) so that little
/// nutation is excited: energy $E = \tfrac32 mga\sin\alpha$ falls at eq 75's rate, so
/// $\dot\alpha = -\tfrac23\epsilon\Omega^\beta/\cos\alpha$ and $\dot\Omega = K\Omega^{\beta+3}$ with
/// $K = \epsilon k a / 3g$; epsilon is chosen from the latter for the duration.
fn spin_down(beta: f64) -> Scene {
    let (a, k, g, alpha0, duration) = (0.0375, 0.25, 9.81, 0.12, 9.0);
    let omega0 = (g / (k * a * f64::sin(alpha0))).sqrt();
    let epsilon = 3.0 * g / (k * a * (beta + 2.0) * omega0.powf(beta + 2.0) * duration);
    let alpha_dot = -2.0 / 3.0 * epsilon * omega0.powf(beta) / alpha0.cos();
    let yaml = format!(
        "name: spin-down-beta-{beta}\n\
         disk: {{ radius: {a}, k: {k}, mass: 0.4, g: {g} }}\n\
         model: dissipative\n\
         dissipation: {{ epsilon: {epsilon:e}, beta: {beta} }}\n\
         start: {{ steady: {{ alpha0: {alpha0}, b: 0.0 }}, perturb: {{ alpha_dot: {alpha_dot:e} }} }}\n\
         stop: {{ time: 30.0, alpha_below: 1.0e-4 }}\n\
         solver: {{ method: dop853, rtol: 1.0e-10, atol: 1.0e-12 }}\n"
    );
    Scene::parse(&yaml, "test").expect("valid scene")
}

/// The dissipative model is not eq 79 exactly: the steady start excites some nutation and the
/// centre of mass drifts off b = 0 as the disk spins down, so 1/Omega departs from the law by
/// about 1 % (the fit's reduced chi2 is 100-750 at 5 mV noise). The fits' uncertainties are
/// statistical and do not cover that departure; here we check that the model's own beta and
/// end time come back to within what that departure allows. The strict checks of bias and
/// coverage are on traces that follow the law exactly (below).
#[test]
fn model_spin_downs_give_back_their_beta_and_t0() {
    for beta in [0.0, 1.0, 2.0, 2.5, 4.0] {
        let trace = simulate_trace(&spin_down(beta), &LightModel::default()).unwrap();
        let tr = trace.truth.clone().unwrap();
        assert!(tr.tau_rem < 1e-3, "{tr:?}");
        let a = analyze(&trace, &AnalysisSettings::default()).unwrap();
        println!("{a}");
        assert!((a.eq84.beta - beta).abs() < 0.2, "beta {beta}: {a}");
        assert!((a.eq85.beta - beta).abs() < 0.2, "beta {beta}: {a}");
        assert!((a.eq84.t0 - tr.t0).abs() < 0.04, "beta {beta}: {a}");
    }
}

#[test]
fn law_traces_give_back_their_beta_and_t0() {
    let disk = Disk::uniform(0.0375);
    for beta in [0.0, 1.0, 2.0, 2.5, 4.0] {
        // Omega = 100 rad/s seven seconds before t0.
        let law = Law {
            beta,
            c: 100f64.powf(beta + 2.0) * 7.0,
        };
        let trace = law_trace(&law, &disk, &LightModel::default()).unwrap();
        let a = analyze(&trace, &AnalysisSettings::default()).unwrap();
        let s = a.score.unwrap();
        println!("{a}");
        assert!(
            s.beta84_pull.abs() < 3.5 && s.beta85_pull.abs() < 3.5,
            "{a}"
        );
        assert!(s.t0_error_samples.abs() < 3.0, "{a}");
        let ln_c = law.c.ln();
        assert!(
            (a.eq84.ln_c - ln_c).abs() < 4.0 * a.eq84.ln_c_sigma + 1e-3,
            "{a}"
        );
    }
}

#[test]
fn uncertainties_cover_the_truth_as_often_as_they_claim() {
    let disk = Disk::uniform(0.0375);
    let law = Law {
        beta: 2.0,
        c: 100f64.powi(4) * 7.0,
    };
    let runs = 100;
    let mut within = [[0usize; 2]; 3]; // [beta84, t0, beta85] x [1 sigma, 2 sigma]
    for seed in 0..runs {
        let mut light = LightModel::default();
        light.scope.seed = 1000 + seed as u64;
        let trace = law_trace(&law, &disk, &light).unwrap();
        let s = analyze(&trace, &AnalysisSettings::default())
            .unwrap()
            .score
            .unwrap();
        for (k, pull) in [s.beta84_pull, s.t0_pull, s.beta85_pull].iter().enumerate() {
            within[k][0] += usize::from(pull.abs() <= 1.0);
            within[k][1] += usize::from(pull.abs() <= 2.0);
        }
    }
    println!(
        "within 1 and 2 sigma of {runs}: beta84 {:?}, t0 {:?}, beta85 {:?}",
        within[0], within[1], within[2]
    );
    for w in within {
        assert!((55..=80).contains(&w[0]), "{within:?}");
        assert!((82..=100).contains(&w[1]), "{within:?}");
    }
}

#[test]
fn a_trace_survives_its_csv() {
    let disk = Disk::uniform(0.0375);
    let mut light = LightModel::default();
    light.scope.samples = 2000;
    light.scope.end_at = 0.3;
    let trace = law_trace(&Law::paper(), &disk, &light).unwrap();
    let back = parse_trace(&trace.to_csv(), "x.csv").unwrap();
    assert_eq!(back.t, trace.t);
    assert_eq!(back.v, trace.v);
    assert_eq!(back.truth, trace.truth);
}

fn err(text: &str) -> String {
    parse_trace(text, "scope.csv").unwrap_err().to_string()
}

#[test]
fn bad_csvs_are_refused_with_file_and_line() {
    let e = err("time_s,signal_V\n");
    assert!(
        e.starts_with("scope.csv:1:") && e.contains("no data rows"),
        "{e}"
    );
    let e = err("");
    assert!(e.starts_with("scope.csv:") && e.contains("empty"), "{e}");
    let e = err("time_s,signal_V\n0,1\n0.1,1\n0.1,2\n");
    assert!(
        e.starts_with("scope.csv:4:") && e.contains("does not increase"),
        "{e}"
    );
    let e = err("time_s,signal_V\n0,1\n0.2,1\n0.1,2\n");
    assert!(
        e.starts_with("scope.csv:4:") && e.contains("does not increase"),
        "{e}"
    );
    let e = err("time_s,signal_V\n0,1\n0.1,NaN\n");
    assert!(e.starts_with("scope.csv:3:") && e.contains("NaN"), "{e}");
    let e = err("time_s,signal_V\n0,1\n0.1\n");
    assert!(
        e.starts_with("scope.csv:3:") && e.contains("column is missing"),
        "{e}"
    );
    let e = err("time_s\n0\n");
    assert!(
        e.starts_with("scope.csv:1:") && e.contains("column is missing"),
        "{e}"
    );
    let e = err("# a comment\ntime_s,signal_V\n0,1\n0.1,one\n");
    assert!(
        e.starts_with("scope.csv:4:") && e.contains("\"one\" is not a number"),
        "{e}"
    );

    let flat: String = std::iter::once("time_s,signal_V\n".to_string())
        .chain((0..1000).map(|j| format!("{},{}\n", j as f64 * 2e-4, 0.5)))
        .collect();
    let trace = parse_trace(&flat, "flat.csv").unwrap();
    let e = analyze(&trace, &AnalysisSettings::default())
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("flat.csv:") && e.contains("flat"), "{e}");

    let few: String = std::iter::once("time_s,signal_V\n".to_string())
        .chain((0..1000).map(|j| {
            let t = j as f64 * 2e-4;
            format!("{t},{}\n", 1.0 + (2.0 * PI * 20.0 * t).cos())
        }))
        .collect();
    let trace = parse_trace(&few, "few.csv").unwrap();
    let e = analyze(&trace, &AnalysisSettings::default())
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("few.csv:") && e.contains("fewer than"), "{e}");

    let missing = read_trace("/nonexistent/scope.csv")
        .unwrap_err()
        .to_string();
    assert!(missing.starts_with("/nonexistent/scope.csv:"), "{missing}");
}

#[test]
fn the_papers_numbers_are_recomputed() {
    let n = paper_numbers();
    assert!((n.omega_one_period - 560.0).abs() < 5.0, "{n}");
    assert!((n.time_one_period - 0.011).abs() < 0.0005, "{n}");
    assert!((n.omega_lift_off - 1030.0).abs() < 10.0, "{n}");
    assert!((n.time_lift_off - 0.001).abs() < 0.0001, "{n}");
    // For beta = 2 and k = 1/4 the brackets of eqs 80-81 are 1: C^(1/3) and C^(-1/3).
    assert!((n.omega_lift_off - n.c.powf(1.0 / 3.0)).abs() < 1e-9 * n.omega_lift_off);
    let air = n.exponents.iter().find(|e| e.beta == 4.0).unwrap();
    assert!((air.omega_vs_time + 1.0 / 6.0).abs() < 1e-15);
    let rolling = n.exponents.iter().find(|e| e.beta == 2.0).unwrap();
    assert!((rolling.omega_vs_time + 0.25).abs() < 1e-15 && rolling.omega_dot_slope == 5.0);
}

#[test]
fn an_analysis_is_written_to_a_directory() {
    let disk = Disk::uniform(0.0375);
    let trace = law_trace(&Law { beta: 2.0, c: 7e8 }, &disk, &LightModel::default()).unwrap();
    let a = analyze(&trace, &AnalysisSettings::default()).unwrap();
    let dir = std::env::temp_dir().join(format!("rolling-disk-exp-{}", std::process::id()));
    let files = write_analysis(&a, &dir).unwrap();
    assert_eq!(files.len(), 4);
    let omega = std::fs::read_to_string(dir.join("omega.csv")).unwrap();
    assert_eq!(omega.lines().count(), a.cycles.len() + 1);
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("analysis.json")).unwrap()).unwrap();
    assert!(json["eq84"]["beta"].as_f64().is_some());
    std::fs::remove_dir_all(&dir).unwrap();
}
