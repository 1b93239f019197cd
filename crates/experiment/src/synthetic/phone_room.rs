//! A phone's recording of a real spin in a real room, made independently of the analysis: the
//! realistic set on which the sound analysis is measured.
//!
//! The disk follows eq 79 exactly, $\Omega = (C/(t_0 - t))^{1/(\beta+2)}$, with the heading
//! $\psi(t) = -C^{p}(t_0 - t)^{1-p}/(1-p)$, $p = 1/(\beta+2)$ ([`Law`]). Its sound is the
//! contact point's fundamental and harmonics,
//! $$p(t) = A\,g(t)\sum_{h=1}^{H} a_h \sin(h\psi + \phi_h), \qquad
//!   g = \min\!\left(1, (\Omega/\Omega_{end})^{\gamma}\right),$$
//! from the moment the disk is heard (faded in over 0.2 s) to $t_0$. What a room and a phone add,
//! each drawn from its seed by [`PhoneRoom::draw`]:
//!
//! - a lead-in before the disk is heard, with handling bumps (damped thumps of 20-80 Hz, often
//!   to full scale), and now and then a bump during the spin;
//! - a rattle of the rim before $t_0$ and the disk's shudder after it (broadband bursts with a
//!   ringing mode, decaying);
//! - low-passed room noise and the room's reverberation ([`reverb`]);
//! - two microphones: the second hears the room later by up to 1.5 ms, at its own gain, with its
//!   own noise;
//! - the phone's high-pass at 20-200 Hz ([`high_pass`]), which may leave the fundamental far
//!   below its second harmonic;
//! - mains hum picked up by the phone: 50 or 60 Hz wandering slowly, with 1-8 harmonics;
//! - the phone's automatic gain control ([`agc`]), a DC offset and clipping;
//! - 16- or 24-bit integer or float WAV at 16-96 kS/s ([`PhoneRecording::wav`]).

use crate::error::ExperimentError;
use crate::formats::channel::Channels;
use crate::formats::recording::parse_recording;
use crate::formats::wav::{encode_wav_channels, WavCoding};
use crate::synthetic::law::Law;
use crate::synthetic::room_filters::{agc, high_pass, reverb};
use crate::trace::{Trace, Truth};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, StandardNormal};
use serde::{Deserialize, Serialize};
use std::f64::consts::TAU;

/// The sample rates a phone or recorder uses (S/s).
pub const PHONE_RATES: [u32; 6] = [16_000, 22_050, 32_000, 44_100, 48_000, 96_000];

/// The mains hum a phone picks up.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PhoneHum {
    /// The grid's frequency (Hz): 50 or 60.
    pub mains: f64,
    /// Its slow wander (Hz), a sine of period 12 s.
    pub wander: f64,
    /// Amplitudes of the mains frequency's harmonics $1, 2, \ldots$ (full scale).
    pub lines: Vec<f64>,
}

/// One recording's settings: the disk, the room and the phone.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PhoneRoom {
    /// Samples per second.
    pub sample_rate: u32,
    /// Eq 79's law the disk follows.
    pub law: Law,
    /// Seconds before the disk is heard.
    pub lead: f64,
    /// Seconds of the disk's sound before $t_0$.
    pub sound: f64,
    /// Seconds recorded after $t_0$.
    pub tail: f64,
    /// Amplitudes $a_h$ of the fundamental and its harmonics.
    pub harmonics: Vec<f64>,
    /// Their phases $\phi_h$ (rad).
    pub phases: Vec<f64>,
    /// $\gamma$ of the level's rise.
    pub level_exponent: f64,
    /// $A$ (full scale) at the loudest.
    pub amplitude: f64,
    /// Each microphone's own noise (full-scale rms).
    pub noise: f64,
    /// Low-passed (300 Hz) room noise (full-scale rms).
    pub room: f64,
    /// Handling bumps: time (s) and peak amplitude (full scale).
    pub bumps: Vec<(f64, f64)>,
    /// The rim's rattle before $t_0$ and the shudder after it, relative to $A$.
    pub rattle: f64,
    /// How long the shudder after $t_0$ lasts (s, its decay time).
    pub shudder: f64,
    /// Reverberation: $T_{60}$ (s) and the wet fraction.
    pub reverb: (f64, f64),
    /// The second microphone's delay (s) and gain.
    pub stereo: (f64, f64),
    /// The phone's high-pass corner (Hz).
    pub high_pass: f64,
    /// The mains hum.
    pub hum: PhoneHum,
    /// The AGC's target level (full scale), or 0 without AGC.
    pub agc: f64,
    /// DC offset (full scale).
    pub dc: f64,
    /// Clipping level (full scale).
    pub clip: f64,
    /// The WAV's coding: 16 or 24 (integer) or 32 (float).
    pub bits: u16,
    /// The noise's seed.
    pub seed: u64,
}

