//! Unit tests of the steady-motion checks.

use super::*;
use crate::equations::steady::lab::LabSteady;
use crate::equations::steady::lab::LAB_ALPHAS;
use crate::equations::steady_reference::steady_ref;
use crate::equations::steady_reference::KS;
use crate::finding::Verdict;

fn run(number: u32) -> (Finding, Finding) {
    let e = EQUATIONS.iter().find(|e| e.number == number).unwrap();
    (
        (e.check)(&Bench::default()),
        (e.check)(&Bench::perturbed(1e-3)),
    )
}

#[test]
fn every_check_holds_and_fails_when_perturbed() {
    for e in EQUATIONS {
        let (ok, bad) = run(e.number);
        eprintln!(
            "eq {}: {} err {:.3e} tol {:.1e} at {}; perturbed {} err {:.3e}",
            e.number, ok.verdict, ok.error, ok.tolerance.value, ok.at, bad.verdict, bad.error
        );
        assert_eq!(ok.verdict, Verdict::Holds, "eq {}: {ok:?}", e.number);
        assert_eq!(bad.verdict, Verdict::Fails, "eq {} perturbed", e.number);
    }
}

/// Eqs 33-37 against the lab-frame model: hold, and fail under either sign of perturbation.
#[test]
fn section_5_holds_in_the_lab_frame_and_fails_when_perturbed() {
    for number in 33..=37 {
        let e = EQUATIONS.iter().find(|e| e.number == number).unwrap();
        let ok = (e.check)(&Bench::default());
        eprintln!(
            "eq {number}: {} err {:.3e} tol {:.1e} at {}",
            ok.verdict, ok.error, ok.tolerance.value, ok.at
        );
        assert_eq!(ok.verdict, Verdict::Holds, "eq {number}: {ok:?}");
        for p in [1e-3, -1e-3] {
            let bad = (e.check)(&Bench::perturbed(p));
            eprintln!(
                "eq {number} under {p}: {} err {:.3e}",
                bad.verdict, bad.error
            );
            assert_eq!(bad.verdict, Verdict::Fails, "eq {number} under {p}");
        }
    }
}

/// The lab runs really are steady b = 0 motions of both senses, with the rates measured.
#[test]
fn lab_runs_are_steady() {
    let runs = LabSteady::all(&Bench::default());
    assert_eq!(runs.len(), KS.len() * LAB_ALPHAS.len() * 2);
    for run in runs.iter() {
        assert!(run.unsteadiness < 1e-9, "{}", run.unsteadiness);
        let m = steady_ref(&run.disk, run.alpha0, 0.0).unwrap();
        assert!((run.precession.abs() - m.precession).abs() < 1e-9 * m.precession);
    }
}
