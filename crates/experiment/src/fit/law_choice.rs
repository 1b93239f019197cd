//! Which dissipation law do the data support? Eq 84 with $\beta$ free against $\beta$ fixed at
//! the mechanisms around eq 75 ($P \propto \Omega^\beta$ from a drag force $\propto \Omega^{\beta-1}$:
//! 1, a drag independent of speed; 2, rolling friction proportional to the contact point's speed;
//! 3, air drag proportional to its square; 4, Moffatt's viscous air film), and a two-mechanism
//! law, compared by AIC and BIC on the same cycles.
//!
//! The errors' scale is not known (the peak-time variances may understate the scatter), so the
//! Gaussian likelihood is maximised over a common scale factor $s^2$ as well:
//! $$-2\ln\hat L = n\ln\frac{\chi^2_w}{n} + \ln\det\Sigma + n(1 + \ln 2\pi),$$
//! with $\chi^2_w$ the whitened residuals' sum of squares and $\Sigma$ the peak-time covariance
//! of the residuals; $k$ counts the law's parameters plus the scale;
//! $\mathrm{AIC} = -2\ln\hat L + 2k$, $\mathrm{BIC} = -2\ln\hat L + k\ln n$.
//! A difference $\Delta$ from the best of 0-2 is "as good", 2-6 "positive", 6-10 "strong" and
//! above 10 "decisive" evidence against (Kass & Raftery's scale, read for $\Delta\mathrm{BIC}$).
//! The two-mechanism law is called only where its exponents differ as two mechanisms' do,
//! calibrated on records of one mechanism ([`model_choice`](crate::model_choice)).

#[cfg(doc)]
use crate::fit::crossover::fit_crossover;
use crate::fit::crossover::CrossoverFit;
use crate::fit::eq84_85::{fit_eq84_fixed, Eq84Fit};
use crate::fit::law_choice_record::calibration_sentence;
use serde::Serialize;
use std::f64::consts::PI;

/// The name of the two-mechanism candidate in a [`Comparison`].
pub const TWO_MECHANISMS: &str = "two mechanisms";

/// The least change of exponent that two mechanisms make: the closest pair of exponents among
/// the mechanisms the tool knows ([`Mechanism::exponent`]: viscous rolling friction's 2 and the
/// air boundary layer's 5/2).
pub const MIN_EXPONENT_CHANGE: f64 = 0.5;

/// Whether the two-mechanism law's exponents, $\beta_1 \pm \sigma_1$ below $\Omega_c$ and
/// $\beta_2 \pm \sigma_2$ above, differ as two mechanisms' do: by at least
/// [`MIN_EXPONENT_CHANGE`] and by more than three standard uncertainties
/// $\sqrt{\sigma_1^2 + \sigma_2^2}$.
pub fn admits_two(beta_below: (f64, f64), beta_above: (f64, f64)) -> bool {
    let change = (beta_above.0 - beta_below.0).abs();
    change >= MIN_EXPONENT_CHANGE && change > 3.0 * beta_below.1.hypot(beta_above.1)
}

/// One candidate law's fit and its scores.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Candidate {
    /// The law, in words.
    pub name: String,
    /// Its fitted parameters, in words with numbers.
    pub parameters: String,
    /// Parameters counted (the law's plus the common scale).
    pub k: usize,
    /// Whitened $\chi^2$.
    pub chi2: f64,
    /// AIC.
    pub aic: f64,
    /// BIC.
    pub bic: f64,
    /// AIC minus the smallest AIC.
    pub delta_aic: f64,
    /// BIC minus the smallest BIC.
    pub delta_bic: f64,
    /// Akaike weight $e^{-\Delta/2}/\sum e^{-\Delta/2}$.
    pub weight: f64,
}

