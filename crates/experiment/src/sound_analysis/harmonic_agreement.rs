//! Whether the disk's harmonics, each fitted alone, agree on eq 79's $\beta$ and $t_0$: what a
//! room and a phone do to the lines' phases that neither the noise nor the high-pass's lead
//! explains.
//!
//! Every harmonic follows the same heading: the $h$-th one's phase is $h\psi$ plus a constant,
//! plus what the filters between the disk and the file do to it at $h\Omega$. The high-pass's lead
//! $\varphi(h\Omega)$ is taken out with the corner the splits read
//! ([`high_pass`](crate::sound_analysis::high_pass)); what remains differs from line to line: a
//! room's reverberation adds to each line its echoes, whose phase against the line's own swings
//! with the line's frequency, at places unrelated from one harmonic to the next (the combs'
//! resonances lie at whole multiples of their own rates, not of the disk's), and a corner read
//! wrong leaves a lead that falls differently with $h$. A heading bent this way fits eq 79 with a
//! $\beta$ and $t_0$ off by more than the blocks' noise says, and with residuals that, a few
//! parameters absorbing the bend, need not show it.
//!
//! **Each harmonic fitted alone.** Harmonic $h$'s heading in block $k$ is
//! $$y_{h,k} = d_k + \frac{\mathrm{wrap}\bigl(\arg z_{h,k} - \varphi(h\Omega_k) - h\,d_k -
//!   \kappa_h\bigr)}{h},$$
//! $d_k$ the block's combined heading less the lead taken out of it (the best-determined, so the
//! turn of $\arg z_{h,k}$ is taken near it) and $\kappa_h$ the circular mean of the wrapped
//! difference; it does not depend on the other harmonics' phases. Eq 79 with its offset is fitted
//! to it ([`phase_fit`](crate::sound_analysis::phase_fit)'s fit, its sigma from its own
//! residuals) over the blocks where harmonic $h$ stands [`BlockSettings::min_snr`] above its
//! noise, as the fundamental must for a block to be kept, where they are at least
//! [`BlockSettings::min_blocks`].
//!
//! **Their disagreement.** With $m \ge 2$ harmonics' $\hat\beta_h \pm \sigma_h$, weights $w_h =
//! \sigma_h^{-2}$ and $Q = \sum_h w_h(\hat\beta_h - \bar\beta)^2$ about their weighted mean, the
//! harmonics' own errors $b_h$ (independent from line to line, as above) have the variance
//! (DerSimonian and Laird's moment estimate, 1986)
//! $$\hat\tau^2 = \max\Bigl(0,\ \frac{Q - (m - 1)}{\sum w_h - \sum w_h^2/\sum w_h}\Bigr),$$
//! whose expectation is $\tau^2$ and which is 0 where the harmonics agree within their noise. The
//! combined fit weighs the harmonics by their inverse variances, nearly $\hat w_h = w_h/\sum w$,
//! so the harmonics' own errors move it by $\tau\sqrt{\sum \hat w_h^2}$: that is stated as an
//! uncertainty of the phase's fit, for $\beta$ and likewise for $t_0$.

use crate::sound_analysis::high_pass::lead;
use crate::sound_analysis::phase_blocks::{wrap, Block, BlockSettings, HARMONICS};
use rustfft::num_complex::Complex;
use serde::Serialize;

/// One harmonic's fit of eq 79 alone.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct HarmonicFit {
    /// The harmonic, $h$.
    pub h: usize,
    /// Blocks fitted.
    pub n: usize,
    /// $\hat\beta_h$ and its standard uncertainty.
    pub beta: f64,
    /// (see `beta`)
    pub beta_sigma: f64,
    /// $\hat t_0$ (s) and its standard uncertainty.
    pub t0: f64,
    /// (s)
    pub t0_sigma: f64,
}

/// The harmonics' fits and what their disagreement makes of the combined fit.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HarmonicAgreement {
    /// Each harmonic's fit, where it could be made.
    pub fits: Vec<HarmonicFit>,
    /// $\hat\tau\sqrt{\sum \hat w_h^2}$ of $\beta$ (0 where the harmonics agree within their
    /// noise).
    pub beta: f64,
    /// The same of $t_0$ (s).
    pub t0: f64,
}

/// What the estimates `x` with standard uncertainties `s` disagree by beyond their noise, as it
/// moves their inverse-variance mean: $\hat\tau\sqrt{\sum \hat w_h^2}$ (the module's
/// documentation); 0 with fewer than two.
pub fn beyond_noise(x: &[f64], s: &[f64]) -> f64 {
    let w: Vec<f64> = s.iter().map(|s| s.powi(-2)).collect();
    if x.len() < 2 || w.iter().any(|w| !(w.is_finite() && *w > 0.0)) {
        return 0.0;
    }
    let s1: f64 = w.iter().sum();
    let s2: f64 = w.iter().map(|w| w * w).sum();
    let mean = x.iter().zip(&w).map(|(x, w)| x * w).sum::<f64>() / s1;
    let q: f64 = x.iter().zip(&w).map(|(x, w)| w * (x - mean).powi(2)).sum();
    let tau2 = ((q - (x.len() - 1) as f64) / (s1 - s2 / s1)).max(0.0);
    (tau2 * s2 / (s1 * s1)).sqrt()
}

