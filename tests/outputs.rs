//! Outputs as a careful tool writes them: a closed pipe ends the program quietly, `-` is
//! standard output, a symlink, a FIFO or a device is written through and never replaced, a
//! read-only file is refused, and `experiment analyze --out` touches only the files it wrote.

use crate::common::{cli_in, temp_dir};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_rolling-disk"))
}

/// A spin-down scope trace (4 s, a few thousand rows), written once per test that needs one.
fn spin_down_csv(dir: &Path) -> PathBuf {
    let csv = dir.join("trace.csv");
    let (ok, _, err) = cli_in(dir, &["experiment", "simulate", "--csv", "trace.csv"]);
    assert!(ok, "{err}");
    csv
}

/// Runs `args` with standard output a pipe whose reader is already gone: the program must end
/// with status 0 or 141 (128 + SIGPIPE), without a panic and without a word on standard error
/// about the pipe.
fn closed_pipe(dir: &Path, args: &[&str]) {
    let mut child = bin()
        .args(args)
        .current_dir(dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary starts");
    drop(child.stdout.take());
    let out = child.wait_with_output().expect("the binary ends");
    let err = String::from_utf8_lossy(&out.stderr);
    let code = out.status.code();
    assert!(
        code == Some(0) || code == Some(141),
        "{args:?}: status {:?}, stderr {err}",
        out.status
    );
    assert!(!err.contains("panicked"), "{args:?}: {err}");
    assert!(!err.contains("Broken pipe"), "{args:?}: {err}");
}

#[test]
fn a_closed_pipe_ends_every_printing_command_quietly() {
    let dir = temp_dir("outputs", "pipe");
    let csv = spin_down_csv(&dir);
    let (ok, _, err) = cli_in(&dir, &["experiment", "simulate", "--wav", "sound.wav"]);
    assert!(ok, "{err}");
    let csv = csv.to_str().unwrap_or("");
    for args in [
        &["scenes"][..],
        &["check", "--only", "23-25"],
        &["check", "--only", "23-25", "--json"],
        &["experiment", "analyze", csv],
        &["experiment", "analyze", "sound.wav"],
        &["simulate", "spinning-coin", "--csv", "-"],
    ] {
        closed_pipe(&dir, args);
    }
}

#[test]
fn a_dash_is_standard_output_and_no_file_named_dash_appears() {
    let dir = temp_dir("outputs", "dash");
    let (ok, out, err) = cli_in(&dir, &["simulate", "spinning-coin", "--csv", "-"]);
    assert!(ok, "{err}");
    assert!(out.starts_with("t_s,alpha_rad,"), "{out:.200}");
    assert!(err.contains("rows written to -"), "{err}");
    let (ok, out, err) = cli_in(&dir, &["experiment", "simulate", "--csv", "-"]);
    assert!(ok, "{err}");
    assert!(out.lines().count() > 1000, "{out:.200}");
    assert!(!out.contains("samples written"), "{out:.200}");
    let (ok, out, err) = cli_in(&dir, &["experiment", "simulate", "--wav", "-"]);
    assert!(ok, "{err}");
    assert!(
        out.starts_with("RIFF"),
        "{:?}",
        &out.as_bytes()[..4.min(out.len())]
    );
    assert!(!dir.join("-").exists());
}

#[cfg(unix)]
#[test]
fn a_symlink_is_written_through_and_a_read_only_file_is_refused_untouched() {
    use std::os::unix::fs::PermissionsExt;
    let dir = temp_dir("outputs", "links");
    std::fs::write(dir.join("real.csv"), "mine").expect("written");
    std::os::unix::fs::symlink("real.csv", dir.join("link.csv")).expect("a symlink");
    let (ok, _, err) = cli_in(&dir, &["simulate", "spinning-coin", "--csv", "link.csv"]);
    assert!(ok, "{err}");
    let meta = std::fs::symlink_metadata(dir.join("link.csv")).expect("still there");
    assert!(meta.file_type().is_symlink());
    let text = std::fs::read_to_string(dir.join("real.csv")).unwrap_or_default();
    assert!(text.starts_with("t_s,"), "{text:.100}");

    let ro = dir.join("ro.csv");
    std::fs::write(&ro, "keep me").expect("written");
    std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o444)).expect("chmod");
    for args in [
        &["simulate", "spinning-coin", "--csv", "ro.csv"][..],
        &["experiment", "simulate", "--csv", "ro.csv"],
        &["experiment", "simulate", "--wav", "ro.csv"],
    ] {
        let (ok, _, err) = cli_in(&dir, args);
        assert!(!ok, "{args:?}");
        assert!(err.contains("ro.csv: is read-only"), "{err}");
        assert_eq!(std::fs::read_to_string(&ro).unwrap_or_default(), "keep me");
    }
}

