//! `check --snapshot`, `--against`, `--bless` and `--fail-on` as an author's loop uses them: a
//! copy of the paper, a snapshot of its derived results, the paper edited (eq 76's two 5s made
//! 3s), the changes said and the run failed with status 3, the change accepted, and CI's exit
//! statuses. The rule for a number (its check's tolerance times max(1, |x|)) is tested on both
//! sides of its bound.

use crate::common::{cli_status, temp_dir};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// Section 11's chain: eq 76 and the equations that follow from it.
const ONLY: &str = "76-79,84";

/// A copy of the built-in paper's files in `dir/paper`.
fn paper_copy(dir: &Path) -> PathBuf {
    let from = Path::new(env!("CARGO_MANIFEST_DIR")).join("paper");
    let to = dir.join("paper");
    std::fs::create_dir_all(&to).unwrap();
    for f in [
        "equations.yaml",
        "symbols.yaml",
        "claims.yaml",
        "corrections.yaml",
    ] {
        std::fs::copy(from.join(f), to.join(f)).unwrap();
    }
    to
}

/// Eq 76 with its two 5s made 3s, in the copy at `paper`.
fn edit_eq_76(paper: &Path) {
    let path = paper.join("equations.yaml");
    let text = std::fs::read_to_string(&path).unwrap();
    let at = text.find("label: e104").expect("eq 76's entry");
    let line_start = at + text[at..].find("latex: ").expect("its latex");
    let line_end = line_start + text[line_start..].find('\n').unwrap();
    let line = &text[line_start..line_end];
    assert_eq!(line.matches(r"\frac{2 \epsilon}{5}").count(), 2, "{line}");
    let edited = line.replace(r"\frac{2 \epsilon}{5}", r"\frac{2 \epsilon}{3}");
    let text = format!("{}{edited}{}", &text[..line_start], &text[line_end..]);
    std::fs::write(&path, text).unwrap();
}

fn json(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn check(dir: &Path, extra: &[&str]) -> (i32, String, String) {
    let mut args = vec!["check", "--paper", "paper", "--only", ONLY];
    args.extend_from_slice(extra);
    cli_status(dir, &args)
}

/// The line of the diff for `check` and `what`.
fn diff_line<'a>(out: &'a str, check: &str, what: &str) -> Option<&'a str> {
    out.lines().find(|l| {
        let mut w = l.split_whitespace();
        l.starts_with(check) && w.nth(check.split_whitespace().count()) == Some(what)
    })
}

