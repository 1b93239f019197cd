//! The sound of the synthetic experiment in the experiment's section: a paragraph on the phone's
//! recording of the same spin-down and its analysis ([`studies::sound`]), citing its figures.

use crate::number::measured;
use studies::sound::SoundStudy;

/// The paragraph; `spectrogram` and `residuals` are the figures' numbers, when drawn.
pub fn paragraph(s: &SoundStudy, spectrogram: Option<usize>, residuals: Option<usize>) -> String {
    let a = &s.analysis;
    let cite =
        |n: Option<usize>, what: &str| n.map_or(String::new(), |n| format!(" Figure {n} {what}."));
    let found = match &a.phase {
        Some(p) => {
            let l = a.law();
            format!(
                "eq 79 integrated to the heading and fitted to the sound's phase over {:.0} turns \
                 in {} blocks of whole turns gives β = {} and t₀ = {} s (total uncertainties: the \
                 fit's and, where the later half of the blocks moves them, the law's drift; \
                 reduced chi-squared {:.1})",
                p.turns,
                p.n,
                measured(l.beta, l.beta_sigma),
                measured(l.t0, l.t0_sigma),
                p.chi2_dof
            )
        }
        None => format!(
            "the phase was not fitted ({}); the pitch track alone gives β = {}",
            a.phase_refused.as_deref().unwrap_or("no reason given"),
            measured(a.fit.beta, a.fit.beta_sigma)
        ),
    };
    format!(
        "The same spin-down as a phone beside the disk records it (48 kS/s; harmonics of the \
         contact point's rate Ω/2π, the level rising to the end, a rattle, clicks, room noise and \
         2 % of 50 Hz hum): {found}.{}{}",
        cite(
            spectrogram,
            "draws its spectrogram with the fitted pitch and its harmonics"
        ),
        cite(residuals, "draws the residuals of the phase's fit")
    )
}
