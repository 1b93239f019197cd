//! What the phone study's recordings can tell at best (`studies::phone_bound`): the Cramér-Rao
//! bound of each recording of the stored phone study and of a second set, stored in
//! `snapshots/phone_bound.json` by the ignored test below, proved current by computing it again,
//! set beside the phone study's outcomes, and stated in docs/experiment.md.

use studies::phone_bound::{
    bound_set, cross, BoundSet, Crossed, Standing, StoredPhoneBound as Stored, ANALYSIS_LOSS,
    INFORMATION_LIMITED,
};
use studies::phone_coverage::StoredPhoneCoverage;

/// The second set: `SECOND.1` recordings from seed `SECOND.0`.
const SECOND: (u64, usize) = (1001, 100);
/// The command that stores it.
const COMMAND: &str = "ROLLING_DISK_BLESS=1 cargo test --release --test integration \
                       experiment_phone_bound:: -- --ignored";

fn root() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).to_path_buf()
}

fn path() -> std::path::PathBuf {
    root().join("snapshots/phone_bound.json")
}

/// The stored phone study, whose seeds the first set takes.
fn phone_study() -> StoredPhoneCoverage {
    let text = std::fs::read_to_string(root().join("snapshots/phone_coverage.json"))
        .expect("snapshots/phone_coverage.json");
    serde_json::from_str(&text).expect("snapshots/phone_coverage.json holds the phone study")
}

fn stored() -> Stored {
    let text = std::fs::read_to_string(path()).expect("snapshots/phone_bound.json");
    serde_json::from_str(&text).expect("snapshots/phone_bound.json holds the bound study")
}

/// The study as the command makes it: the phone study's seeds, then the second set's.
fn study() -> Stored {
    let phone = phone_study();
    Stored {
        command: COMMAND.into(),
        sets: vec![
            bound_set(phone.seed0, phone.study.runs).unwrap(),
            bound_set(SECOND.0, SECOND.1).unwrap(),
        ],
    }
}

fn text(s: &Stored) -> String {
    serde_json::to_string_pretty(s).unwrap() + "\n"
}

#[test]
fn the_stored_bound_is_what_the_command_makes() {
    let s = stored();
    let phone = phone_study();
    assert_eq!(s.command, COMMAND);
    let seeds: Vec<u64> = s.sets[0].recordings.iter().map(|r| r.seed).collect();
    let phone_seeds: Vec<u64> = phone.study.outcomes.iter().map(|o| o.seed).collect();
    assert_eq!(seeds, phone_seeds);
    assert_eq!((s.sets[1].seed0, s.sets[1].runs), SECOND);
    // Byte for byte.
    assert!(
        text(&s) == std::fs::read_to_string(path()).unwrap() && study() == s,
        "snapshots/phone_bound.json is not what the code makes now: store it again with {COMMAND}"
    );
}

/// The phone study's recordings beside their bounds, by standing.
fn crossed() -> Vec<Crossed> {
    cross(&stored().sets[0], &phone_study().study)
}

/// The median of `v`.
fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Prints the refused and missed recordings with their bounds, grouped, and the analysed ones'
/// efficiency (`--nocapture` to read them).
#[test]
fn the_refusals_and_misses_beside_their_bounds() {
    let c = crossed();
    assert_eq!(c.len(), phone_study().study.runs);
    for (standing, what) in [
        (
            Standing::RefusedInformative,
            "refused, bound < 0.005 (the analysis's loss)",
        ),
        (Standing::RefusedBetween, "refused, bound 0.005-0.0255"),
        (
            Standing::RefusedLimited,
            "refused, bound > 0.05/1.96 (the recording's)",
        ),
        (Standing::Missed, "analysed but missed"),
    ] {
        let group: Vec<&Crossed> = c.iter().filter(|x| x.standing == standing).collect();
        println!("{what}: {}", group.len());
        for x in group {
            let (o, b) = (&x.outcome, &x.bound);
            println!(
                "  seed {:>3}: {:>5} S/s, {:5.2} s from {:4.1} Hz, {:6.0} turns; bound beta {:.5} \
                 t0 {:.2e} s; {}",
                o.seed,
                o.rate,
                o.sound,
                b.start_hz,
                b.turns,
                b.beta_sigma,
                b.t0_sigma,
                match &o.refused {
                    Some(r) => r.chars().take(110).collect::<String>(),
                    None => format!(
                        "beta err {:+.4} +- {:.4} ({:.1}x bound), t0 err {:+.2e} +- {:.2e} ({:.1}x)",
                        o.beta_error.unwrap(),
                        o.beta_sigma.unwrap(),
                        x.beta_efficiency.unwrap(),
                        o.t0_error.unwrap(),
                        o.t0_sigma.unwrap(),
                        x.t0_efficiency.unwrap()
                    ),
                }
            );
        }
    }
    let eff: Vec<f64> = c.iter().filter_map(|x| x.beta_efficiency).collect();
    let t0_eff: Vec<f64> = c.iter().filter_map(|x| x.t0_efficiency).collect();
    println!(
        "analysed {}: stated sigma over the bound, beta median {:.2} (below 1 on {}), t0 median \
         {:.2} (below 1 on {})",
        eff.len(),
        median(eff.clone()),
        eff.iter().filter(|e| **e < 1.0).count(),
        median(t0_eff.clone()),
        t0_eff.iter().filter(|e| **e < 1.0).count()
    );
    for s in &stored().sets {
        println!("{}", s.summary());
    }
    // Each standing is what its definition says of the stored outcome and bound.
    for x in &c {
        let refused = x.outcome.refused.is_some();
        let b = x.bound.beta_sigma;
        match x.standing {
            Standing::RefusedInformative => assert!(refused && b < ANALYSIS_LOSS),
            Standing::RefusedLimited => assert!(refused && b > INFORMATION_LIMITED),
            Standing::RefusedBetween => assert!(refused),
            Standing::Missed | Standing::Met => assert!(!refused),
        }
    }
}

