//! Which of a sound's two fits of eq 79 is the result, and the uncertainty it states.
//!
//! A recording gives eq 79, $\Omega = (C/(t_0 - t))^{1/(\beta+2)}$, twice: fitted to the heading
//! the phase follows turn by turn ([`phase_fit`](crate::sound_analysis::phase_fit)) and to the
//! pitch track's frame rates ([`analysis`](crate::sound_analysis::analysis)). The phase's is the
//! more precise and is the result unless it is implausible ([`SoundAnalysis::phase_implausible`]):
//! then the pitch track's is, and the analysis says why, in its text and in its JSON
//! (`result.why_not_phase`).
//!
//! The stated standard uncertainty of the phase's fit is, in quadrature, the sum of
//! ([`Terms`]): the fit's own (the sandwich with the residuals' stationary covariance); the
//! phone's high-pass, whose corner the harmonics' phases measure
//! ([`high_pass`](crate::sound_analysis::high_pass)); the harmonics' disagreement, each fitted
//! alone ([`harmonic_agreement`](crate::sound_analysis::harmonic_agreement)); the law's drift over the record
//! ([`law_stability`](crate::fit::law_stability)); and the two fits' disagreement where it
//! exceeds their noise and the phase's fit is in doubt ([`SoundAnalysis::phase_in_doubt`]).
//!
//! **Residuals with structure: the pitch's fit is the result, unless the law's drift is
//! stated.** Where the phase fit's whitened residuals show structure
//! ([`residual_structure`](crate::sound_analysis::residual_structure): the heading it states does
//! not hold over the record), its sigma, read from residuals taken as the noise of a law that
//! holds, does not bound its error. Where the later half's refit measures eq 79 drifting over the
//! record ([`law_stability`](crate::fit::law_stability)), the shift is stated in its uncertainty
//! and the structure has a measured part in it: the phase's fit stays the result, in doubt (its
//! disagreement with the pitch's counted, below). Where no drift is measured, nothing stated
//! measures what bends the heading (an uncorrected part of a high-pass's lead, reverberation,
//! clipping): the pitch track's fit is reported instead, and the analysis says why. The pitch
//! track's frames are fitted apart from the heading's run of turns, and its sigma is read from
//! residuals that hold the frames' scatter.
//!
//! **Which fit a disagreement speaks against.** Two fits that disagree beyond their noise say
//! that one of them is wrong, not which. The phase's fit is charged with the disagreement only
//! where its own evidence or the lack of any other cause puts it in doubt: its residuals show
//! structure with the law's drift stated (above), or no mains hum was found, so that nothing
//! known biases the pitch track alone. Where hum was found and the residuals are noise, the
//! disagreement is the pitch track's: the hum's lines cross the disk's harmonics as the pitch
//! rises, and the frames the track keeps near them are pulled by an amount their scatter does not
//! show, so the pitch fit's sigma (from its residuals) leaves its bias out, while the phase is
//! fitted only where the disk's harmonics keep clear of the hum
//! ([`HUM_GUARD`](crate::sound_analysis::phase_fit::HUM_GUARD)). Charging that bias to the phase's
//! fit would widen an interval the phase's residuals give no reason to widen (in a quiet room
//! with 2 % hum, beta right to 2e-4 with a sigma of 1.2e-4 would be stated as +- 0.0095).

use crate::fit::law_stability::DRIFT_SIGMAS;
use crate::sound_analysis::analysed::SoundAnalysis;
use crate::sound_analysis::phase_fit::PhaseFit;
use serde::Serialize;

