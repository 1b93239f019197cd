//! `positive-b-unstable-large-tilt` read as what the fall does: "the disk soon falls over to a
//! rolling motion with $\alpha_0 \lesssim 60°$" judged on the runs of `studies::sliding::fall`
//! (the thin disk from the middle of each unstable band, rolling and on each Coulomb table of
//! `MUS`), not on one extreme of them.
//!
//! A table bears the claim out when every start settles into a lower steady rolling
//! (`studies::sliding::swing`) with its late mean at or below the claim's reading of "about
//! 60°" (claims.yaml's `within`: at most $60(1 + w)$ deg). Without dissipation the rolling disk is
//! conservative and nutates between its first dip and nearly $\alpha_0$ for ever; the runs show
//! that only a contact that slides dissipates enough to settle. Whether the table lets it slide
//! is a choice the paper does not make (sec. 7 assumes rolling), so the verdict depends on it.

use crate::finding::Verdict;
use crate::harness::Bench;
use crate::robustness::Alternative;
use studies::sliding::fall::{band, fall_from, FallCase, DURATION, MUS, TILTS_DEG};

/// The choice the fall's verdict rests on.
pub(super) const SLIDES: &str = "whether the contact can slide (the table's $\\mu$)";

/// The fall from every start of `TILTS_DEG` on one table (`None`: rolling, eqs 23-25), judged
/// against "at most `top` deg": the alternative and its words for the card.
fn table(b: &Bench, mu: Option<f64>, top: f64) -> (Alternative, String) {
    let d = studies::sliding::toy_disk();
    let settings = b.settings();
    let runs: Vec<(f64, Option<FallCase>)> = TILTS_DEG
        .iter()
        .filter_map(|&a| {
            let start = band(&d, a.to_radians())?.start;
            let run = fall_from(&d, a.to_radians(), start, mu, &settings)
                .ok()
                .flatten();
            Some((a, run))
        })
        .collect();
    let name = match mu {
        None => "rolling without slip (eqs 23-25, unlimited friction)".to_string(),
        Some(mu) => format!("the sliding model on a table with $\\mu = {mu}$"),
    };
    let settled = |c: &FallCase| c.swing.late_mean_deg.filter(|_| c.swing.settles);
    let holds = !runs.is_empty()
        && runs
            .iter()
            .all(|(_, c)| c.as_ref().and_then(settled).is_some_and(|x| x <= top));
    // The highest late mean over the starts: where a start settles, its lower rolling; where it
    // does not, the mean of its swing's late half.
    let reference = runs
        .iter()
        .filter_map(|(_, c)| c.as_ref().and_then(|c| c.swing.late_mean_deg))
        .fold(f64::NAN, f64::max);
    let each: Vec<String> = runs
        .iter()
        .map(|(a, c)| match c {
            None => format!("from {a:.0} deg: no run"),
            Some(c) => {
                let w = c.swing;
                let slid = if c.slip_time > 0.0 {
                    format!("slides {:.2} s, ", c.slip_time)
                } else {
                    String::new()
                };
                match settled(c) {
                    Some(m) => format!(
                        "from {a:.0} deg: {slid}min {:.1}, settles, late mean {m:.1}",
                        w.min_deg
                    ),
                    None => format!(
                        "from {a:.0} deg: {slid}min {:.1}, max {:.1}, does not settle, mean {:.1}",
                        w.min_deg, w.max_deg, w.mean_deg
                    ),
                }
            }
        })
        .collect();
    let settles = runs
        .iter()
        .filter(|(_, c)| c.as_ref().and_then(settled).is_some())
        .count();
    let alternative = format!(
        "{name}: {settles} of {} starts settle into a lower rolling at or below {top:.0} deg \
         (highest late mean {reference:.1} deg)",
        runs.len()
    );
    let verdict = if holds {
        Verdict::Holds
    } else {
        Verdict::Fails
    };
    (
        Alternative::new(SLIDES, alternative, reference, verdict),
        format!("{name}: {}", each.join("; ")),
    )
}

/// The fall judged on every table, rolling first: each table's alternative, and the card's
/// account of the runs (deg; the thin disk, $k = 1/4$, $b$ mid-band, over `DURATION` s).
pub(super) fn fall_readings(b: &Bench, claimed: f64, within: f64) -> (Vec<Alternative>, String) {
    let top = claimed * (1.0 + within);
    let tables = std::iter::once(None).chain(MUS.iter().map(|&mu| Some(mu)));
    let (alternatives, texts): (Vec<_>, Vec<_>) = tables.map(|mu| table(b, mu, top)).unzip();
    let text = format!(
        "the fall of the thin disk ($k = 1/4$, $a = 37.5$ mm) from b mid-band over {DURATION} s, judged on whether \
         it settles into a lower rolling at or below {top:.0} deg (tilts in deg): {}",
        texts.join(" | ")
    );
    (alternatives, text)
}