/// docs/experiment.md states the stored bound's counts.
#[test]
fn the_docs_state_the_stored_bound() {
    let doc = std::fs::read_to_string(root().join("docs/experiment.md"))
        .unwrap()
        .replace('\n', " ");
    let s = stored();
    let c = crossed();
    let count = |st: Standing| c.iter().filter(|x| x.standing == st).count();
    let refused = c.iter().filter(|x| x.outcome.refused.is_some()).count();
    let eff: Vec<f64> = c.iter().filter_map(|x| x.beta_efficiency).collect();
    let by_fit = |phase: bool| -> Vec<f64> {
        c.iter()
            .filter(|x| x.outcome.from_phase == Some(phase))
            .filter_map(|x| x.beta_efficiency)
            .collect()
    };
    let mut lines: Vec<String> = s.sets.iter().map(BoundSet::summary).collect();
    lines.extend([
        format!(
            "of the {refused} refused, {} have a bound below 0.005, {} above 0.05/1.96 and {} between",
            count(Standing::RefusedInformative),
            count(Standing::RefusedLimited),
            count(Standing::RefusedBetween)
        ),
        format!(
            "{} of the {} analysed miss",
            count(Standing::Missed),
            eff.len()
        ),
        format!(
            "the stated sigma of beta is a median {:.2} times the bound",
            median(eff.clone())
        ),
        format!(
            "below the bound on {}",
            eff.iter().filter(|e| **e < 1.0).count()
        ),
        format!(
            "{:.1} times by the phase's fit and {:.1} times by the pitch track's",
            median(by_fit(true)),
            median(by_fit(false))
        ),
        format!(
            "the phase's fit comes within {:.2} of it at best",
            by_fit(true).into_iter().fold(f64::MAX, f64::min)
        ),
        format!(
            "the missed ones' bound is at most {:.4}",
            c.iter()
                .filter(|x| x.standing == Standing::Missed)
                .map(|x| x.bound.beta_sigma)
                .fold(0.0, f64::max)
        ),
    ]);
    for set in &s.sets {
        let top = set
            .recordings
            .iter()
            .max_by(|a, b| a.beta_sigma.total_cmp(&b.beta_sigma))
            .unwrap();
        lines.push(format!(
            "from seed {} is {:.4} (seed {}, {:.2} s of sound from {:.1} Hz, {:.0} turns)",
            set.seed0, top.beta_sigma, top.seed, top.sound, top.start_hz, top.turns
        ));
    }
    let missing: Vec<&String> = lines.iter().filter(|l| !doc.contains(l.as_str())).collect();
    assert!(
        missing.is_empty(),
        "docs/experiment.md should state: {missing:#?}"
    );
}

/// Computes the study and, with ROLLING_DISK_BLESS=1, stores it.
#[test]
#[ignore = "stores snapshots/phone_bound.json: run with ROLLING_DISK_BLESS=1"]
fn record_the_phone_bound() {
    let s = study();
    for set in &s.sets {
        println!("{}", set.summary());
    }
    if std::env::var("ROLLING_DISK_BLESS").is_ok() {
        std::fs::write(path(), text(&s)).unwrap();
    }
}
