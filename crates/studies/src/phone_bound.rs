//! What the realistic set's recordings can tell at best: each [`PhoneRoom`] recording's
//! Cramér-Rao bound on $\beta$ and $t_0$ ([`SoundInformation`], from the generator's own
//! settings, independently of the analysis), and from it how many recordings no estimator could
//! bring within a tolerance of $\beta$ with a 95 % interval that holds it.
//!
//! The bound limits an unbiased estimator's variance, not the chance that one error is small,
//! and at low information real estimators do worse than it (the threshold effect). So two
//! counts are stated, both optimistic: the recordings whose $\sigma_\beta$ at the bound exceeds
//! $0.05/1.96$ (an honest 95 % interval is then wider than $\pm 0.05$, so such a recording can be
//! both covered and within 0.05 only by luck), and the number expected within 0.05 if every
//! recording were analysed at the bound with Gaussian errors,
//! $$\sum_i \operatorname{erf}\!\left(\frac{0.05}{\sqrt2\,\sigma_i}\right),$$
//! against what issue 47's done-when implies ($0.9 \times 0.9$ of the set). Each is given for the
//! span the phase fit can use (to 1 ms before $t_0$) and for all of the disk's sound (to $t_0$).
//! [`cross`] sets the bound beside the phone study's outcomes ([`PhoneCoverage`]): which refusals
//! and misses are the analysis's loss and which the recording's.

use crate::phone_coverage::{PhoneCoverage, PhoneOutcome};
use experiment::error::ExperimentError;
use experiment::synthetic::bound::SoundInformation;
use experiment::synthetic::phone_room::PhoneRoom;
use serde::{Deserialize, Serialize};
use std::f64::consts::TAU;

/// The done-when's tolerance on $|\hat\beta - \beta|$.
pub const BETA_TOLERANCE: f64 = 0.05;
/// $\sigma_\beta$ at the bound above which no 95 % interval within the tolerance is honest.
pub const INFORMATION_LIMITED: f64 = BETA_TOLERANCE / 1.96;
/// $\sigma_\beta$ at the bound below which a refusal is the analysis's loss.
pub const ANALYSIS_LOSS: f64 = 0.005;
/// The done-when's fractions: analysed, and of those within the tolerance.
const DONE_WHEN: (f64, f64) = (0.9, 0.9);

/// One recording's bound.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RecordingBound {
    /// The recording's seed ([`PhoneRoom::draw`]).
    pub seed: u64,
    /// Its rate (S/s).
    pub rate: u32,
    /// Seconds of the disk's sound.
    pub sound: f64,
    /// The fundamental's frequency where the sound starts (Hz).
    pub start_hz: f64,
    /// True $\beta$.
    pub beta: f64,
    /// The disk's turns in the span to 1 ms before $t_0$.
    pub turns: f64,
    /// $\sigma_\beta$ at the bound on the span to 1 ms before $t_0$.
    pub beta_sigma: f64,
    /// $\sigma_{t_0}$ (s) at the bound on that span.
    pub t0_sigma: f64,
    /// $\sigma_\beta$ at the bound on all the disk's sound, to $t_0$.
    pub beta_sigma_whole: f64,
    /// $\sigma_{t_0}$ (s) at the bound on all the disk's sound.
    pub t0_sigma_whole: f64,
}

/// A set of recordings' bounds and their counts.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BoundSet {
    /// The first recording's seed.
    pub seed0: u64,
    /// Recordings.
    pub runs: usize,
    /// How many have $\sigma_\beta$ at the bound above [`INFORMATION_LIMITED`], on the span
    /// to 1 ms before $t_0$.
    pub information_limited: usize,
    /// The same on all the disk's sound.
    pub information_limited_whole: usize,
    /// $\sum_i \operatorname{erf}(0.05/(\sqrt2\sigma_i))$ on the span to 1 ms before $t_0$.
    pub expected_within: f64,
    /// The same on all the disk's sound.
    pub expected_within_whole: f64,
    /// What the done-when implies: $0.9 \times 0.9 \times$ `runs`.
    pub done_when: f64,
    /// Each recording's bound, by seed.
    pub recordings: Vec<RecordingBound>,
}

impl BoundSet {
    /// One line of the counts.
    pub fn summary(&self) -> String {
        format!(
            "{} recordings from seed {}: sigma_beta at the bound above 0.05/1.96 on {} ({} with \
             all the sound to t0); expected within 0.05 at the bound {:.1} ({:.1}), against the \
             {:.0} the done-when implies",
            self.runs,
            self.seed0,
            self.information_limited,
            self.information_limited_whole,
            self.expected_within,
            self.expected_within_whole,
            self.done_when
        )
    }
}

/// The study as stored in `snapshots/phone_bound.json`, with the command that made it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StoredPhoneBound {
    /// The command that ran and stored it.
    pub command: String,
    /// The phone study's set, then the second set.
    pub sets: Vec<BoundSet>,
}

/// The bound of the recording of seed `seed`.
pub fn recording_bound(seed: u64) -> Result<RecordingBound, ExperimentError> {
    let room = PhoneRoom::draw(seed);
    let span = SoundInformation::of_phone(&room);
    let whole = SoundInformation {
        end_before: 0.0,
        ..span.clone()
    };
    let (b, w) = (span.bound()?, whole.bound()?);
    Ok(RecordingBound {
        seed,
        rate: room.sample_rate,
        sound: room.sound,
        start_hz: room.law.precession(room.sound) / TAU,
        beta: room.law.beta,
        turns: span.span_samples_and_turns().1,
        beta_sigma: b.beta_sigma,
        t0_sigma: b.t0_sigma,
        beta_sigma_whole: w.beta_sigma,
        t0_sigma_whole: w.t0_sigma,
    })
}

