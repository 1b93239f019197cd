//! Eq 79's heading fitted to the sound's phase ([`phase_blocks`](crate::sound_analysis::phase_blocks)): the turns of the
//! contact point counted to the last one the record holds.
//!
//! Eq 79, $\Omega = (C/(t_0 - t))^{1/(\beta+2)}$, integrates to the heading
//! $$\psi(t) = \psi_0 - \frac{C^{q}\,(t_0 - t)^{1-q}}{1 - q}, \qquad q = \frac{1}{\beta + 2},$$
//! fitted for $(\beta, t_0, \ln C, \psi_0)$ to the blocks' headings $\Phi_{ref}(\bar t_k) +
//! \delta_k$, each weighted by its variance from the noise. The blocks do not overlap and their
//! noise is independent; the covariance is the sandwich with the whitened residuals' stationary
//! covariance ([`least_squares`](crate::fit::least_squares), [`Scale::Stationary`]), so the noise
//! variances are relative weights whose common size and correlation the residuals measure.
//!
//! **Iterated.** The reference starts at the pitch track's fit (its offset from the heading may
//! drift by turns over the record, so the first blocks' offsets are unwrapped from block to block);
//! each fit becomes the next reference, so that the offsets shrink to the noise and each block's
//! mean offset sits at its centroid; the blocks near $t_0$ reach up to five of the last fit's
//! $\sigma_{t_0}$ (and at least one millisecond) before it.
//!
//! **A phone's high-pass.** Its phase leads the heading by an amount that falls as the pitch
//! rises; the harmonics' phases measure its corner apart from the law, each block's heading is
//! corrected by the lead it holds, and the corner's uncertainty is carried into $\beta$'s and
//! $t_0$'s ([`high_pass`](crate::sound_analysis::high_pass)). The lead is taken out only where
//! the record shows a high-pass and the correction keeps the turns counted (the rule and its
//! reason: [`high_pass::CORNER_SIGMAS`](crate::sound_analysis::high_pass::CORNER_SIGMAS) and
//! [`high_pass::MAX_TURN_CHANGE`](crate::sound_analysis::high_pass::MAX_TURN_CHANGE)). A corner
//! read but not shown is not shown absent either: the heading is fitted as heard, and the
//! largest shift of $\beta$ and of $t_0$ that taking out the lead of $\omega_c$ or of $\omega_c
//! \pm \sigma_{\omega_c}$ would make (where it keeps the turns counted) is stated as the
//! high-pass's uncertainty, so that the interval holds the truth whether the phone filtered the
//! sound or not.
//!
//! **What the lines' phases disagree on.** Each harmonic is fitted alone, with the lead taken
//! out of the heading taken out of it; where their $\beta$s or $t_0$s disagree beyond their
//! noise (a room's reverberation, a corner read wrong), what that disagreement moves the combined
//! fit by is stated as its uncertainty
//! ([`harmonic_agreement`](crate::sound_analysis::harmonic_agreement)).
//!
//! **The law's own error.** The heading is refitted on the later half of the blocks; where
//! $\beta$ or $t_0$ moves by more than [`DRIFT_SIGMAS`](crate::fit::law_stability::DRIFT_SIGMAS) of the half's uncertainty, the shift is
//! stated as the law's systematic uncertainty, as for the light signal
//! ([`law_stability`](crate::fit::law_stability)).

use crate::fit::band::Row;
use crate::fit::eq84_85::phase;
use crate::fit::law_fit::LawFit;
use crate::fit::law_stability::LawStability;
use crate::fit::least_squares::{solve, FitError, Problem, Scale};
use crate::sound_analysis::harmonic_agreement::{agreement, HarmonicAgreement};
use crate::sound_analysis::high_pass::{block_leads, fit_corner, rates, Corner, MAX_TURN_CHANGE};
use crate::sound_analysis::mains::hum::remove_hum_clear;
use crate::sound_analysis::phase_blocks::{blocks, Block, BlockSettings, Samples};
use crate::sound_analysis::residual_structure::Structure;
use nalgebra::SVector;
use serde::Serialize;
use std::borrow::Cow;
use std::f64::consts::TAU;

/// Rounds of blocks and fit.
const ROUNDS: usize = 3;