/// The parts of a stated standard uncertainty, each added in quadrature.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct Terms {
    /// The fit's own standard uncertainty.
    pub fit: f64,
    /// What the uncertainty of the high-pass's corner makes of the parameter: where the fit
    /// takes out its lead, half the difference of the fits at the corner $\pm$ its sigma; where
    /// a corner is read but the record does not show it, the largest shift its lead would make
    /// ([`PhaseFit::beta_high_pass`]).
    pub high_pass: f64,
    /// What the harmonics, each fitted alone, disagree by beyond their noise, as it moves the
    /// combined fit ([`PhaseFit::beta_harmonics`]).
    pub harmonics: f64,
    /// The law's drift over the record: the later half's shift where it exceeds
    /// [`DRIFT_SIGMAS`] of the half's own uncertainty, else 0.
    pub law: f64,
    /// The two fits' disagreement $|\hat x_{phase} - \hat x_{pitch}|$ where it exceeds
    /// [`DRIFT_SIGMAS`] times $\sqrt{\sigma_{phase}^2 + \sigma_{pitch}^2}$ and the phase's fit is
    /// in doubt ([`SoundAnalysis::phase_in_doubt`]; the rule and its reason: the module's
    /// documentation), else 0. Both fits
    /// estimate the same parameter from the same sound; their difference has the variance of
    /// the sum at most (the errors of two fits of one record are correlated positively, if at
    /// all), so a difference beyond [`DRIFT_SIGMAS`] of it is a systematic error the noise
    /// does not explain (a nuisance that moves one fit more than the other), and, as for the
    /// law's drift, the shift itself is stated as its size.
    pub disagreement: f64,
}

impl Terms {
    /// The total: the terms in quadrature.
    pub fn total(&self) -> f64 {
        self.fit
            .hypot(self.high_pass)
            .hypot(self.harmonics)
            .hypot(self.law)
            .hypot(self.disagreement)
    }
}

/// Eq 79's parameters as a sound analysis states them.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SoundLaw {
    /// $\beta$ and its total standard uncertainty ([`Terms::total`] of `beta_terms`).
    pub beta: f64,
    /// (see `beta`)
    pub beta_sigma: f64,
    /// $t_0$ (s) and its total standard uncertainty.
    pub t0: f64,
    /// (s)
    pub t0_sigma: f64,
    /// Whether they come from the phase (else from the pitch track).
    pub from_phase: bool,
    /// The parts of `beta_sigma`.
    pub beta_terms: Terms,
    /// The parts of `t0_sigma` (s).
    pub t0_terms: Terms,
}

/// The result as the analysis's JSON states it: the law, the fit it comes from, and why the
/// phase's fit is not the result when it was fitted and is not.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SoundResult {
    /// The law stated.
    pub law: SoundLaw,
    /// `"phase"` or `"pitch"`.
    pub fitted_on: &'static str,
    /// Why the phase's fit is not the result.
    pub why_not_phase: Option<String>,
    /// Where the two fits disagree beyond their noise: whether the disagreement is counted in the
    /// phase's uncertainty, and why.
    pub disagreement: Option<String>,
}

/// The disagreement of estimates `a` and `b` with standard uncertainties `sa` and `sb` where it
/// exceeds [`DRIFT_SIGMAS`] of their noise, else 0.
fn disagreement(a: f64, sa: f64, b: f64, sb: f64) -> f64 {
    let d = (a - b).abs();
    if d > DRIFT_SIGMAS * sa.hypot(sb) {
        d
    } else {
        0.0
    }
}

