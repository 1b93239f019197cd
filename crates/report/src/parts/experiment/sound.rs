//! The sound of the synthetic experiment in the experiment's section: a paragraph on the phone's
//! recording of the same spin-down and its analysis ([`studies::sound`]), citing its figures
//! (`templates/parts/experiment/sound.txt.tera`).

use crate::error::ReportError;
use crate::number::measured;
use crate::parts::prose::paragraph;
use serde_json::json;
use studies::sound::SoundStudy;

/// The paragraph; `spectrogram` and `residuals` are the figures' numbers, when drawn.
pub fn paragraph_of(
    s: &SoundStudy,
    spectrogram: Option<usize>,
    residuals: Option<usize>,
) -> Result<String, ReportError> {
    let a = &s.analysis;
    let phase = a.phase.as_ref().map(|p| {
        let l = a.law();
        json!({
            "turns": format!("{:.0}", p.turns),
            "blocks": p.n,
            "beta": measured(l.beta, l.beta_sigma),
            "t0": measured(l.t0, l.t0_sigma),
            "chi2": format!("{:.1}", p.chi2_dof),
        })
    });
    let values = json!({
        "phase": phase,
        "refused": a.phase_refused.as_deref().unwrap_or("no reason given"),
        "pitch_beta": measured(a.fit.beta, a.fit.beta_sigma),
        "spectrogram": spectrogram,
        "residuals": residuals,
    });
    paragraph(&super::ABOUT.templates, "sound", &values)
}