#[cfg(unix)]
#[test]
fn a_fifo_and_a_device_are_written_through_never_replaced() {
    use std::os::unix::fs::FileTypeExt;
    let dir = temp_dir("outputs", "fifo");
    let fifo = dir.join("pipe.csv");
    let made = Command::new("mkfifo").arg(&fifo).status();
    if made.is_ok_and(|s| s.success()) {
        let reader = {
            let fifo = fifo.clone();
            std::thread::spawn(move || std::fs::read_to_string(fifo).unwrap_or_default())
        };
        let (ok, _, err) = cli_in(&dir, &["simulate", "spinning-coin", "--csv", "pipe.csv"]);
        assert!(ok, "{err}");
        let text = reader.join().unwrap_or_default();
        assert!(text.starts_with("t_s,"), "{text:.100}");
        let meta = std::fs::symlink_metadata(&fifo).expect("still there");
        assert!(meta.file_type().is_fifo());
    }
    // Only the devices this machine has as character devices (a sandbox may have regular files).
    let device =
        |p: &str| std::fs::symlink_metadata(p).is_ok_and(|m| m.file_type().is_char_device());
    let devices: Vec<&str> = ["/dev/null", "/dev/full"]
        .into_iter()
        .filter(|d| device(d))
        .collect();
    if devices.contains(&"/dev/null") {
        let (ok, _, err) = cli_in(&dir, &["simulate", "spinning-coin", "--csv", "/dev/null"]);
        assert!(ok, "{err}");
    }
    if devices.contains(&"/dev/full") {
        let (ok, _, err) = cli_in(&dir, &["experiment", "simulate", "--csv", "/dev/full"]);
        assert!(!ok);
        assert!(err.contains("/dev/full"), "{err}");
    }
    for dev in devices {
        assert!(device(dev), "{dev} replaced");
    }
}

