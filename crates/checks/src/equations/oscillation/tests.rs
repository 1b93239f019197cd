//! Tests of this module.

use super::*;
use crate::finding::Verdict;

#[test]
fn every_check_passes_and_fails_when_perturbed() {
    for e in EQUATIONS {
        let t0 = std::time::Instant::now();
        let ok = (e.check)(&Bench::default());
        let dt = t0.elapsed();
        let bad = (e.check)(&Bench::perturbed(1e-3));
        eprintln!(
            "eq {}: {} err {:.3e} tol {:.1e} claimed {:.6e} ref {:.6e} at {} [{dt:?}]; perturbed {} err {:.3e}",
            e.number, ok.verdict, ok.error, ok.tolerance.value, ok.claimed, ok.reference, ok.at, bad.verdict, bad.error
        );
        assert!(ok.verdict.passes(), "eq {}: {ok:?}", e.number);
        assert_eq!(bad.verdict, Verdict::Fails, "eq {} perturbed", e.number);
    }
}
