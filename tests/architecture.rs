//! The rules of the layout, enforced. First, the crate graph is the layers of the design: the
//! references (`physics`, and the `experiment` and `studies` built on them) never see the
//! paper's claims, so a reference cannot end up checking a claim against itself, and the
//! compiler refuses an import that would break that. Then: figures and renderers never
//! integrate, and figures take no function from `physics` (`architecture/figures.rs`); no check
//! file imports another (what checks share lives in the harness); only the `paper` crate reads
//! the paper's files; no source file is over 600 lines. Each rule has a test
//! showing that its scan can fail.

use std::path::Path;

mod figures;

/// The workspace crates each crate may depend on: the layers of the design. The references
/// (`physics`) and the paper's reader (`paper`) never see each other, and nothing below
/// `checks` sees the claims, so a reference cannot end up checking a claim against itself.
#[rustfmt::skip]
const LAYERS: &[(&str, &[&str])] = &[
    ("numerics", &[]),
    ("files", &[]),
    ("physics", &["numerics", "files"]),
    ("paper", &["numerics", "files"]),
    ("experiment", &["numerics", "files", "physics"]),
    ("studies", &["numerics", "files", "physics", "experiment"]),
    ("checks", &["numerics", "files", "physics", "paper", "experiment", "studies"]),
    ("report", &["numerics", "files", "physics", "paper", "experiment", "studies", "checks"]),
];

/// The arrows of `graph` (crate, the workspace crates it depends on) that [`LAYERS`] does not
/// allow, and the layers that `graph` lacks.
fn forbidden_arrows(graph: &[(String, Vec<String>)]) -> Vec<String> {
    let mut out = Vec::new();
    for (name, allowed) in LAYERS {
        match graph.iter().find(|(n, _)| n == name) {
            None => out.push(format!("no crate `{name}` in the workspace")),
            Some((_, deps)) => out.extend(
                deps.iter()
                    .filter(|d| !allowed.contains(&d.as_str()))
                    .map(|d| format!("{name} -> {d}")),
            ),
        }
    }
    out
}