fn names(dir: &Path) -> Vec<String> {
    let mut n: Vec<String> = std::fs::read_dir(dir)
        .map(|d| {
            d.flatten()
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    n.sort();
    n
}

#[test]
fn analyze_out_touches_only_its_own_set() {
    let dir = temp_dir("outputs", "analyze-out");
    let csv = spin_down_csv(&dir);
    let csv = csv.to_str().unwrap_or("");
    let (ok, _, err) = cli_in(&dir, &["experiment", "simulate", "--wav", "sound.wav"]);
    assert!(ok, "{err}");

    // A directory of someone else's files is refused and kept.
    std::fs::create_dir_all(dir.join("theirs")).expect("made");
    std::fs::write(dir.join("theirs/thesis.tex"), "mine").expect("written");
    let (ok, _, err) = cli_in(&dir, &["experiment", "analyze", csv, "--out", "theirs"]);
    assert!(!ok);
    assert!(
        err.contains("not a set of outputs written by this tool"),
        "{err}"
    );
    assert_eq!(names(&dir.join("theirs")), vec!["thesis.tex".to_string()]);

    // A set is written, then replaced whole by another analysis: no stale file is left.
    let (ok, _, err) = cli_in(
        &dir,
        &["experiment", "analyze", "sound.wav", "--out", "set"],
    );
    assert!(ok, "{err}");
    assert!(names(&dir.join("set")).contains(&"track.csv".to_string()));
    let (ok, _, err) = cli_in(&dir, &["experiment", "analyze", csv, "--out", "set"]);
    assert!(ok, "{err}");
    let after = names(&dir.join("set"));
    assert!(after.contains(&"peaks.csv".to_string()), "{after:?}");
    assert!(!after.contains(&"track.csv".to_string()), "{after:?}");

    // A file of the user's put into the set is not deleted: the run is refused.
    std::fs::write(dir.join("set/notes.txt"), "mine").expect("written");
    let (ok, _, err) = cli_in(&dir, &["experiment", "analyze", csv, "--out", "set"]);
    assert!(!ok);
    assert!(err.contains("holds notes.txt"), "{err}");
    assert_eq!(
        std::fs::read_to_string(dir.join("set/notes.txt")).unwrap_or_default(),
        "mine"
    );
}

#[cfg(unix)]
#[test]
fn a_read_only_empty_directory_given_to_out_is_refused_and_kept() {
    use std::os::unix::fs::PermissionsExt;
    let dir = temp_dir("outputs", "ro-out");
    let csv = spin_down_csv(&dir);
    let ro = dir.join("locked");
    std::fs::create_dir_all(&ro).expect("made");
    std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o555)).expect("chmod");
    let (ok, _, err) = cli_in(
        &dir,
        &[
            "experiment",
            "analyze",
            csv.to_str().unwrap_or(""),
            "--out",
            "locked",
        ],
    );
    assert!(!ok);
    assert!(err.contains("cannot write to"), "{err}");
    let mode = std::fs::metadata(&ro).map(|m| m.permissions().mode() & 0o777);
    assert_eq!(mode.ok(), Some(0o555));
    assert!(names(&ro).is_empty());
    std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o755)).ok();
}

/// The report command's closing line counts every equation, in every verdict the report
/// tallies: the counts add up to the paper's 85 and agree with `check --json`; its claims are
/// check's closing line on the claims, word for word.
#[test]
fn the_report_commands_count_is_every_equation() {
    let dir = temp_dir("outputs", "count");
    let out = dir.join("r");
    let (ok, stdout, err) = cli_in(&dir, &["report", "--format", "json", "--out", "r"]);
    assert!(ok, "{err}");
    let line = stdout.lines().next().unwrap_or_default();
    let (ok, json, err) = cli_in(&dir, &["check", "--json"]);
    assert!(ok, "{err}");
    let doc: serde_json::Value = serde_json::from_str(&json).expect("check --json");
    let s = &doc["summary"]["equations"];
    let n = |k: &str| s[k].as_u64().unwrap_or(0);
    let total = [
        "holds",
        "holds_approximately",
        "definitions",
        "estimates",
        "premise_fails",
        "fails",
        "depends",
        "dimensional_slips",
        "not_run",
    ]
    .iter()
    .map(|k| n(k))
    .sum::<u64>();
    assert_eq!(total, 85, "{s}");
    assert!(
        line.starts_with(&format!("{total} equations checked: {} hold,", n("holds"))),
        "{line}"
    );
    let fail = if n("fails") == 1 { "fails" } else { "fail" };
    assert!(line.contains(&format!("{} {fail}", n("fails"))), "{line}");
    // The claims are counted in check's own closing line's words, every verdict class (parts
    // of another claim's statement, restatements, depends) included.
    let (ok, text, err) = cli_in(&dir, &["check"]);
    assert!(ok, "{err}");
    let claims = text
        .lines()
        .find(|l| {
            l.split_once(' ')
                .is_some_and(|(n, rest)| n.parse::<u64>().is_ok() && rest.starts_with("claims: "))
        })
        .expect("check's closing line on the claims");
    assert!(
        line.ends_with(&format!("; {claims}")),
        "{line}\nagainst check's: {claims}"
    );
    assert!(out.join("report.json").is_file());
    let _ = std::fs::remove_dir_all(&dir);
}
