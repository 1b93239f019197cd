//! A phone's high-pass, read from the phases of the disk's harmonics, and the lead it puts on
//! the heading the blocks hold ([`phase_blocks`](crate::sound_analysis::phase_blocks)).
//!
//! A phone filters its microphone with a high-pass of a corner $\omega_c$ of tens to hundreds
//! of hertz. Its phase $\varphi(\omega)$ leads the sound at $\omega$, and falls toward 0 as the
//! pitch rises: its group delay $-d\varphi/d\omega$ makes the pitch heard late, so a heading
//! fitted without it puts $t_0$ late (by milliseconds at a corner of 100 Hz) and moves $\beta$.
//! Fitted as a fifth parameter beside eq 79's, the lead is nearly a combination of the law's
//! own derivatives over a record's span (far above the corner it is $\propto 1/\Omega \propto
//! (t_0 - t)^{1/(\beta+2)}$) and the law's uncertainties grow many-fold.
//!
//! **The harmonics measure it apart from the law.** The heading moves harmonic $h$'s phase by $h$
//! times the fundamental's; the filter moves it by $\varphi(h\Omega)$. So each block's
//! $\mathrm{split}_h = \arg z_h - c_h - h u_b$, against the offset $u_b$ read from the base
//! harmonic $b$ ([`Block::base`], the fundamental unless it is heard in too few blocks),
//! does not depend on the heading at all and holds
//! $$g_h(\Omega) + \kappa_h, \qquad g_h = \varphi(h\Omega) - \frac{h}{b}\,\varphi(b\Omega),$$
//! a constant $\kappa_h$ (what $c_h$ left) aside, **to a whole turn**: the splits are phases,
//! wrapped to $(-\pi, \pi]$, and where the fundamental lies below the corner $g_h$ runs over more
//! than a turn across the record (at a tenth of the corner $g_3 \approx -2\pi$). $\omega_c$ is
//! fitted to the splits alone (one parameter, the rates $\Omega_k$ from the reference law), each
//! residual the wrapped difference $\mathrm{wrap}(\mathrm{split}_h - g_h - \kappa_h)$ and
//! $\kappa_h$ the splits' circular mean about $g_h$ at that corner ([`Splits::constant`]); the
//! blocks' headings are corrected by the lead their data hold,
//! $$\frac{\varphi(b\Omega)}{b} + \sum_{h \ne b} W_h\,\frac{g_h(\Omega) + \kappa_h}{h},$$
//! each harmonic's term taken to the turn of the block's own split, and $\omega_c$'s uncertainty
//! is carried into $\beta$'s and $t_0$'s by refitting at $\omega_c \pm \sigma_{\omega_c}$.
//!
//! **Taken out only where the record shows a high-pass.** A recording without one has
//! $\omega_c = 0$; the fit, held to positive corners, still finds one in the splits' noise and in
//! what other filters (a room's reverb, the disk's own harmonics) do to them, and far below a
//! corner the lead nears $\pi$: a large, wrong correction at low pitch. So the lead is taken out
//! only where the corner stands [`CORNER_SIGMAS`] of its own uncertainty above zero and its fit
//! beats no high-pass at all ($\omega_c = 0$, no lead) by as many sigmas of the splits' own
//! scatter ([`Corner::why_not_used`]), and where taking it out keeps the turns counted: a high-pass's lead
//! lies between 0 and $\pi$ at every pitch, so it moves the heading's run from the first block to
//! the last by less than half a turn, and a corrected fit whose count differs from the
//! uncorrected one's by [`MAX_TURN_CHANGE`] or more has slipped a turn
//! ([`phase_fit`](crate::sound_analysis::phase_fit)). Otherwise the heading is fitted as heard and
//! the reason is stated; where a corner was read but is not shown, what its lead would move the
//! fit by is stated as an uncertainty ([`phase_fit`](crate::sound_analysis::phase_fit)): the
//! record tells such a high-pass from none no better than it tells it from zero.
//!
//! **The filter's form** is a second-order Butterworth high-pass's,
//! $$\varphi(\omega) = \operatorname{atan2}\bigl(\sqrt2\,\omega\,\omega_c,\ \omega^2 - \omega_c^2\bigr),$$
//! the biquad of a phone's audio path; far above its corner any high-pass's lead is
//! $\propto 1/\omega$, where a first-order's at $\sqrt2\,\omega_c$ is the same.

