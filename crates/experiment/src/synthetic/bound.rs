//! The Cramér-Rao bound of a simulated sound: how well its samples can tell $\beta$ and $t_0$
//! at best, computed from the simulator's own settings, independently of any analysis.
//!
//! The disk's sound is $s(t) = A\,g(t)\sum_{h=1}^{H} a_h \sin(h\psi(t) + \phi_h)$ with eq 79's
//! heading $\psi = -C^q\tau^{1-q}/(1-q)$, $q = 1/(\beta+2)$, $\tau = t_0 - t$, and the level
//! $g = \min(1, (\Omega/\Omega_{ref})^\gamma)\,\min(1, (t - t_s)/T_f)$ (heard from $t_s$, faded in
//! over $T_f$). Each harmonic is a narrow line at $h\Omega/2\pi$, so near it the noise is locally
//! white (the Whittle approximation), with the variance per sample
//! $$N_h(t) = S_{room}(f) + r^2(t) + \frac{\sigma^2 + \sigma_q^2/|H_{hp}(f)|^2}{\sum_c G_c^2},
//!   \qquad f = \frac{h\Omega}{2\pi}:$$
//! the room's one-pole (300 Hz) low-passed noise at the line's frequency,
//! $S_{room}(f) = b^2/|1 - \rho e^{-2\pi i f \Delta t}|^2$, and the rim's rattle
//! $r(t) = r_0 e^{-\tau/30\,ms}$ in the last 0.2 s, both heard by every microphone with the disk
//! (the room's sound reaches microphone $c$ at gain $G_c$); each microphone's own white noise
//! $\sigma$; and the noise added after the phone's high-pass $H_{hp}$ (the WAV's quantization,
//! $\sigma_q = \mathrm{LSB}/\sqrt{12}$), which is what the high-pass's attenuation of a line
//! counts against: the high-pass scales the line and every noise before it alike. The
//! microphones combine as one (Sherman-Morrison on the covariance $S\,vv^H + \sigma^2 I$ with
//! $v_c = G_c$): their common noise is not averaged away, their own is, by $\sum_c G_c^2$.
//! The Fisher information of $\theta = (\beta, t_0, \ln C, \phi_1..\phi_H)$ is
//! $$F_{ab} = \sum_j \sum_h \frac{(A g a_h)^2}{2 N_h}\,
//!   \frac{\partial(h\psi + \phi_h)}{\partial\theta_a}\frac{\partial(h\psi + \phi_h)}{\partial\theta_b},
//!   \quad \frac{\partial\psi}{\partial(\beta, t_0, \ln C)} =
//!   \left(-q^2\psi\,\frac{\partial E}{\partial q},\ -\Omega,\ q\psi\right),\
//!   E = q\ln C + (1-q)\ln\tau - \ln(1-q),$$
//! over the samples $t_j$ of the span, lines at or above the Nyquist frequency left out, and
//! the bound is $\sigma_\beta \ge \sqrt{(F^{-1})_{\beta\beta}}$, $\sigma_{t_0} \ge
//! \sqrt{(F^{-1})_{t_0 t_0}}$ for any unbiased estimator.
//!
//! **The span** runs from the first sample at which the disk is heard ($t_s$, the fade-in's start)
//! to the last more than `end_before` before $t_0$: for a phone's recording 1 ms
//! ([`PHASE_FIT_END`]), where the sound analysis's phase fit stops at the latest (its blocks
//! end at least 1 ms before its $t_0$); with `end_before` 0 the span holds all of the disk's sound.
//!
//! **The summand is smooth in $t$** (no oscillation: the phases enter only through their
//! derivatives), so [`SoundInformation::fisher`] sums it on a coarse grid of cells, each weighted by
//! its sample count and evaluated at its samples' mean time, the cells at most 1 % of $\tau$ and
//! 10 ms long and cut where the summand jumps (the fade-in's end, the rattle's start, a line
//! crossing the Nyquist frequency); [`SoundInformation::fisher_per_sample`] is the sum itself.
//!
//! **What is left out, and which way it moves the bound.** Each simplification makes the bound
//! lower (optimistic: no estimator does better than it, and real ones do worse), except the
//! reverberation in one case, stated last:
//! - the amplitudes' parameters ($A$, $a_h$, $\gamma$, the fade), the microphones' gains and
//!   delay, the high-pass's corner and the room's level are taken as known (a known nuisance can
//!   only lower a bound); the amplitudes are orthogonal to the phases for lines many cycles long;
//! - mains hum (lines added after the high-pass), bumps during the spin and clipping are left
//!   out: each adds noise or destroys samples; a DC offset is a known constant;
//! - the AGC multiplies the line and every noise before it alike (their ratio unchanged) by an
//!   unknown gain; against the quantization its gain is taken at its largest, 30;
//! - the second microphone's fractional delay (a linear interpolation, which attenuates the room's
//!   sound slightly) is taken as a gain $G_2$ at all frequencies; float samples as exact;
//! - the reverberation passes the line, the room's noise and the rattle together, so where they
//!   dominate the ratio is unchanged and what the reverberation adds (earlier sound, a
//!   nuisance of unknown $T_{60}$) can only raise the bound; against the microphones' own
//!   noise, a steady line at a comb's peak gains up to $1 + w\,\frac14\sum_k (1-g_k)^{-1}$
//!   (about 2 at the phone set's longest $T_{60}$ and wettest mix), so where the microphones'
//!   noise dominates, the bound may overstate the best $\sigma$ by up to that factor on lines
//!   that sit at such peaks.

