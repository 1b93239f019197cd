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
