//! The sound of a spinning disk, synthesised: what a microphone beside Euler's Disk records.
//!
//! The disk's contact point runs round its circle once per turn of the heading $\psi$
//! ($\dot\psi = \Omega$), and the sound one hears is at $\Omega/2\pi$ (sec. 11's closing
//! remarks), rising until it stops at once when the disk settles. We model the pressure as the
//! contact's fundamental with harmonics ([`Voice`]),
//! $$p(t) = A\,g(t)\sum_h a_h \sin(h\psi + \phi_h), \qquad
//!   g(t) = \left(\frac{\Omega(t)}{\Omega_{max}}\right)^{\gamma},$$
//! silent once the disk lies flat (and, for a phone's recording, before the disk is heard),
//! plus the microphone's Gaussian noise (seeded), and then whatever [`Artifacts`] a bench
//! recording adds. A phone's recording ([`Microphone::phone`]) adds the room: a rattle of the
//! rim in the last moments, clicks, low-passed room noise.
use crate::error::ExperimentError;
use crate::synthetic::artifacts::Artifacts;
use crate::synthetic::law::Law;
use crate::synthetic::simulate::simulate_motion;
use crate::trace::{Trace, Truth};
use physics::scene::Scene;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, StandardNormal};
use serde::{Deserialize, Serialize};

/// How the disk sounds, beyond its fundamental.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Voice {
    /// Amplitudes $a_h$ of the fundamental and three harmonics.
    pub harmonics: [f64; 4],
    /// Their phases $\phi_h$ (rad).
    pub phases: [f64; 4],
    /// $\gamma$: the level grows as $\Omega^\gamma$ toward the end (0: constant level).
    pub level_exponent: f64,
    /// Rattle of the rim in the last moments: broadband bursts of this amplitude (relative to
    /// $A$) at the end, decaying as $e^{-(t_0 - t)/30\,\mathrm{ms}}$.
    pub rattle: f64,
    /// Clicks (1 ms decaying pulses of half full scale's amplitude $A$) per second.
    pub clicks_per_s: f64,
    /// Room noise, low-passed at 300 Hz (full-scale rms).
    pub room: f64,
    /// Seconds of the record's start in which the disk is not heard.
    pub lead: f64,
}

impl Voice {
    /// A fundamental with two harmonics at a constant level, no room.
    pub fn plain() -> Self {
        Self {
            harmonics: [1.0, 0.5, 0.25, 0.0],
            phases: [0.0, 0.3, 0.7, 0.0],
            level_exponent: 0.0,
            rattle: 0.0,
            clicks_per_s: 0.0,
            room: 0.0,
            lead: 0.0,
        }
    }

    /// A phone beside the disk: three harmonics, the level rising as $\Omega^{1/2}$, a rattle,
    /// a click every two seconds, room noise of 0.01 rms, a second of silence first.
    pub fn phone() -> Self {
        Self {
            harmonics: [1.0, 0.6, 0.35, 0.2],
            phases: [0.0, 0.3, 0.7, 1.9],
            level_exponent: 0.5,
            rattle: 0.5,
            clicks_per_s: 0.5,
            room: 0.01,
            lead: 1.0,
        }
    }
}

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
    /// How the disk and the room sound.
    pub voice: Voice,
}