use crate::error::ExperimentError;
use crate::synthetic::law::Law;
use crate::synthetic::phone_room::PhoneRoom;
use crate::synthetic::room_filters::high_pass_gain;
use crate::synthetic::sound::Microphone;
use nalgebra::DMatrix;
use serde::{Deserialize, Serialize};
use std::f64::consts::TAU;

/// How long before $t_0$ a phone's span ends (s): where the phase fit's blocks stop at the latest.
pub const PHASE_FIT_END: f64 = 1e-3;
/// The room noise's one-pole low-pass corner (Hz), as both simulators make it.
const ROOM_CORNER: f64 = 300.0;
/// The rattle's decay time (s) and how long before $t_0$ it sounds (s), as both simulators make it.
const RATTLE: (f64, f64) = (0.03, 0.2);
/// A phone recording's fade-in (s), as [`PhoneRoom`] makes it.
const FADE_IN: f64 = 0.2;
/// The largest gain of the phone's AGC, as [`PhoneRoom::record`] sets it.
const AGC_MAX_GAIN: f64 = 30.0;
/// The grid's cells: at most this fraction of $\tau$ and this many seconds long.
const CELL: (f64, f64) = (0.01, 0.01);

/// A recording's lines and noise, as the bound sees them (see the module's documentation).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SoundInformation {
    /// Eq 79's law.
    pub law: Law,
    /// $t_0$ in record time (s).
    pub t0: f64,
    /// Samples per second.
    pub sample_rate: f64,
    /// Samples in the record.
    pub samples: usize,
    /// $t_s$: when the disk is first heard (s).
    pub start: f64,
    /// $T_f$: the fade-in's length (s), 0 for none.
    pub fade_in: f64,
    /// The span ends this long before $t_0$ (s).
    pub end_before: f64,
    /// $A$ (full scale).
    pub amplitude: f64,
    /// $a_h$ of the fundamental and its harmonics.
    pub harmonics: Vec<f64>,
    /// $\gamma$ of the level's rise.
    pub level_exponent: f64,
    /// $\Omega_{ref}$ (rad/s), where the level reaches 1.
    pub level_reference: f64,
    /// The room's low-passed noise (full-scale rms).
    pub room: f64,
    /// $r_0$: the rattle's rms at $t_0$ (full scale).
    pub rattle: f64,
    /// $G_c$: each microphone's gain for the room's sound.
    pub gains: Vec<f64>,
    /// $\sigma$: each microphone's own white noise (full-scale rms).
    pub noise: f64,
    /// The phone's high-pass corner (Hz), if any.
    pub high_pass: Option<f64>,
    /// $\sigma_q$: the white noise added after the high-pass (full-scale rms).
    pub quantization: f64,
}