/// The workspace's manifests as `cargo metadata` reads them (without dependencies' own).
pub(crate) fn cargo_metadata() -> serde_json::Value {
    let out = std::process::Command::new(env!("CARGO"))
        .args([
            "metadata",
            "--format-version",
            "1",
            "--no-deps",
            "--offline",
        ])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("cargo metadata runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).expect("metadata is JSON");
    doc
}

/// The workspace's crates and, for each, the workspace crates it depends on (from
/// `cargo metadata`, which reads the manifests only).
fn workspace_graph() -> Vec<(String, Vec<String>)> {
    let doc = cargo_metadata();
    let packages = doc["packages"].as_array().expect("packages");
    let names: Vec<String> = packages
        .iter()
        .map(|p| p["name"].as_str().unwrap_or_default().to_string())
        .collect();
    packages
        .iter()
        .map(|p| {
            let deps = p["dependencies"]
                .as_array()
                .into_iter()
                .flatten()
                .filter(|d| d["kind"].is_null())
                .filter_map(|d| d["name"].as_str())
                .filter(|d| names.iter().any(|n| n == d))
                .map(str::to_string)
                .collect();
            (p["name"].as_str().unwrap_or_default().to_string(), deps)
        })
        .collect()
}

#[test]
fn the_crate_graph_is_the_architecture() {
    let graph = workspace_graph();
    assert!(graph.len() > LAYERS.len(), "{graph:?}");
    let bad = forbidden_arrows(&graph);
    assert_none("dependencies the layers forbid", &bad);
}

#[test]
fn the_layer_rule_would_catch_a_reference_reading_the_paper() {
    let mut graph: Vec<(String, Vec<String>)> = LAYERS
        .iter()
        .map(|(n, d)| (n.to_string(), d.iter().map(|s| s.to_string()).collect()))
        .collect();
    assert!(forbidden_arrows(&graph).is_empty());
    graph[2].1.push("paper".to_string());
    graph[3].1.push("physics".to_string());
    assert_eq!(
        forbidden_arrows(&graph),
        vec![
            "physics -> paper".to_string(),
            "paper -> physics".to_string()
        ]
    );
}

pub(crate) fn rust_files(path: &Path, out: &mut Vec<std::path::PathBuf>) {
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

/// Every source directory of the workspace: the binary's and each crate's.
pub(crate) fn source_dirs() -> Vec<std::path::PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut dirs = vec![root.join("src")];
    dirs.extend(
        LAYERS
            .iter()
            .map(|(n, _)| root.join("crates").join(n).join("src")),
    );
    dirs
}

/// What computes a study: the solver, the scene runner, the simulations, the checks, the
/// precision study and the studies behind the figures.
const COMPUTES: &[&str] = &[
    "physics::dispatch",
    "physics::run::run",
    "run::run(",
    "precision::study(",
    "run_checks",
    "simulate_trace",
    "simulate_motion",
    "simulate_sound",
    "law_trace",
    "analyze(",
    "Reference::compute",
    "::compute(",
    "pipeline::compute",
    "sliding::studies(",
];

/// The lines of `text` before its unit tests (`#[cfg(test)]`), numbered from 1.
pub(crate) fn code_lines(text: &str) -> Vec<(usize, &str)> {
    text.lines()
        .enumerate()
        .take_while(|(_, l)| !l.trim_start().starts_with("#[cfg(test)]"))
        .map(|(i, l)| (i + 1, l))
        .filter(|(_, l)| !l.trim_start().starts_with("//"))
        .collect()
}

/// True when `line` takes the integrator itself (`solve`, `solve_with`) from the solver's
/// module; its plain data (a `Method`, a `Settings`) may be read anywhere.
fn imports_the_solver(line: &str) -> bool {
    line.split_once("physics::solve").is_some_and(|(_, after)| {
        after
            .split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .any(|w| w == "solve" || w == "solve_with")
    })
}

fn computing_lines(files: &[std::path::PathBuf]) -> Vec<String> {
    let mut offenders = Vec::new();
    for f in files {
        let text = std::fs::read_to_string(f).unwrap();
        for (n, line) in code_lines(&text) {
            if let Some(c) = COMPUTES.iter().find(|c| line.contains(*c)) {
                offenders.push(format!("{}:{n}: {} ({c})", f.display(), line.trim()));
            } else if imports_the_solver(line) {
                offenders.push(format!("{}:{n}: {} (solve)", f.display(), line.trim()));
            }
        }
    }
    offenders
}

/// One pipeline: figures are pure functions of the results, and the report's renderers read
/// results; in the report crate only `pipeline.rs` (which runs each study once) and the
/// studies it runs (`study/`) compute.
#[test]
fn figures_and_renderers_never_integrate() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("crates/report/src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    let files: Vec<_> = files
        .into_iter()
        .filter(|f| {
            let rel = f
                .strip_prefix(&src)
                .unwrap()
                .to_string_lossy()
                .replace('\\', "/");
            // The executor and its studies are where the report computes.
            rel != "pipeline.rs" && !rel.starts_with("study/")
        })
        .collect();
    assert!(files.len() >= 15, "only {} files found", files.len());
    let offenders = computing_lines(&files);
    assert_none("figures or renderers that compute", &offenders);
}

#[test]
fn the_purity_rule_would_catch_an_integration() {
    // The scan must be able to fail: the studies, which the report only reads, are caught
    // when scanned.
    let studies = Path::new(env!("CARGO_MANIFEST_DIR")).join("crates/studies/src");
    let mut files = Vec::new();
    rust_files(&studies, &mut files);
    let caught = computing_lines(&files);
    assert!(
        caught.iter().any(|l| l.ends_with("(solve)"))
            && caught.iter().any(|l| l.ends_with("(simulate_motion)")),
        "{caught:?}"
    );
}

/// One concept per file, and files a reader can hold: no source or test file over this many
/// lines.
const MOST_LINES: usize = 600;

/// The files over [`MOST_LINES`] lines under the directories `dirs`, with their lengths.
fn long_files(dirs: &[std::path::PathBuf]) -> Vec<String> {
    let mut files = Vec::new();
    for d in dirs {
        rust_files(d, &mut files);
    }
    files
        .iter()
        .filter_map(|f| {
            let n = std::fs::read_to_string(f).unwrap().lines().count();
            (n > MOST_LINES).then(|| format!("{}: {n} lines", f.display()))
        })
        .collect()
}

#[test]
fn no_file_is_longer_than_600_lines() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut dirs = source_dirs();
    dirs.extend(["tests", "benches"].map(|d| root.join(d)));
    let long = long_files(&dirs);
    assert_none("split these by concept", &long);
}

