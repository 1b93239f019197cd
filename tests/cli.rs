//! The command line as a user meets it.

use crate::common::{last_row, temp_dir};
use std::process::Command;

fn cli(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_rolling-disk"))
        .args(args)
        .output()
        .expect("the binary runs");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn scenes_lists_the_built_in_scenes() {
    let (ok, out, _) = cli(&["scenes"]);
    assert!(ok);
    for name in [
        "spinning-coin",
        "nutating-coin",
        "wheel-straight",
        "vertical-spin-frictionless",
        "spin-down",
        "benchmark",
    ] {
        assert!(out.contains(name), "{name} missing from:\n{out}");
    }
}

#[test]
fn simulate_prints_a_summary_and_writes_csv() {
    let dir = temp_dir("cli", "csv");
    let csv = dir.join("coin.csv");
    let (ok, out, err) = cli(&["simulate", "spinning-coin", "--csv", csv.to_str().unwrap()]);
    assert!(ok, "{err}");
    for word in [
        "final",
        "energy drift",
        "right-hand-side evaluations",
        "accepted",
        "rejected",
    ] {
        assert!(out.contains(word), "{word} missing from:\n{out}");
    }
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next().unwrap(),
        "t_s,alpha_rad,precession_rad_per_s,spin_rad_per_s,x_m,y_m,energy_J"
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|c| c.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 501, "every 10 ms over 5 s, both ends included");
    assert!(rows
        .iter()
        .all(|r| r.len() == 7 && (r[1] - 0.3).abs() < 1e-9));
    // No temporary file is left beside the output.
    let leftovers = std::fs::read_dir(&dir).unwrap().count();
    assert_eq!(leftovers, 1);
    // The same inputs give the same bytes.
    let csv2 = dir.join("again.csv");
    assert!(cli(&["simulate", "spinning-coin", "--csv", csv2.to_str().unwrap()]).0);
    assert_eq!(text, std::fs::read_to_string(&csv2).unwrap());
}

#[test]
fn a_bad_scene_file_fails_with_its_name_and_line() {
    let dir = temp_dir("cli", "bad");
    let path = dir.join("negative-radius.yaml");
    std::fs::write(
        &path,
        "name: x\ndisk: { radius: -1, k: 0.25, mass: 1 }\nmodel: rolling\nstart: { steady: { alpha0: 0.3, b: 0 } }\nstop: { time: 1 }\n",
    )
    .unwrap();
    let (ok, out, err) = cli(&["simulate", path.to_str().unwrap()]);
    assert!(!ok);
    assert!(out.is_empty());
    assert!(err.contains(&format!("{}:2:", path.display())), "{err}");
    assert!(err.contains("radius must be a positive"), "{err}");
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn a_missing_scene_says_how_to_find_one() {
    let (ok, _, err) = cli(&["simulate", "no-such-scene"]);
    assert!(!ok);
    assert!(
        err.contains("no-such-scene") && err.contains("rolling-disk scenes"),
        "{err}"
    );
}

#[test]
fn an_unwritable_csv_is_an_error_not_a_panic() {
    let (ok, _, err) = cli(&[
        "simulate",
        "spinning-coin",
        "--csv",
        "/nonexistent-dir/x.csv",
    ]);
    assert!(!ok);
    assert!(err.contains("cannot write /nonexistent-dir/x.csv"), "{err}");
}

#[test]
fn check_runs_the_selected_checks_and_refuses_unknown_ones() {
    let (ok, out, err) = cli(&["check", "--only", "23-25,29"]);
    assert!(ok, "{err}");
    for eq in ["eq 23", "eq 24", "eq 25", "eq 29"] {
        assert!(out.contains(eq), "{eq} missing:\n{out}");
    }
    assert!(out.contains("4 equations:"), "{out}");
    let (ok, _, err) = cli(&["check", "--only", "99"]);
    assert!(!ok && err.contains("1 to 85"), "{err}");
    let (ok, _, err) = cli(&["check", "--only", "no-such-claim"]);
    assert!(!ok && err.contains("no-such-claim"), "{err}");
}

/// `schemas/check.schema.json`, checked equal to the schema of the code (bless with
/// `ROLLING_DISK_BLESS=1`).
fn check_schema() -> serde_json::Value {
    let path =
        std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("schemas/check.schema.json");
    let generated = report::json::check_schema().unwrap();
    if std::env::var_os("ROLLING_DISK_BLESS").is_some() {
        std::fs::write(&path, &generated).unwrap();
    }
    let published = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        published == generated,
        "{} is not the schema of the code: run `ROLLING_DISK_BLESS=1 cargo test --release --test \
         integration cli::check_json` and commit it",
        path.display()
    );
    serde_json::from_str(&published).unwrap()
}

