//! `peer compare` through the binary on every raw peer run (`tests/reference/peer-raw/`), each
//! within 2 s: every mode change either paired by direction and time, or, where one run changes
//! mode and the other does not, the rows whose modes differ reported, and a whole-run mismatch
//! said as such. (`peer_raw` holds the same runs' differences against an independent alignment.)

use super::sandbox::bounded;
use std::path::Path;
use std::time::Duration;

/// The counts on the line `rolling/sliding changes: P in the peer, H here; ...`, and how many
/// it pairs.
fn changes(out: &str) -> Option<(usize, usize, usize)> {
    let line = out
        .lines()
        .find_map(|l| l.trim().strip_prefix("rolling/sliding changes: "))?;
    let number = |s: &str| s.split_whitespace().next()?.parse::<usize>().ok();
    let (peer, rest) = line.split_once(" in the peer, ")?;
    let (here, rest) = rest.split_once(" here; ")?;
    let paired = if rest.starts_with("none paired") {
        0
    } else {
        number(rest)?
    };
    Some((number(peer)?, number(here)?, paired))
}

#[test]
fn peer_compare_pairs_every_mode_change_or_reports_the_rows_that_differ() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reference/peer-raw");
    let mut runs: Vec<_> = std::fs::read_dir(&root)
        .expect("the raw runs")
        .flatten()
        .map(|e| e.path())
        .collect();
    runs.sort();
    assert_eq!(runs.len(), 10, "{runs:?}");
    let mut switching = 0;
    for run in runs {
        let (scene, result) = (run.join("scene.yaml"), run.join("result.txt"));
        let args = [
            "peer",
            "compare",
            scene.to_str().expect("a UTF-8 path"),
            result.to_str().expect("a UTF-8 path"),
        ];
        let ran = bounded(&root, &args, Duration::from_secs(2));
        assert!(ran.ok, "{}: {}", run.display(), ran.stderr);
        let (peer, here, paired) = changes(&ran.stdout)
            .unwrap_or_else(|| panic!("{}: no changes line in\n{}", run.display(), ran.stdout));
        if peer == here {
            assert_eq!(paired, peer, "{}: {}", run.display(), ran.stdout);
            switching += peer;
        } else {
            // An unpaired change: the rows in different modes from it on are reported.
            assert!(
                ran.stdout.contains("modes: they differ in"),
                "{}: {}",
                run.display(),
                ran.stdout
            );
        }
        // Modes that differ throughout are said to.
        if ran.stdout.contains("they differ in every one") {
            assert!(ran.stdout.contains("different modes throughout"));
        }
        // Nothing that does not pair is given a paired time difference.
        if paired == 0 {
            assert!(
                !ran.stdout.contains("paired by direction"),
                "{}",
                ran.stdout
            );
        }
    }
    assert!(switching >= 3, "{switching} paired changes in all");
}
