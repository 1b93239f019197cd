//! The sound of a spinning disk, synthesised: what a microphone beside Euler's Disk records.
//!
//! The disk's contact point runs round its circle once per turn of the heading $\psi$
//! ($\dot\psi = \Omega$), and the sound one hears is at $\Omega/2\pi$ (sec. 11's closing
//! remarks), rising until it stops at once when the disk settles. We model the pressure as the
//! contact's fundamental with two harmonics,
//! $$p(t) = A\left[\sin\psi + \tfrac12\sin(2\psi + 0.3) + \tfrac14\sin(3\psi + 0.7)\right],$$
//! silent once the disk lies flat, plus the microphone's Gaussian noise (seeded), and then
//! whatever [`Artifacts`] a bench recording adds.

use crate::experiment::artifacts::Artifacts;
use crate::experiment::error::ExperimentError;
use crate::experiment::law::Law;
use crate::experiment::simulate::simulate_motion;
use crate::experiment::trace::{Trace, Truth};
use crate::scene::Scene;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, StandardNormal};
use serde::{Deserialize, Serialize};

/// A microphone and its recorder.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Microphone {
    /// Samples per second.
    pub sample_rate: u32,
    /// Samples in the record.
    pub samples: usize,
    /// Record time at which the spin-down ends (s).
    pub end_at: f64,
    /// Amplitude $A$ of the sound (full scale 1).
    pub amplitude: f64,
    /// Gaussian noise (full scale rms).
    pub noise: f64,
    /// Seed of the noise.
    pub seed: u64,
}

impl Default for Microphone {
    /// 8 kHz, 10 s, the end at 7.27 s (as the scope's), amplitude 0.3, noise 0.01.
    fn default() -> Self {
        Self {
            sample_rate: 8000,
            samples: 80_000,
            end_at: 7.27,
            amplitude: 0.3,
            noise: 0.01,
            seed: 1,
        }
    }
}

impl Microphone {
    /// Checks the settings.
    pub fn validate(&self) -> Result<(), ExperimentError> {
        let span = self.samples as f64 / f64::from(self.sample_rate.max(1));
        if self.sample_rate < 1000 || self.samples < 1024 {
            return Err(ExperimentError::Setting(format!(
                "a sound record needs at least 1000 S/s and 1024 samples, got {} S/s and {}",
                self.sample_rate, self.samples
            )));
        }
        if !(self.end_at > 0.0 && self.end_at < span) {
            return Err(ExperimentError::Setting(format!(
                "the spin-down's end must fall inside the {span} s record, got {} s",
                self.end_at
            )));
        }
        if !(self.amplitude > 0.0 && self.amplitude <= 1.0 && self.noise >= 0.0) {
            return Err(ExperimentError::Setting(
                "the amplitude must be in (0, 1] and the noise >= 0".into(),
            ));
        }
        Ok(())
    }

    /// The pressure of heading `psi` (NaN once the disk lies flat: silence).
    fn pressure(&self, psi: f64) -> f64 {
        if psi.is_nan() {
            return 0.0;
        }
        self.amplitude
            * (psi.sin() + 0.5 * (2.0 * psi + 0.3).sin() + 0.25 * (3.0 * psi + 0.7).sin())
    }

    /// Records headings at times `t`: pressure, noise, then `artifacts` (dropped samples zeroed).
    fn record(
        &self,
        t: Vec<f64>,
        heading: &[f64],
        artifacts: &Artifacts,
        source: String,
        truth: Truth,
    ) -> Result<Trace, ExperimentError> {
        artifacts.validate()?;
        let mut rng = ChaCha8Rng::seed_from_u64(self.seed);
        let mut v: Vec<f64> = heading
            .iter()
            .map(|&psi| {
                let g: f64 = StandardNormal.sample(&mut rng);
                self.pressure(psi) + self.noise * g
            })
            .collect();
        let dropped = artifacts.apply(&t, &mut v);
        for (x, d) in v.iter_mut().zip(dropped) {
            if d {
                *x = 0.0;
            }
            *x = x.clamp(-1.0, 1.0);
        }
        Ok(Trace {
            source,
            t,
            v,
            truth: Some(truth),
        })
    }
}

/// The sound of a disk that follows eq 79's `law` exactly.
pub fn law_sound(
    law: &Law,
    mic: &Microphone,
    artifacts: &Artifacts,
) -> Result<Trace, ExperimentError> {
    mic.validate()?;
    let rate = f64::from(mic.sample_rate);
    let t: Vec<f64> = (0..mic.samples).map(|j| j as f64 / rate).collect();
    let heading: Vec<f64> = t
        .iter()
        .map(|&t| {
            let tau = mic.end_at - t;
            if tau > 0.0 {
                law.heading(tau)
            } else {
                f64::NAN
            }
        })
        .collect();
    let truth = Truth {
        beta: law.beta,
        t0: mic.end_at,
        t_stop: mic.end_at,
        tau_rem: 0.0,
        c: Some(law.c),
        origin: "eq 79 exactly".into(),
    };
    mic.record(
        t,
        &heading,
        artifacts,
        format!("sound:law:beta={},C={:e}", law.beta, law.c),
        truth,
    )
}

/// The sound of a dissipative or sliding scene's spin-down.
pub fn simulate_sound(
    scene: &Scene,
    mic: &Microphone,
    artifacts: &Artifacts,
) -> Result<Trace, ExperimentError> {
    mic.validate()?;
    let m = simulate_motion(scene, mic.end_at, f64::from(mic.sample_rate), mic.samples)?;
    mic.record(
        m.t,
        &m.heading,
        artifacts,
        format!("sound:{}", scene.name),
        m.truth,
    )
}
