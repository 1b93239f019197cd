//! Figures draw results: no file of `report::figures` takes a function from `physics` (its
//! plain data types, a `Motion` or a `Method`, it may read); what a figure needs computed is a
//! study's result (`report::study`).

use super::{assert_none, code_lines, rust_files};
use std::path::Path;

/// Reads the path (or `use` tree) at the start of `s`, pushing the last name of each of its
/// paths to `leaves`; returns the bytes read. `model::{Motion, steady::steady_motion}` gives
/// `Motion` and `steady_motion`; a glob gives `*`.
fn use_tree(s: &str, leaves: &mut Vec<String>) -> usize {
    let blank = |t: &str| t.len() - t.trim_start().len();
    if s.starts_with('{') {
        let mut at = 1;
        while at < s.len() {
            at += blank(&s[at..]);
            if s[at..].starts_with('}') {
                return at + 1;
            }
            let read = use_tree(&s[at..], leaves);
            at += read + blank(&s[at + read..]);
            if s[at..].starts_with(',') {
                at += 1;
            } else if read == 0 {
                break;
            }
        }
        return at;
    }
    if s.starts_with('*') {
        leaves.push("*".into());
        return 1;
    }
    let n = s
        .find(|c: char| !(c.is_alphanumeric() || c == '_'))
        .unwrap_or(s.len());
    if n > 0 && s[n..].starts_with("::") {
        return n + 2 + use_tree(&s[n + 2..], leaves);
    }
    if n > 0 {
        leaves.push(s[..n].to_string());
    }
    n
}

/// The names `code` takes from `physics::` last on each path, with the line of each:
/// `use physics::model::{Motion, steady::steady_motion}` takes `Motion` and `steady_motion`;
/// `physics::Disk::uniform(a)` takes `uniform`. A `use` tree may go on over the next lines.
fn physics_leaves(code: &[(usize, &str)]) -> Vec<(usize, String)> {
    let mut leaves = Vec::new();
    for (i, (n, line)) in code.iter().enumerate() {
        for (at, _) in line.match_indices("physics::") {
            let rest: String = std::iter::once(&line[at + 9..])
                .chain(code[i + 1..].iter().map(|(_, l)| *l))
                .collect::<Vec<_>>()
                .join("\n");
            let mut found = Vec::new();
            use_tree(&rest, &mut found);
            leaves.extend(found.into_iter().map(|l| (*n, l)));
        }
    }
    leaves
}

/// The lines of `files` that take a function (or a module, through which one could call a
/// function) from `physics`: a name that is not a type's (types are capitalised).
fn physics_functions(files: &[std::path::PathBuf]) -> Vec<String> {
    let mut offenders = Vec::new();
    for f in files {
        let text = std::fs::read_to_string(f).unwrap();
        for (n, leaf) in physics_leaves(&code_lines(&text)) {
            if !leaf.starts_with(|c: char| c.is_ascii_uppercase()) {
                offenders.push(format!("{}:{n}: physics::..::{leaf}", f.display()));
            }
        }
    }
    offenders
}

/// Figures draw results: no file of `report::figures` (its unit tests aside) takes a function
/// from `physics`, only its plain data types; what a figure needs computed is a study's result.
#[test]
fn figures_take_no_physics_function() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("crates/report/src/figures");
    let mut files = Vec::new();
    rust_files(&dir, &mut files);
    files.retain(|f| !f.ends_with("tests.rs"));
    assert!(files.len() >= 20, "only {} files found", files.len());
    assert_none(
        "figures that take a physics function",
        &physics_functions(&files),
    );
}

#[test]
fn the_figure_rule_would_catch_a_physics_function() {
    let code = [
        (1, "use physics::model::{Motion, steady::steady_motion};"),
        (2, "use physics::solve::Method;"),
        (3, "let d = physics::Disk::uniform(0.0375);"),
        (4, "use physics::{"),
        (5, "    run::run, model::*,"),
        (6, "};"),
        (7, "let m = physics::model::Motion { alpha: 1.0 };"),
    ];
    let leaves = physics_leaves(&code);
    let named = |n: usize| -> Vec<&str> {
        leaves
            .iter()
            .filter(|l| l.0 == n)
            .map(|l| l.1.as_str())
            .collect()
    };
    assert_eq!(named(1), ["Motion", "steady_motion"]);
    assert_eq!(named(2), ["Method"]);
    assert_eq!(named(3), ["uniform"]);
    assert_eq!(named(4), ["run", "*"]);
    assert_eq!(named(7), ["Motion"]);
}