#[test]
fn an_edited_paper_is_said_changed_then_blessed() {
    let dir = temp_dir("snapshot", "loop");
    let paper = paper_copy(&dir);

    let (code, out, err) = check(&dir, &["--snapshot", "snap.json"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("wrote snapshot snap.json"), "{out}");
    let snap = json(&dir.join("snap.json"));
    let names: Vec<&str> = snap["checks"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["name"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["eq 76", "eq 77", "eq 78", "eq 79", "eq 84"]);
    let (_, version, _) = cli_status(&dir, &["-V"]);
    assert_eq!(
        format!("rolling-disk {}", snap["tool"]["version"].as_str().unwrap()),
        version.trim()
    );
    assert_eq!(snap["paper"]["sha256"].as_str().unwrap().len(), 64);
    for c in snap["checks"].as_array().unwrap() {
        assert_eq!(c["verdict"], "fails", "{c}");
        assert_eq!(c["cause"], "inherits from eq 73", "{c}");
        let t = c["tolerance"].as_f64().unwrap();
        for n in ["claimed", "reference", "error"] {
            let x = c["numbers"][n]["value"].as_f64().unwrap();
            let allowed = c["numbers"][n]["tolerance"].as_f64().unwrap();
            assert_eq!(allowed, t * x.abs().max(1.0), "{c}");
        }
    }

    // The same inputs give the same bytes; the unchanged paper exits 0.
    let (code, out, err) = check(&dir, &["--snapshot", "again.json"]);
    assert_eq!(code, 0, "{out}{err}");
    assert_eq!(
        std::fs::read(dir.join("snap.json")).unwrap(),
        std::fs::read(dir.join("again.json")).unwrap()
    );
    let (code, out, err) = check(&dir, &["--against", "snap.json"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(
        out.contains("against snap.json: no change in 5 checks"),
        "{out}"
    );
    assert!(!out.contains("note:"), "{out}");

    // Eq 76 corrected: it holds approximately, eq 77 becomes the root cause, 78, 79 and 84
    // inherit from it; every one of these is said, and the run exits 3.
    edit_eq_76(&paper);
    let (code, out, err) = check(&dir, &["--against", "snap.json"]);
    assert_eq!(code, 3, "{out}{err}");
    let line = diff_line(&out, "eq 76", "verdict").unwrap_or_else(|| panic!("{out}"));
    assert!(
        line.contains("fails") && line.contains("holds approximately"),
        "{line}"
    );
    let line = diff_line(&out, "eq 77", "cause").unwrap_or_else(|| panic!("{out}"));
    assert!(
        line.contains("inherits from eq 73") && line.contains("root cause"),
        "{line}"
    );
    for eq in ["eq 78", "eq 79", "eq 84"] {
        let line = diff_line(&out, eq, "cause").unwrap_or_else(|| panic!("{eq}: {out}"));
        assert!(line.contains("inherits from eq 77"), "{line}");
    }
    assert!(out.contains("note: paper sha256:"), "{out}");
    assert!(
        out.contains("against snap.json: 5 of 5 checks changed: eq 76, eq 77, eq 78, eq 79, eq 84"),
        "{out}"
    );
    assert!(
        err.contains("5 of 5 checks changed") && err.contains("--bless"),
        "{err}"
    );
    // docs/loop.md shows this run's lines as the tool prints them.
    let doc = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/loop.md"))
        .unwrap();
    let shown: Vec<&str> = doc
        .lines()
        .skip_while(|l| !l.starts_with("note: paper sha256"))
        .skip(1)
        .take_while(|l| !l.starts_with("```"))
        .collect();
    let printed: Vec<&str> = out.lines().filter(|l| !l.starts_with("note:")).collect();
    assert_eq!(shown, printed, "docs/loop.md's diff against the tool's");
    assert_eq!(
        json(&dir.join("snap.json")),
        snap,
        "--against alone wrote the snapshot"
    );

    // Accepted: the snapshot is rewritten, and the edited paper then exits 0 against it.
    let (code, out, err) = check(&dir, &["--against", "snap.json", "--bless"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("blessed: snap.json"), "{out}");
    assert_eq!(
        json(&dir.join("snap.json"))["checks"][0]["verdict"],
        "holds approximately"
    );
    let (code, out, err) = check(&dir, &["--against", "snap.json"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("no change in 5 checks"), "{out}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A number moved by 0.9 of the change it may take is no change; by 1.1 of it, it is, and the
/// diff names the check, the number, both values and the tolerance.
#[test]
fn a_number_moves_beyond_its_tolerance_or_not() {
    let dir = temp_dir("snapshot", "numbers");
    paper_copy(&dir);
    let (code, out, err) = check(&dir, &["--snapshot", "snap.json"]);
    assert_eq!(code, 0, "{out}{err}");
    let snap = json(&dir.join("snap.json"));
    let moved = |factor: f64| {
        let mut s = snap.clone();
        let n = &mut s["checks"][1]["numbers"]["reference"];
        let x = n["value"].as_f64().unwrap();
        let t = n["tolerance"].as_f64().unwrap();
        n["value"] = (x + factor * t).into();
        std::fs::write(dir.join("moved.json"), serde_json::to_string(&s).unwrap()).unwrap();
        (x, t)
    };
    moved(0.9);
    let (code, out, err) = check(&dir, &["--against", "moved.json"]);
    assert_eq!(code, 0, "{out}{err}");
    let (x, t) = moved(1.1);
    let (code, out, err) = check(&dir, &["--against", "moved.json"]);
    assert_eq!(code, 3, "{out}{err}");
    let line = diff_line(&out, "eq 77", "reference").unwrap_or_else(|| panic!("{out}"));
    assert!(line.contains(&format!("{x:.9e}")), "{line}");
    assert!(line.contains(&format!("{t:.3e}")), "{line}");
    assert!(out.contains("1 of 5 checks changed: eq 77"), "{out}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `--fail-on` for CI: 4 when a verdict of its kind is found, 0 when none is; eq 80 holds only
/// under a premise that fails, so `fails` passes it and `premise` does not.
#[test]
fn fail_on_gives_status_4_for_its_kind_only() {
    let dir = temp_dir("snapshot", "fail-on");
    let run =
        |only: &str, kind: &str| cli_status(&dir, &["check", "--only", only, "--fail-on", kind]);
    let (code, out, err) = run("76", "fails");
    assert_eq!(code, 4, "{out}{err}");
    assert!(
        err.contains("--fail-on fails: 1 check(s) met it: eq 76"),
        "{err}"
    );
    let (code, out, err) = run("80", "fails");
    assert_eq!(code, 0, "{out}{err}");
    let (code, out, err) = run("80", "premise");
    assert_eq!(code, 4, "{out}{err}");
    assert!(err.contains("eq 80"), "{err}");
    let (code, out, err) = run("3", "any");
    assert_eq!(code, 0, "{out}{err}");
    let (code, _, err) = cli_status(&dir, &["check", "--fail-on", "most"]);
    assert_eq!(code, 2, "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A snapshot that cannot be read is said with its file and what to do, status 1; `--bless`
/// creates one that is not there yet, and cannot rewrite standard input.
#[test]
fn bad_snapshots_are_refused_with_a_fix() {
    let dir = temp_dir("snapshot", "bad");
    let (code, _, err) = cli_status(&dir, &["check", "--only", "3", "--against", "absent.json"]);
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains("absent.json")
            && err.contains("--snapshot absent.json")
            && err.contains("--bless"),
        "{err}"
    );
    std::fs::write(dir.join("broken.json"), "{\n  \"schema\": \n").unwrap();
    let (code, _, err) = cli_status(&dir, &["check", "--only", "3", "--against", "broken.json"]);
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("broken.json:3:"), "{err}");
    std::fs::write(dir.join("other.json"), "{\"schema\": \"elsewhere\"}").unwrap();
    let (code, _, err) = cli_status(&dir, &["check", "--only", "3", "--against", "other.json"]);
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains("other.json: key schema is `elsewhere`"),
        "{err}"
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("other.json")).unwrap(),
        "{\"schema\": \"elsewhere\"}"
    );

    let (code, out, err) = cli_status(
        &dir,
        &["check", "--only", "3", "--against", "new.json", "--bless"],
    );
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("no snapshot yet"), "{out}");
    assert_eq!(json(&dir.join("new.json"))["checks"][0]["name"], "eq 3");
    let (code, _, err) = cli_status(&dir, &["check", "--only", "3", "--against", "-", "--bless"]);
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains("--bless") && err.contains("standard input"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
