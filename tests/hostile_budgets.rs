//! Budgets and limits as a hostile user sets them (issue 48): a wall-time budget too small for
//! a check is a refusal naming the check and the budget that does, never a panic and never a
//! verdict computed from a cut-short integration; a budget is honoured however small; a fillet of
//! exactly the largest size the scene's message allows is run. A property test draws budgets
//! over six decades, the twin of `fuzz/fuzz_targets/budgets.rs`.

use crate::common::{cli_timed, temp_dir};
use proptest::prelude::*;
use std::path::Path;

/// The outcome of `check --only 65 --max-seconds SECONDS`: refused naming the check cut short
/// (eq 65 or one of its premises) and the budget that does, or a table; never a panic.
fn check_65_within(seconds: f64) -> Result<(), TestCaseError> {
    let dir = std::env::temp_dir();
    let s = format!("{seconds}");
    let (ok, out, err, _) = cli_timed(&dir, &["check", "--only", "65", "--max-seconds", &s]);
    prop_assert!(!err.contains("panicked"), "{seconds}: {err}");
    if ok {
        prop_assert!(out.contains("eq 65") && out.contains("holds"), "{out}");
    } else {
        prop_assert!(
            err.contains("the check of eq ") && err.contains("--max-seconds 600"),
            "{seconds}: {err}"
        );
        prop_assert!(!out.contains("holds") && !out.contains("fails"), "{out}");
    }
    Ok(())
}

#[test]
fn a_check_cut_short_by_its_budget_is_refused_and_the_advice_works() {
    let dir = temp_dir("hostile-budgets", "check");
    // A microsecond: no check of eq 65 or of its premises finishes within it on any machine
    // (at 0.01 s an idle machine finishes them, and nothing is refused).
    let (ok, out, err, _) = cli_timed(&dir, &["check", "--only", "65", "--max-seconds", "1e-6"]);
    assert!(!ok && !err.contains("panicked"), "{out}{err}");
    assert!(
        err.contains("the check of eq ") && err.contains("--max-seconds 600"),
        "{err}"
    );
    assert!(!out.contains("holds") && !out.contains("fails"), "{out}");
    let (ok, out, err, _) = cli_timed(&dir, &["check", "--only", "65", "--max-seconds", "600"]);
    assert!(ok, "{err}");
    assert!(out.contains("eq 65"), "{out}");
}

#[test]
fn simulate_honours_a_budget_of_a_microsecond() {
    let dir = temp_dir("hostile-budgets", "simulate");
    let (ok, _, err, _) = cli_timed(
        &dir,
        &["simulate", "spinning-coin", "--max-seconds", "1e-6"],
    );
    assert!(!ok && !err.contains("panicked"), "{err}");
    assert!(err.contains("wall-time budget"), "{err}");
}

#[test]
fn a_fillet_of_half_the_thickness_is_run() {
    let dir = temp_dir("hostile-budgets", "fillet");
    let scene = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reference/peer/thick-fall/scene.yaml"),
    )
    .unwrap_or_default();
    let half = scene.replace("fillet: 0.002", "fillet: 0.0064");
    assert_ne!(half, scene);
    std::fs::write(dir.join("half.yaml"), &half).ok();
    let (ok, out, err, _) = cli_timed(&dir, &["simulate", "half.yaml"]);
    assert!(ok && !err.contains("panicked"), "{out}{err}");
    // Just over the limit the message gives is refused with it.
    std::fs::write(
        dir.join("over.yaml"),
        scene.replace("fillet: 0.002", "fillet: 0.00641"),
    )
    .ok();
    let (ok, _, err, _) = cli_timed(&dir, &["simulate", "over.yaml"]);
    assert!(!ok && err.contains("half the thickness (0.0064)"), "{err}");
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 6, failure_persistence: None, rng_seed: proptest::test_runner::RngSeed::Fixed(20_261_128), ..ProptestConfig::default() })]
    /// Budgets from a microsecond to a second: each a table or a refusal naming the check.
    #[test]
    fn no_budget_makes_a_check_panic(log_seconds in -6.0f64..0.0) {
        check_65_within(10f64.powf(log_seconds))?;
    }
}
