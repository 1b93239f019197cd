//! The stored coverage studies the report draws (`snapshots/coverage.json`) are this code's:
//! the first recordings of each are run again and must give the same pulls.

use studies::coverage_record::{run, stored, study, StoredCoverage};

/// The studies, as `ROLLING_DISK_BLESS=1 cargo test --release --test integration coverage_record:: --
/// --ignored` runs and stores them: 400 clean recordings (seeds 5000-5399) and 500 with every
/// artifact (seeds 10000-10499), the same as the full studies of `tests/experiment.rs`, and 200
/// phone sounds with hum (seeds 20000-20199, `studies::sound_coverage`).
const STUDIES: [(&str, usize, u64, bool, bool); 3] = [
    ("clean", 400, 5000, false, false),
    ("artifact-laden", 500, 10_000, true, false),
    ("phone sound", 200, 20_000, false, true),
];

#[test]
fn the_stored_coverage_studies_are_this_codes() {
    let s = stored().unwrap();
    assert_eq!(s.len(), STUDIES.len(), "run the studies: see STUDIES");
    for (st, (name, runs, seed0, artifacts, sound)) in s.iter().zip(STUDIES) {
        assert_eq!(
            (
                st.recordings.as_str(),
                st.coverage.runs,
                st.seed0,
                st.artifacts,
                st.sound
            ),
            (name, runs, seed0, artifacts, sound)
        );
        assert_eq!(st.coverage.beta_pulls.len() + st.coverage.refused, runs);
        // The first recordings again: the same pulls (a refusal among them would shift the
        // stored ones, and fails here too).
        let again = study(3, seed0, artifacts, sound).unwrap();
        assert_eq!(again.refused, 0, "{}", st.line());
        for (a, b) in [
            (&again.beta_pulls, &st.coverage.beta_pulls),
            (&again.t0_pulls, &st.coverage.t0_pulls),
        ] {
            for (x, y) in a.iter().zip(b.iter()) {
                assert!(
                    (x - y).abs() <= 1e-12 * y.abs().max(1.0),
                    "{x} vs stored {y}"
                );
            }
        }
        println!("{}", st.line());
    }
}

/// Runs the studies and, with ROLLING_DISK_BLESS=1, stores them; with ROLLING_DISK_STUDY=NAME,
/// runs that study alone and keeps the others as stored (the fast test above proves them
/// current). Tens of minutes for all on two cores.
#[test]
#[ignore = "slow: 900 light recordings and 200 sounds, tens of minutes; run with ROLLING_DISK_BLESS=1 to store them"]
fn record_the_coverage_studies() {
    let date = std::env::var("ROLLING_DISK_DATE").unwrap_or_else(|_| "undated".into());
    let only = std::env::var("ROLLING_DISK_STUDY").ok();
    let kept = stored().unwrap_or_default();
    let command = "ROLLING_DISK_BLESS=1 cargo test --release --test integration coverage_record:: -- --ignored";
    let studies: Vec<StoredCoverage> = STUDIES
        .iter()
        .map(|&(name, runs, seed0, artifacts, sound)| {
            if let Some(old) = kept
                .iter()
                .find(|k| k.recordings == name && only.as_deref().is_some_and(|o| o != name))
            {
                return old.clone();
            }
            let command = match &only {
                Some(o) => format!("ROLLING_DISK_STUDY='{o}' {command}"),
                None => command.to_string(),
            };
            let s = run(name, (runs, seed0), (artifacts, sound), &command, &date).unwrap();
            println!("{}", s.line());
            s
        })
        .collect();
    if std::env::var("ROLLING_DISK_BLESS").is_ok() {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("snapshots/coverage.json");
        let text = serde_json::to_string_pretty(&studies).unwrap() + "\n";
        std::fs::write(&path, text).unwrap();
        println!("stored in {}", path.display());
    }
}

/// docs/experiment.md tabulates the stored studies: each row's counts and percentages are the
/// stored file's.
#[test]
fn the_docs_table_is_the_stored_studies() {
    let rows: Vec<String> = stored()
        .unwrap()
        .iter()
        .map(|st| {
            let c = &st.coverage;
            let cell = |pulls: &[f64], z: f64| {
                let within = pulls.iter().filter(|p| p.abs() <= z).count();
                format!("{within} ({:.1} %)", 100.0 * c.fraction(pulls, z))
            };
            format!(
                "| {} | {} | {} | {} | {} | {} | {} | {} |",
                st.recordings,
                c.runs,
                c.refused,
                cell(&c.beta_pulls, 1.0),
                cell(&c.beta_pulls, 1.96),
                cell(&c.t0_pulls, 1.0),
                cell(&c.t0_pulls, 1.96),
                c.law_drifts
            )
        })
        .collect();
    crate::common::experiment_docs_say(&rows);
}
