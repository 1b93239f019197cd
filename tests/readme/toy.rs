//! The README's numbers of the real toy, against the toy study that the report shows.

use super::written::{number_after, prose};

#[test]
fn the_readmes_toy_numbers_are_the_toy_studys() {
    let readme = prose("README.md");
    let start = readme
        .find("**The toy the paper measured is not a thin disk.**")
        .expect("the README's toy paragraph");
    let text = &readme[start..];
    let stored = std::fs::read_dir("tests/reference/peer")
        .expect("the stored peer runs")
        .filter(|e| e.as_ref().is_ok_and(|e| e.path().is_dir()))
        .count()
        .to_string();
    assert_eq!(
        number_after(text, "independent program on "),
        Some(stored.as_str())
    );
    let t = studies::thickness::compute().expect("the toy study");
    let steady = t
        .steady
        .iter()
        .find(|p| p.alpha0 == 1.0)
        .expect("the steady motion at 1 rad");
    let change = format!("{:.1}", 100.0 * (steady.toy / steady.eq29 - 1.0));
    assert_eq!(
        number_after(text, "toy's steady precession is "),
        Some(change.as_str())
    );
    let fall = t
        .falls
        .iter()
        .find(|f| f.alpha0_deg == 75.0)
        .expect("the fall from 75 degrees");
    let (thin, toy) = fall.fell_to_deg;
    let toy = format!("{:.1}", toy.expect("the toy falls"));
    let thin = format!("{:.1}", thin.expect("the thin disk falls"));
    assert_eq!(
        number_after(text, "the first dip of the nutation reaches "),
        Some(toy.as_str())
    );
    assert_eq!(
        number_after(text, "° for the toy and "),
        Some(thin.as_str())
    );
    let (lo, hi) = studies::toy_steady::compute()
        .expect("the toy's steady motions")
        .no_spin_in_place_deg;
    let (lo, hi) = (format!("{lo:.1}"), format!("{hi:.1}"));
    assert_eq!(
        number_after(text, "but the toy cannot between "),
        Some(lo.as_str())
    );
    assert_eq!(number_after(text, "° and "), Some(hi.as_str()));
}
