//! `-` for standard input and output wherever a command reads or writes a file: a scene piped
//! into `simulate -`, the trajectory written by `--csv -`, a scope CSV and a WAV piped into
//! `experiment analyze -`, a snapshot written by `check --snapshot -` and read by `--against -`.
//! Each gives what the same file would; what cannot be done with a stream (a set of files on
//! standard output, standard input read twice, a blessed snapshot on standard input) is refused
//! in a sentence.

use crate::common::{cli_piped, cli_status, temp_dir};
use std::path::Path;

/// A short nutating coin as YAML (0.05 s of it).
fn short_scene(dir: &Path) -> String {
    let (code, template, err) = cli_status(dir, &["scenes", "--show", "nutating-coin"]);
    assert_eq!(code, 0, "{err}");
    assert!(template.contains("stop: { time: 1.0 }"), "{template}");
    template.replace("stop: { time: 1.0 }", "stop: { time: 0.05 }")
}

/// The summary lines but the scene's (which names its source).
fn without_source(summary: &str) -> Vec<&str> {
    summary
        .lines()
        .filter(|l| !l.starts_with("scene ") && !l.starts_with("trajectory:"))
        .collect()
}

#[test]
fn a_scene_is_read_from_standard_input_and_its_rows_written_to_standard_output() {
    let dir = temp_dir("stdio", "scene");
    let yaml = short_scene(&dir);
    std::fs::write(dir.join("coin.yaml"), &yaml).unwrap();
    let (code, from_file, err) = cli_status(&dir, &["simulate", "coin.yaml", "--csv", "coin.csv"]);
    assert_eq!(code, 0, "{err}");
    let (code, piped, err) = cli_piped(&dir, &["simulate", "-"], yaml.as_bytes());
    assert_eq!(code, 0, "{err}");
    assert!(
        piped.contains("scene       nutating-coin (stdin)"),
        "{piped}"
    );
    assert_eq!(without_source(&piped), without_source(&from_file));

    // Scene in, rows out: standard output carries the CSV alone, the summary goes to stderr.
    let (code, csv, err) = cli_piped(&dir, &["simulate", "-", "--csv", "-"], yaml.as_bytes());
    assert_eq!(code, 0, "{err}");
    assert_eq!(csv, std::fs::read_to_string(dir.join("coin.csv")).unwrap());
    assert!(err.contains("rows written to -"), "{err}");

    // A scene on standard input that is wrong is said with stdin and its line.
    let bad = yaml.replace("model: rolling", "model: rollin");
    let (code, _, err) = cli_piped(&dir, &["simulate", "-"], bad.as_bytes());
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("stdin:"), "{err}");
    let (code, _, err) = cli_piped(&dir, &["simulate", "-"], b"\xff\xfe");
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("stdin:1:") && err.contains("UTF-8"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The analysis of a text without its file's name: the lines that name the file dropped.
fn analysis_lines<'a>(text: &'a str, name: &str) -> Vec<&'a str> {
    text.lines().filter(|l| !l.contains(name)).collect()
}

#[test]
fn a_scope_csv_and_a_wav_are_analysed_from_standard_input() {
    let dir = temp_dir("stdio", "recording");
    // The scope's CSV, written to standard output.
    let (code, csv, err) = cli_status(&dir, &["experiment", "simulate", "--csv", "-"]);
    assert_eq!(code, 0, "{err}");
    assert!(
        csv.lines().any(|l| l == "time_s,signal_V"),
        "{}",
        &csv[..csv.len().min(400)]
    );
    std::fs::write(dir.join("trace.csv"), &csv).unwrap();
    let (code, from_file, err) = cli_status(&dir, &["experiment", "analyze", "trace.csv"]);
    assert_eq!(code, 0, "{err}");
    let (code, piped, err) = cli_piped(&dir, &["experiment", "analyze", "-"], csv.as_bytes());
    assert_eq!(code, 0, "{err}");
    assert!(!from_file.trim().is_empty());
    assert_eq!(
        analysis_lines(&piped, "stdin"),
        analysis_lines(&from_file, "trace.csv")
    );

    // A WAV: told apart from a CSV by its first bytes.
    let (code, _, err) = cli_status(&dir, &["experiment", "simulate", "--wav", "spin.wav"]);
    assert_eq!(code, 0, "{err}");
    let wav = std::fs::read(dir.join("spin.wav")).unwrap();
    let (code, from_file, err) = cli_status(&dir, &["experiment", "analyze", "spin.wav", "--json"]);
    assert_eq!(code, 0, "{err}");
    let (code, piped, err) = cli_piped(&dir, &["experiment", "analyze", "-", "--json"], &wav);
    assert_eq!(code, 0, "{err}");
    let a: serde_json::Value = serde_json::from_str(&from_file).unwrap();
    let b: serde_json::Value = serde_json::from_str(&piped).unwrap();
    assert_eq!(a["fit"], b["fit"], "{piped}");
    assert!(a["fit"].is_object(), "{from_file}");

    // Bytes that are neither: said, with what to pipe instead.
    let (code, _, err) = cli_piped(&dir, &["experiment", "analyze", "-"], b"\x00\x01\x02\xff");
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains("stdin") && err.contains("not a sound file"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_snapshot_goes_to_standard_output_and_comes_back_from_standard_input() {
    let dir = temp_dir("stdio", "snapshot");
    let (code, snapshot, err) = cli_status(&dir, &["check", "--only", "3,23", "--snapshot", "-"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value =
        serde_json::from_str(&snapshot).expect("stdout is the snapshot alone");
    assert_eq!(v["checks"].as_array().map(Vec::len), Some(2));
    let (code, out, err) = cli_piped(
        &dir,
        &["check", "--only", "3,23", "--against", "-"],
        snapshot.as_bytes(),
    );
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("against -: no change in 2 checks"), "{out}");
    let (code, _, err) = cli_status(&dir, &["check", "--only", "3", "--snapshot", "-", "--json"]);
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("both write to standard output"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn what_a_stream_cannot_hold_is_refused() {
    let dir = temp_dir("stdio", "refused");
    for args in [
        &["report", "--out", "-"][..],
        &["figures", "--only", "stability-map", "--out", "-"][..],
        &["experiment", "analyze", "x.csv", "--out", "-"][..],
    ] {
        let (code, _, err) = cli_status(&dir, args);
        assert_eq!(code, 1, "{args:?}: {err}");
        assert!(
            err.contains("--out -") && err.contains("name a directory"),
            "{args:?}: {err}"
        );
    }
    let yaml = short_scene(&dir);
    let (code, _, err) = cli_piped(&dir, &["simulate", "-", "--against", "-"], yaml.as_bytes());
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("already read by another argument"), "{err}");
    let (code, _, err) = cli_status(&dir, &["simulate", "nutating-coin", "--csv", "-", "--json"]);
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("both write to standard output"), "{err}");
    assert_eq!(
        std::fs::read_dir(&dir).unwrap().count(),
        0,
        "a file was written"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