use crate::fit::band::Row;
use crate::fit::eq84_85::phase;
use crate::fit::least_squares::{solve, Problem, Scale};
use crate::sound_analysis::phase_blocks::{wrap, Block, HARMONICS};
use nalgebra::SVector;
use std::f64::consts::{SQRT_2, TAU};

/// The lead (rad) of a second-order Butterworth high-pass of corner `wc` at `w` (both rad/s),
/// and its derivative by `wc`.
pub fn lead(wc: f64, w: f64) -> (f64, f64) {
    let (u, v) = (SQRT_2 * w * wc, w * w - wc * wc);
    let d = (u * u + v * v).max(f64::MIN_POSITIVE);
    (u.atan2(v), (v * SQRT_2 * w + u * 2.0 * wc) / d)
}

/// $g_h(\Omega) = \varphi(h\Omega) - (h/b)\,\varphi(b\Omega)$ for the base harmonic `base` $= b$
/// and its derivative by $\omega_c$.
fn g(h: usize, base: usize, wc: f64, w: f64) -> (f64, f64) {
    let (hh, bb) = (h as f64, base as f64);
    let (a, da) = lead(wc, hh * w);
    let (b, db) = lead(wc, bb * w);
    let r = hh / bb;
    (a - r * b, da - r * db)
}

/// The splits of blocks `bl` with rates `omega` (rad/s): data (block, harmonic) pairs.
struct Splits<'a> {
    bl: &'a [Block],
    omega: &'a [f64],
    /// (block, harmonic h) of each datum.
    at: Vec<(usize, usize)>,
    y: Vec<f64>,
    /// The last corner's constants of each harmonic ([`Splits::constant`]), kept: every datum
    /// of one evaluation asks for them at the same corner.
    constants: std::cell::RefCell<Option<(f64, Constants)>>,
}

/// Each harmonic's constant phase and its derivative by the corner ([`Splits::constant`]), by
/// harmonic.
type Constants = [(f64, f64); HARMONICS];

impl<'a> Splits<'a> {
    fn new(bl: &'a [Block], omega: &'a [f64]) -> (Self, Vec<f64>) {
        let (mut at, mut y, mut var) = (Vec::new(), Vec::new(), Vec::new());
        for h in 1..=HARMONICS {
            for (k, b) in bl.iter().enumerate() {
                if h != b.base && b.split[h - 1].is_finite() && b.split_var[h - 1] > 0.0 {
                    at.push((k, h));
                    y.push(b.split[h - 1]);
                    var.push(b.split_var[h - 1]);
                }
            }
        }
        let constants = std::cell::RefCell::new(None);
        (
            Self {
                bl,
                omega,
                at,
                y,
                constants,
            },
            var,
        )
    }

    /// [`Splits::constant`] of harmonic `h` at corner `wc`, from the kept constants when they
    /// are `wc`'s (the same numbers, computed once per corner).
    fn constant_at(&self, h: usize, wc: f64) -> (f64, f64) {
        let mut kept = self.constants.borrow_mut();
        match *kept {
            Some((c, m)) if c.to_bits() == wc.to_bits() => m[h - 1],
            _ => {
                let mut m = [(f64::NAN, f64::NAN); HARMONICS];
                for (j, mj) in m.iter_mut().enumerate() {
                    *mj = self.constant(j + 1, wc);
                }
                *kept = Some((wc, m));
                m[h - 1]
            }
        }
    }