#[test]
fn check_json_validates_and_says_root_causes_and_inherited_errors() {
    let (ok, out, err) = cli(&["check", "--only", "26,72-79", "--json"]);
    assert!(ok, "{err}");
    let doc: serde_json::Value = serde_json::from_str(&out).unwrap();
    let validator = jsonschema::validator_for(&check_schema()).unwrap();
    let errors: Vec<String> = validator.iter_errors(&doc).map(|e| e.to_string()).collect();
    assert!(errors.is_empty(), "{errors:?}");
    assert!(!out.contains("\"Ok\"") && !out.contains("\"Err\""), "{out}");
    let checks = doc["checks"].as_array().unwrap();
    let eq = |n: u64| {
        checks
            .iter()
            .find(|c| c["equation"] == n)
            .unwrap_or_else(|| panic!("eq {n} missing"))
    };
    assert_eq!(eq(26)["outcome"]["status"], "checked");
    assert!(eq(26)["cause"].is_null());
    assert_eq!(eq(72)["cause"]["kind"], "root_cause");
    assert_eq!(eq(73)["cause"]["kind"], "root_cause");
    assert_eq!(
        eq(73)["cause"]["also_inherits_from"],
        serde_json::json!([72])
    );
    for n in [76, 77, 78, 79] {
        assert_eq!(eq(n)["cause"]["kind"], "inherits", "eq {n}");
        assert_eq!(eq(n)["cause"]["roots"], serde_json::json!([73]), "eq {n}");
        assert_eq!(
            eq(n)["derivation"]["verdict"]
                .as_str()
                .map(|v| v != "fails"),
            Some(true)
        );
    }
    let roots = &doc["summary"]["root_causes"];
    assert_eq!(roots[1]["equation"], 73, "{roots}");
    assert_eq!(
        roots[1]["consequences"],
        serde_json::json!([76, 77, 78, 79])
    );
    // Premises were run to classify, but only what was asked is listed.
    assert_eq!(checks.len(), 9);
}

/// Every checked finding says what unit its printed and true values are in (the
/// unit of a printed relation's sides from the chain's one-symbol side, `order` for an
/// approximation's orders, otherwise stated by the check), and the report shows it.
#[test]
fn every_checked_finding_states_the_unit_of_its_values() {
    let (ok, out, err) = cli(&["check", "--json"]);
    assert!(ok, "{err}");
    let doc: serde_json::Value = serde_json::from_str(&out).unwrap();
    let mut missing = Vec::new();
    let mut checked = 0;
    for c in doc["checks"].as_array().unwrap() {
        let o = &c["outcome"];
        if o["status"] != "checked" {
            continue;
        }
        checked += 1;
        if o["unit"].as_str().is_none_or(|u| u.is_empty()) {
            missing.push(c["name"].to_string());
        }
    }
    assert!(checked > 100, "{checked}");
    assert!(missing.is_empty(), "no unit: {missing:?}");
    let unit = |name: &str| {
        doc["checks"]
            .as_array()
            .unwrap()
            .iter()
            .find(|c| c["name"] == name)
            .map(|c| c["outcome"]["unit"].clone())
    };
    // From a one-symbol side of the chain: eq 26's E, eq 3's omega_123, eq 29's Omega_0^2 (the
    // check states it: no side is one symbol), eq 55's orders.
    assert_eq!(unit("eq 26"), Some(serde_json::json!("J")));
    assert_eq!(unit("eq 3"), Some(serde_json::json!("rad/s")));
    assert_eq!(unit("eq 29"), Some(serde_json::json!("rad^2/s^2")));
    assert_eq!(unit("eq 55"), Some(serde_json::json!("order")));
}

