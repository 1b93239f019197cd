//! The "Friction and contact" section's full output, as a program prints it: every run of the
//! friction studies ([`studies::sliding::Studies`]) in plain fixed-width tables, for the HTML
//! `<pre>` and the LaTeX listing. What it prints and how is
//! `templates/parts/friction/listing.txt.tera`; this file gathers the values that template reads
//! beside the studies (the fall study read against the paper's claim, the notes' numbering).

use crate::error::ReportError;
use crate::parts::prose::paragraph;
use serde::Serialize;
use studies::sliding::fall::{Fall, FallCase, ACROSS, DURATION, LEFT, NUDGE};
use studies::sliding::swing::Swing;
use studies::sliding::Studies;

/// The claim the fall study answers (paper/claims.yaml).
const FALL_CLAIM: &str = "positive-b-unstable-large-tilt";

/// The fall claim's printed tilt (deg) and its reading `within` (a relative distance), from
/// `paper`'s claims; `None` if the claim or that reading is missing.
pub(crate) fn fall_claim(paper: &paper::Paper) -> Option<(f64, f64)> {
    let c = paper.claims.iter().find(|c| c.id == FALL_CLAIM)?;
    Some((c.claimed_value?, c.rule.as_ref()?.within?))
}

/// A radial-slippage run and the number of its note, when it halted before its end.
#[derive(Serialize)]
struct SpiralRun<'s> {
    run: &'s studies::sliding::spiral::Spiral,
    note: Option<usize>,
}

/// A fall run judged on what its motion does over the run: whether it settles into a lower
/// steady rolling, and where (its late mean) against the claim's reading.
#[derive(Serialize)]
struct FallRun<'s> {
    run: &'s FallCase,
    /// Whether the run settles with its late mean within the reading.
    holds: bool,
    /// "above", "below" or "inside" the reading, by the late mean of a run that settles;
    /// `None`: it does not settle, so there is no lower rolling to place.
    side: Option<&'static str>,
    /// How far outside the reading (deg).
    by: f64,
}

/// Whether a run whose tilt does `swing` bears out "falls into a rolling motion at about the claimed tilt", read as
/// `lo` to `hi` deg: it settles into a lower steady rolling and its late mean is within the
/// reading. The first dip alone never does: it is one extreme of a swing.
pub(crate) fn bears_out(swing: &Swing, lo: f64, hi: f64) -> bool {
    swing.settles && swing.late_mean_deg.is_some_and(|x| (lo..=hi).contains(&x))
}

/// Whether run `c` settles into a lower steady rolling at `hi` deg or below (the LaTeX's
/// "$\lesssim$").
pub(crate) fn settles_at_most(c: &FallCase, hi: f64) -> bool {
    c.swing.settles && c.swing.late_mean_deg.is_some_and(|x| x <= hi)
}

/// An unstable band and what the rolling disk falls to across it.
#[derive(Serialize)]
struct FallBand<'s> {
    band: &'s studies::sliding::fall::Band,
    e_folding: f64,
    period: f64,
    across: Vec<&'s FallCase>,
}

/// The fall study read against the claim's "about" (`lo` to `hi` deg around `claimed`).
#[derive(Serialize)]
struct FallReading<'s> {
    claimed: f64,
    lo: f64,
    hi: f64,
    bands: Vec<FallBand<'s>>,
    runs: Vec<FallRun<'s>>,
    /// Runs that settle with their late mean within the reading.
    held: usize,
    /// Runs that settle with their late mean at or below the reading's top.
    below: usize,
    /// Runs that settle into a lower steady rolling at all.
    settled: usize,
    slowest: f64,
    lowest_across: f64,
    highest_across: f64,
}

/// What the listing's template reads.
#[derive(Serialize)]
struct Listing<'s> {
    s: &'s Studies,
    spiral: Vec<SpiralRun<'s>>,
    spiral_duration: f64,
    rising_duration: f64,
    fall_claim: &'static str,
    fall: Option<FallReading<'s>>,
    fall_duration: f64,
    fall_left: f64,
    fall_nudge: f64,
    fall_across: &'static [f64],
    gives_two: Vec<&'s str>,
}