    /// Harmonic `h`'s constant $\kappa_h$ at corner `wc` and its derivative by `wc`: the
    /// circular mean of $\mathrm{split}_h - g_h$ over the blocks holding `h`, weighted by
    /// their inverse variances $w_k$,
    /// $$\kappa_h = \arg \sum_k w_k\, e^{i(\mathrm{split}_{h,k} - g_h(\Omega_k))}, \qquad
    ///   \frac{d\kappa_h}{d\omega_c} = -\frac{\sum_k w_k \cos r_k\, \partial_{\omega_c} g_h(\Omega_k)}
    ///   {\sum_k w_k \cos r_k},$$
    /// $r_k = \mathrm{split}_{h,k} - g_h(\Omega_k) - \kappa_h$.
    fn constant(&self, h: usize, wc: f64) -> (f64, f64) {
        let held = |k: usize| {
            let b = &self.bl[k];
            (b.split[h - 1].is_finite() && b.split_var[h - 1] > 0.0)
                .then(|| (b.split[h - 1], 1.0 / b.split_var[h - 1]))
        };
        let (mut sin, mut cos) = (0.0, 0.0);
        for k in 0..self.bl.len() {
            if let Some((y, w)) = held(k) {
                let (sk, ck) = (y - g(h, self.bl[k].base, wc, self.omega[k]).0).sin_cos();
                sin += w * sk;
                cos += w * ck;
            }
        }
        let kappa = sin.atan2(cos);
        let (mut num, mut den) = (0.0, 0.0);
        for k in 0..self.bl.len() {
            if let Some((y, w)) = held(k) {
                let (gv, dg) = g(h, self.bl[k].base, wc, self.omega[k]);
                let c = (y - gv - kappa).cos();
                num += w * c * dg;
                den += w * c;
            }
        }
        (kappa, -num / den)
    }

    /// The model of datum `y` of harmonic `h` against the base harmonic `base` at rate `w` and
    /// corner `wc`, $g_h + \kappa_h$ taken to the turn nearest `y` (the splits are phases, known
    /// to a whole turn), and its derivative by `wc`.
    fn near(&self, y: f64, h: usize, base: usize, wc: f64, w: f64) -> (f64, f64) {
        let (gv, dg) = g(h, base, wc, w);
        let (kappa, dk) = self.constant_at(h, wc);
        (y - wrap(y - gv - kappa), dg + dk)
    }
}

impl Problem<1> for Splits<'_> {
    fn y(&self) -> &[f64] {
        &self.y
    }
    fn model(&self, p: &SVector<f64, 1>, i: usize) -> (f64, SVector<f64, 1>) {
        let (k, h) = self.at[i];
        let (m, dm) = self.near(self.y[i], h, self.bl[k].base, p[0], self.omega[k]);
        (m, SVector::<f64, 1>::new(dm))
    }
    fn rows(&self, _p: &SVector<f64, 1>) -> Vec<Row> {
        (0..self.y.len())
            .map(|i| Row {
                start: i,
                coef: vec![1.0],
            })
            .collect()
    }
    fn admissible(&self, p: &SVector<f64, 1>) -> bool {
        p[0].is_finite() && p[0] > 0.0
    }
}

/// The high-pass's corner read from the splits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Corner {
    /// $\omega_c$ (rad/s) and its standard uncertainty.
    pub omega_c: f64,
    /// (rad/s)
    pub sigma: f64,
    /// How far the corner's fit beats no high-pass at all, in sigmas:
    /// $\sqrt{(\chi^2(0) - \chi^2(\hat\omega_c)) / (\chi^2(\hat\omega_c)/(n-1))}$, the splits'
    /// $\chi^2$ scaled by its own residuals.
    pub shown: f64,
}

/// How many of its own standard uncertainties a corner must stand above zero for its lead to be
/// taken out.
pub const CORNER_SIGMAS: f64 = 3.0;

/// The change in the turns counted (turns) at and above which the lead is not taken out: half a
/// turn, more than a high-pass's lead (between 0 and $\pi$) can move the heading's run.
pub const MAX_TURN_CHANGE: f64 = 0.5;

impl Corner {
    /// Why the record does not show this corner (`None` when it stands [`CORNER_SIGMAS`] of its
    /// uncertainty above zero).
    pub fn why_not_used(&self) -> Option<String> {
        if self.omega_c <= CORNER_SIGMAS * self.sigma {
            Some(format!(
                "it is within {CORNER_SIGMAS} of its sigmas of zero, so the record shows no high-pass"
            ))
        } else if self.shown.is_nan() || self.shown <= CORNER_SIGMAS {
            Some(format!(
                "it fits the harmonics' phases better than no high-pass by {:.1} sigmas, not \
                 {CORNER_SIGMAS}, so the record shows none",
                self.shown
            ))
        } else {
            None
        }
    }
}