/// A phone's recording as made: two channels and the truth.
#[derive(Debug, Clone, PartialEq)]
pub struct PhoneRecording {
    /// Samples per second.
    pub sample_rate: u32,
    /// The two channels (full scale).
    pub channels: [Vec<f64>; 2],
    /// The disk's truth.
    pub truth: Truth,
    /// How many bits the WAV stores per sample (16, 24 integer; 32 float).
    pub bits: u16,
}

impl PhoneRecording {
    /// The recording as a stereo WAV file's bytes.
    pub fn wav(&self) -> Result<Vec<u8>, ExperimentError> {
        let coding = match self.bits {
            16 => WavCoding::Int16,
            24 => WavCoding::Int24,
            _ => WavCoding::Float32,
        };
        let [l, r] = &self.channels;
        encode_wav_channels(&[l, r], self.sample_rate, coding)
            .map_err(|e| ExperimentError::Setting(format!("the WAV cannot be encoded ({e})")))
    }

    /// The recording as the tool reads it: its WAV file's bytes, named `file`, read back
    /// through the tool's reader with the channels mixed as `experiment analyze` mixes them,
    /// with the disk's truth attached.
    pub fn read_back(&self, file: &str) -> Result<Trace, ExperimentError> {
        self.read_wav(self.wav()?, file)
    }

    /// [`PhoneRecording::read_back`] of `wav`, this recording's bytes already made
    /// ([`PhoneRecording::wav`]), so that a caller can tell an encoding's failure from a
    /// reading's.
    pub fn read_wav(&self, wav: Vec<u8>, file: &str) -> Result<Trace, ExperimentError> {
        let mut trace = parse_recording(wav, file, Channels::Mix)?.trace;
        trace.truth = Some(self.truth.clone());
        Ok(trace)
    }
}

/// A uniform draw in `[a, b)`.
fn uniform(rng: &mut ChaCha8Rng, (a, b): (f64, f64)) -> f64 {
    a + (b - a) * rng.random::<f64>()
}

