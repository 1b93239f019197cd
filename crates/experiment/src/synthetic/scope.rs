//! The scope: sample rate, record length, where in the record the spin-down ends, and what the
//! electronics add: Gaussian noise (`rand_distr`, seeded ChaCha8: the same seed gives the same
//! bytes on every machine) and quantisation.

use crate::error::ExperimentError;
use crate::synthetic::artifacts::Artifacts;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, StandardNormal};
use serde::{Deserialize, Serialize};

/// A digital scope as in section 11: 5 kS/s, 50,000 samples.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Scope {
    /// Samples per second.
    pub sample_rate: f64,
    /// Samples in the record.
    pub samples: usize,
    /// Record time at which the spin-down ends (s); the paper's data put it at 7.26-7.28 s.
    pub end_at: f64,
    /// Gaussian noise added to each sample (V rms).
    pub noise: f64,
    /// Seed of the noise.
    pub seed: u64,
    /// ADC resolution in bits; 0 for none.
    pub bits: u32,
    /// The ADC's input range (V): values outside clip.
    pub range: (f64, f64),
}

impl Default for Scope {
    /// 5 kS/s, 50,000 samples, the end at 7.27 s, 5 mV noise, 8 bits over 0-2.5 V.
    fn default() -> Self {
        Self {
            sample_rate: 5000.0,
            samples: 50_000,
            end_at: 7.27,
            noise: 0.005,
            seed: 1,
            bits: 8,
            range: (0.0, 2.5),
        }
    }
}

impl Scope {
    /// Checks the settings.
    pub fn validate(&self) -> Result<(), ExperimentError> {
        if !(self.sample_rate.is_finite() && self.sample_rate > 0.0) {
            return Err(ExperimentError::Setting(format!(
                "the sample rate must be positive (5000 S/s in the paper), got {}",
                self.sample_rate
            )));
        }
        if self.samples < 16 {
            return Err(ExperimentError::Setting(format!(
                "a record needs at least 16 samples (50,000 in the paper), got {}",
                self.samples
            )));
        }
        let span = self.samples as f64 / self.sample_rate;
        if !(self.end_at.is_finite() && self.end_at > 0.0 && self.end_at < span) {
            return Err(ExperimentError::Setting(format!(
                "the end of the spin-down must fall inside the {span} s record, got {} s",
                self.end_at
            )));
        }
        if !(self.noise.is_finite() && self.noise >= 0.0) {
            return Err(ExperimentError::Setting(format!(
                "the noise must be >= 0 V rms, got {}",
                self.noise
            )));
        }
        if self.bits > 32 {
            return Err(ExperimentError::Setting(format!(
                "at most 32 bits, got {}",
                self.bits
            )));
        }
        let (lo, hi) = self.range;
        if !(lo.is_finite() && hi.is_finite() && hi > lo) {
            return Err(ExperimentError::Setting(format!(
                "the input range must be low < high volts, got {lo}..{hi}"
            )));
        }
        Ok(())
    }

    /// The sample interval (s).
    pub fn dt(&self) -> f64 {
        1.0 / self.sample_rate
    }

    /// The record times $t_j = j/f_s$.
    pub fn times(&self) -> Vec<f64> {
        (0..self.samples).map(|j| j as f64 * self.dt()).collect()
    }

    /// The quantisation step (V), 0 without an ADC.
    pub fn lsb(&self) -> f64 {
        if self.bits == 0 {
            0.0
        } else {
            (self.range.1 - self.range.0) / ((1u64 << self.bits) - 1) as f64
        }
    }

    /// What the scope records of a clean signal: plus noise, clipped to the range, quantised.
    pub fn record(&self, clean: &mut [f64]) {
        let mut rng = ChaCha8Rng::seed_from_u64(self.seed);
        let lsb = self.lsb();
        let (lo, hi) = self.range;
        for v in clean.iter_mut() {
            let g: f64 = StandardNormal.sample(&mut rng);
            let mut x = *v + self.noise * g;
            if self.bits > 0 {
                x = lo + ((x.clamp(lo, hi) - lo) / lsb).round() * lsb;
            }
            *v = x;
        }
    }
}

/// What a simulated CSV records of how it was made, one `# KEY: VALUE` comment line each
/// (without the `#`): the scope (rate, samples, noise, ADC, its seed) and the bench's artifacts
/// with their seed, so that the file alone says how to make it again.
pub fn header_notes(scope: &Scope, a: &Artifacts) -> Vec<String> {
    let adc = if scope.bits == 0 {
        "none".to_string()
    } else {
        format!(
            "{} bits over {}..{} V",
            scope.bits, scope.range.0, scope.range.1
        )
    };
    vec![
        format!(
            "scope: {} S/s, {} samples, noise {} V rms, ADC {adc}, seed {}",
            scope.sample_rate, scope.samples, scope.noise, scope.seed
        ),
        format!(
            "artifacts: drift {} V rms, hum {} V at {} Hz (wander {} Hz), clip above {} of the \
             range, glitches {}/s of {} V, dropped {}, seed {}",
            a.drift,
            a.hum,
            a.mains,
            a.mains_wander,
            a.clip,
            a.glitches_per_s,
            a.glitch,
            a.dropped,
            a.seed
        ),
    ]
}
