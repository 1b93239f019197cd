//! The "Friction and contact" section's full output, as a program prints it: every run of the
//! friction studies ([`studies::sliding::Studies`]) in plain fixed-width tables, for the HTML
//! `<pre>` and the LaTeX listing. What it prints and how is
//! `templates/parts/friction/listing.txt.tera`; this file gathers the values that template reads
//! beside the studies (the fall study read against the paper's claim, the notes' numbering).

use crate::error::ReportError;
use crate::parts::prose::paragraph;
use serde::Serialize;
use studies::sliding::fall::{Fall, FallCase, ACROSS, DURATION, LEFT, NUDGE};
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

/// A fall run and how its tilt fallen to stands against the claim's reading.
#[derive(Serialize)]
struct FallRun<'s> {
    run: &'s FallCase,
    /// Whether the tilt fallen to is within the reading (`None`: it did not fall).
    holds: Option<bool>,
    /// "above" or "below" the reading, or "inside" it (`None`: it did not fall).
    side: Option<&'static str>,
    /// How far outside the reading (deg).
    by: f64,
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
    held: usize,
    below: usize,
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
            let x = c.fell_to_deg;
            let (side, by) = match x {
                Some(x) if x > hi => (Some("above"), x - hi),
                Some(x) if x < lo => (Some("below"), lo - x),
                Some(_) => (Some("inside"), 0.0),
                None => (None, 0.0),
            };
            FallRun {
                run: c,
                holds: x.map(|x| (lo..=hi).contains(&x)),
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
        held: runs.iter().filter(|r| r.holds == Some(true)).count(),
        below: f
            .cases
            .iter()
            .filter(|c| c.fell_to_deg.is_some_and(|x| x <= hi))
            .count(),
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
}