impl PhoneRoom {
    /// Draws a recording's settings from `seed`: a rate of [`PHONE_RATES`], $\beta$ in 1.5-3,
    /// 1-60 s of sound (log-uniform) starting at 4-30 Hz, a 0.5-3 s lead-in with one to three
    /// bumps (and one during the spin in three recordings of ten), 3-6 lines of the disk,
    /// $\gamma$ 0-1.5, reverberation of 0.2-0.8 s at 5-30 %, a second microphone 0-1.5 ms
    /// later, a high-pass at 20-200 Hz, 0-3 % of hum with 1-8 harmonics, AGC in half the
    /// recordings, DC up to 5 %, clipping at 60-100 % of full scale.
    pub fn draw(seed: u64) -> Self {
        let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x005e_ed0f_d15c);
        let rate = PHONE_RATES[rng.random_range(0..PHONE_RATES.len())];
        let beta = uniform(&mut rng, (1.5, 3.0));
        let sound = uniform(&mut rng, (0.0, 60f64.ln())).exp();
        let f_start = uniform(&mut rng, (4.0, 30.0));
        let c = (TAU * f_start).powf(beta + 2.0) * sound;
        let lead = uniform(&mut rng, (0.5, 3.0));
        let n_lines = rng.random_range(3..=6);
        let harmonics: Vec<f64> = (0..n_lines)
            .map(|h| uniform(&mut rng, (0.3, 1.0)) / (1.0 + 0.5 * h as f64))
            .collect();
        let phases = (0..n_lines)
            .map(|_| uniform(&mut rng, (0.0, TAU)))
            .collect();
        let mut bumps: Vec<(f64, f64)> = (0..rng.random_range(1..=3))
            .map(|_| {
                let t = uniform(&mut rng, (0.05, lead));
                (t, uniform(&mut rng, (0.2, 1.0)))
            })
            .collect();
        if rng.random::<f64>() < 0.3 {
            let t = lead + uniform(&mut rng, (0.1, 0.9)) * sound;
            bumps.push((t, uniform(&mut rng, (0.1, 0.6))));
        }
        let n_hum = rng.random_range(1..=8);
        let hum_level = if rng.random::<f64>() < 0.2 {
            0.0
        } else {
            uniform(&mut rng, (0.002, 0.03))
        };
        let lines = (0..n_hum)
            .map(|k| hum_level * uniform(&mut rng, (0.3, 1.0)) / (1.0 + 0.3 * k as f64))
            .collect();
        Self {
            sample_rate: rate,
            law: Law { beta, c },
            lead,
            sound,
            tail: uniform(&mut rng, (0.5, 2.0)),
            harmonics,
            phases,
            level_exponent: uniform(&mut rng, (0.0, 1.5)),
            amplitude: uniform(&mut rng, (0.1, 0.5)),
            noise: uniform(&mut rng, (0.0005, 0.005)),
            room: uniform(&mut rng, (0.0, 0.01)),
            bumps,
            rattle: uniform(&mut rng, (0.2, 1.0)),
            shudder: uniform(&mut rng, (0.05, 0.3)),
            reverb: (
                uniform(&mut rng, (0.2, 0.8)),
                uniform(&mut rng, (0.05, 0.3)),
            ),
            stereo: (
                uniform(&mut rng, (0.0, 1.5e-3)),
                uniform(&mut rng, (0.6, 1.0)),
            ),
            high_pass: uniform(&mut rng, (20f64.ln(), 200f64.ln())).exp(),
            hum: PhoneHum {
                mains: if rng.random::<bool>() { 50.0 } else { 60.0 },
                wander: uniform(&mut rng, (0.0, 0.1)),
                lines,
            },
            agc: if rng.random::<bool>() {
                uniform(&mut rng, (0.1, 0.4))
            } else {
                0.0
            },
            dc: uniform(&mut rng, (-0.05, 0.05)),
            clip: uniform(&mut rng, (0.6, 1.0)),
            bits: [16, 24, 32][rng.random_range(0..3)],
            seed,
        }
    }

    /// $t_0$ in record time (s).
    pub fn t0(&self) -> f64 {
        self.lead + self.sound
    }

    /// Samples in the record.
    pub fn samples(&self) -> usize {
        ((self.t0() + self.tail) * f64::from(self.sample_rate)).ceil() as usize
    }

    /// Checks the settings.
    pub fn validate(&self) -> Result<(), ExperimentError> {
        let finite = [
            self.law.beta,
            self.law.c,
            self.lead,
            self.sound,
            self.tail,
            self.amplitude,
            self.high_pass,
        ]
        .iter()
        .all(|x| x.is_finite() && *x > 0.0);
        if !(finite
            && self.harmonics.len() == self.phases.len()
            && !self.harmonics.is_empty()
            && self.stereo.0 >= 0.0
            && self.clip > 0.0
            && (1000..=384_000).contains(&self.sample_rate))
        {
            return Err(ExperimentError::Setting(format!(
                "a phone's recording needs a law, lead-in, sound, tail, amplitude and high-pass \
                 above 0, one phase per harmonic, a clip level above 0 and 1-384 kS/s, got {self:?}"
            )));
        }
        Ok(())
    }

    /// The sound in the room, before the microphones: the disk, its rattle and shudder, the
    /// bumps and the room's noise, then the reverberation.
    fn room_sound(&self, rng: &mut ChaCha8Rng) -> Vec<f64> {
        let rate = f64::from(self.sample_rate);
        let (t0, n) = (self.t0(), self.samples());
        let omega_end = self.law.precession(1e-3);
        let ring = (3000f64).min(0.3 * rate);
        let lp = 1.0 - (-TAU * 300.0 / rate).exp();
        let room_gain = self.room * ((2.0 - lp) / lp).sqrt();
        let mut room = 0.0;
        let mut x = vec![0.0; n];
        for (j, x) in x.iter_mut().enumerate() {
            let t = j as f64 / rate;
            let tau = t0 - t;
            let mut v = 0.0;
            if tau > 0.0 && t >= self.lead {
                let psi = self.law.heading(tau);
                let g = (self.law.precession(tau) / omega_end)
                    .powf(self.level_exponent)
                    .min(1.0)
                    * ((t - self.lead) / 0.2).min(1.0);
                let sum: f64 = self
                    .harmonics
                    .iter()
                    .zip(&self.phases)
                    .enumerate()
                    .map(|(h, (a, ph))| a * ((h + 1) as f64 * psi + ph).sin())
                    .sum();
                v += self.amplitude * g * sum;
                if tau < 0.2 {
                    let r: f64 = StandardNormal.sample(rng);
                    v += 0.3 * self.rattle * self.amplitude * (-tau / 0.03).exp() * r;
                }
            } else if tau <= 0.0 {
                let r: f64 = StandardNormal.sample(rng);
                let decay = (tau / self.shudder).exp();
                v += self.rattle * self.amplitude * decay * (0.5 * r + (TAU * ring * t).sin());
            }
            for &(tb, amp) in &self.bumps {
                let s = t - tb;
                if (0.0..0.3).contains(&s) {
                    v += amp * (-s / 0.03).exp() * (TAU * 40.0 * s).sin();
                }
            }
            let r: f64 = StandardNormal.sample(rng);
            room += lp * (room_gain * r - room);
            *x = v + room;
        }
        reverb(&mut x, self.reverb.0, self.reverb.1, rate);
        x
    }

    /// The hum at sample `j` (the grid's phase integrated through its wander).
    fn hum_at(&self, t: f64) -> f64 {
        let h = &self.hum;
        let period = 12.0;
        // The phase of f_m + w sin(2 pi t / P), integrated.
        let phase =
            TAU * (h.mains * t + h.wander * period / TAU * (1.0 - (TAU * t / period).cos()));
        h.lines
            .iter()
            .enumerate()
            .map(|(k, a)| a * ((k + 1) as f64 * phase + 0.7 * k as f64).sin())
            .sum()
    }

    /// Records the spin: the room's sound through two microphones and the phone.
    pub fn record(&self) -> Result<PhoneRecording, ExperimentError> {
        self.validate()?;
        let rate = f64::from(self.sample_rate);
        let mut rng = ChaCha8Rng::seed_from_u64(self.seed);
        let x = self.room_sound(&mut rng);
        let shift = self.stereo.0 * rate;
        let (whole, frac) = (shift.floor() as usize, shift.fract());
        let delayed = |j: usize| -> f64 {
            let at = |k: usize| if k <= j { x[j - k] } else { 0.0 };
            (1.0 - frac) * at(whole) + frac * at(whole + 1)
        };
        let mut channels = [x.clone(), (0..x.len()).map(delayed).collect::<Vec<_>>()];
        for (c, gain) in channels.iter_mut().zip([1.0, self.stereo.1]) {
            for v in c.iter_mut() {
                let r: f64 = StandardNormal.sample(&mut rng);
                *v = gain * *v + self.noise * r;
            }
            high_pass(c, self.high_pass, rate);
            for (j, v) in c.iter_mut().enumerate() {
                *v += self.hum_at(j as f64 / rate);
            }
            if self.agc > 0.0 {
                agc(c, self.agc, 30.0, (0.001, 0.5), rate);
            }
            for v in c.iter_mut() {
                *v = (*v + self.dc).clamp(-self.clip, self.clip);
            }
        }
        Ok(PhoneRecording {
            sample_rate: self.sample_rate,
            channels,
            truth: Truth {
                beta: self.law.beta,
                t0: self.t0(),
                t_stop: self.t0(),
                tau_rem: 0.0,
                c: Some(self.law.c),
                origin: "eq 79 exactly, recorded by a phone in a room".into(),
            },
            bits: self.bits,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_same_seed_gives_the_same_recording_and_another_seed_another() {
        let a = PhoneRoom::draw(3);
        assert_eq!(a, PhoneRoom::draw(3));
        assert_ne!(a, PhoneRoom::draw(4));
        let mut short = a.clone();
        short.sound = 1.0;
        short.sample_rate = 8000;
        assert_eq!(short.record().unwrap(), short.record().unwrap());
    }

    #[test]
    fn draws_span_the_stated_ranges() {
        let rooms: Vec<PhoneRoom> = (0..200).map(PhoneRoom::draw).collect();
        let span = |f: &dyn Fn(&PhoneRoom) -> f64| {
            let v: Vec<f64> = rooms.iter().map(f).collect();
            (
                v.iter().copied().fold(f64::MAX, f64::min),
                v.iter().copied().fold(f64::MIN, f64::max),
            )
        };
        let (b0, b1) = span(&|r| r.law.beta);
        assert!(
            (1.5..1.6).contains(&b0) && b1 <= 3.0 && b1 > 2.9,
            "beta {b0}-{b1}"
        );
        let (s0, s1) = span(&|r| r.sound);
        assert!(
            (1.0..1.3).contains(&s0) && s1 <= 60.0 && s1 > 40.0,
            "sound {s0}-{s1}"
        );
        for rate in PHONE_RATES {
            assert!(rooms.iter().any(|r| r.sample_rate == rate), "{rate} S/s");
        }
        assert!(rooms.iter().any(|r| r.hum.lines.len() == 8));
        assert!(rooms.iter().any(|r| r.bumps.iter().any(|b| b.0 > r.lead)));
    }

    #[test]
    fn the_second_microphone_hears_the_room_later() {
        let mut room = PhoneRoom::draw(11);
        room.sample_rate = 48_000;
        room.sound = 1.0;
        room.stereo = (1e-3, 1.0);
        room.noise = 0.0;
        room.hum.lines.clear();
        room.agc = 0.0;
        room.clip = 1.0;
        room.dc = 0.0;
        let r = room.record().unwrap();
        let [l, rr] = &r.channels;
        let lag = |k: usize| -> f64 { (0..l.len() - k).map(|j| l[j] * rr[j + k]).sum() };
        let best = (0..100).max_by(|a, b| lag(*a).total_cmp(&lag(*b))).unwrap();
        assert_eq!(best, 48, "the right channel lags by {best} samples");
    }
}
