//! The one rule of the layout, enforced: the references (models, the solver and its events,
//! numerics, the friction studies, the experiment's analysis) never see the paper's claims. A
//! reference that imported `paper`, `equations` (the checks), `mutation` or `catalogue` could
//! end up checking a claim against itself.

use std::path::Path;

/// The reference modules, as paths under src/.
const REFERENCES: &[&str] = &[
    "model",
    "solve",
    "events.rs",
    "numerics",
    "disk.rs",
    "friction",
    "experiment",
    "budget.rs",
];

/// What they may not import.
const CLAIMS: &[&str] = &[
    "crate::paper",
    "crate::equations",
    "crate::mutation",
    "crate::catalogue",
    "rolling_disk::paper",
    "rolling_disk::equations",
];

fn rust_files(path: &Path, out: &mut Vec<std::path::PathBuf>) {
    if path.is_dir() {
        let mut entries: Vec<_> = std::fs::read_dir(path)
            .unwrap()
            .map(|e| e.unwrap().path())
            .collect();
        entries.sort();
        for p in entries {
            rust_files(&p, out);
        }
    } else if path.extension().is_some_and(|e| e == "rs") {
        out.push(path.to_path_buf());
    }
}

#[test]
fn references_never_import_the_claims() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    for r in REFERENCES {
        rust_files(&src.join(r), &mut files);
    }
    assert!(files.len() > 20, "only {} files found", files.len());
    let mut offenders = Vec::new();
    for f in &files {
        let text = std::fs::read_to_string(f).unwrap();
        for (i, line) in text.lines().enumerate() {
            if CLAIMS.iter().any(|c| line.contains(c)) {
                offenders.push(format!("{}:{}: {}", f.display(), i + 1, line.trim()));
            }
        }
    }
    assert!(
        offenders.is_empty(),
        "references importing claims:\n{}",
        offenders.join("\n")
    );
}

#[test]
fn the_rule_would_catch_an_import() {
    // The scan itself must be able to fail: a line as a reference would write it.
    let line = "use crate::paper::Paper;";
    assert!(CLAIMS.iter().any(|c| line.contains(c)));
}
