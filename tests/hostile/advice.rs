//! Issue 48's wrong advice, each case refused with advice that is then applied and must work:
//! a premise that is no equation and a cycle of premises in equations.yaml (file, line, key and
//! the change), a CSV whose header cells are quoted (read as the plain one), a CSV with
//! semicolons and decimal commas (named as such, and read once the commas are points), and
//! `figures` under a budget too small (one direction of advice, the budget, for every figure).
//! Every run must end without a panic, and every refusal within 2 s.

use super::sandbox::cli_timed;
use crate::common::temp_dir;
use paper::Paper;
use std::path::Path;
use std::time::Duration;

const EQUATIONS: &str = include_str!("../../paper/equations.yaml");

/// Runs the binary in `dir`, asserting no panic: (success, stdout, stderr, time).
fn run(dir: &Path, args: &[&str]) -> (bool, String, String, Duration) {
    let (ok, out, err, took) = cli_timed(dir, args);
    assert!(!err.contains("panicked"), "{args:?} panicked: {err}");
    (ok, out, err, took)
}

/// `text` with `n` taken out of the `premises: [...]` list on the 1-based `line`.
fn without(text: &str, line: usize, n: u32) -> String {
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let l = &mut lines[line - 1];
    let (head, list) = l.split_once('[').expect("a premises list on the line");
    let kept: Vec<&str> = list
        .trim_end_matches(']')
        .split(',')
        .map(str::trim)
        .filter(|p| !p.is_empty() && *p != n.to_string())
        .collect();
    *l = format!("{head}[{}]", kept.join(", "));
    lines.join("\n") + "\n"
}

/// `text` with eq `number`'s premises list `from` replaced by `to` (the list must be there).
fn edited(number: u32, from: &str, to: &str) -> String {
    let at = EQUATIONS
        .find(&format!("- number: {number}\n"))
        .expect("the entry");
    let rel = EQUATIONS[at..].find(from).expect("its premises") + at;
    format!(
        "{}{to}{}",
        &EQUATIONS[..rel],
        &EQUATIONS[rel + from.len()..]
    )
}

/// The paper of a folder holding `equations` as its equations.yaml.
fn load(dir: &Path, equations: &str) -> Result<Paper, String> {
    std::fs::write(dir.join("equations.yaml"), equations).expect("written");
    Paper::from_dir(dir).map_err(|e| e.to_string())
}

/// The line number after `file:` in a message.
fn line_after(message: &str, file: &str) -> usize {
    message
        .split(&format!("{file}:"))
        .nth(1)
        .and_then(|r| r.split(':').next())
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("no line after {file} in {message}"))
}

#[test]
fn a_premise_that_is_no_equation_is_refused_at_its_line_and_the_fix_loads() {
    let dir = temp_dir("hostile-advice", "premise-999");
    let file = dir.join("equations.yaml").display().to_string();
    let bad = edited(3, "premises: [4]", "premises: [4, 999]");
    let e = load(&dir, &bad).expect_err("premise 999 refused");
    let line = line_after(&e, &file);
    assert!(
        bad.lines()
            .nth(line - 1)
            .unwrap()
            .contains("premises: [4, 999]"),
        "{e}"
    );
    assert!(
        e.contains("eq 3, key `premises`: 999 is not an equation number") && e.contains("1 to 85"),
        "{e}"
    );
    // Through the binary: refused at once, naming the file's line.
    let (ok, _, err, took) = run(&dir, &["check", "--only", "3", "--paper", "."]);
    assert!(!ok && took < Duration::from_secs(2), "{err}");
    assert!(err.contains(&format!("equations.yaml:{line}")), "{err}");
    // The fix: without 999.
    load(&dir, &without(&bad, line, 999)).expect("the list without 999 loads");
}

#[test]
fn a_cycle_of_premises_is_refused_and_either_fix_loads() {
    let dir = temp_dir("hostile-advice", "premise-cycle");
    let file = dir.join("equations.yaml").display().to_string();
    // Eq 77 follows from eq 76; made to follow from eq 77 too, eq 76 closes a cycle.
    let bad = edited(76, "premises: [31, 73, 75]", "premises: [31, 73, 75, 77]");
    let e = load(&dir, &bad).expect_err("the cycle refused");
    assert!(
        e.contains("a cycle of premises (eq 76 -> eq 77 -> eq 76)")
            || e.contains("a cycle of premises (eq 77 -> eq 76 -> eq 77)"),
        "{e}"
    );
    // "remove A from eq B's `premises`, or C from eq D's (line L)": both changes load.
    let words: Vec<&str> = e.split_whitespace().collect();
    let at = words.iter().position(|w| *w == "remove").expect("a fix");
    let first: u32 = words[at + 1].parse().expect("a number");
    let line = line_after(&e, &file);
    load(&dir, &without(&bad, line, first)).expect("the first fix loads");
    let second: u32 = words[at + 7].parse().expect("a number");
    let other: usize = e
        .split("(line ")
        .nth(1)
        .and_then(|r| r.split(')').next())
        .and_then(|n| n.parse().ok())
        .expect("the other line");
    load(&dir, &without(&bad, other, second)).expect("the second fix loads");
    // An equation that lists itself.
    let own = edited(76, "premises: [31, 73, 75]", "premises: [31, 73, 75, 76]");
    let e = load(&dir, &own).expect_err("refused");
    assert!(
        e.contains("(eq 76 -> eq 76)") && e.contains("remove 76 from eq 76's"),
        "{e}"
    );
}