/// The comparison.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Comparison {
    /// Points compared.
    pub n: usize,
    /// The candidates, best BIC first.
    pub candidates: Vec<Candidate>,
    /// The verdict in words.
    pub summary: String,
    /// True when the two-mechanism law has the least BIC but its exponents differ by less than
    /// two mechanisms' do ([`admits_two`]): read as one law that drifts over the window, and
    /// the best single law chosen.
    pub drift: bool,
}

impl Comparison {
    /// Whether the comparison calls two mechanisms: their law first by BIC and admitted.
    pub fn calls_two(&self) -> bool {
        !self.drift
            && self
                .candidates
                .first()
                .is_some_and(|c| c.name == TWO_MECHANISMS)
    }

    /// The law chosen: the least BIC, or the best single law where the two-mechanism law is
    /// read as drift.
    pub fn chosen(&self) -> Option<&Candidate> {
        self.candidates
            .iter()
            .find(|c| !(self.drift && c.name == TWO_MECHANISMS))
    }
}

/// The words of Kass & Raftery's scale for a BIC difference.
pub fn strength(delta: f64) -> &'static str {
    if delta < 2.0 {
        "not worth more than a mention"
    } else if delta < 6.0 {
        "positive"
    } else if delta < 10.0 {
        "strong"
    } else {
        "decisive"
    }
}

/// Kass & Raftery's verdict on a BIC difference as a phrase: "decisive evidence against it",
/// or, below 2, "evidence against it not worth more than a mention".
fn evidence(delta: f64) -> String {
    match strength(delta) {
        weak if delta < 2.0 => format!("evidence against it {weak}"),
        word => format!("{word} evidence against it"),
    }
}

/// Scores candidates `(name, parameters, law parameters, chi2, ln det Sigma)` fitted to the
/// same `n` points.
pub fn compare(n: usize, fits: Vec<(String, String, usize, f64, f64)>) -> Comparison {
    let nf = n as f64;
    let mut c: Vec<Candidate> = fits
        .into_iter()
        .filter(|f| f.3.is_finite() && f.3 > 0.0)
        .map(|(name, parameters, p, chi2, ln_det)| {
            let k = p + 1;
            let m2ll = nf * (chi2 / nf).ln() + ln_det + nf * (1.0 + (2.0 * PI).ln());
            Candidate {
                name,
                parameters,
                k,
                chi2,
                aic: m2ll + 2.0 * k as f64,
                bic: m2ll + k as f64 * nf.ln(),
                delta_aic: 0.0,
                delta_bic: 0.0,
                weight: 0.0,
            }
        })
        .collect();
    let best_aic = c.iter().map(|x| x.aic).fold(f64::INFINITY, f64::min);
    let best_bic = c.iter().map(|x| x.bic).fold(f64::INFINITY, f64::min);
    for x in c.iter_mut() {
        x.delta_aic = x.aic - best_aic;
        x.delta_bic = x.bic - best_bic;
    }
    let total: f64 = c.iter().map(|x| (-0.5 * x.delta_aic).exp()).sum();
    for x in c.iter_mut() {
        x.weight = (-0.5 * x.delta_aic).exp() / total;
    }
    c.sort_by(|a, b| a.bic.total_cmp(&b.bic));
    let summary = match (c.first(), c.get(1)) {
        (Some(a), Some(b)) => format!(
            "the data support {} ({}); the next, {}, is {:.1} higher in BIC: {}",
            a.name,
            a.parameters,
            b.name,
            b.delta_bic,
            evidence(b.delta_bic)
        ),
        (Some(a), None) => format!("only {} could be fitted", a.name),
        _ => "no law could be fitted".into(),
    };
    Comparison {
        n,
        candidates: c,
        summary,
        drift: false,
    }
}