impl SoundAnalysis {
    /// The result: eq 79 fitted to the phase when it was and is plausible, else to the pitch
    /// track; the phase's uncertainty with its law's drift and the fits' disagreement.
    pub fn law(&self) -> SoundLaw {
        let x = &self.fit;
        match &self.phase {
            Some(p) if self.phase_implausible().is_none() => {
                let law = p.law.as_ref();
                let doubt = if self.phase_in_doubt().is_some() {
                    1.0
                } else {
                    0.0
                };
                let beta_terms = Terms {
                    fit: p.beta_sigma,
                    high_pass: p.beta_high_pass,
                    harmonics: p.beta_harmonics(),
                    law: law.map_or(0.0, |l| l.beta_systematic()),
                    disagreement: doubt * disagreement(p.beta, p.beta_sigma, x.beta, x.beta_sigma),
                };
                let t0_terms = Terms {
                    fit: p.t0_sigma,
                    high_pass: p.t0_high_pass,
                    harmonics: p.t0_harmonics(),
                    law: law.map_or(0.0, |l| l.t0_systematic()),
                    disagreement: doubt * disagreement(p.t0, p.t0_sigma, x.t0, x.t0_sigma),
                };
                SoundLaw {
                    beta: p.beta,
                    beta_sigma: beta_terms.total(),
                    t0: p.t0,
                    t0_sigma: t0_terms.total(),
                    from_phase: true,
                    beta_terms,
                    t0_terms,
                }
            }
            _ => {
                let (beta_terms, t0_terms) = (
                    Terms {
                        fit: x.beta_sigma,
                        ..Terms::default()
                    },
                    Terms {
                        fit: x.t0_sigma,
                        ..Terms::default()
                    },
                );
                SoundLaw {
                    beta: x.beta,
                    beta_sigma: x.beta_sigma,
                    t0: x.t0,
                    t0_sigma: x.t0_sigma,
                    from_phase: false,
                    beta_terms,
                    t0_terms,
                }
            }
        }
    }

    /// The result with the fit it comes from and why the phase's is not it.
    pub fn result(&self) -> SoundResult {
        let law = self.law();
        SoundResult {
            law,
            fitted_on: if law.from_phase { "phase" } else { "pitch" },
            why_not_phase: self.phase_implausible(),
            disagreement: self.disagreement_note(),
        }
    }

    /// Why the phase's fit, plausible, is in doubt by its own evidence or for want of another
    /// cause, when it is: then the two fits' disagreement, where it exceeds their noise, is
    /// counted in its uncertainty (the rule and its reason: the module's documentation).
    pub fn phase_in_doubt(&self) -> Option<String> {
        let p = self.phase.as_ref()?;
        match p.structure {
            Some(s) if s.shown() => Some(format!("its residuals show structure ({s})")),
            _ if self.track.hum.is_empty() => {
                Some("no mains hum was found, so nothing known biases the pitch track alone".into())
            }
            _ => None,
        }
    }

    /// Where the phase's plausible fit and the pitch's disagree beyond their noise: the
    /// disagreement, whether it is counted in the stated uncertainty, and why.
    pub fn disagreement_note(&self) -> Option<String> {
        let p = self.phase.as_ref()?;
        if self.phase_implausible().is_some() {
            return None;
        }
        let x = &self.fit;
        let sigmas = |a: f64, sa: f64, b: f64, sb: f64| (a - b).abs() / sa.hypot(sb);
        let zb = sigmas(p.beta, p.beta_sigma, x.beta, x.beta_sigma);
        let zt = sigmas(p.t0, p.t0_sigma, x.t0, x.t0_sigma);
        if zb <= DRIFT_SIGMAS && zt <= DRIFT_SIGMAS {
            return None;
        }
        let what = format!(
            "the phase's and the pitch's fits disagree by {:.5} in beta ({zb:.1} sigma) and \
             {:.6} s in t0 ({zt:.1} sigma)",
            (p.beta - x.beta).abs(),
            (p.t0 - x.t0).abs()
        );
        Some(match self.phase_in_doubt() {
            Some(why) => format!(
                "{what}; counted where beyond {DRIFT_SIGMAS} sigma in the phase's uncertainty, \
                 which is in doubt: {why}"
            ),
            None => format!(
                "{what}; not counted in the phase's uncertainty: its residuals show no structure \
                 and the pitch track is under mains hum at {}, which pulls it by more than its \
                 scatter shows",
                hum_lines(&self.track.hum)
            ),
        })
    }

