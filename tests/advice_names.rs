//! Every `--option` and every scene key that the tool's own messages and advice name exists:
//! the string literals of every source file, held against the command line's help and the
//! scene keys.

use crate::limits::cli;
use physics::scene::Scene;
use std::path::{Path, PathBuf};

/// Every `--option` named anywhere in the sources (messages and advice) exists in the CLI's
/// own help, and every `section.key` a message names is a key a scene accepts.
#[test]
fn every_option_and_key_that_advice_names_exists() {
    let mut help = String::new();
    for sub in [
        "",
        "simulate",
        "report",
        "figures",
        "scenes",
        "check",
        "precision",
        "experiment",
    ] {
        let args: Vec<&str> = sub
            .split(' ')
            .filter(|s| !s.is_empty())
            .chain(["--help"])
            .collect();
        help.push_str(&cli(&args).1);
    }
    for sub in ["simulate", "analyze"] {
        help.push_str(&cli(&["experiment", sub, "--help"]).1);
    }
    let mut sources = String::new();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    collect(&root.join("src"), &mut sources);
    collect(&root.join("crates"), &mut sources);
    let mut options: Vec<&str> = Vec::new();
    let mut keys: Vec<(&str, &str)> = Vec::new();
    for (i, _) in sources.match_indices("--") {
        // A cargo command quoted in the sources names cargo's options (and, after `cargo test
        // ... --`, the test harness's); after `cargo run ... --` they are this tool's again.
        let line = &sources[sources[..i].rfind('\n').map_or(0, |j| j + 1)..i];
        if let Some(c) = line.rfind("cargo ") {
            let command = &line[c..];
            if command.starts_with("cargo test") || !command.contains(" -- ") {
                continue;
            }
        }
        let rest = &sources[i + 2..];
        let name_len = rest
            .find(|c: char| !(c.is_ascii_alphanumeric() || c == '-'))
            .unwrap_or(rest.len());
        if name_len > 1 && rest.starts_with(|c: char| c.is_ascii_lowercase()) {
            options.push(&sources[i..i + 2 + name_len]);
        }
    }
    for section in ["solver", "stop", "disk", "start", "dissipation"] {
        for (i, _) in sources.match_indices(&format!("{section}.")) {
            let before = sources[..i].chars().next_back().unwrap_or(' ');
            let rest = &sources[i + section.len() + 1..];
            let len = rest
                .find(|c: char| !(c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_'))
                .unwrap_or(rest.len());
            if len > 0 && !before.is_ascii_alphanumeric() && !"_.-/".contains(before) {
                keys.push((section, &rest[..len]));
            }
        }
    }
    options.sort_unstable();
    options.dedup();
    assert!(options.contains(&"--max-seconds"), "{options:?}");
    for o in &options {
        assert!(
            help.contains(o),
            "{o} is named in the sources but is not an option"
        );
    }
    keys.sort_unstable();
    keys.dedup();
    assert!(keys.contains(&("solver", "max_steps")), "{keys:?}");
    for (section, key) in keys {
        // A misspelt key inside the section makes the reader list the section's keys.
        let probe = format!("{section}: {{ zzz_not_a_key: 1 }}\n");
        let e = Scene::parse(&probe, "probe.yaml").expect_err("refused");
        let listed = e.message.split("the keys here are ").nth(1).unwrap_or("");
        let valid: Vec<&str> = listed.split(", ").collect();
        assert!(
            valid.contains(&key),
            "{section}.{key} is named but not a key ({e})"
        );
    }
}

fn collect(dir: &Path, into: &mut String) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let mut paths: Vec<PathBuf> = entries.flatten().map(|e| e.path()).collect();
    paths.sort();
    for p in paths {
        if p.is_dir() {
            collect(&p, into);
        } else if p.extension().is_some_and(|e| e == "rs")
            // A build script's literals are the options of the programs it runs (git), never
            // shown to a user.
            && p.file_name().is_some_and(|n| n != "build.rs")
        {
            string_literals(&std::fs::read_to_string(&p).unwrap_or_default(), into);
        }
    }
}

/// The contents of the string literals of Rust source `src`, one per line, with comments,
/// char literals and lifetimes skipped: the text a user can be shown.
fn string_literals(src: &str, into: &mut String) {
    let c: Vec<char> = src.chars().collect();
    let mut i = 0;
    while i < c.len() {
        match c[i] {
            '/' if c.get(i + 1) == Some(&'/') => {
                while i < c.len() && c[i] != '\n' {
                    i += 1;
                }
            }
            '/' if c.get(i + 1) == Some(&'*') => {
                while i + 1 < c.len() && !(c[i] == '*' && c[i + 1] == '/') {
                    i += 1;
                }
                i += 2;
            }
            '\'' => {
                // A char literal ('x' or '\x'), else a lifetime.
                if c.get(i + 1) == Some(&'\\') {
                    i += 2;
                    while i < c.len() && c[i] != '\'' {
                        i += 1;
                    }
                    i += 1;
                } else if c.get(i + 2) == Some(&'\'') {
                    i += 3;
                } else {
                    i += 1;
                }
            }
            'r' if matches!(c.get(i + 1), Some('"') | Some('#'))
                && (i == 0 || !c[i - 1].is_alphanumeric()) =>
            {
                let mut hashes = 0;
                i += 1;
                while c.get(i) == Some(&'#') {
                    hashes += 1;
                    i += 1;
                }
                i += 1;
                while i < c.len() {
                    if c[i] == '"' && (1..=hashes).all(|k| c.get(i + k) == Some(&'#')) {
                        i += 1 + hashes;
                        break;
                    }
                    into.push(c[i]);
                    i += 1;
                }
                into.push('\n');
            }
            '"' => {
                i += 1;
                while i < c.len() && c[i] != '"' {
                    if c[i] == '\\' {
                        i += 1;
                    }
                    if let Some(&ch) = c.get(i) {
                        into.push(ch);
                    }
                    i += 1;
                }
                i += 1;
                into.push('\n');
            }
            _ => i += 1,
        }
    }
}