/// Eq 79's heading with an offset: parameters $(\beta, t_0, \ln C, \psi_0)$.
struct Heading<'a> {
    t: &'a [f64],
    y: &'a [f64],
    last: f64,
}

impl Problem<4> for Heading<'_> {
    fn y(&self) -> &[f64] {
        self.y
    }
    fn model(&self, p: &SVector<f64, 4>, i: usize) -> (f64, SVector<f64, 4>) {
        let p3 = SVector::<f64, 3>::new(p[0], p[1], p[2]);
        let (phi, _, g) = phase(&p3, self.t[i]);
        (phi + p[3], SVector::<f64, 4>::new(g[0], g[1], g[2], 1.0))
    }
    fn rows(&self, _p: &SVector<f64, 4>) -> Vec<Row> {
        (0..self.y.len())
            .map(|i| Row {
                start: i,
                coef: vec![1.0],
            })
            .collect()
    }
    fn admissible(&self, p: &SVector<f64, 4>) -> bool {
        p.iter().all(|v| v.is_finite()) && p[0] > -0.9 && p[0] < 50.0 && p[1] > self.last
    }
}

/// A block of the fit, kept for plotting.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PhasePoint {
    /// Block start and end (s).
    pub a: f64,
    /// (s)
    pub b: f64,
    /// The centroid time (s).
    pub t: f64,
    /// Turns in the block.
    pub turns: usize,
    /// The heading's residual from the fitted law (rad).
    pub residual: f64,
    /// Its standard uncertainty from the noise (rad).
    pub sigma: f64,
    /// The base harmonic's power over the noise's
    /// ([`Block::base`](crate::sound_analysis::phase_blocks::Block::base)).
    pub snr: f64,
}

/// Eq 79 fitted to the sound's phase.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PhaseFit {
    /// Eq 79's $\beta$, $t_0$ and $\ln C$ with their uncertainties, read as this fit's own
    /// fields.
    #[serde(flatten)]
    pub parameters: LawFit,
    /// The phone's high-pass corner $\omega_c/2\pi$ (Hz) read from the harmonics' phases and
    /// its standard uncertainty, when a harmonic above the fundamental was followed.
    pub corner: Option<(f64, f64)>,
    /// Why the corner read is not taken out of the heading (`None` when it is, or when no
    /// corner was read).
    pub corner_not_used: Option<String>,
    /// What the corner's uncertainty makes of $\beta$'s and $t_0$'s (s): where its lead is taken
    /// out, half the difference of the fits at $\omega_c \pm \sigma_{\omega_c}$; where a corner is
    /// read but the record does not show it, the largest shift its lead would make (the
    /// module's documentation); 0 without a corner.
    pub beta_high_pass: f64,
    /// (s)
    pub t0_high_pass: f64,
    /// Turns of the heading followed, from the first block's start to the last block's end.
    pub turns: f64,
    /// The rms residual (rad).
    pub rms: f64,
    /// The reduced $\chi^2$ of the residuals weighted by their noise variances.
    pub chi2_dof: f64,
    /// Blocks fitted.
    pub n: usize,
    /// The blocks.
    pub points: Vec<PhasePoint>,
    /// The later half's fit against this one: whether eq 79 drifts over the record.
    pub law: Option<LawStability>,
    /// The harmonics fitted alone and what their disagreement moves this fit by (`None` where
    /// fewer than two could be fitted).
    pub harmonics: Option<HarmonicAgreement>,
    /// The tests of the blocks' whitened residuals for structure (`None` below
    /// [`MIN_BLOCKS`](crate::sound_analysis::residual_structure::MIN_BLOCKS)).
    pub structure: Option<Structure>,
}

impl PhaseFit {
    /// $\beta$'s standard uncertainty from the fit, the high-pass's corner, the harmonics'
    /// disagreement and the law, in quadrature.
    pub fn beta_total(&self) -> f64 {
        let law = self.law.as_ref().map_or(0.0, LawStability::beta_systematic);
        self.beta_sigma
            .hypot(self.beta_high_pass)
            .hypot(self.beta_harmonics())
            .hypot(law)
    }

    /// $t_0$'s standard uncertainty (s) from the fit, the high-pass's corner, the harmonics'
    /// disagreement and the law, in quadrature.
    pub fn t0_total(&self) -> f64 {
        let law = self.law.as_ref().map_or(0.0, LawStability::t0_systematic);
        self.t0_sigma
            .hypot(self.t0_high_pass)
            .hypot(self.t0_harmonics())
            .hypot(law)
    }

