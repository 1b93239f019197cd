//! No input may hang, exhaust memory or yield a silent wrong answer. Each class of
//! hostile input found by the hostile runs has a test here, run through the binary as a user
//! would, with a time bound where the complaint was a hang.

use crate::common::temp_dir;
use physics::scene::Scene;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const BIN: &str = env!("CARGO_BIN_EXE_rolling-disk");

/// Runs the binary; (success, stdout, stderr, seconds taken).
pub(crate) fn cli(args: &[&str]) -> (bool, String, String, f64) {
    let started = Instant::now();
    let out = Command::new(BIN)
        .args(args)
        .stdin(Stdio::null())
        .output()
        .expect("the binary runs");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
        started.elapsed().as_secs_f64(),
    )
}

const SPIN_DOWN: &str = include_str!("../paper/scenes/spin-down.yaml");
const NUTATING: &str = include_str!("../paper/scenes/nutating-coin.yaml");

/// Writes `text` as a scene and simulates it; asserts a refusal in one sentence within `secs`.
fn refused(tag: &str, text: &str, secs: f64, words: &[&str]) -> String {
    let dir = temp_dir("limits", tag);
    let path = dir.join("scene.yaml");
    std::fs::write(&path, text).expect("written");
    let (ok, out, err, took) = cli(&["simulate", path.to_str().expect("utf-8 path")]);
    assert!(!ok, "{tag}: accepted:\n{out}");
    assert!(took < secs, "{tag}: took {took:.2} s");
    assert_eq!(err.lines().count(), 1, "{tag}: not one line:\n{err}");
    assert!(err.len() < 700, "{tag}: {} characters", err.len());
    for w in words {
        assert!(err.contains(w), "{tag}: expected {w:?} in {err}");
    }
    let _ = std::fs::remove_dir_all(&dir);
    err
}

#[test]
fn tiny_sample_and_step_are_refused_in_under_a_second() {
    let sample = SPIN_DOWN.replace("solver:", "sample: 1.0e-9\nsolver:");
    refused(
        "sample",
        &sample,
        1.0,
        &["scene.yaml:", "sample", "raise sample"],
    );
    let step = SPIN_DOWN.replace(
        "method: dop853, rtol: 1.0e-10, atol: 1.0e-12",
        "method: rk4, step: 1.0e-9, max_steps: 4294967295",
    );
    refused("step", &step, 1.0, &["max_steps must lie between 1 and"]);
    let step = SPIN_DOWN.replace(
        "method: dop853, rtol: 1.0e-10, atol: 1.0e-12",
        "method: rk4, step: 1.0e-9, max_steps: 50000000",
    );
    refused(
        "step2",
        &step,
        1.0,
        &["solver: rk4 with step 1e-9 s", "raise step"],
    );
}