/// The bound: the smallest standard deviations an unbiased estimator can reach.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct CramerRao {
    /// $\sqrt{(F^{-1})_{\beta\beta}}$.
    pub beta_sigma: f64,
    /// $\sqrt{(F^{-1})_{t_0 t_0}}$ (s).
    pub t0_sigma: f64,
    /// $\sqrt{(F^{-1})_{\ln C \ln C}}$.
    pub ln_c_sigma: f64,
}

/// $\partial\psi/\partial(\beta, t_0, \ln C)$ at $\tau = t_0 - t$ for eq 79's heading
/// $\psi = -e^E$, $E = q\ln C + (1-q)\ln\tau - \ln(1-q)$, $q = 1/(\beta+2)$:
/// $(-q^2\psi\,\partial E/\partial q,\ -\Omega,\ q\psi)$.
fn heading_gradient(law: &Law, tau: f64) -> [f64; 3] {
    let q = 1.0 / (law.beta + 2.0);
    let psi = law.heading(tau);
    let de_dq = law.c.ln() - tau.ln() + 1.0 / (1.0 - q);
    [psi * de_dq * (-q * q), -law.precession(tau), psi * q]
}

/// The first index in `lo..hi` at which `pred`, false and then true, holds (or `hi`).
fn first_where(mut lo: usize, mut hi: usize, pred: impl Fn(usize) -> bool) -> usize {
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if pred(mid) {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    lo
}

impl SoundInformation {
    /// A phone's recording ([`PhoneRoom`]), its span ending [`PHASE_FIT_END`] before $t_0$.
    pub fn of_phone(room: &PhoneRoom) -> Self {
        let lsb = match room.bits {
            16 => 1.0 / 32767.0,
            24 => 1.0 / 8_388_607.0,
            _ => 0.0,
        };
        let agc = if room.agc > 0.0 { AGC_MAX_GAIN } else { 1.0 };
        Self {
            law: room.law,
            t0: room.t0(),
            sample_rate: f64::from(room.sample_rate),
            samples: room.samples(),
            start: room.lead,
            fade_in: FADE_IN,
            end_before: PHASE_FIT_END,
            amplitude: room.amplitude,
            harmonics: room.harmonics.clone(),
            level_exponent: room.level_exponent,
            level_reference: room.law.precession(1e-3),
            room: room.room,
            rattle: 0.3 * room.rattle * room.amplitude,
            gains: vec![1.0, room.stereo.1],
            noise: room.noise,
            high_pass: Some(room.high_pass),
            quantization: lsb / 12f64.sqrt() / agc,
        }
    }

    /// The sound of `law` recorded by `mic` ([`crate::synthetic::sound::law_sound`]; its clicks
    /// left out), the span ending `end_before` before $t_0$.
    pub fn of_microphone(law: &Law, mic: &Microphone, end_before: f64) -> Self {
        let fs = f64::from(mic.sample_rate);
        let heading = |j: usize| {
            let tau = mic.end_at - j as f64 / fs;
            if tau > 0.0 {
                law.heading(tau)
            } else {
                f64::NAN
            }
        };
        // The level's reference, as the simulator takes it: the largest rate by central differences.
        let top = (1..mic.samples.saturating_sub(1))
            .map(|j| (heading(j + 1) - heading(j - 1)) * fs / 2.0)
            .filter(|w| w.is_finite())
            .map(f64::abs)
            .fold(0.0, f64::max);
        let v = &mic.voice;
        Self {
            law: *law,
            t0: mic.end_at,
            sample_rate: fs,
            samples: mic.samples,
            start: v.lead,
            fade_in: 0.0,
            end_before,
            amplitude: mic.amplitude,
            harmonics: v.harmonics.to_vec(),
            level_exponent: v.level_exponent,
            level_reference: top,
            room: v.room,
            rattle: v.rattle * mic.amplitude,
            gains: vec![1.0],
            noise: mic.noise,
            high_pass: None,
            quantization: 0.0,
        }
    }

    /// Checks the settings.
    pub fn validate(&self) -> Result<(), ExperimentError> {
        let positive = [
            self.t0,
            self.sample_rate,
            self.amplitude,
            self.law.c,
            self.level_reference,
        ]
        .iter()
        .all(|x| x.is_finite() && *x > 0.0);
        let non_negative = [
            self.start,
            self.fade_in,
            self.end_before,
            self.level_exponent,
            self.room,
            self.rattle,
            self.noise,
            self.quantization,
        ]
        .iter()
        .chain(&self.harmonics)
        .chain(&self.gains)
        .all(|x| x.is_finite() && *x >= 0.0);
        if !(positive
            && non_negative
            && self.law.beta.is_finite()
            && self.law.beta > -1.0
            && !self.harmonics.is_empty()
            && self.gains.iter().any(|g| *g > 0.0)
            && self.noise + self.room + self.quantization > 0.0
            && self.high_pass.is_none_or(|c| c.is_finite() && c > 0.0))
        {
            return Err(ExperimentError::Setting(format!(
                "a Cramér-Rao bound needs beta > -1, C, t0, the rate, the amplitude and the \
                 level's reference above 0, at least one harmonic and one microphone's gain \
                 above 0, some noise, and every level, gain and time >= 0, got {self:?}"
            )));
        }
        Ok(())
    }

    /// The time of sample `j` (s).
    fn time(&self, j: usize) -> f64 {
        j as f64 / self.sample_rate
    }

    /// The span's samples: the first heard and one past the last before `end_before`.
    fn span(&self) -> (usize, usize) {
        let first = first_where(0, self.samples, |j| self.time(j) >= self.start);
        let end = first_where(first, self.samples, |j| {
            self.t0 - self.time(j) <= self.end_before
        });
        (first, end)
    }

    /// The span's samples and the disk's turns in it.
    pub fn span_samples_and_turns(&self) -> (usize, f64) {
        let (first, end) = self.span();
        if end <= first {
            return (0, 0.0);
        }
        let psi = |j: usize| self.law.heading(self.t0 - self.time(j));
        (end - first, (psi(end - 1) - psi(first)) / TAU)
    }

    /// The room's low-passed noise per sample at `f` Hz: $b^2/|1 - \rho e^{-i\omega}|^2$.
    fn room_density(&self, f: f64) -> f64 {
        let lp = 1.0 - (-TAU * ROOM_CORNER / self.sample_rate).exp();
        let b = lp * self.room * ((2.0 - lp) / lp).sqrt();
        let rho = 1.0 - lp;
        let w = TAU * f / self.sample_rate;
        b * b / (1.0 - 2.0 * rho * w.cos() + rho * rho)
    }

    /// Adds `weight` samples' Fisher information at time `t` to `fisher`.
    fn add_summand(&self, t: f64, weight: f64, fisher: &mut DMatrix<f64>) {
        let law = &self.law;
        let tau = self.t0 - t;
        let omega = law.precession(tau);
        let fade = if self.fade_in > 0.0 {
            ((t - self.start) / self.fade_in).min(1.0)
        } else {
            1.0
        };
        let level = (omega / self.level_reference)
            .powf(self.level_exponent)
            .min(1.0)
            * fade;
        let rattle = if tau < RATTLE.1 {
            (self.rattle * (-tau / RATTLE.0).exp()).powi(2)
        } else {
            0.0
        };
        let gains: f64 = self.gains.iter().map(|g| g * g).sum();
        let d = heading_gradient(law, tau);
        let nyquist = 0.5 * self.sample_rate;
        for (h, a_h) in self.harmonics.iter().enumerate() {
            let order = (h + 1) as f64;
            let f = order * omega / TAU;
            if f >= nyquist {
                continue;
            }
            let hp = self
                .high_pass
                .map_or(1.0, |c| high_pass_gain(c, self.sample_rate, f));
            let own = self.noise.powi(2) + (self.quantization / hp).powi(2);
            let noise = self.room_density(f) + rattle + own / gains;
            let w = weight * (self.amplitude * level * a_h).powi(2) / (2.0 * noise);
            let at = [0, 1, 2, 3 + h];
            let grad = [order * d[0], order * d[1], order * d[2], 1.0];
            for (r, gr) in at.iter().zip(grad) {
                for (c, gc) in at.iter().zip(grad) {
                    fisher[(*r, *c)] += w * gr * gc;
                }
            }
        }
    }

    /// The Fisher information summed sample by sample.
    pub fn fisher_per_sample(&self) -> Result<DMatrix<f64>, ExperimentError> {
        self.validate()?;
        let n = 3 + self.harmonics.len();
        let mut fisher = DMatrix::zeros(n, n);
        let (first, end) = self.span();
        for j in first..end {
            self.add_summand(self.time(j), 1.0, &mut fisher);
        }
        Ok(fisher)
    }

    /// The grid's cells, as sample ranges `[a, b)` (see the module's documentation).
    fn cells(&self) -> Vec<(usize, usize)> {
        let (first, end) = self.span();
        if end <= first {
            return Vec::new();
        }
        let tau = |j: usize| self.t0 - self.time(j);
        let nyquist = 0.5 * self.sample_rate;
        let mut cuts = vec![
            first,
            end,
            first_where(first, end, |j| self.time(j) - self.start >= self.fade_in),
            first_where(first, end, |j| tau(j) < RATTLE.1),
            first_where(first, end, |j| {
                self.law.precession(tau(j)) >= self.level_reference
            }),
        ];
        for h in 1..=self.harmonics.len() {
            let order = h as f64;
            cuts.push(first_where(first, end, |j| {
                order * self.law.precession(tau(j)) / TAU >= nyquist
            }));
        }
        let mut j = first;
        while j < end {
            cuts.push(j);
            let long = (CELL.0 * tau(j)).min(CELL.1) * self.sample_rate;
            j += (long.floor() as usize).max(1);
        }
        cuts.sort_unstable();
        cuts.dedup();
        cuts.windows(2).map(|w| (w[0], w[1])).collect()
    }

    /// The Fisher information summed on the grid of cells, each its sample count times the
    /// summand at its samples' mean time.
    pub fn fisher(&self) -> Result<DMatrix<f64>, ExperimentError> {
        self.validate()?;
        let n = 3 + self.harmonics.len();
        let mut fisher = DMatrix::zeros(n, n);
        for (a, b) in self.cells() {
            let mid = 0.5 * (a + b - 1) as f64 / self.sample_rate;
            self.add_summand(mid, (b - a) as f64, &mut fisher);
        }
        Ok(fisher)
    }

    /// The bound from the grid's Fisher information.
    pub fn bound(&self) -> Result<CramerRao, ExperimentError> {
        cramer_rao(&self.fisher()?)
    }
}

/// The bound from a Fisher information over $(\beta, t_0, \ln C, \phi_1..\phi_H)$: the phases
/// of lines never heard (no information) are left out, and the rest inverted after scaling by
/// its diagonal.
pub fn cramer_rao(fisher: &DMatrix<f64>) -> Result<CramerRao, ExperimentError> {
    let kept: Vec<usize> = (0..fisher.nrows())
        .filter(|&k| fisher[(k, k)] > 0.0 && fisher[(k, k)].is_finite())
        .collect();
    if kept.len() < 4 || kept[..3] != [0, 1, 2] {
        return Err(ExperimentError::Setting(
            "a Cramér-Rao bound needs a line heard below the Nyquist frequency within the span: \
             start the sound earlier or end the span later"
                .into(),
        ));
    }
    let n = kept.len();
    let scale: Vec<f64> = kept.iter().map(|&k| fisher[(k, k)].sqrt()).collect();
    let scaled = DMatrix::from_fn(n, n, |r, c| {
        fisher[(kept[r], kept[c])] / (scale[r] * scale[c])
    });
    let inverse = scaled.cholesky().map(|c| c.inverse()).ok_or_else(|| {
        ExperimentError::Setting(
            "the Fisher information is singular: beta, t0 and C cannot be told apart from this \
             sound; give it more turns"
                .into(),
        )
    })?;
    let sigma = |k: usize| inverse[(k, k)].sqrt() / scale[k];
    Ok(CramerRao {
        beta_sigma: sigma(0),
        t0_sigma: sigma(1),
        ln_c_sigma: sigma(2),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A phone's recording of seed `seed` cut to `sound` seconds of sound.
    fn short(seed: u64, sound: f64) -> PhoneRoom {
        let mut room = PhoneRoom::draw(seed);
        let f_start = room.law.precession(room.sound) / TAU;
        room.sound = sound;
        room.law.c = (TAU * f_start).powf(room.law.beta + 2.0) * sound;
        room
    }

    #[test]
    fn the_heading_gradient_is_the_headings_own_by_differences() {
        let law = Law {
            beta: 2.3,
            c: (TAU * 12.0f64).powf(4.3) * 5.0,
        };
        for tau in [4.0, 0.3, 2e-3] {
            let d = heading_gradient(&law, tau);
            let central = |f: &dyn Fn(f64) -> f64, h: f64| (f(h) - f(-h)) / (2.0 * h);
            let numeric = [
                central(
                    &|h| {
                        Law {
                            beta: law.beta + h,
                            ..law
                        }
                        .heading(tau)
                    },
                    1e-6,
                ),
                central(&|h| law.heading(tau + h), 1e-4 * tau),
                central(
                    &|h| {
                        Law {
                            c: law.c * h.exp(),
                            ..law
                        }
                        .heading(tau)
                    },
                    1e-6,
                ),
            ];
            for (a, n) in d.iter().zip(numeric) {
                assert!(
                    (a / n - 1.0).abs() < 1e-6,
                    "tau {tau}: {d:?} against {numeric:?}"
                );
            }
        }
    }

    #[test]
    fn the_grid_sums_what_the_samples_sum() {
        for (seed, sound) in [(1, 2.0), (5, 1.0), (17, 4.0), (33, 1.5)] {
            let info = SoundInformation::of_phone(&short(seed, sound));
            let grid = cramer_rao(&info.fisher().unwrap()).unwrap();
            let each = cramer_rao(&info.fisher_per_sample().unwrap()).unwrap();
            let rel = |a: f64, b: f64| (a / b - 1.0).abs();
            assert!(
                rel(grid.beta_sigma, each.beta_sigma) < 1e-3
                    && rel(grid.t0_sigma, each.t0_sigma) < 1e-3,
                "seed {seed}: grid {grid:?}, per sample {each:?}"
            );
            assert!(info.cells().len() * 10 < info.span_samples_and_turns().0);
        }
    }

    #[test]
    fn more_noise_or_fewer_turns_raise_the_bound() {
        let room = short(3, 3.0);
        let base = SoundInformation::of_phone(&room).bound().unwrap();
        let noisy = SoundInformation {
            noise: 10.0 * room.noise,
            room: 10.0 * room.room,
            ..SoundInformation::of_phone(&room)
        }
        .bound()
        .unwrap();
        let shorter = SoundInformation::of_phone(&short(3, 1.5)).bound().unwrap();
        assert!(
            noisy.beta_sigma > 5.0 * base.beta_sigma,
            "{noisy:?} {base:?}"
        );
        assert!(shorter.beta_sigma > base.beta_sigma, "{shorter:?} {base:?}");
        // A second microphone with its own noise tells more than one alone.
        let one = SoundInformation {
            gains: vec![1.0],
            ..SoundInformation::of_phone(&room)
        }
        .bound()
        .unwrap();
        assert!(one.beta_sigma > base.beta_sigma, "{one:?} {base:?}");
    }

    #[test]
    fn bad_settings_are_refused_not_panicked_on() {
        let mut info = SoundInformation::of_phone(&short(2, 1.0));
        info.end_before = 10.0;
        assert!(info.bound().is_err());
        info.end_before = f64::NAN;
        assert!(info.bound().is_err());
        let mut info = SoundInformation::of_phone(&short(2, 1.0));
        info.harmonics.clear();
        assert!(info.bound().is_err());
    }
}
