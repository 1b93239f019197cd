//! The command line's conventions: `--version` names the commit, completions and the manual page
//! come from the command line's definition, `--quiet` keeps only what a command is for, and a
//! mistyped name gets the nearest one.

use std::process::{Command, Output};

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_rolling-disk"))
        .args(args)
        .output()
        .expect("the binary runs")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

#[test]
fn the_version_names_the_commit_it_is_built_from() {
    let out = run(&["--version"]);
    assert!(out.status.success());
    let version = text(&out.stdout);
    assert!(
        version.starts_with(&format!(
            "rolling-disk {} (commit ",
            env!("CARGO_PKG_VERSION")
        )),
        "{version}"
    );
    let first = version.lines().next().unwrap_or_default();
    let commit = first
        .split("(commit ")
        .nth(1)
        .and_then(|s| s.strip_suffix(')'))
        .expect("a commit in brackets");
    assert!(!commit.is_empty(), "{version}");
    // Built from a git checkout, it is that checkout's commit (possibly marked dirty).
    let head = Command::new("git")
        .args(["rev-parse", "--short=12", "HEAD"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .ok()
        .filter(|h| h.status.success());
    if let Some(h) = head {
        let head = text(&h.stdout).trim().to_string();
        assert!(commit.contains(&head), "{commit} is not HEAD {head}");
    }
}

#[test]
fn the_long_version_names_the_built_in_papers_hash_as_the_outputs_do() {
    let long = text(&run(&["--version"]).stdout);
    let short = text(&run(&["-V"]).stdout);
    let mut lines = long.lines();
    assert_eq!(lines.next(), short.lines().next(), "--version starts as -V");
    let hash = lines
        .next()
        .and_then(|l| l.strip_prefix("built-in paper: sha256 "))
        .unwrap_or_else(|| panic!("no paper hash in {long:?}"));
    let out = run(&["check", "--only", "22", "--json"]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(json["paper"]["source"], "built-in");
    assert_eq!(json["paper"]["sha256"], hash, "check --json's provenance");
}

#[test]
fn every_output_names_the_version_and_commit_that_made_it() {
    let version = text(&run(&["-V"]).stdout);
    let version = version
        .trim()
        .strip_prefix("rolling-disk ")
        .unwrap()
        .to_string();
    let out = run(&["check", "--only", "22", "--json"]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(
        json["tool"]["version"],
        version.as_str(),
        "check --json's provenance"
    );
}

#[test]
fn completions_name_every_command() {
    let commands = [
        "simulate",
        "report",
        "figures",
        "scenes",
        "mutants",
        "check",
        "precision",
        "experiment",
        "peer",
        "completions",
        "manual",
    ];
    for shell in ["bash", "zsh", "fish", "elvish", "powershell"] {
        let out = run(&["completions", shell]);
        assert!(out.status.success(), "{shell}: {}", text(&out.stderr));
        let script = text(&out.stdout);
        for c in commands {
            assert!(script.contains(c), "{shell}'s completions lack {c}");
        }
        // fish names a long option as `-l paper`, the others as `--paper`.
        assert!(script.contains("paper"), "{shell}: no option --paper");
    }
    let out = run(&["completions", "tcsh"]);
    assert!(!out.status.success());
    assert!(text(&out.stderr).contains("bash"), "{}", text(&out.stderr));
}

#[test]
fn the_manual_page_is_roff_of_the_program_or_of_one_command() {
    let out = run(&["manual"]);
    assert!(out.status.success());
    // roff writes a hyphen as `\-`.
    let page = text(&out.stdout).replace("\\-", "-");
    assert!(page.contains(".TH rolling-disk"), "{page}");
    assert!(page.contains("check") && page.contains("experiment"));
    let check = text(&run(&["manual", "check"]).stdout).replace("\\-", "-");
    assert!(check.contains(".TH rolling-disk-check"), "{check}");
    assert!(check.contains("only"), "the check page lists its options");
    let wrong = run(&["manual", "chek"]);
    assert!(!wrong.status.success());
    assert!(text(&wrong.stderr).contains("the commands are: "));
}

#[test]
fn quiet_keeps_the_data_and_drops_the_notes() {
    let dir = std::env::temp_dir().join(format!("rd-quiet-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let out_dir = dir.join("figs");
    let out_arg = out_dir.to_str().unwrap();
    let loud = run(&["figures", "--only", "stability-map", "--out", out_arg]);
    assert!(loud.status.success(), "{}", text(&loud.stderr));
    assert!(text(&loud.stdout).contains("wrote "));
    let quiet = run(&[
        "--quiet",
        "figures",
        "--only",
        "stability-map",
        "--out",
        out_arg,
    ]);
    assert!(quiet.status.success(), "{}", text(&quiet.stderr));
    assert_eq!(text(&quiet.stdout), "", "--quiet still noted what it wrote");
    // Progress is for a person at a terminal: a pipe (as here) gets none.
    assert_eq!(text(&quiet.stderr), "");
    assert!(out_dir.join("stability-map.svg").exists());
    // The data a command is for is kept.
    let listed = run(&["-q", "figures", "--list"]);
    assert!(text(&listed.stdout).lines().any(|l| l == "stability-map"));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn figures_are_listed_and_a_mistyped_name_gets_the_nearest() {
    let out = run(&["figures", "--list"]);
    assert!(out.status.success());
    let names: Vec<String> = text(&out.stdout).lines().map(String::from).collect();
    assert!(
        names.len() > 10 && names.contains(&"fig1".to_string()),
        "{names:?}"
    );
    let wrong = run(&[
        "figures",
        "--only",
        "stabilty-map",
        "--out",
        "/nonexistent/x",
    ]);
    assert!(!wrong.status.success());
    let message = text(&wrong.stderr);
    assert!(message.contains("did you mean stability-map?"), "{message}");
    // Applying the advice works.
    let dir = std::env::temp_dir().join(format!("rd-nearest-{}", std::process::id()));
    let right = run(&[
        "figures",
        "--only",
        "stability-map",
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert!(right.status.success(), "{}", text(&right.stderr));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_mistyped_scene_gets_the_nearest_built_in_one() {
    let wrong = run(&["simulate", "spinning-con"]);
    assert!(!wrong.status.success());
    let message = text(&wrong.stderr);
    assert!(message.contains("did you mean "), "{message}");
    let suggested = message
        .split("did you mean ")
        .nth(1)
        .and_then(|s| s.split('?').next())
        .unwrap()
        .to_string();
    let scenes = text(&run(&["scenes"]).stdout);
    assert!(
        scenes.contains(&suggested),
        "{suggested} is not a built-in scene"
    );
    // A name far from every scene gets no guess.
    let far = text(&run(&["simulate", "zzzzzzzzzzzz"]).stderr);
    assert!(!far.contains("did you mean"), "{far}");
}
