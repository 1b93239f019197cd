//! Unit tests of the kinematics checks: each passes as printed and fails when its claim moves.

use super::*;
use crate::equations::kinematics::rolling::steady_sweep;
use crate::finding::Verdict;

fn verdicts(number: u32) -> (Finding, Finding) {
    let e = EQUATIONS.iter().find(|e| e.number == number).unwrap();
    (
        (e.check)(&Bench::default()),
        (e.check)(&Bench::perturbed(1e-3)),
    )
}

fn expect(number: u32, verdict: Verdict) {
    let (ok, bad) = verdicts(number);
    eprintln!(
        "eq {number}: {} error {:.2e} at {}; perturbed: {} error {:.2e}",
        ok.verdict, ok.error, ok.at, bad.verdict, bad.error
    );
    assert_eq!(ok.verdict, verdict, "eq {number}: {ok:?}");
    // Equations read from the LaTeX are mutated in their text by tests/mutation.rs (a
    // relative change of a side that is zero, as in eq 12, would change nothing).
    if !crate::equations::from_latex().contains(&number) {
        assert_eq!(
            bad.verdict,
            Verdict::Fails,
            "eq {number} perturbed: {bad:?}"
        );
    }
}

#[test]
fn definitions_are_consistent_and_perturbations_fail() {
    for n in [1, 2, 8, 11, 14, 17, 18] {
        expect(n, Verdict::Definition);
    }
}

#[test]
fn identities_hold_and_perturbations_fail() {
    for n in [3, 4, 5, 6, 7, 9, 10, 12, 13, 15, 16, 19, 20, 21, 22] {
        expect(n, Verdict::Holds);
    }
}

#[test]
fn the_registry_lists_equations_1_to_22() {
    let numbers: Vec<u32> = EQUATIONS.iter().map(|e| e.number).collect();
    assert_eq!(numbers, (1..=22).collect::<Vec<_>>());
}

#[test]
fn the_constructed_triad_is_right_handed_and_alpha_is_the_tilt() {
    for (h, t) in sample(99, 50, RATE) {
        let k = kin1(&h, t);
        let [one, two, three, r] = k.axes;
        let e = (one.cross(&two) - three).norm();
        assert!(e < 1e-14, "{e}");
        assert!(two[2].abs() < 1e-14 && r[2].abs() < 1e-14);
        // 3 dips below the horizontal by the plane's tilt.
        assert!((three[2] + k.alpha.sin()).abs() < 1e-14);
    }
}

#[test]
fn steady_sweep_covers_positive_zero_and_negative_b() {
    let s = steady_sweep();
    assert!(s.iter().any(|s| s.b > 1e-3 * A));
    assert!(s.iter().any(|s| s.b < -1e-3 * A));
    assert!(s.iter().any(|s| s.b.abs() < 1e-12));
    // Kinematically r = b + a cos(alpha) takes either sign; r < 0 (b < -a cos(alpha)) is
    // excluded only dynamically, by eq 30's bound, for alpha < pi/2.
    assert!(s.iter().any(|s| s.r < 0.0) && s.iter().any(|s| s.r > 0.0));
}

#[test]
fn checks_are_fast() {
    let start = std::time::Instant::now();
    for e in EQUATIONS {
        (e.check)(&Bench::default());
    }
    let elapsed = start.elapsed().as_secs_f64();
    eprintln!("22 checks in {elapsed:.3} s");
    if !cfg!(debug_assertions) {
        assert!(elapsed < 0.5);
    }
}
