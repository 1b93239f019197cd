//! The corrections of paper/corrections.yaml, each checked by its equation's own check against
//! the same reference as the printed form: the printed form fails (or holds only as the
//! order-of-magnitude estimate it is read as), the corrected one holds.

use checks::corrections::verify;
use checks::equations::Bench;

#[test]
fn every_correction_holds_where_the_printed_form_fails() {
    let cs = paper::Paper::built_in_shared().corrections.clone();
    let verified = verify(&Bench::default(), &cs, 2).unwrap();
    assert_eq!(verified.len(), cs.len());
    let mut wrong = Vec::new();
    for v in &verified {
        eprintln!(
            "eq {}: printed {} ({}), corrected {} ({})",
            v.number, v.printed.verdict, v.printed.detail, v.corrected.verdict, v.corrected.detail
        );
        let estimate = |verdict: &str| verdict.starts_with("order-of-magnitude estimate");
        let printed_short = !v.printed.holds || estimate(&v.printed.verdict);
        if !printed_short || !v.corrected.holds || estimate(&v.corrected.verdict) {
            wrong.push(v.number);
        }
    }
    assert!(
        wrong.is_empty(),
        "corrections that do not do their job: {wrong:?}"
    );
}

/// The derivation checks of `paper` with `corrections` substituted together, failing ones
/// listed: each corrected equation must follow from its corrected premises.
fn derivations_failing(
    paper: &paper::Paper,
    corrections: &[paper::correction::Correction],
) -> Vec<String> {
    let corrected = checks::corrections::apply(paper, corrections).expect("they substitute");
    let bench = Bench::with_paper(&corrected);
    checks::equations::derivations()
        .into_iter()
        .filter_map(|d| {
            let f = (d.check)(&bench);
            (!f.verdict.passes()).then(|| format!("eq {}: {} ({})", d.number, f.verdict, f.at))
        })
        .collect()
}

/// Corrections that close: substituted together, every corrected equation follows from its
/// corrected premises by the same derivation checks that classify root causes (eq 73 from eq
/// 72, eq 76 from eqs 73 and 75, and on to eq 84); a correction planted wrong (eq 77 keeping
/// the printed 5 where the corrected eq 76 gives 3) breaks the chain there.
#[test]
fn the_corrections_substituted_together_follow_from_each_other() {
    let paper = paper::Paper::built_in_shared();
    let cs = paper.corrections.clone();
    let failing = derivations_failing(paper, &cs);
    assert!(failing.is_empty(), "{failing:#?}");
    let mut planted = cs.clone();
    let c77 = planted
        .iter_mut()
        .find(|c| c.number == 77)
        .expect("eq 77 is corrected");
    assert!(c77.latex.contains("(\\beta + 2)}{3}"), "{}", c77.latex);
    c77.latex = c77.latex.replace("(\\beta + 2)}{3}", "(\\beta + 2)}{5}");
    let failing = derivations_failing(paper, &planted);
    assert!(
        failing
            .iter()
            .any(|f| f.starts_with("eq 77") || f.starts_with("eq 78")),
        "{failing:#?}"
    );
}