    /// What the harmonics' disagreement beyond their noise moves $\beta$ by (0 without it).
    pub fn beta_harmonics(&self) -> f64 {
        self.harmonics.as_ref().map_or(0.0, |a| a.beta)
    }

    /// What it moves $t_0$ by (s).
    pub fn t0_harmonics(&self) -> f64 {
        self.harmonics.as_ref().map_or(0.0, |a| a.t0)
    }
}

/// Fits eq 79's heading to the phase of `rec` from `first` (s, where the pitch track first holds
/// the line) toward $t_0$, starting from `start` = $(\beta, t_0, \ln C)$ with $t_0$'s uncertainty
/// `t0_sigma` (s). The mains lines `hum` (Hz) are subtracted from the record first, each fitted
/// where the disk's first eight harmonics by `start` keep [`HUM_GUARD`] away from it.
pub fn fit_phase(
    rec: &Samples<'_>,
    hum: &[f64],
    first: f64,
    start: SVector<f64, 3>,
    t0_sigma: f64,
    settings: &BlockSettings,
) -> Result<PhaseFit, FitError> {
    fit_phase_reading(rec, hum, first, start, t0_sigma, settings, &fit_corner)
}

/// How a fit reads the high-pass's corner from its blocks and their rates (rad/s):
/// [`fit_corner`] from the splits, or a corner known otherwise (a diagnosis with the truth).
pub type ReadCorner<'a> = &'a dyn Fn(&[Block], &[f64]) -> Option<Corner>;

/// [`fit_phase`] with the corner read by `read_corner`.
pub fn fit_phase_reading(
    rec: &Samples<'_>,
    hum: &[f64],
    first: f64,
    start: SVector<f64, 3>,
    t0_sigma: f64,
    settings: &BlockSettings,
    read_corner: ReadCorner<'_>,
) -> Result<PhaseFit, FitError> {
    let x = without_hum(rec, hum, &start);
    let rec = &Samples {
        x: &x,
        t_start: rec.t_start,
        dt: rec.dt,
    };
    let mut p = start;
    let (mut shift, mut sigma_t0) = (0.0, t0_sigma);
    let mut result = None;
    for round in 0..ROUNDS {
        let end =
            (p[1] - (5.0 * sigma_t0).max(1e-3)).min(rec.t_start + rec.x.len() as f64 * rec.dt);
        let bl = blocks(rec, &p, shift, (first, end), round == 0, settings);
        FitError::at_least("phase blocks", bl.len(), settings.min_blocks, "")?;
        let omega = rates(&bl, &p);
        let leads = |wc: f64| block_leads(&bl, &omega, wc);
        let read = read_corner(&bl, &omega);
        let plain = fit_blocks(&bl, &p, shift, &vec![0.0; bl.len()])?;
        let (corner, not_used, lead, (mut fit, p4)) = match read.map(|c| (c, c.why_not_used())) {
            Some((c, None)) => {
                let lead = leads(c.omega_c);
                let corrected = fit_blocks(&bl, &p, shift, &lead)?;
                let change = corrected.0.turns - plain.0.turns;
                if change.abs() < MAX_TURN_CHANGE {
                    (Some(c), None, lead, corrected)
                } else {
                    let why = format!(
                        "its lead would change the turns counted by {change:+.2}, more than \
                         the {MAX_TURN_CHANGE} turn a high-pass's lead can move them"
                    );
                    (None, Some(why), vec![0.0; bl.len()], plain)
                }
            }
            Some((_, why)) => (None, why, vec![0.0; bl.len()], plain),
            None => (None, None, vec![0.0; bl.len()], plain),
        };
        if round + 1 == ROUNDS {
            fit.corner = read.map(|c: Corner| (c.omega_c / TAU, c.sigma / TAU));
            fit.corner_not_used = not_used;
            if let Some(c) = corner {
                let (hi, _) = fit_blocks(&bl, &p, shift, &leads(c.omega_c + c.sigma))?;
                let (lo, _) = fit_blocks(&bl, &p, shift, &leads(c.omega_c - c.sigma))?;
                fit.beta_high_pass = 0.5 * (hi.beta - lo.beta).abs();
                fit.t0_high_pass = 0.5 * (hi.t0 - lo.t0).abs();
            } else if let Some(c) = read.filter(|c| c.why_not_used().is_some()) {
                (fit.beta_high_pass, fit.t0_high_pass) = unshown_lead(&bl, &p, shift, &fit, c);
                if let Some(why) = fit.corner_not_used.as_mut() {
                    why.push_str(
                        "; the shift its lead would make is stated as the corner's uncertainty",
                    );
                }
            }
            fit.law = later_half(&bl, &p, shift, &lead, &fit);
            let wc = corner.map_or(0.0, |c| c.omega_c);
            let alone = |hb: &[Block]| {
                let (f, _) = fit_blocks(hb, &p, shift, &vec![0.0; hb.len()]).ok()?;
                Some([f.beta, f.beta_sigma, f.t0, f.t0_sigma])
            };
            fit.harmonics = agreement(&bl, &omega, &lead, wc, settings, &alone);
        }
        p = SVector::<f64, 3>::new(p4[0], p4[1], p4[2]);
        shift = p4[3];
        sigma_t0 = fit.t0_sigma;
        result = Some(fit);
    }
    result.ok_or_else(|| FitError::Numerics("no round".into()))
}

