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
fn a_fifo_or_a_symlink_to_one_is_refused_at_once() {
    let dir = scratch("fifo");
    let fifo = dir.join("paper.tex");
    let made = Command::new("mkfifo").arg(&fifo).status();
    if !made.is_ok_and(|s| s.success()) {
        eprintln!("skipped: mkfifo is not available");
        return;
    }
    let link = dir.join("link.tex");
    #[cfg(unix)]
    std::os::unix::fs::symlink(&fifo, &link).unwrap();
    for path in [&fifo, &link, &PathBuf::from("/dev/zero")] {
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
