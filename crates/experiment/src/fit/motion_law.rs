//! What eq 79 says of a simulated spin-down itself, without light, noise or artifacts: the
//! reference that separates the analysis's error from the model's departure from the law.
//!
//! A model's spin-down is not eq 79 exactly (its centre drifts off $b = 0$ as the tilt falls,
//! by eq 23, and its last cycles are not adiabatic), so an analysis that fits eq 84 to it
//! finds a $t_0$ and $\beta$ that differ from the model's own end and exponent even on perfect
//! data. To score the analysis alone, the same fit (eq 84, the same cycles, the same weights) is
//! made to the exact times at which the model's heading passes the direction where the light
//! peaks: whatever remains between the analysis and this fit is the analysis's error (peak
//! timing under noise, drift, hum, clipping, glitches, dropped samples); whatever lies between
//! this fit and the truth is the law's.
//!
//! **The light's peak heading.** The detector reads the most when the face normal
//! $\hat{\mathbf n}(\alpha, \psi)$ sends the lamp's mirror image closest to it; at a tilt
//! $\alpha$ that is one heading $\psi_p(\alpha)$, found here by golden-section search of
//! [`LightModel::intensity`] over $\psi$ (for the default lamp and detector, both in the lab's
//! x-z plane, the pulse is symmetric about $\psi_p = \pi/2$ at every tilt).
//!
//! **Exact passage times.** Near each analysed peak $t_i$ the heading samples are interpolated by
//! the cubic through four samples ([`cubic_root`], the crossing finder of the oscillation
//! checks) and solved for $\psi(t) = \psi_p + 2\pi n$, $n$ the turn
//! nearest to $\psi(t_i)$. At 5 kS/s and $\Omega$ = 700 rad/s the cubic's error is below
//! $10^{-9}$ rad (it is the fourth derivative of $\psi$ times $\Delta t^4$).

use crate::error::ExperimentError;
use crate::fit::eq84_85::{fit_eq84, Eq84Fit};
use crate::light_analysis::analysis::Analysis;
use crate::synthetic::light::LightModel;
use crate::trace::Motion;
use crate::trace::Truth;
use numerics::minimize::golden_min;
use numerics::oscillation::cubic_root;
use std::f64::consts::TAU;

/// Eq 84 fitted, as the analysis fitted it, to the exact passage times of the motion's heading
/// through the light's peak direction, for the peaks of the cycles the analysis used.
pub fn law_of_motion(
    motion: &Motion,
    light: &LightModel,
    analysis: &Analysis,
) -> Result<Eq84Fit, ExperimentError> {
    let cycles = &analysis.window.cycles;
    let exact = |i: usize| -> Result<f64, ExperimentError> {
        passage(motion, light, analysis.peaks[i].t).ok_or_else(|| {
            ExperimentError::Setting(format!(
                "the motion's heading does not pass the light's peak near t = {:.6} s",
                analysis.peaks[i].t
            ))
        })
    };
    let mut ta = Vec::with_capacity(cycles.len());
    let mut tb = Vec::with_capacity(cycles.len());
    for &i in cycles {
        ta.push(exact(i)?);
        tb.push(exact(i + 1)?);
    }
    let w: Vec<f64> = analysis.peaks.iter().map(|p| p.sigma * p.sigma).collect();
    fit_eq84(&ta, &tb, cycles, &w).map_err(|e| ExperimentError::Fit {
        file: "the simulated motion".into(),
        what: "eq 84 on exact passage times".into(),
        message: e.to_string(),
    })
}

/// The error of `analysis` split into the analysis's own (against `law`, from
/// [`law_of_motion`]) and the law's (`law` against the model's `truth`), as lines of text.
pub fn split(analysis: &Analysis, law: &Eq84Fit, truth: &Truth) -> String {
    let a = &analysis.eq84;
    format!(
        "  the error split: eq 84 on the motion's exact passages through the light's peak (same \
         cycles and weights, no light): beta = {:.4}, t0 = {:.6} s, {:+.3} ms from the model's \
         end (the law's part: the model is not eq 79)\n\
         \x20 the analysis against it: beta {:+.4}, t0 {:+.3} ms (the analysis's part; stated t0 \
         uncertainty {:.3} ms)\n",
        law.beta,
        law.t0,
        1e3 * (law.t0 - truth.t0),
        a.beta - law.beta,
        1e3 * (a.t0 - law.t0),
        1e3 * a.t0_sigma,
    )
}

/// The heading at which the light peaks at tilt `alpha` (rad, in $[0, 2\pi)$).
pub fn peak_heading(light: &LightModel, alpha: f64) -> f64 {
    // The coarse scan picks the lobe; golden-section refines inside one step of it.
    let steps = 720;
    let h = TAU / steps as f64;
    let best = (0..steps)
        .map(|k| k as f64 * h)
        .max_by(|a, b| {
            light
                .intensity(alpha, *a)
                .total_cmp(&light.intensity(alpha, *b))
        })
        .unwrap_or(0.0);
    let (psi, _) = golden_min(best - h, best + h, 1e-12, |p| -light.intensity(alpha, p));
    psi.rem_euclid(TAU)
}

/// The time near `t` at which the motion's heading passes the light's peak direction.
fn passage(motion: &Motion, light: &LightModel, t: f64) -> Option<f64> {
    let (ts, psi) = (&motion.t, &motion.heading);
    let dt = ts.get(1)? - ts[0];
    let j = ((t - ts[0]) / dt).floor() as isize;
    if j < 1 || j as usize + 2 >= ts.len() {
        return None;
    }
    let j = j as usize;
    let alpha = motion.alpha[j];
    if !(alpha.is_finite() && psi[j - 1..=j + 2].iter().all(|p| p.is_finite())) {
        return None;
    }
    let p = peak_heading(light, alpha);
    let here = psi[j] + (psi[j + 1] - psi[j]) * ((t - ts[j]) / dt);
    let sign = if psi[j + 1] >= psi[j] { 1.0 } else { -1.0 };
    let target = p + TAU * ((here - p) / TAU).round();
    // Search the samples around t for the interval that brackets the target.
    let lo = j.saturating_sub(20).max(1);
    let hi = (j + 20).min(ts.len() - 3);
    (lo..=hi)
        .filter(|&k| (psi[k] - target) * (psi[k + 1] - target) <= 0.0)
        .map(|k| {
            // The shared crossing finder takes a rising signal: a falling heading is negated.
            let up: Vec<f64> = psi[k - 1..=k + 2].iter().map(|p| sign * p).collect();
            cubic_root(&ts[k - 1..=k + 2], &up, sign * target)
        })
        .min_by(|a, b| (a - t).abs().total_cmp(&(b - t).abs()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn the_default_light_peaks_at_a_quarter_turn_at_every_tilt() {
        let light = LightModel::default();
        for alpha in [0.01, 0.05, 0.12] {
            let p = peak_heading(&light, alpha);
            assert!((p - PI / 2.0).abs() < 1e-6, "{alpha}: {p}");
        }
    }
}