/// What the lead of corner `c`, read from the harmonics but not shown by the record
/// ([`Corner::why_not_used`]), would move the fit `plain` (fitted without it) by: the largest
/// shift of $\beta$ and of $t_0$ (s) among the fits with the lead of $\omega_c$ and of
/// $\omega_c \pm \sigma_{\omega_c}$ (those above zero) taken out, each kept only where it keeps
/// the turns counted ([`MAX_TURN_CHANGE`]). A corner not shown is not shown absent either: the
/// record cannot tell a high-pass whose lead moves the heading by this much from none, so the
/// shift is stated as an uncertainty of the fit, which holds the truth whichever it is.
fn unshown_lead(
    bl: &[Block],
    p: &SVector<f64, 3>,
    shift: f64,
    plain: &PhaseFit,
    c: Corner,
) -> (f64, f64) {
    let omega = rates(bl, p);
    [c.omega_c - c.sigma, c.omega_c, c.omega_c + c.sigma]
        .into_iter()
        .filter(|wc| wc.is_finite() && *wc > 0.0)
        .filter_map(|wc| fit_blocks(bl, p, shift, &block_leads(bl, &omega, wc)).ok())
        .filter(|(f, _)| (f.turns - plain.turns).abs() < MAX_TURN_CHANGE)
        .map(|(f, _)| ((f.beta - plain.beta).abs(), (f.t0 - plain.t0).abs()))
        .filter(|(b, t)| b.is_finite() && t.is_finite())
        .fold((0.0, 0.0), |(b, t), (fb, ft)| (b.max(fb), t.max(ft)))
}

/// The heading refitted on the later half of the blocks `bl` (demodulated against `p` plus
/// `shift`), against the whole fit `whole`: where $\beta$ or $t_0$ moves by more than
/// [`DRIFT_SIGMAS`](crate::fit::law_stability::DRIFT_SIGMAS) of the later half's own uncertainty, eq 79 drifts over the record and the
/// shift is the law's systematic uncertainty ([`law_stability`](crate::fit::law_stability), as for
/// the light). `None` when the half has too few blocks to fit.
fn later_half(
    bl: &[Block],
    p: &SVector<f64, 3>,
    shift: f64,
    lead: &[f64],
    whole: &PhaseFit,
) -> Option<LawStability> {
    let h = bl.len() / 2;
    let (half, _) = fit_blocks(&bl[h..], p, shift, &lead[h..]).ok()?;
    Some(LawStability::of_halves(
        bl.len() - h,
        bl[h].a,
        [half.beta, half.beta_sigma, half.t0, half.t0_sigma],
        [whole.beta, whole.t0],
    ))
}