/// Harmonic `h`'s blocks: copies of those of `bl` (rates `omega`, rad/s) where it stands
/// `settings.min_snr` above its noise, each holding its heading $y_{h,k}$ as the offset, with
/// the high-pass's lead of corner `wc` (rad/s; none at 0) taken out, and its sigma; `lead` is
/// the lead taken out of each block's combined heading.
pub fn harmonic_blocks(
    bl: &[Block],
    omega: &[f64],
    lead_taken: &[f64],
    wc: f64,
    h: usize,
    settings: &BlockSettings,
) -> Vec<Block> {
    let hh = h as f64;
    let max_var = 1.0 / (2.0 * settings.min_snr);
    let used: Vec<(usize, f64, f64)> = (0..bl.len())
        .filter_map(|k| {
            let b = &bl[k];
            let (ph, var) = (b.phase[h - 1], b.phase_var[h - 1]);
            (ph.is_finite() && var > 0.0 && var <= max_var).then(|| {
                let filter = if wc > 0.0 {
                    lead(wc, hh * omega[k]).0
                } else {
                    0.0
                };
                let d = b.offset - lead_taken[k];
                (k, ph - filter - hh * d, var)
            })
        })
        .collect();
    let kappa = used
        .iter()
        .map(|&(_, e, var)| Complex::from_polar(1.0 / var, e))
        .sum::<Complex<f64>>()
        .arg();
    used.iter()
        .map(|&(k, e, var)| {
            let mut b = bl[k];
            b.offset = (b.offset - lead_taken[k]) + wrap(e - kappa) / hh;
            b.sigma = var.sqrt() / hh;
            b
        })
        .collect()
}

/// The harmonics $1..$[`HARMONICS`] fitted alone by `fit` (a block set to $\beta$, $t_0$ and
/// their sigmas, or `None` where it fails) and their disagreement; `None` where fewer than two
/// harmonics hold `settings.min_blocks` blocks.
pub fn agreement(
    bl: &[Block],
    omega: &[f64],
    lead_taken: &[f64],
    wc: f64,
    settings: &BlockSettings,
    fit: &dyn Fn(&[Block]) -> Option<[f64; 4]>,
) -> Option<HarmonicAgreement> {
    let fits: Vec<HarmonicFit> = (1..=HARMONICS)
        .filter_map(|h| {
            let hb = harmonic_blocks(bl, omega, lead_taken, wc, h, settings);
            if hb.len() < settings.min_blocks {
                return None;
            }
            let [beta, beta_sigma, t0, t0_sigma] = fit(&hb)?;
            [beta, beta_sigma, t0, t0_sigma]
                .iter()
                .all(|v| v.is_finite())
                .then_some(HarmonicFit {
                    h,
                    n: hb.len(),
                    beta,
                    beta_sigma,
                    t0,
                    t0_sigma,
                })
        })
        .collect();
    if fits.len() < 2 {
        return None;
    }
    let col = |f: &dyn Fn(&HarmonicFit) -> f64| fits.iter().map(f).collect::<Vec<f64>>();
    let beta = beyond_noise(&col(&|f| f.beta), &col(&|f| f.beta_sigma));
    let t0 = beyond_noise(&col(&|f| f.t0), &col(&|f| f.t0_sigma));
    Some(HarmonicAgreement { fits, beta, t0 })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Estimates that agree within their noise move nothing; estimates whose spread exceeds
    /// their noise give the moment estimate: two of equal sigma $s$ that differ by $D$ give
    /// $\tau^2 = D^2/2 - s^2$ and move their mean by $\tau/\sqrt2$.
    #[test]
    fn disagreement_beyond_the_noise() {
        assert_eq!(beyond_noise(&[1.0, 1.5], &[1.0, 1.0]), 0.0);
        assert_eq!(beyond_noise(&[1.0], &[0.1]), 0.0);
        let (d, s) = (1.0, 0.1);
        let tau2: f64 = d * d / 2.0 - s * s;
        let got = beyond_noise(&[0.0, d], &[s, s]);
        assert!((got - (tau2 / 2.0).sqrt()).abs() < 1e-12, "{got}");
        assert_eq!(beyond_noise(&[0.0, 1.0], &[0.0, 1.0]), 0.0);
    }

    /// A phone's recording (seed 31 of the phone study: 3.4 s of sound at 22 kS/s behind a
    /// 149 Hz high-pass, with 23 % of reverberation) whose heading the room bends: $eta$ is
    /// off by more than the fit's own 95 % interval, the harmonics fitted alone disagree beyond
    /// their noise, and the stated interval with their disagreement holds the truth. The same
    /// room without its reverberation leaves the harmonics closer, and its interval holds too.
    #[test]
    fn reverberation_shows_in_the_harmonics_disagreement() {
        use crate::fit::plausibility::Plausibility;
        use crate::sound_analysis::analysis::analyze_sound;
        use crate::sound_analysis::track::TrackSettings;
        use crate::synthetic::phone_room::PhoneRoom;
        let analysed = |room: &PhoneRoom| {
            let trace = room.record().unwrap().read_back("x.wav").unwrap();
            analyze_sound(&trace, &TrackSettings::default(), &Plausibility::default()).unwrap()
        };
        let room = PhoneRoom::draw(31);
        let a = analysed(&room);
        let l = a.law();
        let err = (l.beta - room.law.beta).abs();
        assert!(l.from_phase, "{a}");
        assert!(err > 1.96 * l.beta_terms.fit, "{err}\n{a}");
        assert!(l.beta_terms.harmonics > l.beta_terms.fit, "{err}\n{a}");
        assert!(err <= 1.96 * l.beta_sigma, "{err}\n{a}");
        let mut dry = room.clone();
        dry.reverb.1 = 0.0;
        let b = analysed(&dry);
        let m = b.law();
        assert!(m.beta_terms.harmonics < l.beta_terms.harmonics, "{b}");
        assert!((m.beta - room.law.beta).abs() <= 1.96 * m.beta_sigma, "{b}");
    }
}
