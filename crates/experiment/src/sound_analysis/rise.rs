//! The rise of a sound's rate that its spin-down is judged on.
//!
//! A spin-down's rate rises without bound toward $t_0$ (eq 79,
//! $\Omega = (C/(t_0 - t))^{1/(\beta+2)}$), and the plausibility checks ask it to rise by at least
//! [`Plausibility::min_rise`](crate::fit::plausibility::Plausibility::min_rise) across the
//! points fitted ([`plausibility`](crate::fit::plausibility)). For the light those are all the
//! cycles the record holds. For a sound the pitch track's frames may end well before $t_0$ (a
//! spin-down's last second holds its fastest rise, in frames that the rising pitch smears, a bump
//! or the rim's rattle covers), while the phase is followed turn by turn from the track's first
//! frame to a few of $t_0$'s sigmas before it ([`phase_fit`](crate::sound_analysis::phase_fit)):
//! each of its blocks holds the disk's base harmonic (the fundamental, or behind a phone's
//! high-pass the line heard in most blocks) at least `min_snr` times above its noise at the
//! heading eq 79 states there, a line the blocks would not find where the pitch did not follow
//! the law. So where the track's frames alone rise too little and every other check passed, the
//! rise is judged again over the phase's blocks,
//! $$\frac{\Omega(\bar t_{last})}{\Omega(\bar t_{first})}, \qquad \Omega = \dot\psi \text{ of the phase's fit},$$
//! when the phase's fit is the result ([`SoundAnalysis::phase_implausible`]) and its turns agree
//! with the track's ([`turn_count`](crate::sound_analysis::turn_count)); otherwise the refusal
//! stands.

use crate::error::ExperimentError;
use crate::fit::eq84_85::phase;
use crate::fit::plausibility::Plausibility;
use crate::sound_analysis::analysed::SoundAnalysis;
use crate::sound_analysis::refusal::SoundRefusal;
use nalgebra::SVector;

impl SoundAnalysis {
    /// The rate's rise over the phase's blocks, the last block's centroid over the first's, by
    /// the phase's fit, when the phase's fit is the result; else `None`.
    pub fn phase_rise(&self) -> Option<f64> {
        let p = self.phase.as_ref()?;
        if self.phase_implausible().is_some() {
            return None;
        }
        let law = SVector::<f64, 3>::new(p.beta, p.t0, p.ln_c);
        let rate = |t: f64| phase(&law, t).1;
        let (first, last) = (p.points.first()?, p.points.last()?);
        let rise = rate(last.t) / rate(first.t);
        rise.is_finite().then_some(rise)
    }
}

impl SoundAnalysis {
    /// The analysis, or its refusal, once its spin-down is judged: where the track's frames
    /// passed every check but the rise (`rise_alone`), on the phase's rise, else as it stands.
    /// `file` and `heard` ([`what_was_heard`](crate::sound_analysis::refusal::what_was_heard))
    /// word the refusal.
    pub fn judged_on_phase(
        mut self,
        rise_alone: bool,
        checks: &Plausibility,
        file: String,
        heard: &str,
    ) -> Result<Self, Box<SoundRefusal>> {
        if !rise_alone {
            return Ok(self);
        }
        match self.phase_rise().filter(|r| *r >= checks.min_rise) {
            Some(r) => {
                self.rise_on_phase = Some(r);
                Ok(self)
            }
            None => Err(Box::new(SoundRefusal {
                error: ExperimentError::Refused {
                    file,
                    reason: format!(
                        "{}; {}; {heard}",
                        self.verdict.refusals.join("; "),
                        self.phase_rise_refused()
                    ),
                },
                track: Some(self.track),
            })),
        }
    }

    /// Why the phase did not show the rise the track's frames lack, for the refusal: the
    /// phase's own refusal, why its fit is not the result, or the rise its blocks hold.
    pub fn phase_rise_refused(&self) -> String {
        match (&self.phase, &self.phase_refused) {
            (None, Some(why)) => format!("nor is the rise heard in the phase: {why}"),
            (None, None) => "nor is the rise heard in the phase: it was not followed".into(),
            (Some(p), _) => match (self.phase_implausible(), self.phase_rise()) {
                (Some(why), _) => {
                    format!("nor is the rise heard in the phase: its fit is not the result, {why}")
                }
                (None, r) => format!(
                    "nor is the rise heard in the phase: its blocks, from {:.2} s to {:.2} s, \
                     rise by a factor {:.2}",
                    p.points.first().map_or(f64::NAN, |b| b.a),
                    p.points.last().map_or(f64::NAN, |b| b.b),
                    r.unwrap_or(f64::NAN)
                ),
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::fit::plausibility::Plausibility;
    use crate::sound_analysis::analysis::{analyze_sound, SoundAnalysis};
    use crate::sound_analysis::track::TrackSettings;
    use crate::synthetic::phone_room::PhoneRoom;

    /// The phone room of `seed` (the realistic set's, `studies::phone_coverage`) analysed as
    /// `experiment analyze` does, with its truth ($\beta$, $t_0$).
    fn room(seed: u64) -> (Result<SoundAnalysis, String>, f64, f64) {
        let room = PhoneRoom::draw(seed);
        let trace = room.record().unwrap().read_back("phone.wav").unwrap();
        let a = analyze_sound(&trace, &TrackSettings::default(), &Plausibility::default())
            .map_err(|e| e.to_string());
        (a, room.law.beta, room.t0())
    }

    /// Seed 26 (3.1 s of sound): the track's frames rise by a factor under 1.5, every other
    /// check passes, and the phase's blocks, followed past the track's last frame, rise by
    /// more: it is analysed from the phase, says so, and its 95 % intervals hold the truth.
    #[test]
    fn a_rise_the_track_misses_is_judged_on_the_phase() {
        let (a, beta, t0) = room(26);
        let a = a.unwrap();
        let checks = Plausibility::default();
        assert!(a.verdict.rise < checks.min_rise, "{a}");
        let r = a.rise_on_phase.expect("judged on the phase");
        assert!(r >= checks.min_rise && Some(r) == a.phase_rise(), "{a}");
        let l = a.law();
        assert!(l.from_phase, "{a}");
        assert!((l.beta - beta).abs() <= 1.96 * l.beta_sigma, "{a}");
        assert!((l.t0 - t0).abs() <= 1.96 * l.t0_sigma, "{a}");
        assert!(
            a.to_string().contains("over the phase's blocks, on which"),
            "{a}"
        );
    }

    /// Seed 151 (a high-pass at 191 Hz, its fundamental at 8-12 Hz): the track's frames rise by
    /// 1.44 and no phase block holds the fundamental above its noise, so the refusal stands and
    /// says why the phase did not show the rise.
    #[test]
    fn a_rise_neither_the_track_nor_the_phase_shows_is_refused_saying_why() {
        let e = room(151).0.expect_err("refused");
        assert!(e.contains("the rate does not rise enough"), "{e}");
        assert!(
            e.contains("nor is the rise heard in the phase: the phase could not be fitted"),
            "{e}"
        );
    }
}
