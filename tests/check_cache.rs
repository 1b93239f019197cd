//! `check` keeps the squeeze film's dissipation number between runs (`report::kept_film`): the
//! checks from a cold cache, a warm one and an altered entry are the same to the byte, an
//! altered entry is said and solved again, never trusted, and `--no-cache` writes nothing.

use crate::common::{cli_in, temp_dir};
use std::path::{Path, PathBuf};

/// The cache's entries of the film.
fn film_entries(cache: &Path) -> Vec<PathBuf> {
    std::fs::read_dir(cache)
        .map(|d| {
            d.map(|e| e.unwrap().path())
                .filter(|p| {
                    let n = p.file_name().unwrap().to_string_lossy();
                    n.starts_with("film-") && n.ends_with(".cbor")
                })
                .collect()
        })
        .unwrap_or_default()
}

#[test]
fn checks_from_a_cold_a_warm_or_an_altered_cache_are_the_same_to_the_byte() {
    let dir = temp_dir("check", "cache");
    let cache = dir.join("cache");
    // The air film's checks (eq 82 solves the film) and one that does not need it.
    let run = || {
        let (ok, out, err) = cli_in(
            &dir,
            &[
                "check",
                "--only",
                "82,5",
                "--snapshot",
                "-",
                "--cache-dir",
                cache.to_str().unwrap(),
            ],
        );
        assert!(ok, "{err}");
        (out, err)
    };
    let (cold, _) = run();
    assert!(cold.contains("\"eq 82\""), "{cold}");
    let entries = film_entries(&cache);
    assert_eq!(entries.len(), 1, "{entries:?}");
    let written = std::fs::read(&entries[0]).unwrap();

    let (warm, said) = run();
    assert!(!said.contains("warning"), "{said}");
    assert!(warm == cold, "a warm cache changed the checks");
    assert_eq!(std::fs::read(&entries[0]).unwrap(), written);

    // One bit of the kept number flipped: not trusted, solved again, kept again.
    let mut bytes = written.clone();
    let last = bytes.len() - 1;
    bytes[last] ^= 0x01;
    std::fs::write(&entries[0], &bytes).unwrap();
    let (again, said) = run();
    assert!(said.contains("warning: film: the cached result"), "{said}");
    assert!(said.contains("did not pass its checks"), "{said}");
    assert!(again == cold, "an altered entry changed the checks");
    assert_eq!(std::fs::read(&entries[0]).unwrap(), written);
    let _ = std::fs::remove_dir_all(&dir);
}

/// `--no-cache` writes nothing in the cache folder (here the one `$XDG_CACHE_HOME` names, the
/// default), and a run that never needs the film writes nothing either.
#[test]
fn no_cache_or_no_film_writes_no_cache() {
    let dir = temp_dir("check", "no-cache");
    let xdg = dir.join("xdg");
    for args in [
        &["check", "--only", "82", "--no-cache"][..],
        &["check", "--only", "5"][..],
    ] {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_rolling-disk"))
            .args(args)
            .env("XDG_CACHE_HOME", &xdg)
            .current_dir(&dir)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(!xdg.exists(), "{args:?} wrote {}", xdg.display());
    }
    let _ = std::fs::remove_dir_all(&dir);
}