/// The fall study `f` read as the claim's reading `(claimed, within)`.
fn fall_reading(f: &Fall, (claimed, within): (f64, f64)) -> FallReading<'_> {
    let (lo, hi) = (claimed * (1.0 - within), claimed * (1.0 + within));
    let runs: Vec<FallRun> = f
        .cases
        .iter()
        .map(|c| {
            let settled = c.swing.late_mean_deg.filter(|_| c.swing.settles);
            let (side, by) = match settled {
                Some(x) if x > hi => (Some("above"), x - hi),
                Some(x) if x < lo => (Some("below"), lo - x),
                Some(_) => (Some("inside"), 0.0),
                None => (None, 0.0),
            };
            FallRun {
                run: c,
                holds: bears_out(&c.swing, lo, hi),
                side,
                by,
            }
        })
        .collect();
    let across = f.across.iter().filter_map(|c| c.fell_to_deg);
    FallReading {
        claimed,
        lo,
        hi,
        bands: f
            .bands
            .iter()
            .map(|b| FallBand {
                band: b,
                e_folding: 1.0 / b.growth,
                period: 2.0 * std::f64::consts::PI / b.precession.abs(),
                across: f
                    .across
                    .iter()
                    .filter(|c| c.alpha0_deg == b.alpha0_deg)
                    .collect(),
            })
            .collect(),
        held: runs.iter().filter(|r| r.holds).count(),
        below: f.cases.iter().filter(|c| settles_at_most(c, hi)).count(),
        settled: f.cases.iter().filter(|c| c.swing.settles).count(),
        slowest: f
            .cases
            .iter()
            .filter_map(|c| c.fall_periods)
            .fold(0.0, f64::max),
        lowest_across: across.clone().fold(f64::INFINITY, f64::min),
        highest_across: across.fold(f64::NEG_INFINITY, f64::max),
        runs,
    }
}

/// The section's full output; the fall study is read against `paper`'s claim.
pub fn listing(s: &Studies, paper: &paper::Paper) -> Result<String, ReportError> {
    let mut notes = 0;
    let spiral = s
        .spiral
        .iter()
        .map(|r| SpiralRun {
            run: r,
            note: r.radius_end.is_none().then(|| {
                notes += 1;
                notes
            }),
        })
        .collect();
    let listing = Listing {
        s,
        spiral,
        spiral_duration: studies::sliding::spiral::DURATION,
        rising_duration: studies::sliding::rising::DURATION,
        fall_claim: FALL_CLAIM,
        fall: fall_claim(paper).map(|reading| fall_reading(&s.fall, reading)),
        fall_duration: DURATION,
        fall_left: LEFT,
        fall_nudge: NUDGE,
        fall_across: &ACROSS,
        gives_two: s
            .mechanisms
            .spin_downs
            .iter()
            .filter(|r| r.gives(2.0))
            .map(|r| r.mechanism.as_str())
            .collect(),
    };
    Ok(paragraph(&super::ABOUT.templates, "listing", &listing)? + "\n")
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_fall_claim_and_its_reading_are_found() {
        let paper = paper::Paper::built_in_shared();
        assert_eq!(super::fall_claim(paper), Some((60.0, 0.05)));
    }

    /// A claim planted at 43 deg, the toy's first dip from 75 deg: read off that one extreme it
    /// would hold, judged on the motion over the run it fails (the toy nutates on, its mean
    /// far above). A run that settles bears out a claim at its late mean, and only there.
    #[test]
    fn a_claim_planted_at_the_first_dip_fails_and_one_at_a_settled_tilt_holds() {
        use studies::thickness::{fall_to, Shape};
        let d = physics::disk::toy_disk();
        let alpha0 = 75f64.to_radians();
        let band = studies::sliding::fall::band(&d, alpha0).unwrap();
        let b = band.start * d.a;
        let om = Shape::Toy.rolling().steady(alpha0, b).unwrap().precession;
        let (dip, swing) = fall_to(Shape::Toy, alpha0, b, om).unwrap();
        let (lo, hi) = (43.0 * 0.95, 43.0 * 1.05);
        assert!(dip.is_some_and(|x| (lo..=hi).contains(&x)), "{dip:?}");
        assert!((lo..=hi).contains(&swing.min_deg), "{swing:?}");
        assert!(swing.mean_deg > hi + 20.0 && !swing.settles, "{swing:?}");
        assert!(!super::bears_out(&swing, lo, hi));

        let settings = physics::solve::Settings::dop853(1e-10, 1e-12);
        let f = studies::sliding::fall::fall(&d, &settings).unwrap();
        let planted = super::fall_reading(&f, (43.0, 0.05));
        assert_eq!(planted.held, 0);
        let settled = f.cases.iter().find(|c| c.swing.settles).unwrap();
        let at = settled.swing.late_mean_deg.unwrap();
        let r = super::fall_reading(&f, (at, 0.05));
        assert!(r.held >= 1);
        for x in r.runs.iter().filter(|x| x.holds) {
            let late = x.run.swing.late_mean_deg.unwrap();
            assert!(
                x.run.swing.settles && (late - at).abs() <= 0.05 * at,
                "{late}"
            );
        }
        let nutating = f.cases.iter().find(|c| c.mu.is_none()).unwrap();
        let r = super::fall_reading(&f, (nutating.fell_to_deg.unwrap(), 0.05));
        let x = r
            .runs
            .iter()
            .find(|x| std::ptr::eq(x.run, nutating))
            .unwrap();
        assert!(!x.holds && x.side.is_none());
    }
}