#[test]
fn an_unstable_rk4_run_is_reported_as_unstable_with_no_numbers() {
    let rk4 = SPIN_DOWN.replace(
        "{ method: dop853, rtol: 1.0e-10, atol: 1.0e-12 }",
        "{ method: rk4 }",
    );
    let dir = temp_dir("limits", "rk4");
    let path = dir.join("rk4.yaml");
    std::fs::write(&path, rk4).expect("written");
    let (ok, out, err, _) = cli(&["simulate", path.to_str().expect("utf-8")]);
    assert!(!ok);
    assert!(err.contains("rk4 went unstable"), "{err}");
    assert!(!out.contains("alpha ="), "numbers printed:\n{out}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn solver_settings_and_physical_values_that_cannot_mean_anything_are_refused() {
    let solver = "{ method: dop853, rtol: 1.0e-10, atol: 1.0e-12 }";
    for (tag, from, to, word) in [
        (
            "rtol-big",
            solver,
            "{ rtol: 1.0e300 }",
            "rtol must lie strictly between 0 and 1",
        ),
        (
            "rtol-one",
            solver,
            "{ rtol: 1.0 }",
            "rtol must lie strictly between 0 and 1",
        ),
        (
            "atol",
            solver,
            "{ atol: -1.0 }",
            "atol must be a number of at least 1e-30",
        ),
        (
            "atol-zero",
            solver,
            "{ atol: 0 }",
            "atol must be a number of at least 1e-30",
        ),
        ("rtol-nan", solver, "{ rtol: .nan }", "rtol"),
        (
            "radius",
            "radius: 0.01213",
            "radius: 1.0e308",
            "disk.radius = 1e308 is outside",
        ),
        (
            "mass",
            "mass: 0.00567",
            "mass: 1.0e300",
            "disk.mass = 1e300 is outside",
        ),
        ("g", "g: 9.81", "g: 1.0e-300", "disk.g = 1e-300 is outside"),
        ("k", "k: 0.25", "k: 1.0e200", "disk.k = 1e200 is outside"),
        (
            "spin",
            "perturb: { alpha: 1.0e-3 }",
            "perturb: { spin: 1.0e300 }",
            "spin = 1e300 rad/s is beyond",
        ),
    ] {
        assert!(NUTATING.contains(from), "{tag}");
        refused(tag, &NUTATING.replace(from, to), 1.0, &[word]);
    }
}

#[test]
fn a_byte_order_mark_and_every_line_end_read_the_same() {
    let plain = Scene::parse(NUTATING, "x.yaml").expect("the built-in scene");
    for (tag, text) in [
        ("bom", format!("\u{feff}{NUTATING}")),
        ("crlf", NUTATING.replace('\n', "\r\n")),
        ("cr", NUTATING.replace('\n', "\r")),
        (
            "bom-crlf",
            format!("\u{feff}{}", NUTATING.replace('\n', "\r\n")),
        ),
    ] {
        let s = Scene::parse(&text, "x.yaml").unwrap_or_else(|e| panic!("{tag}: {e}"));
        assert_eq!(s, plain, "{tag}");
    }
    // And through the file reader: a line number counts CR-only lines as lines.
    let bad = NUTATING.replace("k: 0.25", "k: -1").replace('\n', "\r");
    refused("cr-line", &bad, 1.0, &["scene.yaml:5:", "inertia factor"]);
}

#[test]
fn tabs_and_unknown_keys_get_sentences_in_the_tools_terms() {
    let tab = "name: t\ndisk:\n\tradius: 0.1\n";
    let e = refused("tab", tab, 1.0, &["scene.yaml:3:", "spaces"]);
    assert!(!e.contains("struct"), "{e}");
    let typo = NUTATING.replace("radius:", "raduis:");
    refused(
        "typo",
        &typo,
        1.0,
        &["unknown key `raduis`", "did you mean `radius`?"],
    );
    let jargon = NUTATING.replace("k: 0.25", "k: { a: 1 }");
    let e = refused(
        "map",
        &jargon,
        1.0,
        &["disk.k: expected a number, found a mapping"],
    );
    for word in ["f64", "invalid type", "map,", "struct", "variant", "field"] {
        assert!(!e.contains(word), "jargon {word:?} in {e}");
    }
}

#[test]
fn a_huge_value_is_quoted_cut() {
    let long = "x".repeat(10 << 20);
    let text = NUTATING.replace("k: 0.25", &format!("k: \"{long}\""));
    // Over the 1 MiB limit of a scene file: refused before parsing.
    refused(
        "huge-file",
        &text,
        2.0,
        &["larger than the limit of 1048576 bytes"],
    );
    let long = "x".repeat(900_000);
    let text = NUTATING.replace("k: 0.25", &format!("k: \"{long}\""));
    refused("huge-value", &text, 2.0, &["(900000 characters)"]);
}

#[test]
fn deep_nesting_is_refused_at_once() {
    let flow = format!("name: {}{}\n", "[".repeat(100_000), "]".repeat(100_000));
    refused("flow", &flow, 1.0, &["nests deeper than 32 levels"]);
    let block: String = (0..1000)
        .map(|i| format!("{}k{i}:\n", " ".repeat(i)))
        .collect();
    refused("block", &block, 1.0, &["nests deeper than 32 levels"]);
}

#[test]
fn fifos_devices_and_directories_are_refused_at_once() {
    let dir = temp_dir("limits", "special");
    let fifo = dir.join("scene.fifo");
    let made = Command::new("mkfifo").arg(&fifo).status();
    let mut paths = vec![PathBuf::from("/dev/zero"), dir.clone()];
    if made.is_ok_and(|s| s.success()) {
        paths.push(fifo);
    }
    for p in paths {
        let (ok, _, err, took) = cli(&["simulate", p.to_str().expect("utf-8")]);
        assert!(!ok);
        assert!(took < 1.0, "{}: {took:.2} s", p.display());
        assert!(err.contains("not a regular file"), "{err}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn empty_selections_are_refused() {
    for args in [
        &["check", "--only", ""][..],
        &["check", "--only", " , "],
        &["figures", "--only", ""],
    ] {
        let (ok, _, err, _) = cli(args);
        assert!(!ok, "{args:?} accepted");
        assert!(err.contains("--only was given"), "{err}");
    }
    let (ok, _, err, _) = cli(&["--max-seconds", "0", "scenes"]);
    assert!(
        !ok && err.contains("--max-seconds") && err.contains("above 0, at most 86400"),
        "{err}"
    );
}

#[test]
fn the_wall_time_budget_ends_a_long_integration_and_says_so() {
    let long = NUTATING
        .replace("stop: { time: 1.0 }", "stop: { time: 10000.0 }")
        .replace("sample: 0.0005", "sample: 1.0")
        .replace(
            "rtol: 1.0e-10, atol: 1.0e-12",
            "rtol: 1.0e-13, atol: 1.0e-15",
        );
    let dir = temp_dir("limits", "wall");
    let path = dir.join("long.yaml");
    std::fs::write(&path, long).expect("written");
    let (ok, _, err, took) = cli(&["--max-seconds", "0.3", "simulate", path.to_str().expect("")]);
    assert!(!ok);
    assert!(took < 5.0, "took {took:.2} s");
    assert!(err.contains("wall-time budget of 0.3 s ran out"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn report_refuses_an_unusable_out_before_computing() {
    let dir = temp_dir("limits", "out");
    let file = dir.join("a-file");
    std::fs::write(&file, "x").expect("written");
    std::fs::write(dir.join("notes.txt"), "mine").expect("written");
    for (out, word) in [
        (file.join("report"), "cannot write beside it"),
        (file.clone(), "is not a directory"),
        (dir.clone(), "is not a set of outputs written by this tool"),
    ] {
        let (ok, _, err, took) = cli(&["report", "--out", out.to_str().expect("utf-8")]);
        assert!(!ok);
        assert!(took < 1.0, "{}: {took:.2} s", out.display());
        assert!(err.contains(word), "{err}");
    }
    assert!(dir.join("notes.txt").is_file());
    let _ = std::fs::remove_dir_all(&dir);
}

/// The report set: killed at random moments many times (a seeded sequence of delays spread
/// over a whole run), the output directory always holds one complete set, the previous or the
/// new, whose manifest lists exactly its files; once a run completes, nothing temporary is
/// left beside it. Successive runs alternate the format so that a mix of two runs would show.
#[test]
fn killing_report_at_random_moments_never_leaves_a_mixed_or_partial_set() {
    let root = temp_dir("limits", "kill");
    let out = root.join("report");
    let run = |format: &str| {
        Command::new(BIN)
            .args(["report", "--format", format, "--out"])
            .arg(&out)
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .expect("the binary starts")
    };
    // One complete run, timed, so that the kills spread over a whole run.
    let started = Instant::now();
    let status = run("json").wait().expect("it runs");
    assert!(status.success());
    let whole = started.elapsed().as_secs_f64();
    check_set(&out);
    // Kill until 15 runs were killed before they ended (a run that ends before its kill is
    // checked too, but does not count): how long a run takes varies with the machine's load,
    // so the number of attempts adapts, up to a bound.
    let mut seed: u64 = 0x2001_0816;
    let (wanted, most) = (15, 90);
    let (mut killed_before_end, mut attempts) = (0, 0);
    while killed_before_end < wanted && attempts < most {
        seed = seed
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        let fraction = (seed >> 11) as f64 / (1u64 << 53) as f64;
        let format = if attempts % 2 == 0 { "html" } else { "json" };
        attempts += 1;
        let mut child = run(format);
        std::thread::sleep(Duration::from_secs_f64(fraction * whole * 1.1));
        if child.try_wait().ok().flatten().is_none() {
            killed_before_end += 1;
        }
        let _ = child.kill();
        let _ = child.wait();
        check_set(&out);
    }
    assert!(
        killed_before_end >= wanted,
        "only {killed_before_end} of {attempts} runs were killed before they ended"
    );
    let status = run("json").wait().expect("it runs");
    assert!(status.success());
    check_set(&out);
    let left: Vec<String> = std::fs::read_dir(&root)
        .expect("listed")
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(left, vec!["report".to_string()], "temporaries left behind");
    let _ = std::fs::remove_dir_all(&root);
}

/// `out` holds a complete set: its manifest names every file in it, with its size, and nothing
/// else is there.
fn check_set(out: &Path) {
    let manifest = std::fs::read_to_string(out.join(".rolling-disk-set"))
        .unwrap_or_else(|e| panic!("no manifest in {}: {e}", out.display()));
    let mut listed: Vec<(u64, String)> = manifest
        .lines()
        .filter(|l| !l.starts_with('#'))
        .filter_map(|l| l.split_once(' '))
        .map(|(n, p)| (n.parse().expect("a size"), p.to_string()))
        .collect();
    listed.sort();
    let mut present = Vec::new();
    files(out, out, &mut present);
    present.sort();
    assert_eq!(listed, present, "the manifest and the files differ");
    assert!(!listed.is_empty());
    let kinds: Vec<&str> = listed.iter().map(|(_, p)| p.as_str()).collect();
    assert!(
        kinds == ["report.json"] || kinds == ["report.html"],
        "a mixed set: {kinds:?}"
    );
}

fn files(root: &Path, dir: &Path, into: &mut Vec<(u64, String)>) {
    for e in std::fs::read_dir(dir).expect("listed").flatten() {
        let p = e.path();
        if p.is_dir() {
            files(root, &p, into);
        } else if p.file_name().is_some_and(|n| n != ".rolling-disk-set") {
            let rel = p.strip_prefix(root).expect("inside").display().to_string();
            into.push((e.metadata().expect("metadata").len(), rel));
        }
    }
}

/// The RK4 resolution watch on modes whose stability is known: $\dot y = -\lambda y$ is stable
/// for RK4 up to $h\lambda = 2.785$; an oscillator is stable up to $h\omega = 2\sqrt 2$ and
/// resolved well below. Nothing is flagged where the method is stable and resolving, and the
/// real-axis mode beyond its limit is flagged.
#[test]
fn rk4_is_flagged_exactly_where_its_steps_stop_resolving() {
    use physics::solve::{solve, Dynamics, Ending, Method, Problem, Settings, State};
    struct Decay(f64);
    impl Dynamics<1> for Decay {
        fn rhs(&self, y: &State<1>, dy: &mut State<1>) {
            dy[0] = -self.0 * y[0];
        }
    }
    struct Oscillator(f64);
    impl Dynamics<2> for Oscillator {
        fn rhs(&self, y: &State<2>, dy: &mut State<2>) {
            dy[0] = y[1];
            dy[1] = -self.0 * self.0 * y[0];
        }
    }
    let rk4 = |step: f64| Settings {
        method: Method::Rk4,
        step,
        ..Settings::default()
    };
    for (z, flagged) in [
        (0.5, false),
        (2.0, false),
        (2.7, false),
        (2.9, true),
        (4.0, true),
    ] {
        let sol = solve(
            Problem::new(&Decay(1.0), 0.0, State::<1>::new(1.0), 200.0 * z),
            &rk4(z),
        )
        .expect("valid");
        assert_eq!(
            matches!(sol.ending, Ending::Unstable { .. }),
            flagged,
            "h lambda = {z}: {:?}",
            sol.ending
        );
    }
    for hw in [0.05, 0.3, 1.0] {
        let sol = solve(
            Problem::new(&Oscillator(1.0), 0.0, State::<2>::new(1.0, 0.0), 1000.0),
            &rk4(hw),
        )
        .expect("valid");
        assert_eq!(sol.ending, Ending::TimeReached, "h omega = {hw}");
    }
}

/// A start slip beyond a million times the natural speed sqrt(g a) is refused naming the key.
#[test]
fn a_slip_speed_beyond_its_range_is_refused_naming_the_key() {
    let scene = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("paper/scenes/slip-stick.yaml"),
    )
    .expect("the built-in scene");
    let fast = scene.replace("forward: 0.3", "forward: 1.0e6");
    assert_ne!(fast, scene, "the scene's slip was replaced");
    refused(
        "slip",
        &fast,
        1.0,
        &[
            "scene.yaml:9",
            "slip forward = 1000000 m/s",
            "beyond the supported",
        ],
    );
}
