//! `--paper` on the paper's own LaTeX source (`../shared/paper/` beside the checkout; each test
//! says it is skipped where the source is absent): its 85 equations found by label, each read as
//! the same relations as the built-in transcription, the checks' outcomes identical to the
//! built-in ones; an edited copy re-checked as an edited equations.yaml is; a label missing or
//! an equation without an entry named with its line; a FIFO refused at once.

use checks::check::{run_checks, Selection};
use checks::equations::{equations, Bench};
use paper::Paper;
use std::path::PathBuf;
use std::process::Command;
use std::time::{Duration, Instant};

/// The paper's source, or `None` (with a message) where it is not beside the checkout.
fn source() -> Option<PathBuf> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let path = root.parent()?.join("shared/paper/000_b5819d499ad0b272.txt");
    if path.exists() {
        Some(path)
    } else {
        eprintln!("skipped: the paper's source {} is absent", path.display());
        None
    }
}

/// A scratch directory for this test.
fn scratch(tag: &str) -> PathBuf {
    let dir =
        std::env::temp_dir().join(format!("rolling-disk-source-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The source with `from` replaced by `to` (which must occur), written as `paper.tex` in a
/// scratch directory.
fn edited(tag: &str, from: &str, to: &str) -> Option<PathBuf> {
    let text = std::fs::read_to_string(source()?).unwrap();
    assert!(text.contains(from), "{from}");
    let dir = scratch(tag);
    let file = dir.join("paper.tex");
    std::fs::write(&file, text.replacen(from, to, 1)).unwrap();
    Some(file)
}

#[test]
fn the_source_gives_the_85_equations_as_transcribed_and_the_built_in_outcomes() {
    let Some(src) = source() else { return };
    let from_source = Paper::from_path(&src).unwrap_or_else(|e| panic!("{e}"));
    let built_in = Paper::built_in().unwrap();
    assert_eq!(from_source.equations.len(), 85);
    for (a, b) in from_source.equations.iter().zip(&built_in.equations) {
        assert_eq!(a.entry.label, b.entry.label);
        assert_eq!(a.chains, b.chains, "eq {}: {}", a.number(), a.entry.latex);
    }
    assert!(from_source.notes.is_empty(), "{:#?}", from_source.notes);
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    let all = Selection::default();
    let run = |p: &Paper| {
        let c = run_checks(&Bench::with_paper(p), &all, threads, &|_, _| {}).unwrap();
        serde_json::to_value(&c).unwrap()
    };
    assert_eq!(run(&from_source), run(&built_in));
}

#[test]
fn eq_76_corrected_in_the_source_holds_as_in_equations_yaml() {
    let printed = r"\dot\alpha = - {2 \epsilon \over 5} \Omega^\beta 
\approx - {2 \epsilon \over 5}";
    let corrected = r"\dot\alpha = - {2 \epsilon \over 3} \Omega^\beta 
\approx - {2 \epsilon \over 3}";
    let Some(file) = edited("eq76", printed, corrected) else {
        return;
    };
    let p = Paper::from_path(&file).unwrap_or_else(|e| panic!("{e}"));
    // The difference from the transcription is reported, and the source's form is read.
    assert!(
        p.notes.len() == 1 && p.notes[0].contains("eq 76"),
        "{:?}",
        p.notes
    );
    let bench = Bench::with_paper(&p);
    let eq76 = equations().into_iter().find(|e| e.number == 76).unwrap();
    assert!((eq76.check)(&bench).verdict.passes());
    let built_in = Bench::with_paper(Paper::built_in_shared());
    assert!(!(eq76.check)(&built_in).verdict.passes());
}

#[test]
fn a_label_missing_or_an_equation_without_an_entry_is_named_with_its_line() {
    let Some(file) = edited("nolabel", r"\label{e104}", "") else {
        return;
    };
    let e = Paper::from_path(&file).unwrap_err().to_string();
    assert!(e.contains("e104") && e.contains("eq 76"), "{e}");
    let Some(file) = edited(
        "extra",
        r"\begin{equation}
{\bf a} = a\hat {\bf 3}.",
        r"\begin{equation} x = y \label{new} \end{equation}
\begin{equation}
{\bf a} = a\hat {\bf 3}.",
    ) else {
        return;
    };
    let e = Paper::from_path(&file).unwrap_err().to_string();
    assert!(
        e.contains("paper.tex:") && e.contains("`new`") && e.contains("no entry"),
        "{e}"
    );
}

#[test]
fn a_fifo_a_device_or_a_symlink_to_either_is_refused_at_once() {
    let dir = scratch("fifo");
    let fifo = dir.join("paper.tex");
    let made = Command::new("mkfifo").arg(&fifo).status();
    if !made.is_ok_and(|s| s.success()) {
        eprintln!("skipped: mkfifo is not available");
        return;
    }
    let link = dir.join("link.tex");
    let device_link = dir.join("device.tex");
    #[cfg(unix)]
    {
        std::os::unix::fs::symlink(&fifo, &link).unwrap();
        std::os::unix::fs::symlink("/dev/zero", &device_link).unwrap();
    }
    for path in [&fifo, &link, &PathBuf::from("/dev/zero"), &device_link] {
        let start = Instant::now();
        let mut child = Command::new(env!("CARGO_BIN_EXE_rolling-disk"))
            .args(["check", "--only", "1", "--paper"])
            .arg(path)
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        while child.try_wait().unwrap().is_none() {
            if start.elapsed() > Duration::from_secs(60) {
                child.kill().unwrap();
                panic!("--paper {} hangs", path.display());
            }
            std::thread::sleep(Duration::from_millis(50));
        }
        let out = child.wait_with_output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{}", path.display());
        assert!(
            err.contains("not a regular file"),
            "{}: {err}",
            path.display()
        );
    }
}

/// The command as a user runs it: `check --paper <source> --json` prints the built-in
/// `check --json`: the same checks, value for value, and the rest of the document the same but
/// for the paper it names and the command line.
#[test]
fn check_json_on_the_source_is_the_built_in_one() {
    let Some(src) = source() else { return };
    let run = |paper: Option<&PathBuf>| {
        let mut c = Command::new(env!("CARGO_BIN_EXE_rolling-disk"));
        c.args(["check", "--json"]);
        if let Some(p) = paper {
            c.arg("--paper").arg(p);
        }
        let out = c.output().unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let mut doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        let checks = doc["checks"].take();
        (checks, doc)
    };
    let (from_source, source_doc) = run(Some(&src));
    let (built_in, built_in_doc) = run(None);
    assert_eq!(
        from_source.as_array().map(Vec::len),
        Some(built_in.as_array().unwrap().len())
    );
    assert_eq!(from_source, built_in);
    // The rest of the document differs only where it names the paper read and the command.
    let differing: Vec<&String> = source_doc
        .as_object()
        .unwrap()
        .iter()
        .filter(|(k, v)| built_in_doc.get(k.as_str()) != Some(v))
        .map(|(k, _)| k)
        .collect();
    assert_eq!(differing, ["paper", "settings"]);
    let mut settings = source_doc["settings"].clone();
    settings["command"] = built_in_doc["settings"]["command"].clone();
    assert_eq!(settings, built_in_doc["settings"]);
    assert_eq!(source_doc["paper"]["title"], built_in_doc["paper"]["title"]);
}

/// A symbol with no value in its check (eq 76 written with $\Omega^{\gamma}$; $\gamma$ is a
/// symbol of sec. 7, which eq 76's check does not bind) is an error naming the symbol, with its
/// equation and column, in the text and in `--json`: never a verdict, never NaN.
#[test]
fn a_symbol_without_a_value_is_named_never_a_verdict() {
    let Some(file) = edited(
        "gamma",
        r"\dot\alpha = - {2 \epsilon \over 5} \Omega^\beta",
        r"\dot\alpha = - {2 \epsilon \over 5} \Omega^{\gamma}",
    ) else {
        return;
    };
    for json in [false, true] {
        let mut c = Command::new(env!("CARGO_BIN_EXE_rolling-disk"));
        c.args(["check", "--only", "76", "--paper"]).arg(&file);
        if json {
            c.arg("--json");
        }
        let out = c.output().unwrap();
        let (stdout, stderr) = (
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr),
        );
        assert_eq!(out.status.code(), Some(1), "{stdout}{stderr}");
        let all = format!("{stdout}{stderr}");
        assert!(
            all.contains("with no value in this check: gamma at column")
                && all.contains("of eq 76's latex (quantity gamma"),
            "{all}"
        );
        assert!(!all.to_lowercase().contains("nan"), "{all}");
        if json {
            let doc: serde_json::Value = serde_json::from_str(&stdout).unwrap();
            let eq76 = doc["checks"]
                .as_array()
                .unwrap()
                .iter()
                .find(|c| c["name"] == "eq 76")
                .unwrap_or_else(|| panic!("{stdout}"));
            let text = eq76.to_string();
            assert!(eq76["cause"].is_null(), "{text}");
            assert!(
                !text.contains("\"fails\"") && !text.contains("\"holds"),
                "{text}"
            );
            assert!(text.contains("gamma at column"), "{text}");
        }
    }
}

/// Eq 54 with a symbol its readers do not bind (the claims of sec. 7 draw the band of unstable
/// $b$ from its right side): every check runs to its end, no panic, and the claims that draw on
/// eq 54 could not evaluate it, naming the symbol; none fails.
#[test]
fn eq_54_that_cannot_be_evaluated_is_named_by_the_claims_drawn_from_it() {
    let Some(file) = edited(
        "eq54",
        r" 3 k \cos^2\alpha_0 + \sin^2\alpha_0",
        r" 3 k \cos^2\alpha_0 + \sin^2\alpha_0 + \gamma \alpha_0",
    ) else {
        return;
    };
    let p = Paper::from_path(&file).unwrap_or_else(|e| panic!("{e}"));
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    let checked = run_checks(
        &Bench::with_paper(&p),
        &Selection::default(),
        threads,
        &|_, _| {},
    )
    .unwrap();
    let doc = serde_json::to_value(&checked).unwrap();
    let mut named = 0;
    for c in doc.as_array().unwrap() {
        let text = c.to_string();
        if text.contains("\"fails\"") {
            assert!(
                c["finding"]["Ok"]["claimed"]
                    .as_f64()
                    .is_some_and(f64::is_finite),
                "a failure with a claim that is not a number: {text}"
            );
        }
        if text.contains("gamma at column") && text.contains("eq 54's latex") {
            named += 1;
        }
    }
    // Eq 54's own check, and the two claims drawn from its right side.
    assert!(named >= 3, "{named}");
}