/// The comparison of the laws above on eq 84's cycles (`ta`, `tb`: the peaks that open and
/// close each cycle, `start` their indices, `w` the peak-time variances), given the free fit
/// and the two-mechanism law's ([`fit_crossover`], when it converged): beta free, beta fixed at
/// 1, 2, 3 and 4, and the two-mechanism law.
pub fn compare_laws(
    ta: &[f64],
    tb: &[f64],
    cyc_idx: &[usize],
    w: &[f64],
    eq84: &Eq84Fit,
    crossover: Option<&CrossoverFit>,
) -> Comparison {
    let mut candidates = vec![(
        "beta free".to_string(),
        format!("beta = {:.3} +- {:.3}", eq84.beta, eq84.beta_sigma),
        3,
        eq84.chi2,
        eq84.ln_det_sigma,
    )];
    for beta in [1.0, 2.0, 3.0, 4.0] {
        if let Ok(f) = fit_eq84_fixed(ta, tb, cyc_idx, w, beta, eq84) {
            candidates.push((
                format!("beta = {beta}"),
                format!("t0 = {:.5} +- {:.5} s", f.t0, f.t0_sigma),
                2,
                f.chi2,
                f.ln_det_sigma,
            ));
        }
    }
    if let Some(x) = crossover {
        candidates.push((
            TWO_MECHANISMS.to_string(),
            format!(
                "beta = {:.2} +- {:.2} below Omega_c = {:.0} +- {:.0} rad/s, {:.2} +- {:.2} \
                 above, t0 = {:.5} +- {:.5} s",
                x.beta_below,
                x.beta_below_sigma,
                x.omega_c,
                x.omega_c_sigma,
                x.beta_above,
                x.beta_above_sigma,
                x.t0,
                x.t0_sigma
            ),
            5,
            x.chi2,
            x.ln_det_sigma,
        ));
    }
    let mut c = compare(cyc_idx.len(), candidates);
    if let Some(x) = crossover {
        judge_two(&mut c, x);
    }
    c
}

/// Where the two-mechanism law has the least BIC: admitted ([`admits_two`]), the summary says
/// so with the calibration's false-alarm rate; not admitted, the comparison is marked as drift
/// and its summary chooses the best single law.
fn judge_two(c: &mut Comparison, x: &CrossoverFit) {
    if c.candidates
        .first()
        .is_none_or(|b| b.name != TWO_MECHANISMS)
    {
        return;
    }
    if admits_two(
        (x.beta_below, x.beta_below_sigma),
        (x.beta_above, x.beta_above_sigma),
    ) {
        c.summary = format!(
            "{} (the exponents differ by {:.2}, at least the {MIN_EXPONENT_CHANGE} between two \
             mechanisms'; {})",
            c.summary,
            (x.beta_above - x.beta_below).abs(),
            calibration_sentence()
        );
        return;
    }
    c.drift = true;
    let two_by = c
        .candidates
        .iter()
        .find(|s| s.name != TWO_MECHANISMS)
        .map_or(f64::NAN, |s| s.delta_bic);
    let single = c.chosen().map_or(String::from("none"), |s| {
        format!("{} ({})", s.name, s.parameters)
    });
    c.summary = format!(
        "one law that drifts over the window, not two mechanisms: the two-mechanism law has \
         the least BIC (by {two_by:.1}), but its exponents, {:.2} +- {:.2} and {:.2} +- {:.2}, \
         differ by less than the {MIN_EXPONENT_CHANGE} between two mechanisms' or than three \
         of their uncertainties, as a single law's drift makes them ({}); the best single law \
         is {single}",
        x.beta_below,
        x.beta_below_sigma,
        x.beta_above,
        x.beta_above_sigma,
        calibration_sentence()
    );
}

#[cfg(test)]
mod tests {
    use super::admits_two;

    /// Two exponents are two mechanisms only when they differ by at least
    /// [`MIN_EXPONENT_CHANGE`](super::MIN_EXPONENT_CHANGE) and by three combined sigmas.
    #[test]
    fn the_exponent_change_must_be_large_and_resolved() {
        assert!(admits_two((1.0, 0.05), (4.0, 0.1)));
        assert!(!admits_two((2.0, 0.001), (1.83, 0.001)));
        assert!(!admits_two((1.0, 0.3), (2.0, 0.3)));
    }
}
