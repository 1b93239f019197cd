//! The experiment part's record in `report.json`: the fits of eq 79's law ($\Omega = C^{1/(\beta+2)}
//! (t_0 - t)^{1/(\beta+2)}$, written as eqs 84 and 85 for the light signal) on the simulated
//! light signal and on the phone's sound, with their stated standard uncertainties, beside the
//! simulated model's truth.

use schemars::JsonSchema;
use serde::Serialize;
use studies::sound::SoundStudy;
use studies::synthetic::Synthetic;

/// A fitted $\beta$ and $t_0$ with their stated standard uncertainties.
#[derive(Debug, Clone, PartialEq, Serialize, JsonSchema)]
pub struct LawFit {
    /// $\beta$, the exponent of eq 75's dissipation.
    pub beta: f64,
    /// Its stated standard uncertainty.
    pub beta_sigma: f64,
    /// $t_0$, where eq 79 says the spin ends (s of record time); `None` where the fit has none
    /// (eq 85).
    pub t0: Option<f64>,
    /// Its stated standard uncertainty (s).
    pub t0_sigma: Option<f64>,
}

/// The sound's result, and which fit it is.
#[derive(Debug, Clone, PartialEq, Serialize, JsonSchema)]
pub struct SoundRecord {
    /// The result.
    pub law: LawFit,
    /// "phase" when eq 79 was fitted to the phase, "pitch" when to the pitch track.
    pub fitted_on: String,
}

/// The truth of the simulated model that made the recordings.
#[derive(Debug, Clone, PartialEq, Serialize, JsonSchema)]
pub struct Truth {
    /// The model's $\beta$.
    pub beta: f64,
    /// Its $t_0$ (s of record time).
    pub t0: f64,
}

/// The experiment, simulated.
#[derive(Debug, Clone, PartialEq, Serialize, JsonSchema)]
pub struct ExperimentRecord {
    /// The cycles of the light signal in the fitting window.
    pub cycles: usize,
    /// Eq 84 on the light signal.
    pub eq84: LawFit,
    /// Eq 85 on the light signal.
    pub eq85: LawFit,
    /// Eq 84 on the model's exact passage times, without the light.
    pub eq84_on_the_motion: Option<LawFit>,
    /// The phone's sound of the same spin-down, when analysed.
    pub sound: Option<SoundRecord>,
    /// The model's truth.
    pub truth: Option<Truth>,
}

/// The record of the light signal's analysis `e` and the sound's `sound`.
pub fn record(e: &Synthetic, sound: Option<&SoundStudy>) -> ExperimentRecord {
    let a = &e.analysis;
    let (beta_sigma, t0_sigma) = a.stated_sigmas();
    ExperimentRecord {
        cycles: a.window.cycles.len(),
        eq84: LawFit {
            beta: a.eq84.beta,
            beta_sigma,
            t0: Some(a.eq84.t0),
            t0_sigma: Some(t0_sigma),
        },
        eq85: LawFit {
            beta: a.eq85.beta,
            beta_sigma: a.eq85.beta_sigma,
            t0: None,
            t0_sigma: None,
        },
        eq84_on_the_motion: e.motion_law.as_ref().map(|l| LawFit {
            beta: l.beta,
            beta_sigma: l.beta_sigma,
            t0: Some(l.t0),
            t0_sigma: Some(l.t0_sigma),
        }),
        sound: sound.map(|s| {
            let law = s.analysis.law();
            SoundRecord {
                law: LawFit {
                    beta: law.beta,
                    beta_sigma: law.beta_sigma,
                    t0: Some(law.t0),
                    t0_sigma: Some(law.t0_sigma),
                },
                fitted_on: if law.from_phase { "phase" } else { "pitch" }.into(),
            }
        }),
        truth: e.trace.truth.as_ref().map(|t| Truth {
            beta: t.beta,
            t0: t.t0,
        }),
    }
}