#[test]
fn experiment_simulate_then_analyze_round_trips_and_bad_csvs_are_refused() {
    let dir = temp_dir("cli", "experiment");
    let csv = dir.join("trace.csv");
    let (ok, _, err) = cli(&[
        "experiment",
        "simulate",
        "spin-down",
        "--csv",
        csv.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    let (ok, out, err) = cli(&["experiment", "analyze", csv.to_str().unwrap()]);
    assert!(ok, "{err}");
    assert!(out.contains("beta"), "{out}");
    let bad = dir.join("bad.csv");
    std::fs::write(&bad, "t,v\n0.0,1.0\n0.1,nan\n").unwrap();
    let (ok, _, err) = cli(&["experiment", "analyze", bad.to_str().unwrap()]);
    assert!(!ok);
    assert!(err.contains("bad.csv") && err.contains('3'), "{err}");
    assert!(!err.contains("panicked"), "{err}");
}

/// A user's own sliding spin-down (friction, eq 75's law as a drag) recorded as a scope trace
/// and as a WAV with every artifact, and analysed: the truth line says when the disk first
/// slips; a rolling scene with friction is refused with the key named.
#[test]
fn experiment_simulate_records_a_sliding_spin_down() {
    let dir = temp_dir("cli", "sliding-experiment");
    let scene = dir.join("sliding.yaml");
    std::fs::write(
        &scene,
        "name: sliding-spin-down\n\
         disk: { radius: 0.0375, k: 0.25, mass: 0.4, g: 9.81 }\n\
         model: sliding\n\
         friction: { mu: 0.6, restitution: 0.0 }\n\
         dissipation: { epsilon: 1.14e-6, beta: 2 }\n\
         start: { steady: { alpha0: 0.12, b: 0.0 } }\n\
         stop: { time: 30.0, alpha_below: 1.0e-4 }\n",
    )
    .unwrap();
    for (flag, file) in [("--csv", "sliding.csv"), ("--wav", "sliding.wav")] {
        let out_file = dir.join(file);
        let (ok, out, err) = cli(&[
            "experiment",
            "simulate",
            scene.to_str().unwrap(),
            flag,
            out_file.to_str().unwrap(),
            "--realistic",
        ]);
        assert!(ok, "{err}");
        assert!(
            out.contains("sliding model") && out.contains("first slips at record time"),
            "{out}"
        );
        let (ok, out, err) = cli(&["experiment", "analyze", out_file.to_str().unwrap()]);
        assert!(ok, "{file}: {err}");
        assert!(out.contains("beta"), "{out}");
    }
    let rolling = dir.join("rolling.yaml");
    let text = std::fs::read_to_string(&scene)
        .unwrap()
        .replace("model: sliding", "model: dissipative");
    std::fs::write(&rolling, text).unwrap();
    let (ok, _, err) = cli(&[
        "experiment",
        "simulate",
        rolling.to_str().unwrap(),
        "--csv",
        dir.join("r.csv").to_str().unwrap(),
    ]);
    assert!(!ok);
    assert!(
        err.contains("rolling.yaml") && err.contains("friction"),
        "{err}"
    );
}

#[test]
fn simulate_compares_a_scene_with_the_lab_frame_model() {
    let (ok, out, err) = cli(&["simulate", "nutating-coin", "--compare", "lab-frame"]);
    assert!(ok, "{err}");
    assert!(out.contains("rolling against lab-frame"), "{out}");
    // Every recorded quantity agrees to better than 1e-8 of its range.
    for line in out
        .lines()
        .filter(|l| l.contains("_rad") || l.contains("_J"))
    {
        let cols: Vec<&str> = line.split_whitespace().collect();
        let relative: f64 = cols[2].parse().unwrap();
        assert!(relative < 1e-8, "{line}");
    }
    let (ok, _, err) = cli(&["simulate", "spin-down", "--compare", "lab-frame"]);
    assert!(!ok && err.contains("no dissipation"), "{err}");
}

/// A scene file in `dir`: nutating-coin with its stop time, sampling and solver replaced.
fn nutating_scene(
    dir: &std::path::Path,
    name: &str,
    time: f64,
    sample: f64,
    solver: &str,
) -> String {
    let src = std::fs::read_to_string("paper/scenes/nutating-coin.yaml").unwrap();
    let text: String = src
        .lines()
        .map(|l| {
            if l.starts_with("stop:") {
                format!("stop: {{ time: {time} }}\n")
            } else if l.starts_with("sample:") {
                format!("sample: {sample:e}\n")
            } else if l.starts_with("solver:") {
                format!("{solver}\n")
            } else {
                format!("{l}\n")
            }
        })
        .collect();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.to_str().unwrap().to_string()
}

#[test]
fn simulate_streams_more_rows_than_a_run_held_in_memory_may_hold() {
    let dir = temp_dir("cli", "stream");
    let solver = "solver: { method: dop853, rtol: 1.0e-10, atol: 1.0e-12 }";
    // 0.3 s every 0.25 us: 1,200,000 samples and the end, beyond the 1,000,000 rows a run held
    // in memory may record.
    let scene = nutating_scene(&dir, "fine.yaml", 0.3, 2.5e-7, solver);
    let csv = dir.join("fine.csv");
    let (ok, out, err) = cli(&["simulate", &scene, "--csv", csv.to_str().unwrap()]);
    assert!(ok, "{err}");
    assert!(out.contains("1200001 rows written"), "{out}");
    let text = std::fs::read_to_string(&csv).unwrap();
    assert_eq!(text.lines().count(), 1_200_002, "the header and every row");
    let last = last_row(&text);
    assert_eq!(last[0], 0.3);
    // The same rows to standard output, byte for byte.
    let piped = Command::new(env!("CARGO_BIN_EXE_rolling-disk"))
        .args(["simulate", &scene, "--csv", "-"])
        .output()
        .unwrap();
    assert!(piped.status.success());
    assert!(
        piped.stdout == text.as_bytes(),
        "stdout differs from the file"
    );
    assert_eq!(
        std::fs::read_dir(&dir).unwrap().count(),
        2,
        "no temporary file left"
    );
}

#[test]
fn a_failed_streamed_run_leaves_the_old_csv_and_no_temporary_file() {
    let dir = temp_dir("cli", "stream-fail");
    // rk4 with a step of half a second cannot resolve the coin's nutation: no number of the
    // run means anything, so none may be written.
    let scene = nutating_scene(
        &dir,
        "coarse.yaml",
        1.0,
        1e-4,
        "solver: { method: rk4, step: 0.5 }",
    );
    let csv = dir.join("old.csv");
    std::fs::write(&csv, "old\n").unwrap();
    let (ok, _, err) = cli(&["simulate", &scene, "--csv", csv.to_str().unwrap()]);
    assert!(!ok);
    assert!(err.contains("rk4 went unstable"), "{err}");
    assert_eq!(std::fs::read_to_string(&csv).unwrap(), "old\n");
    assert_eq!(
        std::fs::read_dir(&dir).unwrap().count(),
        2,
        "no temporary file left"
    );
    // To standard output: nothing at all.
    let piped = Command::new(env!("CARGO_BIN_EXE_rolling-disk"))
        .args(["simulate", &scene, "--csv", "-"])
        .output()
        .unwrap();
    assert!(!piped.status.success());
    assert!(
        piped.stdout.is_empty(),
        "{} bytes on stdout",
        piped.stdout.len()
    );
}
