//! The cache of results that depend on nothing but the program (`report::cache`): a report
//! from a cold cache, from a warm one and from an altered entry is the same report, file by
//! file and byte by byte, and an altered entry is said and computed again, never trusted.

use crate::common::{cli_in, temp_dir};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Every file under `dir`, by its path relative to `dir`.
fn files(dir: &Path) -> BTreeMap<PathBuf, Vec<u8>> {
    let mut out = BTreeMap::new();
    let mut todo = vec![dir.to_path_buf()];
    while let Some(d) = todo.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                todo.push(p);
            } else {
                let bytes = std::fs::read(&p).unwrap();
                out.insert(p.strip_prefix(dir).unwrap().to_path_buf(), bytes);
            }
        }
    }
    out
}

/// The cache's entries of the toy study.
fn toy_entries(cache: &Path) -> Vec<PathBuf> {
    std::fs::read_dir(cache)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| {
            let n = p.file_name().unwrap().to_string_lossy();
            n.starts_with("toy-") && n.ends_with(".cbor")
        })
        .collect()
}

#[test]
fn a_report_from_a_cold_a_warm_or_an_altered_cache_is_the_same_report_to_the_byte() {
    let dir = temp_dir("report", "cache");
    let cache = dir.join("cache");
    let run = |out: &str| {
        let (ok, _, err) = cli_in(
            &dir,
            &[
                "report",
                "-v",
                "--out",
                out,
                "--cache-dir",
                cache.to_str().unwrap(),
            ],
        );
        assert!(ok, "{err}");
        (files(&dir.join(out)), err)
    };
    let (cold, said) = run("cold");
    assert!(!said.contains("toy (cached)"), "{said}");
    let entries = toy_entries(&cache);
    assert_eq!(entries.len(), 1, "{entries:?}");

    let (warm, said) = run("warm");
    assert!(said.contains("toy (cached)"), "{said}");
    assert!(cold.len() > 30, "{} files", cold.len());
    assert_eq!(
        cold.keys().collect::<Vec<_>>(),
        warm.keys().collect::<Vec<_>>()
    );
    for (path, bytes) in &cold {
        assert!(&warm[path] == bytes, "{} differs", path.display());
    }

    // One bit of the stored result flipped: the entry is not trusted, the toy is computed
    // again (and stored again), and the report is the same.
    let mut bytes = std::fs::read(&entries[0]).unwrap();
    let last = bytes.len() - 1;
    bytes[last] ^= 0x01;
    std::fs::write(&entries[0], &bytes).unwrap();
    let (again, said) = run("altered");
    assert!(said.contains("warning: toy: the cached result"), "{said}");
    assert!(said.contains("did not pass its checks"), "{said}");
    assert!(!said.contains("toy (cached)"), "{said}");
    assert_eq!(toy_entries(&cache), entries);
    assert_eq!(
        std::fs::read(&entries[0]).unwrap().len(),
        bytes.len(),
        "the entry is written again"
    );
    assert_ne!(std::fs::read(&entries[0]).unwrap(), bytes);
    assert!(again == cold, "the report from an altered entry differs");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `--no-cache` computes every study and writes nothing in the cache folder (here the one
/// `$XDG_CACHE_HOME` names, the default).
#[test]
fn no_cache_computes_every_study_and_writes_no_cache() {
    let dir = temp_dir("report", "no-cache");
    let xdg = dir.join("xdg");
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_rolling-disk"))
        .args([
            "report",
            "-v",
            "--format",
            "json",
            "--out",
            "r",
            "--no-cache",
        ])
        .env("XDG_CACHE_HOME", &xdg)
        .current_dir(&dir)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{err}");
    assert!(err.contains("\ntoy "), "{err}");
    assert!(!err.contains("(cached)"), "{err}");
    assert!(!xdg.exists(), "--no-cache wrote {}", xdg.display());
    let _ = std::fs::remove_dir_all(&dir);
}