/// The number within `tolerance` expected of Gaussian errors of standard deviations `sigmas`.
pub fn expected_within(sigmas: impl Iterator<Item = f64>, tolerance: f64) -> f64 {
    sigmas
        .map(|s| libm::erf(tolerance / (std::f64::consts::SQRT_2 * s)))
        .sum()
}

/// The bounds of `runs` recordings from seed `seed0`.
pub fn bound_set(seed0: u64, runs: usize) -> Result<BoundSet, ExperimentError> {
    let recordings = (seed0..seed0 + runs as u64)
        .map(recording_bound)
        .collect::<Result<Vec<_>, _>>()?;
    let limited = |f: fn(&RecordingBound) -> f64| {
        recordings
            .iter()
            .filter(|r| f(r) > INFORMATION_LIMITED)
            .count()
    };
    let within =
        |f: fn(&RecordingBound) -> f64| expected_within(recordings.iter().map(f), BETA_TOLERANCE);
    Ok(BoundSet {
        seed0,
        runs,
        information_limited: limited(|r| r.beta_sigma),
        information_limited_whole: limited(|r| r.beta_sigma_whole),
        expected_within: within(|r| r.beta_sigma),
        expected_within_whole: within(|r| r.beta_sigma_whole),
        done_when: DONE_WHEN.0 * DONE_WHEN.1 * runs as f64,
        recordings,
    })
}

/// Where a recording of the phone study stands against its bound.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Standing {
    /// Refused, with $\sigma_\beta$ at the bound below [`ANALYSIS_LOSS`]: the analysis's loss.
    RefusedInformative,
    /// Refused, with the bound between [`ANALYSIS_LOSS`] and [`INFORMATION_LIMITED`].
    RefusedBetween,
    /// Refused, with the bound above [`INFORMATION_LIMITED`]: the recording's.
    RefusedLimited,
    /// Analysed, but $|\hat\beta - \beta| > 0.05$ or a 95 % interval missing $\beta$ or $t_0$.
    Missed,
    /// Analysed, within 0.05 and both intervals holding.
    Met,
}

/// One recording of the phone study beside its bound.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Crossed {
    /// The recording's outcome in the phone study.
    pub outcome: PhoneOutcome,
    /// Its bound.
    pub bound: RecordingBound,
    /// Where it stands.
    pub standing: Standing,
    /// The stated $\sigma_\beta$ over the bound's (on the span to 1 ms before $t_0$), when
    /// analysed.
    pub beta_efficiency: Option<f64>,
    /// The stated $\sigma_{t_0}$ over the bound's, when analysed.
    pub t0_efficiency: Option<f64>,
}

/// The phone study's outcomes beside `set`'s bounds, by seed (seeds the set lacks left out).
pub fn cross(set: &BoundSet, coverage: &PhoneCoverage) -> Vec<Crossed> {
    coverage
        .outcomes
        .iter()
        .filter_map(|o| {
            let b = set.recordings.iter().find(|r| r.seed == o.seed)?;
            let holds = |e: Option<f64>, s: Option<f64>| match (e, s) {
                (Some(e), Some(s)) => e.abs() <= 1.96 * s,
                _ => false,
            };
            let standing = match &o.refused {
                Some(_) if b.beta_sigma < ANALYSIS_LOSS => Standing::RefusedInformative,
                Some(_) if b.beta_sigma > INFORMATION_LIMITED => Standing::RefusedLimited,
                Some(_) => Standing::RefusedBetween,
                None if o.beta_error.is_some_and(|e| e.abs() <= BETA_TOLERANCE)
                    && holds(o.beta_error, o.beta_sigma)
                    && holds(o.t0_error, o.t0_sigma) =>
                {
                    Standing::Met
                }
                None => Standing::Missed,
            };
            Some(Crossed {
                outcome: o.clone(),
                bound: b.clone(),
                standing,
                beta_efficiency: o.beta_sigma.map(|s| s / b.beta_sigma),
                t0_efficiency: o.t0_sigma.map(|s| s / b.t0_sigma),
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_expected_count_is_the_gaussian_chance_summed() {
        // One sigma equal to the tolerance: erf(1/sqrt 2) = 0.682 689 49; a tiny one: 1; one of
        // 1000: erf(3.5355e-5) = 2/sqrt(pi) 3.5355e-5 = 3.989e-5.
        let n = expected_within([0.05, 1e-6, 1e3].into_iter(), 0.05);
        assert!((n - (0.682_689_49 + 1.0 + 3.989e-5)).abs() < 1e-6, "{n}");
    }

    #[test]
    fn a_longer_sound_is_told_better_than_a_short_one() {
        let set = bound_set(1, 20).unwrap();
        let short = set
            .recordings
            .iter()
            .filter(|r| r.sound < 3.0)
            .map(|r| r.beta_sigma)
            .fold(0.0, f64::max);
        let long = set
            .recordings
            .iter()
            .filter(|r| r.sound > 20.0)
            .map(|r| r.beta_sigma)
            .fold(f64::MAX, f64::min);
        assert!(short > long, "short {short}, long {long}");
        for r in &set.recordings {
            assert!(r.beta_sigma_whole <= r.beta_sigma * (1.0 + 1e-9), "{r:?}");
        }
    }
}