#[test]
fn the_length_rule_would_catch_a_long_file() {
    // The scan must be able to fail: a file one line over the limit is caught, one at it is not.
    let dir = std::env::temp_dir().join(format!("rolling-disk-long-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("at.rs"), "//\n".repeat(MOST_LINES)).unwrap();
    std::fs::write(dir.join("over.rs"), "//\n".repeat(MOST_LINES + 1)).unwrap();
    let long = long_files(std::slice::from_ref(&dir));
    std::fs::remove_dir_all(&dir).unwrap();
    assert_eq!(long.len(), 1, "{long:?}");
    assert!(long[0].contains("over.rs"), "{long:?}");
}

/// The check modules of src/equations, one per part of the paper. The shared machinery they
/// may all use (mod.rs's harness, spin_down_reference.rs for sec. 11, steady_reference.rs for steady
/// motions) is not among them.
const CHECKS: &[&str] = &[
    "air_film",
    "claims",
    "derivations",
    "dissipation",
    "frictionless",
    "kinematics",
    "motion",
    "oscillation",
    "slippage",
    "steady",
];

/// The check modules other than `own` that a line of code imports. In a file `nested` inside a
/// check's folder, `super::` is that check's own module and names its parts, not other checks.
fn other_checks(own: &str, nested: bool, line: &str) -> Vec<&'static str> {
    let up = if nested { "super::super::" } else { "super::" };
    CHECKS
        .iter()
        .copied()
        .filter(|c| *c != own)
        .filter(|c| {
            [
                format!("{up}{c}::"),
                format!("equations::{c}::"),
                format!("{up}{c};"),
                format!("equations::{c};"),
            ]
            .iter()
            .any(|p| line.contains(p.as_str()))
        })
        .collect()
}

#[test]
fn no_check_imports_another() {
    let eqs = Path::new(env!("CARGO_MANIFEST_DIR")).join("crates/checks/src/equations");
    let mut files = Vec::new();
    rust_files(&eqs, &mut files);
    assert!(files.len() > 30, "only {} files found", files.len());
    let mut offenders = Vec::new();
    for f in &files {
        let rel = f.strip_prefix(&eqs).unwrap();
        let own = rel
            .components()
            .next()
            .unwrap()
            .as_os_str()
            .to_string_lossy()
            .trim_end_matches(".rs")
            .to_string();
        if !CHECKS.contains(&own.as_str()) || rel.ends_with("tests.rs") {
            continue;
        }
        let nested = rel.components().count() > 1 && !rel.ends_with("mod.rs");
        let text = std::fs::read_to_string(f).unwrap();
        for (n, line) in code_lines(&text) {
            for c in other_checks(&own, nested, line) {
                offenders.push(format!("{}:{n}: imports {c}: {}", f.display(), line.trim()));
            }
        }
    }
    assert_none(
        "check files importing other checks (move what they share into the harness)",
        &offenders,
    );
}

#[test]
fn the_check_rule_would_catch_an_import() {
    assert_eq!(
        other_checks("air_film", false, "use super::oscillation::{eq54};"),
        vec!["oscillation"]
    );
    assert!(other_checks("oscillation", false, "use super::oscillation::eq54;").is_empty());
    assert!(other_checks("air_film", false, "use super::spin_down::{disk};").is_empty());
    // Inside claims/, `super::motion` is claims/motion.rs; `super::super::motion` is the check.
    assert!(other_checks("claims", true, "use super::motion::{stated};").is_empty());
    assert_eq!(
        other_checks("claims", true, "use super::super::motion::{eq23};"),
        vec!["motion"]
    );
}

/// The paper's files: only the `paper` crate embeds or opens them, so every consumer reads the one
/// [`paper::Paper`] it was given (a `--paper DIR` then reaches every output).
const PAPER_FILES: &[&str] = &[
    "equations.yaml",
    "symbols.yaml",
    "claims.yaml",
    "corrections.yaml",
];

/// The lines of `text` (code, not comments) that embed or open one of the paper's files: a
/// string literal naming it passed straight to `include_str!`, a read, an open or a path join.
fn paper_file_uses(text: &str) -> Vec<(usize, String)> {
    const READERS: &[&str] = &[
        "include_str!(",
        "read_to_string(",
        "read(",
        "open(",
        "join(",
    ];
    code_lines(text)
        .into_iter()
        .filter(|(_, line)| {
            READERS.iter().any(|r| {
                line.match_indices(r).any(|(i, _)| {
                    let rest = &line[i + r.len()..];
                    rest.starts_with('"')
                        && rest[1..].split('"').next().is_some_and(|lit| {
                            PAPER_FILES
                                .iter()
                                .any(|f| lit == *f || lit.ends_with(&format!("/{f}")))
                        })
                })
            })
        })
        .map(|(n, line)| (n, line.trim().to_string()))
        .collect()
}

#[test]
fn only_the_paper_module_reads_the_paper() {
    let mut files = Vec::new();
    for d in source_dirs() {
        rust_files(&d, &mut files);
    }
    let paper = Path::new(env!("CARGO_MANIFEST_DIR")).join("crates/paper/src");
    let mut offenders = Vec::new();
    for f in files.iter().filter(|f| !f.starts_with(&paper)) {
        let text = std::fs::read_to_string(f).unwrap();
        for (n, line) in paper_file_uses(&text) {
            offenders.push(format!("{}:{n}: {line}", f.display()));
        }
    }
    assert_none(
        "read the paper through paper::Paper, not its files",
        &offenders,
    );
    // The paper module itself embeds the four and opens them in a directory (else the scan
    // looks for the wrong thing).
    let own: usize = files
        .iter()
        .filter(|f| f.starts_with(&paper))
        .map(|f| paper_file_uses(&std::fs::read_to_string(f).unwrap()).len())
        .sum();
    assert_eq!(own, 8, "the paper module's reads of its files");
}

#[test]
fn the_paper_rule_would_catch_a_second_reader() {
    let planted = "fn f() {\n    let t = include_str!(\"../paper/claims.yaml\");\n    \
                   let u = std::fs::read_to_string(dir.join(\"equations.yaml\"));\n}\n";
    assert_eq!(paper_file_uses(planted).len(), 2);
    assert!(paper_file_uses("// the claims of paper/claims.yaml\n").is_empty());
    assert!(paper_file_uses("let s = format!(\"no reading in claims.yaml\");\n").is_empty());
}

/// The functions of Rust source `text` longer than `most` lines (signature to closing brace,
/// comments included): (name, lines).
fn long_functions(text: &str, most: usize) -> Vec<(String, usize)> {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let trimmed = line.trim_start();
        let indent = &line[..line.len() - trimmed.len()];
        let rest = ["pub(crate) ", "pub(super) ", "pub "]
            .iter()
            .find_map(|p| trimmed.strip_prefix(p))
            .unwrap_or(trimmed);
        let Some(name) = rest
            .strip_prefix("fn ")
            .and_then(|r| r.split(|c: char| !(c.is_alphanumeric() || c == '_')).next())
        else {
            continue;
        };
        let Some(open) = (i..lines.len()).find(|&j| {
            let l = lines[j].trim_end();
            l.ends_with('{') || l.ends_with(';')
        }) else {
            continue;
        };
        if lines[open].trim_end().ends_with(';') {
            continue;
        }
        let close = format!("{indent}}}");
        if let Some(end) = (open + 1..lines.len()).find(|&k| lines[k] == close) {
            if end - i + 1 > most {
                out.push((name.to_string(), end - i + 1));
            }
        }
    }
    out
}