impl PhaseFit {
    /// The blocks as CSV: start, end and centroid time (s), turns, the heading's residual from
    /// the fitted law and its standard uncertainty (rad), the base harmonic's signal-to-noise.
    pub fn csv(&self) -> String {
        let mut s = String::from("t_start_s,t_end_s,t_mean_s,turns,residual_rad,sigma_rad,snr\n");
        for p in &self.points {
            s.push_str(&format!(
                "{},{},{},{},{},{},{}\n",
                p.a, p.b, p.t, p.turns, p.residual, p.sigma, p.snr
            ));
        }
        s
    }
}

/// Closest approach (Hz) of the disk's harmonics to a mains line for a sample to enter the line's
/// fit.
pub const HUM_GUARD: f64 = 5.0;

/// The record with the mains lines `hum` subtracted where the disk, by `p`, keeps clear of them.
/// The record itself, uncopied, where there is no hum.
fn without_hum<'a>(rec: &Samples<'a>, hum: &[f64], p: &SVector<f64, 3>) -> Cow<'a, [f64]> {
    if hum.is_empty() {
        return Cow::Borrowed(rec.x);
    }
    let mut x = rec.x.to_vec();
    // The pitch by chunks of 1 ms (NaN past t0, where the disk is silent).
    let chunk = ((1e-3 / rec.dt) as usize).max(1);
    let pitch: Vec<f64> = (0..x.len().div_ceil(chunk))
        .map(|c| {
            let t = rec.t_start + ((c as f64 + 0.5) * chunk as f64) * rec.dt;
            if t < p[1] {
                phase(p, t).1 / TAU
            } else {
                f64::NAN
            }
        })
        .collect();
    let clear = |j: usize, line: f64| {
        let f = pitch[j / chunk];
        !(1..=8).any(|h| (f64::from(h) * f - line).abs() < HUM_GUARD)
    };
    remove_hum_clear(&mut x, 1.0 / rec.dt, hum, &clear);
    Cow::Owned(x)
}

/// Fits the heading to blocks demodulated against `p` plus `shift`, each block's datum less
/// the high-pass's `lead` (rad) it holds.
fn fit_blocks(
    bl: &[Block],
    p: &SVector<f64, 3>,
    shift: f64,
    lead: &[f64],
) -> Result<(PhaseFit, SVector<f64, 4>), FitError> {
    let t: Vec<f64> = bl.iter().map(|b| b.t).collect();
    let y: Vec<f64> = bl
        .iter()
        .zip(lead)
        .map(|(b, l)| phase(p, b.t).0 + shift + b.offset - l)
        .collect();
    let w: Vec<f64> = bl.iter().map(|b| b.sigma * b.sigma).collect();
    let last = bl.iter().map(|b| b.b).fold(f64::MIN, f64::max);
    let law = Heading { t: &t, y: &y, last };
    let p0 = SVector::<f64, 4>::new(p[0], p[1], p[2], {
        let (mut num, mut den) = (0.0, 0.0);
        for (i, b) in bl.iter().enumerate() {
            num += (y[i] - phase(p, b.t).0) / w[i];
            den += 1.0 / w[i];
        }
        num / den
    });
    let s = solve(&law, &w, p0, Scale::Stationary)?;
    let n = y.len();
    let chi2: f64 = s
        .residual
        .iter()
        .zip(&w)
        .map(|(r, w)| r * r / w)
        .sum::<f64>();
    let q = |tt: f64| phase(&SVector::<f64, 3>::new(s.p[0], s.p[1], s.p[2]), tt).0;
    let turns = (q(last) - q(bl[0].a)) / TAU;
    let fit = PhaseFit {
        parameters: LawFit::of(&s),
        corner: None,
        corner_not_used: None,
        beta_high_pass: 0.0,
        t0_high_pass: 0.0,
        turns,
        rms: (s.residual.iter().map(|r| r * r).sum::<f64>() / n as f64).sqrt(),
        chi2_dof: chi2 / (n - 4) as f64,
        n,
        structure: Structure::of(&s.residual, &bl.iter().map(|b| b.sigma).collect::<Vec<_>>()),
        points: bl
            .iter()
            .zip(&s.residual)
            .map(|(b, r)| PhasePoint {
                a: b.a,
                b: b.b,
                t: b.t,
                turns: b.turns,
                residual: *r,
                sigma: b.sigma,
                snr: b.snr,
            })
            .collect(),
        law: None,
        harmonics: None,
    };
    Ok((fit, s.p))
}

crate::fit::law_fit::reads_law_fit!(PhaseFit);
