//! Budgets and limits as a hostile user sets them (issue 48): a wall-time budget too small for
//! a check is a refusal naming the check and the budget that does, never a panic and never a
//! verdict computed from a cut-short integration; a budget is honoured however small; a fillet of
//! exactly the largest size the scene's message allows is run. A property test draws budgets
//! over six decades, the twin of `fuzz/fuzz_targets/budgets.rs`.

use super::sandbox::cli_timed;
use crate::common::temp_dir;
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

/// `simulate` of `scene` (a built-in's text) with `solver: { max_steps, rtol }` and a wall-time
/// budget: it runs, or it is refused naming the stage (the scene's value with its range, the
/// integration's step limit or the wall-time budget); a step limit too small names the
/// `max_steps` that reaches the end, and that value, applied, runs. Never a panic.
fn simulate_within(
    scene: &str,
    max_steps: u64,
    rtol: f64,
    seconds: f64,
) -> Result<(), TestCaseError> {
    let dir = temp_dir("hostile-budgets", "fuzz");
    let src = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("paper/scenes/{scene}.yaml")),
    )
    .unwrap_or_default();
    let with = |steps: u64| {
        src.replace(
            "solver: { method: dop853, rtol: 1.0e-10,",
            &format!("solver: {{ method: dop853, max_steps: {steps}, rtol: {rtol:e},"),
        )
    };
    prop_assert!(with(1) != src, "{scene}: no solver line to edit");
    std::fs::write(dir.join("s.yaml"), with(max_steps)).ok();
    let budget = format!("{seconds:e}");
    let args = ["simulate", "s.yaml", "--max-seconds", &budget];
    let (ok, _, err, _) = cli_timed(&dir, &args);
    prop_assert!(!err.contains("panicked"), "{err}");
    if ok {
        return Ok(());
    }
    let stage = ["s.yaml:", "gave up after", "wall-time budget"];
    prop_assert!(stage.iter().any(|s| err.contains(s)), "{err}");
    if let Some(n) = err
        .split("max_steps: ")
        .nth(1)
        .and_then(|r| r.split(' ').next())
        .and_then(|n| n.parse::<u64>().ok())
        .filter(|_| err.contains("gave up after"))
    {
        std::fs::write(dir.join("s.yaml"), with(n)).ok();
        let (ok, _, again, _) = cli_timed(&dir, &["simulate", "s.yaml", "--max-seconds", "600"]);
        prop_assert!(ok, "max_steps {n} from {err}: {again}");
    }
    Ok(())
}

#[test]
fn a_step_limit_too_small_names_one_that_reaches_the_end_and_it_does() {
    let dir = temp_dir("hostile-budgets", "steps");
    let src = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("paper/scenes/slip-stick.yaml"),
    )
    .unwrap_or_default();
    std::fs::write(
        dir.join("s.yaml"),
        src.replace("solver: {", "solver: { max_steps: 400,"),
    )
    .ok();
    let (ok, _, err, _) = cli_timed(&dir, &["simulate", "s.yaml"]);
    assert!(!ok && err.contains("gave up after 400 steps"), "{err}");
    assert!(err.contains("set solver: { max_steps: "), "{err}");
    simulate_within("slip-stick", 400, 1e-10, 600.0).expect("the advice works");
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 8, failure_persistence: None, rng_seed: proptest::test_runner::RngSeed::Fixed(20_261_128), ..ProptestConfig::default() })]
    /// Step limits from 1 to 5e7, tolerances from 1e-12 to 1e-3 and budgets from a microsecond
    /// to a second, on a rolling scene and a sliding one (the hybrid driver).
    #[test]
    fn no_budget_makes_simulate_panic_and_every_limit_named_works(
        log_steps in 0.0f64..7.7,
        log_rtol in -12.0f64..-3.0,
        log_seconds in -6.0f64..0.0,
        sliding in proptest::bool::ANY,
    ) {
        let scene = if sliding { "slip-stick" } else { "spinning-coin" };
        let steps = 10f64.powf(log_steps).round().max(1.0) as u64;
        simulate_within(scene, steps, 10f64.powf(log_rtol), 10f64.powf(log_seconds))?;
    }
}