impl Default for Microphone {
    /// 8 kHz, 10 s, the end at 7.27 s (as the scope's), amplitude 0.3, noise 0.01, a plain voice.
    fn default() -> Self {
        Self {
            sample_rate: 8000,
            samples: 80_000,
            end_at: 7.27,
            amplitude: 0.3,
            noise: 0.01,
            seed: 1,
            voice: Voice::plain(),
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
        let v = &self.voice;
        let ok = |x: f64| x.is_finite() && x >= 0.0;
        if !(v.harmonics.iter().chain(&v.phases).all(|x| x.is_finite())
            && ok(v.level_exponent)
            && ok(v.rattle)
            && ok(v.clicks_per_s)
            && ok(v.room)
            && ok(v.lead)
            && v.lead < self.end_at)
        {
            return Err(ExperimentError::Setting(format!(
                "the voice's harmonics and phases must be finite, its level exponent, rattle, \
                 clicks, room noise and lead-in >= 0, and the lead-in shorter than the {} s \
                 before the end",
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

    /// A phone's recording at `rate` S/s: 10 s (less where the readers' sample limit asks), the
    /// end 1.5 s before the record's, amplitude 0.3, noise 0.003, [`Voice::phone`].
    pub fn phone(rate: u32, seed: u64) -> Self {
        let rate = rate.max(1);
        let samples = (10 * rate as usize).min(crate::formats::input::MAX_SAMPLES);
        Self {
            sample_rate: rate,
            samples,
            end_at: samples as f64 / f64::from(rate) - 1.5,
            amplitude: 0.3,
            noise: 0.003,
            seed,
            voice: Voice::phone(),
        }
    }

    /// The disk's pressure at headings `heading` sampled at times `t` (zero once the disk lies
    /// flat, where the heading is NaN, and before the lead-in ends).
    fn pressure(&self, t: &[f64], heading: &[f64]) -> Vec<f64> {
        let v = &self.voice;
        let n = heading.len();
        // Omega by central differences of the heading, for the level.
        let omega = |j: usize| -> f64 {
            let (a, b) = (j.saturating_sub(1), (j + 1).min(n - 1));
            let d = (heading[b] - heading[a]) / (t[b] - t[a]);
            if d.is_finite() {
                d.abs()
            } else {
                0.0
            }
        };
        let level: Vec<f64> = if v.level_exponent == 0.0 {
            vec![1.0; n]
        } else {
            let om: Vec<f64> = (0..n).map(omega).collect();
            let top = om
                .iter()
                .copied()
                .fold(0.0, f64::max)
                .max(f64::MIN_POSITIVE);
            om.iter()
                .map(|w| (w / top).powf(v.level_exponent))
                .collect()
        };
        heading
            .iter()
            .zip(t)
            .zip(&level)
            .map(|((&psi, &t), &g)| {
                if psi.is_nan() || t < v.lead {
                    return 0.0;
                }
                let sum: f64 = (0..4)
                    .map(|h| v.harmonics[h] * ((h + 1) as f64 * psi + v.phases[h]).sin())
                    .sum();
                self.amplitude * g * sum
            })
            .collect()
    }

    /// The room: the rim's rattle before `end`, clicks and low-passed room noise.
    fn room(&self, t: &[f64], end: f64, rng: &mut ChaCha8Rng, v: &mut [f64]) {
        let voice = &self.voice;
        let dt = 1.0 / f64::from(self.sample_rate);
        let lp = 1.0 - (-std::f64::consts::TAU * 300.0 * dt).exp();
        // A one-pole low-pass of white noise w has variance lp/(2 - lp) times w's.
        let gain = voice.room * ((2.0 - lp) / lp).sqrt();
        let (mut state, mut click) = (0.0, 0.0);
        let p_click = voice.clicks_per_s * dt;
        let decay = (-dt / 1e-3).exp();
        for (x, &t) in v.iter_mut().zip(t) {
            let g: f64 = StandardNormal.sample(rng);
            state += lp * (gain * g - state);
            let u: f64 = rng.random();
            if u < p_click {
                click += 0.5 * self.amplitude * if rng.random::<bool>() { 1.0 } else { -1.0 };
            }
            click *= decay;
            let tau = end - t;
            let rattle = if voice.rattle > 0.0 && tau > 0.0 && tau < 0.2 {
                let r: f64 = StandardNormal.sample(rng);
                voice.rattle * self.amplitude * (-tau / 0.03).exp() * r
            } else {
                0.0
            };
            *x += state + click + rattle;
        }
    }

    /// Records headings at times `t`: pressure, noise, the room, then `artifacts` (dropped
    /// samples zeroed).
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
        let mut v: Vec<f64> = self
            .pressure(&t, heading)
            .into_iter()
            .map(|p| {
                let g: f64 = StandardNormal.sample(&mut rng);
                p + self.noise * g
            })
            .collect();
        let v_room = &self.voice;
        if v_room.room > 0.0 || v_room.clicks_per_s > 0.0 || v_room.rattle > 0.0 {
            self.room(&t, truth.t_stop, &mut rng, &mut v);
        }
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