/// The beta of eq 84 that `experiment analyze` prints for `csv` in `dir`.
fn beta(dir: &Path, csv: &str) -> Result<String, String> {
    let (ok, out, err, _) = run(dir, &["experiment", "analyze", csv]);
    if !ok {
        return Err(err);
    }
    out.split("eq 84: beta = ")
        .nth(1)
        .and_then(|r| r.split_whitespace().next())
        .map(str::to_string)
        .ok_or(out)
}

#[test]
fn quoted_headers_are_read_and_decimal_commas_are_named_with_a_fix_that_works() {
    let dir = temp_dir("hostile-advice", "csv");
    let (ok, _, err, _) = run(&dir, &["experiment", "simulate", "--csv", "t.csv"]);
    assert!(ok, "{err}");
    let plain = std::fs::read_to_string(dir.join("t.csv")).expect("the trace");
    let want = beta(&dir, "t.csv").expect("the plain trace is analysed");
    // Header cells in double quotes, as spreadsheets write them.
    let quoted = plain.replace("time_s,signal_V", "\"time_s\",\"signal_V\"");
    assert_ne!(quoted, plain);
    std::fs::write(dir.join("q.csv"), quoted).expect("written");
    assert_eq!(beta(&dir, "q.csv").as_ref(), Ok(&want));
    // Semicolons between cells and decimal commas, as a spreadsheet in German writes them.
    let comma: String = plain
        .lines()
        .map(|l| {
            if l.starts_with('#') {
                l.to_string()
            } else {
                l.replace(',', ";").replace('.', ",")
            }
        })
        .collect::<Vec<_>>()
        .join("\n");
    std::fs::write(dir.join("dc.csv"), &comma).expect("written");
    let err = beta(&dir, "dc.csv").expect_err("refused");
    assert!(
        err.contains("dc.csv:") && err.contains("decimal comma") && err.contains("'.'"),
        "{err}"
    );
    // The advice: each decimal comma a point (the semicolons stay).
    let points: String = comma
        .lines()
        .map(|l| {
            if l.starts_with('#') {
                l.to_string()
            } else {
                l.replace(',', ".")
            }
        })
        .collect::<Vec<_>>()
        .join("\n");
    std::fs::write(dir.join("dp.csv"), points).expect("written");
    assert_eq!(beta(&dir, "dp.csv").as_ref(), Ok(&want));
}

#[test]
fn figures_under_a_budget_too_small_advise_only_a_larger_budget_and_it_works() {
    let dir = temp_dir("hostile-advice", "figures");
    let (ok, list, err, _) = run(&dir, &["figures", "--list"]);
    assert!(ok, "{err}");
    let mut refused = 0;
    for name in list.lines() {
        let (ok, _, err, _) = run(
            &dir,
            &[
                "figures",
                "--only",
                name,
                "--max-seconds",
                "0.001",
                "--out",
                "f",
            ],
        );
        if ok {
            continue;
        }
        refused += 1;
        assert!(err.contains("--max-seconds"), "{name}: {err}");
        for wrong in ["lower", "reduce"] {
            assert!(!err.contains(wrong), "{name}: {err}");
        }
    }
    assert!(refused > 0, "no figure was refused at 1 ms");
    // The advice applied, on the figure whose refusal named a scene's sample.
    let (ok, _, err, _) = run(
        &dir,
        &[
            "figures",
            "--only",
            "slip-stick",
            "--max-seconds",
            "600",
            "--out",
            "f",
        ],
    );
    assert!(ok && dir.join("f/slip-stick.svg").is_file(), "{err}");
}

/// A recording cut inside its samples, a damaged one (an AIFF header with no samples) and one in
/// a coding this tool does not decode (Ogg Opus) are refused with what to do; done (the whole
/// file, the recording as WAV), it is analysed. No refusal says "save the CSV as UTF-8" or "save
/// as PCM".
#[test]
fn a_truncated_or_unread_recording_is_refused_with_advice_that_works() {
    let dir = temp_dir("hostile-advice", "recordings");
    let (ok, _, err, _) = run(&dir, &["experiment", "simulate", "--wav", "whole.wav"]);
    assert!(ok, "{err}");
    let whole = std::fs::read(dir.join("whole.wav")).expect("written");
    std::fs::write(dir.join("cut.wav"), &whole[..3000]).expect("written");
    std::fs::write(dir.join("take.aiff"), b"FORM\0\0\0\x10AIFFCOMMjunk").expect("written");
    let opus = b"OggS\0\x02\0\0\0\0\0\0\0\0\x01\0\0\0\0\0\0\0\0\0\0\0\x01\x13OpusHead\x01\x02";
    std::fs::write(dir.join("take.opus"), opus).expect("written");
    for (file, says) in [
        ("cut.wav", "copy or export the whole file again"),
        ("take.aiff", "export it as WAV or FLAC"),
        ("take.opus", "convert it to WAV or FLAC"),
    ] {
        let (ok, _, err, took) = run(&dir, &["experiment", "analyze", file]);
        assert!(!ok && took < Duration::from_secs(2), "{file}: {took:?}");
        assert!(err.contains(file) && err.contains(says), "{file}: {err}");
        for wrong in ["UTF-8", "PCM"] {
            assert!(!err.contains(wrong), "{file}: {err}");
        }
    }
    // Applied: the whole file, a WAV.
    let (ok, out, err, _) = run(&dir, &["experiment", "analyze", "whole.wav"]);
    assert!(ok && out.contains("beta"), "{err}");
}