    /// Why the phase's fit cannot be the result, if it cannot; then [`law`](Self::law) is the
    /// pitch track's fit. Eq 79's $t_0$ is where the disk stops: a $t_0$ more than three of its
    /// sigmas before the middle of the last tracked frame contradicts a pitch that was heard;
    /// a $\beta$ whose standard uncertainty exceeds it is not determined by the fit; and
    /// residuals that show structure
    /// ([`residual_structure`](crate::sound_analysis::residual_structure)) with no drift of the
    /// law across the record measured ([`law_stability`](crate::fit::law_stability)) say that
    /// the heading the fit states does not hold over the record by an amount nothing in its
    /// stated uncertainty measures, so that its sigma, read from residuals taken as noise, does
    /// not bound its error (the rule and its reason: the module's documentation).
    pub fn phase_implausible(&self) -> Option<String> {
        let p = self.phase.as_ref()?;
        let drift_stated = p.law.as_ref().is_some_and(|l| l.drifts);
        if let Some(s) = p.structure.filter(|s| s.shown() && !drift_stated) {
            return Some(format!(
                "its residuals show structure ({s}) and no drift of the law across the record \
                 is measured: the heading it states does not hold over the record, so its sigma \
                 does not bound its error"
            ));
        }
        let last = self.track.points.last().map(|q| 0.5 * (q.a + q.b))?;
        if p.t0 + 3.0 * p.t0_total() < last {
            return Some(format!(
                "its t0 = {:.4} +- {:.4} s is before the last tracked pitch, at {last:.4} s, \
                 where the disk was still heard turning",
                p.t0,
                p.t0_total()
            ));
        }
        let sigma = p.beta_total();
        if sigma.is_nan() || sigma >= p.beta.abs() {
            return Some(format!(
                "its beta = {:.3} +- {sigma:.3} is not determined: the sigma is at least beta",
                p.beta
            ));
        }
        None
    }
}

/// The mains lines `hum` (Hz) as the text names them.
fn hum_lines(hum: &[f64]) -> String {
    let lines: Vec<String> = hum.iter().map(|h| format!("{h:.2}")).collect();
    format!("{} Hz", lines.join(", "))
}

impl SoundLaw {
    /// The phase's fit `p`'s parameters with the terms of their uncertainties in this law, as the
    /// analysis's text states them.
    pub fn describe_terms(&self, p: &PhaseFit) -> String {
        let law = self;
        let part = |name: &str, v: f64, t: &Terms, unit: &str| {
            let mut s = format!("{name} = {v:.6} +- {:.6}{unit} (fit", t.fit);
            if t.high_pass > 0.0 {
                s.push_str(&format!(", +- {:.6} the high-pass's corner", t.high_pass));
            }
            if t.harmonics > 0.0 {
                s.push_str(&format!(
                    ", +- {:.6} the harmonics' disagreement",
                    t.harmonics
                ));
            }
            if t.law > 0.0 {
                s.push_str(&format!(", +- {:.6} the law's drift", t.law));
            }
            if t.disagreement > 0.0 {
                s.push_str(&format!(
                    ", +- {:.6} the two fits' disagreement",
                    t.disagreement
                ));
            }
            s.push_str(&format!("; total {:.6}{unit})", t.total()));
            s
        };
        let corner = match (p.corner, &p.corner_not_used) {
            (None, _) => "no harmonic above the fundamental to read a high-pass's corner from".to_string(),
            (Some((f, s)), None) => format!("a high-pass's corner read from the harmonics' phases: {f:.1} +- {s:.1} Hz, its lead taken out"),
            (Some((f, s)), Some(why)) if s.is_nan() || s >= f => format!("the harmonics' phases determine no high-pass's corner (its sigma is at least the corner), no lead taken out: {why}"),
            (Some((f, s)), Some(why)) => format!("a high-pass's corner read from the harmonics' phases: {f:.1} +- {s:.1} Hz, its lead not taken out: {why}"),
        };
        format!(
            "{}, {}; {corner}",
            part("beta", p.beta, &law.beta_terms, ""),
            part("t0", p.t0, &law.t0_terms, " s"),
        )
    }
}