/// The rates (rad/s) of the law `p` at the blocks' centroids.
pub fn rates(bl: &[Block], p: &SVector<f64, 3>) -> Vec<f64> {
    bl.iter().map(|b| phase(p, b.t).1).collect()
}

/// Fits the corner to the splits of blocks `bl` at rates `omega`: started from the best of
/// corners 2-2000 Hz on a logarithmic grid; `None` where no block holds a harmonic besides the
/// base, or the fit fails.
pub fn fit_corner(bl: &[Block], omega: &[f64]) -> Option<Corner> {
    let (sp, var) = Splits::new(bl, omega);
    if sp.y.len() < 4 {
        return None;
    }
    let chi2 = |wc: f64| -> f64 {
        (0..sp.y.len())
            .map(|i| (sp.y[i] - sp.model(&SVector::<f64, 1>::new(wc), i).0).powi(2) / var[i])
            .sum()
    };
    let start = (0..=60)
        .map(|j| TAU * 2.0 * 1000f64.powf(j as f64 / 60.0))
        .min_by(|a, b| chi2(*a).total_cmp(&chi2(*b)))?;
    let s = solve(&sp, &var, SVector::<f64, 1>::new(start), Scale::Stationary).ok()?;
    let sigma = s.cov[(0, 0)].sqrt();
    let best = chi2(s.p[0]);
    let shown = ((chi2(0.0) - best).max(0.0) / (best / (sp.y.len() - 1) as f64)).sqrt();
    (s.p[0].is_finite() && sigma.is_finite()).then_some(Corner {
        omega_c: s.p[0],
        sigma,
        shown,
    })
}