#[test]
fn no_function_is_longer_than_150_lines() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut dirs = source_dirs();
    dirs.extend(["tests", "benches"].map(|d| root.join(d)));
    let mut files = Vec::new();
    for d in &dirs {
        rust_files(d, &mut files);
    }
    let long: Vec<String> = files
        .iter()
        .flat_map(|f| {
            let text = std::fs::read_to_string(f).unwrap();
            long_functions(&text, 150)
                .into_iter()
                .map(move |(name, n)| format!("{}: fn {name}, {n} lines", f.display()))
        })
        .collect();
    assert_none("split these into named steps", &long);
}

#[test]
fn the_function_rule_would_catch_a_long_function() {
    // 150 lines from signature to brace is allowed, 151 is not.
    let body = "    let x = 1;\n".repeat(148);
    let at = format!("pub fn at() {{\n{body}}}\n");
    let over = format!("fn over() {{\n{body}    let y = 2;\n}}\n");
    assert!(long_functions(&at, 150).is_empty());
    assert_eq!(long_functions(&over, 150), vec![("over".to_string(), 151)]);
}

/// What writes, renames or removes a file directly: outside the `files` crate, every file the
/// tool writes goes through its doors (`output_file::write_output` for a path the user named,
/// `output::SetWriter` and `output::write_set_file` for a set), which never replace a non-regular
/// file, an input or a name the user did not give, and never remove what they did not create.
const WRITES: &[&str] = &[
    "fs::write(",
    "File::create(",
    "OpenOptions",
    "fs::rename(",
    "remove_file(",
    "remove_dir(",
    "remove_dir_all(",
    "fs::copy(",
    "set_permissions(",
    "hard_link(",
    "write_atomically(",
];

