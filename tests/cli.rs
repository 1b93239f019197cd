//! The command line as a user meets it.

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

fn temp_dir(tag: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("rolling-disk-cli-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
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
    let dir = temp_dir("csv");
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
    let dir = temp_dir("bad");
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
