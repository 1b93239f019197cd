//! Unit tests of the frictionless checks.

use super::*;
use physics::disk::toy_sized;
use physics::model::frictionless::accelerations;

fn verdicts(f: fn(&Bench) -> Finding) -> (Finding, Finding) {
    let start = std::time::Instant::now();
    let ok = f(&Bench::default());
    eprintln!("{:?}", start.elapsed());
    let bad = f(&Bench::perturbed(1e-3));
    eprintln!(
        "{}: error {:.3e} (tol {:.1e}) at {}\n   perturbed: {} error {:.3e}",
        ok.verdict, ok.error, ok.tolerance.value, ok.at, bad.verdict, bad.error
    );
    assert_eq!(bad.verdict, Verdict::Fails, "perturbed must fail");
    (ok, bad)
}

/// For an equation printed as `... = 0` (eqs 62, 64), whose claimed side a relative
/// perturbation cannot move: the printed form holds, and every mutant of its LaTeX fails.
fn printed_holds_and_mutants_fail(n: u32, f: fn(&Bench) -> Finding) {
    let b = Bench::default();
    let ok = f(&b);
    assert_eq!(ok.verdict, Verdict::Holds, "eq {n}: {ok:?}");
    let ms = paper::mutate::mutants(&b.paper.equation(n).chains);
    assert!(!ms.is_empty(), "eq {n} has no mutants");
    for m in ms {
        let paper = b.paper.with_chains(n, m.chains);
        let bad = f(&Bench::with_paper(&paper));
        assert_eq!(bad.verdict, Verdict::Fails, "eq {n}: {} survives", m.change);
    }
}

#[test]
fn reference_agrees_with_itself_on_energy() {
    // The Lagrangian reference conserves its energy: a sanity check of the reference.
    let d = toy_sized(0.25);
    let m = Motion {
        alpha: 0.8,
        alpha_dot: 3.0,
        precession: 20.0,
        spin: 5.0,
    };
    let r = reference_rates(&d, &m);
    let rates = accelerations(&d, &m);
    assert!((r[0] - rates.0).abs() < 1e-9 * (1.0 + rates.0.abs()));
    assert!((r[1] - rates.1).abs() < 1e-9 * (1.0 + rates.1.abs()));
    assert!(r[2].abs() < 1e-10);
}

#[test]
fn eq59_is_a_consistent_definition() {
    assert_eq!(verdicts(eq59).0.verdict, Verdict::Definition);
}

#[test]
fn eq60_holds() {
    assert_eq!(verdicts(eq60).0.verdict, Verdict::Holds);
}

#[test]
fn eq61_holds() {
    assert_eq!(verdicts(eq61).0.verdict, Verdict::Holds);
}

#[test]
fn eq62_holds() {
    printed_holds_and_mutants_fail(62, eq62);
}

#[test]
fn eq63_holds() {
    assert_eq!(verdicts(eq63).0.verdict, Verdict::Holds);
}

#[test]
fn eq64_holds() {
    printed_holds_and_mutants_fail(64, eq64);
}

#[test]
fn eq65_holds() {
    assert_eq!(verdicts(eq65).0.verdict, Verdict::Holds);
}

#[test]
fn eq66_is_a_consistent_definition() {
    assert_eq!(verdicts(eq66).0.verdict, Verdict::Definition);
}

#[test]
fn eq67_is_a_consistent_definition() {
    assert_eq!(verdicts(eq67).0.verdict, Verdict::Definition);
}

#[test]
fn eq68_holds() {
    assert_eq!(verdicts(eq68).0.verdict, Verdict::Holds);
}

#[test]
fn eq69_holds() {
    assert_eq!(verdicts(eq69).0.verdict, Verdict::Holds);
}

#[test]
fn eq70_holds() {
    assert_eq!(verdicts(eq70).0.verdict, Verdict::Holds);
}

#[test]
fn eq71_holds() {
    assert_eq!(verdicts(eq71).0.verdict, Verdict::Holds);
}
