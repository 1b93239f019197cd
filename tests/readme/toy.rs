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
    // What each tilt does over the run, not its first dip: least, greatest and mean.
    let (thin, toy) = (
        fall.swing.0,
        fall.swing.1.expect("the toy's steady motion at 75 deg"),
    );
    assert!(!thin.settles && !toy.settles, "{thin:?} {toy:?}");
    for (who, w) in [("the toy's tilt swings", toy), ("the thin disk's", thin)] {
        let [lo, hi, mean] = [w.min_deg, w.max_deg, w.mean_deg].map(|x| format!("{x:.1}"));
        assert_eq!(
            number_after(text, &format!("{who} between ")),
            Some(lo.as_str()),
            "{who}"
        );
        assert_eq!(
            number_after(text, &format!("{who} between {lo}° and ")),
            Some(hi.as_str()),
            "{who}"
        );
        assert_eq!(
            number_after(
                text,
                &format!("{who} between {lo}° and {hi}° with a mean of ")
            ),
            Some(mean.as_str()),
            "{who}"
        );
    }
    // Followed with slip on the smoothest table, the thin disk settles below.
    let slid = studies::sliding::fall::fall(
        &physics::disk::toy_disk(),
        &physics::solve::Settings::dop853(1e-10, 1e-12),
    )
    .expect("the fall study");
    let mu = studies::sliding::fall::MUS[0];
    let run = slid
        .cases
        .iter()
        .find(|c| c.alpha0_deg == 75.0 && c.mu == Some(mu))
        .expect("the 75 deg run on the smoothest table");
    assert!(run.slipped && run.swing.settles, "{run:?}");
    assert_eq!(
        number_after(text, "Followed with slip (μ = "),
        Some(format!("{mu}").as_str())
    );
    let late = format!("{:.1}", run.swing.late_mean_deg.expect("a settled run"));
    assert_eq!(
        number_after(text, "the thin disk does settle, with a mean of "),
        Some(late.as_str())
    );
    let (lo, hi) = studies::toy_steady::compute()
        .expect("the toy's steady motions")
        .no_spin_in_place_deg;
    let (lo, hi) = (format!("{lo:.1}"), format!("{hi:.1}"));
    assert_eq!(
        number_after(text, "but the toy cannot between "),
        Some(lo.as_str())
    );
    assert_eq!(
        number_after(text, &format!("but the toy cannot between {lo}° and ")),
        Some(hi.as_str())
    );
}
