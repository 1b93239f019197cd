//! Every manifest names only what its crate uses: a dependency is used in the crate's `src/`, a
//! dev-dependency in its tests or benchmarks (the role `cargo machete` plays, without a tool to
//! install). Names are read from `cargo metadata` (the manifests only); a use is a path
//! (`name::`), a `use name`, a macro (`name!`) or a derive naming the crate.

use super::architecture::{cargo_metadata, rust_files};
use std::path::{Path, PathBuf};

/// A dependency as its crate's code names it, and its kind: `None` for a normal dependency,
/// `Some("dev")` for a dev-dependency.
type Dependency = (String, Option<String>);

/// A package's directory and its dependencies.
type Manifest = (PathBuf, Vec<Dependency>);

/// Every package of the workspace.
fn manifests() -> Vec<Manifest> {
    let doc = cargo_metadata();
    doc["packages"]
        .as_array()
        .expect("packages")
        .iter()
        .map(|p| {
            let dir = Path::new(p["manifest_path"].as_str().unwrap_or_default())
                .parent()
                .expect("a manifest has a folder")
                .to_path_buf();
            let deps = p["dependencies"]
                .as_array()
                .into_iter()
                .flatten()
                .map(|d| {
                    let name = d["rename"]
                        .as_str()
                        .or(d["name"].as_str())
                        .unwrap_or_default()
                        .replace('-', "_");
                    (name, d["kind"].as_str().map(str::to_string))
                })
                .collect();
            (dir, deps)
        })
        .collect()
}

/// True when `text` uses the crate `name`.
fn uses(text: &str, name: &str) -> bool {
    let bounded = |pat: &str| {
        text.match_indices(pat).any(|(i, _)| {
            !text[..i]
                .chars()
                .next_back()
                .is_some_and(|c| c.is_alphanumeric() || c == '_')
        })
    };
    bounded(&format!("{name}::")) || bounded(&format!("use {name}")) || bounded(&format!("{name}!"))
}

/// The dependencies of each manifest that its crate never uses, as "crate: name (kind)".
fn unused(packages: &[Manifest]) -> Vec<String> {
    let mut found = Vec::new();
    for (dir, deps) in packages {
        let read = |subdirs: &[&str]| {
            let mut files = Vec::new();
            for s in subdirs {
                rust_files(&dir.join(s), &mut files);
            }
            files
                .iter()
                .map(|f| std::fs::read_to_string(f).unwrap_or_default())
                .collect::<Vec<_>>()
                .join("\n")
        };
        let src = read(&["src"]);
        let all = read(&["src", "tests", "benches"]);
        for (name, kind) in deps {
            let text = match kind.as_deref() {
                None => &src,
                Some("dev") => &all,
                Some(_) => continue,
            };
            if !uses(text, name) {
                found.push(format!(
                    "{}: {name} ({})",
                    dir.display(),
                    kind.as_deref().unwrap_or("normal")
                ));
            }
        }
    }
    found
}

#[test]
fn no_manifest_names_an_unused_crate() {
    let found = unused(&manifests());
    assert!(
        found.is_empty(),
        "these dependencies are not used where their kind says (move a dependency only the tests \
         use to [dev-dependencies], or remove it): {found:?}"
    );
}

#[test]
fn the_rule_would_catch_an_unused_crate() {
    let dir = std::env::temp_dir().join(format!("manifests-rule-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("src")).unwrap();
    std::fs::write(
        dir.join("src/lib.rs"),
        "use serde::Serialize;\nfn f() { anyhow!(1) }\n",
    )
    .unwrap();
    let deps = vec![
        ("serde".to_string(), None),
        ("anyhow".to_string(), None),
        ("serde_json".to_string(), None),
        ("rand".to_string(), Some("dev".to_string())),
    ];
    let found = unused(&[(dir.clone(), deps)]);
    std::fs::remove_dir_all(&dir).unwrap();
    assert_eq!(found.len(), 2, "{found:?}");
    assert!(found[0].ends_with("serde_json (normal)"), "{found:?}");
    assert!(found[1].ends_with("rand (dev)"), "{found:?}");
}