/// The lead (rad) each block's datum holds for a corner `wc` (rad/s), at rates `omega`: the
/// base harmonic's $\varphi(b\Omega)/b$ and each other harmonic's split model
/// ([`Splits::near`]) by its weight in the datum.
pub fn block_leads(bl: &[Block], omega: &[f64], wc: f64) -> Vec<f64> {
    let (sp, _) = Splits::new(bl, omega);
    bl.iter()
        .zip(omega)
        .map(|(b, &w)| {
            let base = b.base as f64;
            let mut l = lead(wc, base * w).0 / base;
            for h in (1..=HARMONICS).filter(|&h| h != b.base) {
                let y = b.split[h - 1];
                if b.weight[h - 1] > 0.0 && y.is_finite() {
                    let m = sp.near(y, h, b.base, wc, w).0;
                    if m.is_finite() {
                        l += b.weight[h - 1] * m / h as f64;
                    }
                }
            }
            l
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A phone's sound of eq 79 exactly ($\beta = 2$, 16 kS/s, its fundamental 16-80 Hz)
    /// through a second-order Butterworth high-pass at 120 Hz: the harmonics read the corner
    /// within three of its sigmas, the phase's fit is the result, and its 95 % intervals hold
    /// the true $\beta$ and $t_0$; the pitch track's $t_0$, which the high-pass's group delay
    /// makes late, is further from the truth.
    #[test]
    fn a_known_high_pass_is_read_and_the_intervals_hold_the_truth() {
        use crate::fit::plausibility::Plausibility;
        use crate::sound_analysis::analysis::analyze_sound;
        use crate::sound_analysis::track::TrackSettings;
        use crate::synthetic::artifacts::Artifacts;
        use crate::synthetic::law::Law;
        use crate::synthetic::room_filters::high_pass;
        use crate::synthetic::sound::{law_sound, Microphone};
        let law = Law {
            beta: 2.0,
            c: 100f64.powi(4) * 7.0,
        };
        let mut s = law_sound(&law, &Microphone::phone(16_000, 3), &Artifacts::none()).unwrap();
        high_pass(&mut s.v, 120.0, 16_000.0);
        let a = analyze_sound(&s, &TrackSettings::default(), &Plausibility::default()).unwrap();
        let truth = s.truth.clone().unwrap();
        let (f, sf) = a.phase.as_ref().and_then(|p| p.corner).unwrap();
        assert!((f - 120.0).abs() < 3.0 * sf, "corner {f} +- {sf}\n{a}");
        let l = a.law();
        assert!(l.from_phase, "{a}");
        assert!((l.beta - 2.0).abs() <= 1.96 * l.beta_sigma, "{a}");
        assert!((l.t0 - truth.t0).abs() <= 1.96 * l.t0_sigma, "{a}");
        assert!((a.fit.t0 - truth.t0).abs() > (l.t0 - truth.t0).abs(), "{a}");
    }

    /// The same sound without a high-pass: whatever corner the splits give, its lead is not
    /// taken out (the record shows none); what it would shift is stated as the corner's
    /// uncertainty only where a corner was read, and the phase's fit holds the truth.
    #[test]
    fn without_a_high_pass_no_lead_is_taken_out() {
        use crate::fit::plausibility::Plausibility;
        use crate::sound_analysis::analysis::analyze_sound;
        use crate::sound_analysis::track::TrackSettings;
        use crate::synthetic::artifacts::Artifacts;
        use crate::synthetic::law::Law;
        use crate::synthetic::sound::{law_sound, Microphone};
        let law = Law {
            beta: 2.0,
            c: 100f64.powi(4) * 7.0,
        };
        let s = law_sound(&law, &Microphone::phone(16_000, 3), &Artifacts::none()).unwrap();
        let a = analyze_sound(&s, &TrackSettings::default(), &Plausibility::default()).unwrap();
        let truth = s.truth.clone().unwrap();
        let p = a.phase.as_ref().unwrap();
        assert!(
            p.corner.is_none() || p.corner_not_used.is_some(),
            "{:?}\n{a}",
            p.corner
        );
        match &p.corner_not_used {
            None => assert_eq!((p.beta_high_pass, p.t0_high_pass), (0.0, 0.0), "{a}"),
            Some(why) => assert!(
                why.contains("stated as the corner's uncertainty"),
                "{why}\n{a}"
            ),
        }
        let l = a.law();
        assert!((l.beta - 2.0).abs() <= 1.96 * l.beta_sigma, "{a}");
        assert!((l.t0 - truth.t0).abs() <= 1.96 * l.t0_sigma, "{a}");
    }

    /// A corner within [`CORNER_SIGMAS`] of its sigmas of zero, or whose fit beats no
    /// high-pass by no more than as many sigmas, is not shown by the record; one above both is.
    #[test]
    fn a_corner_is_used_only_above_its_sigmas() {
        let at = |omega_c: f64, shown: f64| {
            Corner {
                omega_c,
                sigma: 10.0,
                shown,
            }
            .why_not_used()
        };
        assert!(at(CORNER_SIGMAS * 10.0, 10.0).is_some());
        assert!(at(CORNER_SIGMAS * 10.0 + 1.0, 10.0).is_none());
        assert!(at(CORNER_SIGMAS * 10.0 + 1.0, CORNER_SIGMAS).is_some());
    }

    /// The lead is 90 degrees at the corner, tends to 180 degrees far below and to
    /// $\sqrt2\,\omega_c/\omega$ far above it; its derivative by the corner is the difference
    /// quotient's.
    #[test]
    fn the_butterworth_lead() {
        let wc = 100.0;
        assert!((lead(wc, wc).0 - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
        assert!((lead(wc, 0.01 * wc).0 - std::f64::consts::PI).abs() < 0.02);
        let far = lead(wc, 1000.0 * wc).0;
        assert!((far / (SQRT_2 / 1000.0) - 1.0).abs() < 1e-5, "{far}");
        for w in [30.0, 100.0, 400.0] {
            let e = 1e-5;
            let dq = (lead(wc + e, w).0 - lead(wc - e, w).0) / (2.0 * e);
            assert!(
                (lead(wc, w).1 - dq).abs() < 1e-7 * dq.abs().max(1e-3),
                "{w}"
            );
        }
    }
}
