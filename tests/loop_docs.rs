//! The loop's documentation is the tool's: the exit statuses of docs/loop.md are those of
//! `src/cli/exit.rs`, and the README's test section and docs/loop.md say how to install the
//! snapshot tool the project's own tests use.

use std::path::Path;

fn read(file: &str) -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(file)).unwrap()
}

/// The rows `| N | meaning |` of a table of statuses.
fn status_rows(text: &str) -> Vec<String> {
    text.lines()
        .map(|l| l.trim_start_matches("//!").trim())
        .filter(|l| {
            l.strip_prefix("| ")
                .is_some_and(|r| r.starts_with(|c: char| c.is_ascii_digit()))
        })
        .map(str::to_string)
        .collect()
}

#[test]
fn the_exit_statuses_written_are_the_tools() {
    let code = status_rows(&read("src/cli/exit.rs"));
    let doc = status_rows(&read("docs/loop.md"));
    assert_eq!(code.len(), 6, "{code:?}");
    assert_eq!(doc, code);
    let exit = read("src/cli/exit.rs");
    assert!(exit.contains("pub const CHANGED: u8 = 3;"));
    assert!(exit.contains("pub const FOUND: u8 = 4;"));
}

#[test]
fn the_snapshot_tool_is_installed_as_written() {
    let install = "cargo install cargo-insta --locked";
    for file in ["README.md", "docs/loop.md"] {
        assert!(
            read(file).contains(install),
            "{file} does not say {install}"
        );
    }
}
