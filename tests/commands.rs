//! A command is one file in `src/cli/` (its clap `Args`, or `Command` for a family of
//! subcommands, and its `run`) plus one row: its variant of `Command` in `src/lib.rs`. This test
//! holds that table complete: every command file has its row, and every row its `--help`.

use std::path::Path;

/// The files of `src/cli/` that define a command's arguments, by module name.
fn command_files(root: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(root.join("src/cli"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "rs"))
        .filter(|p| {
            let text = std::fs::read_to_string(p).unwrap();
            text.contains("pub struct Args") || text.contains("pub enum Command")
        })
        .map(|p| p.file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// The modules of `src/cli/` that `Command`'s rows name (`cli::NAME::Args` or `::Command`).
fn rows(lib: &str) -> Vec<String> {
    let start = lib
        .find("pub enum Command")
        .expect("src/lib.rs has the command list");
    let body = &lib[start..start + lib[start..].find("\n}").expect("the list ends")];
    let mut names: Vec<String> = body
        .match_indices("(cli::")
        .map(|(i, _)| {
            let rest = &body[i + "(cli::".len()..];
            rest[..rest.find("::").expect("a row names a type")].to_string()
        })
        .collect();
    names.sort();
    names
}

#[test]
fn every_command_file_has_its_row() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let lib = std::fs::read_to_string(root.join("src/lib.rs")).unwrap();
    // `paper_input` is the `--paper`/`--accuracy` options that several commands flatten in.
    let files: Vec<String> = command_files(root)
        .into_iter()
        .filter(|n| n != "paper_input")
        .collect();
    assert_eq!(
        rows(&lib),
        files,
        "a command file without its row in src/lib.rs, or a row without its file"
    );
}

#[test]
fn every_row_answers_help() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let lib = std::fs::read_to_string(root.join("src/lib.rs")).unwrap();
    for name in rows(&lib) {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_rolling-disk"))
            .args([&name, "--help"])
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "rolling-disk {name} --help: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
}

#[test]
fn the_rows_are_read_from_the_list() {
    let lib = "pub enum Command {\n    /// a\n    Simulate(cli::simulate::Args),\n    #[command(subcommand)]\n    Peer(cli::peer::Command),\n}\n";
    assert_eq!(rows(lib), vec!["peer".to_string(), "simulate".to_string()]);
}
