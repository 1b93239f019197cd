//! What a real recording adds to a clean signal: baseline drift, mains hum, clipping, isolated
//! glitches and dropped samples. Seeded (ChaCha8 through `rand`), so the same settings give the
//! same bytes.
//!
//! These are applied by `experiment simulate` to synthetic scope traces and sound recordings,
//! so that the analysis is tested on data it did not make for itself.

use crate::error::ExperimentError;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, StandardNormal};
use serde::{Deserialize, Serialize};
use std::f64::consts::TAU;

/// Most glitches per second a recording may be given: isolated spikes, each far from the next
/// at any sample rate the experiment uses (the scope's and the microphone's are kHz).
pub const MAX_GLITCHES_PER_S: f64 = 1000.0;

/// Period (s) of the mains frequency's wander ([`Artifacts::mains_wander`]).
pub const WANDER_PERIOD_S: f64 = 12.0;

/// The artifacts to add. All amplitudes are in the signal's unit (V for a scope trace, full
/// scale 1 for sound).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Artifacts {
    /// Baseline drift: a slow wander of this rms amplitude (a sum of sines of periods 3-20 s).
    pub drift: f64,
    /// Mains hum amplitude at its fundamental (the 2nd and 3rd harmonics at 1/2 and 1/4 of it).
    pub hum: f64,
    /// Mains frequency (Hz): 50 or 60.
    pub mains: f64,
    /// The grid frequency's wander (Hz): the mains runs at $f_m + w\sin(2\pi t/P)$,
    /// $P$ = [`WANDER_PERIOD_S`], as a grid's frequency follows its load (0: steady).
    #[serde(default)]
    pub mains_wander: f64,
    /// Clip the signal above this fraction of its range (1 for no clipping).
    pub clip: f64,
    /// Isolated one-sample glitches per second.
    pub glitches_per_s: f64,
    /// A glitch's amplitude.
    pub glitch: f64,
    /// Fraction of samples dropped (removed from a CSV, zeroed in a sound recording).
    pub dropped: f64,
    /// The seed.
    pub seed: u64,
}

impl Artifacts {
    /// No artifacts.
    pub fn none() -> Self {
        Self {
            drift: 0.0,
            hum: 0.0,
            mains: 50.0,
            mains_wander: 0.0,
            clip: 1.0,
            glitches_per_s: 0.0,
            glitch: 0.0,
            dropped: 0.0,
            seed: 7,
        }
    }

    /// A realistic bench recording for a signal of `span` peak to peak: drift of 5 % of the
    /// span, 50 Hz hum of 2 %, clipping of the top 15 %, two glitches a second of half the span,
    /// 1 % of the samples dropped.
    pub fn realistic(span: f64, seed: u64) -> Self {
        Self {
            drift: 0.05 * span,
            hum: 0.02 * span,
            mains: 50.0,
            mains_wander: 0.0,
            clip: 0.85,
            glitches_per_s: 2.0,
            glitch: 0.5 * span,
            dropped: 0.01,
            seed,
        }
    }

    /// Checks the settings (each bounded, so that the work of [`Artifacts::apply`] is too).
    pub fn validate(&self) -> Result<(), ExperimentError> {
        let bad = |what: &str| Err(ExperimentError::Setting(what.into()));
        let ok = |x: f64| x.is_finite() && x >= 0.0;
        if !(ok(self.drift) && ok(self.hum) && ok(self.glitch) && ok(self.glitches_per_s)) {
            return bad("drift, hum, glitch and glitches_per_s must be finite and >= 0");
        }
        if self.glitches_per_s > MAX_GLITCHES_PER_S {
            return Err(ExperimentError::Setting(format!(
                "--glitches {}: at most {MAX_GLITCHES_PER_S} isolated glitches per second; a \
                 higher rate is noise, not glitches (give --glitches 2 for a realistic bench)",
                self.glitches_per_s
            )));
        }
        if !(self.mains.is_finite() && self.mains > 0.0) {
            return bad("the mains frequency must be positive (50 or 60 Hz)");
        }
        if !(self.mains_wander.is_finite() && self.mains_wander.abs() < 0.1 * self.mains) {
            return bad("the mains frequency's wander must be finite and below a tenth of it (a grid wanders by 0.01-0.2 Hz)");
        }
        if !(self.clip > 0.0 && self.clip <= 1.0) {
            return bad("clip must be in (0, 1]: the fraction of the range kept");
        }
        if !(self.dropped >= 0.0 && self.dropped < 0.5) {
            return bad("dropped must be in [0, 0.5): the fraction of samples lost");
        }
        Ok(())
    }

    /// Adds drift, hum, clipping and glitches to `v` sampled at times `t`; returns which
    /// samples are dropped (the caller removes or zeroes them).
    pub fn apply(&self, t: &[f64], v: &mut [f64]) -> Vec<bool> {
        let mut rng = ChaCha8Rng::seed_from_u64(self.seed);
        let (lo, hi) = v
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
                (a.min(x), b.max(x))
            });
        let top = lo + self.clip * (hi - lo);
        // Drift: four sines of random phase, periods 3 to 20 s, total rms `drift`.
        let periods = [20.0, 11.0, 6.0, 3.0];
        let phases: Vec<f64> = periods.iter().map(|_| rng.random::<f64>() * TAU).collect();
        let a = self.drift * (2.0 / periods.len() as f64).sqrt();
        let hum_phase = rng.random::<f64>() * TAU;
        for (x, &tj) in v.iter_mut().zip(t) {
            *x = x.min(top);
            let d: f64 = periods
                .iter()
                .zip(&phases)
                .map(|(p, f)| (TAU * tj / p + f).sin())
                .sum();
            // The phase of f_m + w sin(2 pi t/P): 2 pi f_m t + w P (1 - cos(2 pi t/P)).
            let wander =
                self.mains_wander * WANDER_PERIOD_S * (1.0 - (TAU * tj / WANDER_PERIOD_S).cos());
            let w = TAU * self.mains * tj + wander + hum_phase;
            *x += a * d + self.hum * (w.sin() + 0.5 * (2.0 * w).sin() + 0.25 * (3.0 * w).sin());
        }
        let n = v.len();
        if n > 1 && self.glitches_per_s > 0.0 {
            let duration = t[n - 1] - t[0];
            let count = (self.glitches_per_s * duration).round() as usize;
            for _ in 0..count {
                let j = rng.random_range(0..n);
                let s: f64 = StandardNormal.sample(&mut rng);
                v[j] += self.glitch * s.signum();
            }
        }
        (0..n).map(|_| rng.random::<f64>() < self.dropped).collect()
    }
}

impl crate::trace::Trace {
    /// This trace as a bench recording would have it: `a`'s drift, hum, clipping and glitches
    /// added, its dropped samples removed (the time column keeps the gaps).
    pub fn with_artifacts(&self, a: &Artifacts) -> Result<Self, ExperimentError> {
        a.validate()?;
        let mut v = self.v.clone();
        let dropped = a.apply(&self.t, &mut v);
        let keep = |j: &usize| !dropped[*j];
        let idx: Vec<usize> = (0..v.len()).filter(keep).collect();
        Ok(Self {
            source: format!("{}+artifacts", self.source),
            t: idx.iter().map(|&j| self.t[j]).collect(),
            v: idx.iter().map(|&j| v[j]).collect(),
            truth: self.truth.clone(),
        })
    }
}