/// The lines of `files` (before their unit tests) that write around the door.
fn writing_lines(files: &[std::path::PathBuf]) -> Vec<String> {
    let mut offenders = Vec::new();
    for f in files {
        let text = std::fs::read_to_string(f).unwrap();
        for (n, line) in code_lines(&text) {
            if let Some(w) = WRITES.iter().find(|w| line.contains(*w)) {
                offenders.push(format!("{}:{n}: {} ({w})", f.display(), line.trim()));
            }
        }
    }
    offenders
}

#[test]
fn every_file_is_written_through_the_door() {
    let files_crate = Path::new(env!("CARGO_MANIFEST_DIR")).join("crates/files");
    let mut files = Vec::new();
    for d in source_dirs()
        .iter()
        .filter(|d| !d.starts_with(&files_crate))
    {
        rust_files(d, &mut files);
    }
    assert_none(
        "write through files::output_file::write_output or files::output (SetWriter, write_set_file)",
        &writing_lines(&files),
    );
}

#[test]
fn the_door_rule_would_catch_a_direct_write() {
    let dir = std::env::temp_dir().join(format!("rolling-disk-door-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let planted = "fn f(p: &Path) {\n    std::fs::rename(&a, p).ok();\n}\n#[cfg(test)]\nfn t() { std::fs::write(p, \"x\"); }\n";
    std::fs::write(dir.join("planted.rs"), planted).unwrap();
    std::fs::write(
        dir.join("door.rs"),
        "fn f() { files::output_file::write_output(p, b); }\n",
    )
    .unwrap();
    let found = writing_lines(&[dir.join("planted.rs"), dir.join("door.rs")]);
    std::fs::remove_dir_all(&dir).unwrap();
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(found[0].contains("planted.rs:2"), "{found:?}");
}

/// Fails with `what` and the offending lines when there are any.
fn assert_none(what: &str, offenders: &[String]) {
    assert!(offenders.is_empty(), "{what}:\n{}", offenders.join("\n"));
}
