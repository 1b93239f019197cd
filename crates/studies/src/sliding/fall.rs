//! Sec. 7 (after eq 54) and the summary (sec. 12): a disk rolling with $b > 0$ at large tilt is
//! unstable "and the disk will appear to fall over quickly into a rolling motion with
//! $\alpha_0 \lesssim 60°$". The linear part (where the steady motion is unstable) is the claim
//! `positive-b-unstable-large-tilt`; this study follows the fall itself, rolling and on
//! Coulomb tables.
//!
//! **The unstable band**, measured on the linearized eqs 23-25 (not on the printed eq 54): at the
//! steady motion $(\alpha_0, b = \beta a)$ of eqs 28-29 the Jacobian $J$ of eqs 23-25 has two zero
//! eigenvalues and a pair whose square is $-\varpi^2 = \mathrm{tr}(J^2)/2$; eq 54 states
//! $$ \frac{\varpi^2}{\Omega_0^2}(k+1) = 3k\cos^2\alpha_0 + \sin^2\alpha_0 + \beta\left((6k+1)\cos\alpha_0 - (2k+1)\frac{\sin^2\alpha_0}{\cos\alpha_0}\right) + 2\beta^2(2k+1), $$
//! a quadratic in $\beta$ that is negative between two roots at large tilt. The study finds the
//! minimum of $\varpi^2$ over $\beta$ by golden section and the two roots by bisection; the start
//! takes $\beta$ at their middle, where the growth rate $\lambda = \sqrt{-\varpi^2}$ is reported.
//!
//! **The runs.** From that steady motion with the tilt lowered by [`NUDGE`] (same $\Omega_0$,
//! $\omega_{10}$, $\dot\alpha = 0$, rolling), for [`DURATION`] seconds:
//! - the rolling model (eqs 23-25: no slip can occur, the table's friction is unlimited);
//! - the sliding model ([`physics::model::sliding`]) on tables with each $\mu$ of [`MUS`]. The
//!   steady start needs $\mu_* = |\mathbf F_h|/F_z = b\Omega_0^2/g$ (eq 20's force: the
//!   centripetal force of the centre over the weight), 0.06 to 0.17 at these starts, so every
//!   table holds the start; whether it slides during the fall is what the runs show.
//!
//! The rolling model is also started across each band ([`ACROSS`]), to show how much the tilt
//! it falls to depends on $b$.
//!
//! **Definitions** (checkable on the tilt sampled every [`SAMPLE`] s, with $\dot\alpha$):
//! - the disk *has fallen* once $\alpha < \alpha_0 - 5°$ ([`LEFT`]);
//! - its *first dip* is the first local minimum of $\alpha$ after that: the first sample
//!   interval where $\dot\alpha$ turns from negative to non-negative, the minimum located on
//!   the cubic Hermite interpolant of $(\alpha, \dot\alpha)$ over it;
//! - *quickly* is the time to that minimum, also in units of the steady precession period
//!   $2\pi/\Omega_0$. Most of it is the growth of the nudge, about $\ln(5°/\delta)/\lambda$
//!   for a nudge $\delta$, so the e-folding time $1/\lambda$ is reported with the band;
//! - what the motion does over the run ([`Swing`]): the least, greatest and mean tilt, and
//!   whether it *settles* into a lower steady rolling (after the fall its swing decays to half
//!   or less and the late mean lies below $\alpha_0 - 5°$).
//!
//! The report judges "falls into a rolling motion with $\alpha_0 \lesssim 60°$" on what the
//! motion does over the run, not on the first dip: a run bears the claim out when it settles
//! and its late mean is within the claim's reading of "about 60°" (`paper/claims.yaml`,
//! `rule: within 0.05`: 57° to 63°). Without dissipation the rolling disk is conservative:
//! after the fall it nutates between the first dip and nearly $\alpha_0$ and never settles, so
//! the first dip is one extreme of a swing, not a new steady tilt. Reported as well: whether
//! the contact slid or left the table before the first dip, and the tilt at the run's end.

use numerics::minimize::golden_min;
use numerics::oscillation::bisect;
use physics::disk::Disk;
use physics::model::lab_frame::Snapshot;
use physics::model::rolling::{self, Rolling};
use physics::model::sliding::{Friction, Mode, Sliding};
use physics::model::steady::steady_motion;
use physics::model::{Extras, Model};
use physics::solve::{solve, Event, Problem, Settings, SettingsError, State};
use serde::Serialize;

use super::swing::{hermite_minimum, Swing};

/// The steady tilts started from (deg).
pub const TILTS_DEG: [f64; 3] = [75.0, 80.0, 85.0];
/// Where across the band the rolling model is also started: $\beta = \beta_- +
/// f(\beta_+ - \beta_-)$ for each fraction $f$.
pub const ACROSS: [f64; 5] = [0.1, 0.25, 0.5, 0.75, 0.9];
/// The Coulomb coefficients tried.
pub const MUS: [f64; 4] = [0.2, 0.4, 0.6, 1.0];
/// How long each run lasts (s).
pub const DURATION: f64 = 3.0;
/// The start's tilt is the steady one lowered by this (rad).
pub const NUDGE: f64 = 1e-3;
/// The disk has fallen once its tilt is this far below the steady tilt (deg).
pub const LEFT: f64 = super::swing::FALLEN;
/// Sampling of the tilt (s).
pub const SAMPLE: f64 = 1e-2;

/// The unstable band of $b$ at one tilt, from the linearized eqs 23-25.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, schemars::JsonSchema)]
pub struct Band {
    /// Steady tilt $\alpha_0$ (deg).
    pub alpha0_deg: f64,
    /// Lower edge of the band, $b/a$.
    pub lower: f64,
    /// Upper edge of the band, $b/a$.
    pub upper: f64,
    /// The start's $b/a$: the band's middle.
    pub start: f64,
    /// Growth rate $\sqrt{-\varpi^2}$ at the start (1/s, toy disk).
    pub growth: f64,
    /// Steady precession rate $\Omega_0$ at the start (rad/s, eq 29).
    pub precession: f64,
    /// Friction the steady start needs, $|\mathbf F_h|/F_z$ from eq 20's force.
    pub mu_needed: f64,
}

/// One run from one start.
#[derive(Debug, Clone, PartialEq, Serialize, schemars::JsonSchema)]
pub struct FallCase {
    /// Steady tilt of the start (deg).
    pub alpha0_deg: f64,
    /// The start's $b/a$.
    pub b_over_a: f64,
    /// "rolling" (eqs 23-25) or "Coulomb friction" (the sliding model).
    pub contact: &'static str,
    /// Coulomb's coefficient; `None` for the rolling model.
    pub mu: Option<f64>,
    /// The first dip (deg): the first local minimum of the tilt after leaving $\alpha_0$ by
    /// [`LEFT`]; `None` when it never left, or never turned back within the run. One extreme
    /// of the motion, not where it settles ([`FallCase::swing`]).
    pub fell_to_deg: Option<f64>,
    /// Time to that minimum (s).
    pub fall_time: Option<f64>,
    /// The same in steady precession periods $2\pi/\Omega_0$.
    pub fall_periods: Option<f64>,
    /// The contact slid before the minimum (before the run's end when there is none).
    pub slipped: bool,
    /// The contact was lost before the minimum (before the run's end when there is none).
    pub lifted: bool,
    /// Time the contact spent sliding over the whole run (s).
    pub slip_time: f64,
    /// The tilt over the whole run: least, greatest, mean, and whether it settles into a lower
    /// steady rolling ([`Swing`]).
    pub swing: Swing,
    /// Tilt at the end of the run (deg).
    pub end_deg: f64,
    /// Time the run ended (s).
    pub end_time: f64,
    /// Why the run ended.
    pub ending: String,
}

/// The study: the bands and every run. It computes only; the report holds the tilts against
/// the claim's reading of "about 60 degrees" (references never read the claims).
#[derive(Debug, Clone, PartialEq, Serialize, schemars::JsonSchema)]
pub struct Fall {
    /// The band at each tilt of [`TILTS_DEG`] (only those where one exists).
    pub bands: Vec<Band>,
    /// Every run: per band, rolling first, then each $\mu$ of [`MUS`].
    pub cases: Vec<FallCase>,
    /// Rolling runs across each band, at the fractions [`ACROSS`] of its width.
    pub across: Vec<FallCase>,
}

/// $\varpi^2$ (1/s²) of the steady motion $(\alpha_0, b = \beta a)$ of disk `d`, from the exact
/// Jacobian of eqs 23-25 (no torque): $\varpi^2 = -\mathrm{tr}(J^2)/2$; negative means unstable
/// with growth rate $\sqrt{-\varpi^2}$. `None` where no steady motion exists (eq 30).
pub fn varpi_squared(d: &Disk, alpha0: f64, beta: f64) -> Option<f64> {
    let m = steady_motion(d, alpha0, beta * d.a).ok()?;
    let j = rolling::jacobian(d, &[m.alpha, m.alpha_dot, m.precession, m.spin]);
    Some(-(j * j).trace() / 2.0)
}

/// The unstable band of $b/a$ at `alpha0` (rad) for disk `d`, with its middle's growth rate and
/// friction need; `None` where every $b > 0$ up to $40a$ is stable.
pub fn band(d: &Disk, alpha0: f64) -> Option<Band> {
    // Scaled by Omega_0^2 the quadratic of eq 54 is unimodal in beta.
    let q = |beta: f64| {
        let w0 = steady_motion(d, alpha0, beta * d.a).ok()?.precession;
        Some(varpi_squared(d, alpha0, beta)? / (w0 * w0))
    };
    let (lo, hi) = (1e-6, 40.0);
    let (deepest, _) = golden_min(lo, hi, 1e-10, |b| q(b).unwrap_or(f64::INFINITY));
    if q(deepest)? >= 0.0 || q(lo)? <= 0.0 || q(hi)? <= 0.0 {
        return None;
    }
    let unstable = |b: f64| q(b).is_some_and(|v| v < 0.0);
    let edge = |(a, b): (f64, f64)| 0.5 * (a + b);
    let lower = edge(bisect(lo, deepest, 1e-12, unstable));
    let upper = edge(bisect(deepest, hi, 1e-12, unstable));
    let start = 0.5 * (lower + upper);
    let m = steady_motion(d, alpha0, start * d.a).ok()?;
    let f = rolling::contact_force(d, &m, &rolling::rates(d, &m, [0.0; 3]));
    Some(Band {
        alpha0_deg: alpha0.to_degrees(),
        lower,
        upper,
        start,
        growth: (-varpi_squared(d, alpha0, start)?).sqrt(),
        precession: m.precession,
        mu_needed: f[1].hypot(f[2]) / f[0],
    })
}

/// What a run's samples say: times, tilts (rad), tilt rates (rad/s) and, per sample, whether
/// the contact slid or flew in the interval that ends there.
struct Samples {
    t: Vec<f64>,
    alpha: Vec<f64>,
    alpha_dot: Vec<f64>,
    slid: Vec<bool>,
    flew: Vec<bool>,
}

impl Samples {
    /// Every local minimum of the tilt, `(index, t, alpha)`: where $\dot\alpha$ turns from
    /// negative to non-negative between samples $j$ and $j+1$, located on the cubic Hermite
    /// interpolant through $(\alpha, \dot\alpha)$ at both ends (error $O(\Delta t^4)$; the
    /// tilt rate is continuous at stick-slip switches, only the accelerations jump).
    fn minima(&self) -> Vec<(usize, f64, f64)> {
        let mut out = Vec::new();
        for j in 0..self.t.len().saturating_sub(1) {
            let (m0, m1) = (self.alpha_dot[j], self.alpha_dot[j + 1]);
            if !(m0 < 0.0 && m1 >= 0.0) {
                continue;
            }
            let (a0, a1, h) = (self.alpha[j], self.alpha[j + 1], self.t[j + 1] - self.t[j]);
            let (t, a) = hermite_minimum(a0, m0 * h, a1, m1 * h)
                .map_or((self.t[j + 1], a1.min(a0)), |(s, a)| (self.t[j] + s * h, a));
            out.push((j, t, a));
        }
        out
    }
}

/// Reads a run's samples by the module's definitions; `alpha0` the steady tilt (rad),
/// `precession` its $\Omega_0$.
fn case(
    alpha0: f64,
    beta: f64,
    precession: f64,
    mu: Option<f64>,
    s: &Samples,
    ending: String,
) -> FallCase {
    let left = s.alpha.iter().position(|&a| a < alpha0 - LEFT.to_radians());
    let minima = s.minima();
    let bottom = left.and_then(|i| minima.iter().find(|m| m.0 + 1 >= i).copied());
    // Slip and flight up to the bottom (its interval included), or over the whole run.
    let upto = bottom.map_or(s.t.len() - 1, |m| m.0 + 1);
    let slip_time =
        s.t.windows(2)
            .zip(&s.slid[1..])
            .filter(|(_, slid)| **slid)
            .map(|(w, _)| w[1] - w[0])
            .fold(0.0, |sum, dt| sum + dt);
    FallCase {
        alpha0_deg: alpha0.to_degrees(),
        b_over_a: beta,
        contact: if mu.is_some() {
            "Coulomb friction"
        } else {
            "rolling"
        },
        mu,
        fell_to_deg: bottom.map(|m| m.2.to_degrees()),
        fall_time: bottom.map(|m| m.1),
        fall_periods: bottom.map(|m| m.1 * precession.abs() / (2.0 * std::f64::consts::PI)),
        slipped: s.slid[..=upto].iter().any(|&x| x),
        lifted: s.flew[..=upto].iter().any(|&x| x),
        slip_time,
        swing: Swing::of(&s.t, &s.alpha, &s.alpha_dot, alpha0),
        end_deg: s.alpha.last().map_or(f64::NAN, |a| a.to_degrees()),
        end_time: s.t.last().copied().unwrap_or(0.0),
        ending,
    }
}

fn no_stops<'a>() -> Vec<Event<'a, 14>> {
    Vec::new()
}

/// The run from the steady motion $(\alpha_0, b = \beta a)$ of disk `d`, its tilt lowered by
/// [`NUDGE`]: rolling (eqs 23-25) for `mu = None`, else the sliding model on a table with
/// that coefficient. `None` where no steady motion exists.
pub fn fall_from(
    d: &Disk,
    alpha0: f64,
    beta: f64,
    mu: Option<f64>,
    settings: &Settings,
) -> Result<Option<FallCase>, SettingsError> {
    let Ok(steady) = steady_motion(d, alpha0, beta * d.a) else {
        return Ok(None);
    };
    let mut m = steady;
    m.alpha -= NUDGE;
    let (s, ending) = match mu {
        None => {
            let model = Rolling::<4>::new(*d, Extras::default(), None);
            let sol = solve(
                Problem::new(&model, 0.0, model.state(&m), DURATION).sampled(SAMPLE),
                settings,
            )?;
            let n = sol.t.len();
            let s = Samples {
                alpha: sol.y.iter().map(|y| y[0]).collect(),
                alpha_dot: sol.y.iter().map(|y| y[1]).collect(),
                t: sol.t,
                slid: vec![false; n],
                flew: vec![false; n],
            };
            (s, sol.ending.to_string())
        }
        Some(mu) => {
            let model = Sliding::new(
                *d,
                Friction {
                    mu,
                    restitution: 0.0,
                },
            );
            let run = model.run(
                &model.start_state(&m),
                DURATION,
                settings,
                Some(SAMPLE),
                &no_stops,
            )?;
            let motions: Vec<_> = run
                .y
                .iter()
                .map(|y: &State<14>| Snapshot::of(d.a, y).motion())
                .collect();
            let s = Samples {
                alpha: motions.iter().map(|m| m.alpha).collect(),
                alpha_dot: motions.iter().map(|m| m.alpha_dot).collect(),
                t: run.t,
                slid: run
                    .mode
                    .iter()
                    .map(|m| matches!(m, Mode::Slip { .. }))
                    .collect(),
                flew: run.mode.iter().map(|m| *m == Mode::Flight).collect(),
            };
            (s, run.ending.to_string())
        }
    };
    Ok(Some(case(alpha0, beta, steady.precession, mu, &s, ending)))
}

/// The whole study for disk `d`: the band at each tilt of [`TILTS_DEG`], from each the rolling
/// run and a sliding run for each $\mu$ of [`MUS`], and rolling runs across the band.
pub fn fall(d: &Disk, settings: &Settings) -> Result<Fall, SettingsError> {
    let bands: Vec<Band> = TILTS_DEG
        .iter()
        .filter_map(|a| band(d, a.to_radians()))
        .collect();
    let mut cases = Vec::new();
    let mut across = Vec::new();
    for b in &bands {
        for f in ACROSS {
            let beta = b.lower + f * (b.upper - b.lower);
            across.extend(fall_from(
                d,
                b.alpha0_deg.to_radians(),
                beta,
                None,
                settings,
            )?);
        }
        let alpha0 = b.alpha0_deg.to_radians();
        cases.extend(fall_from(d, alpha0, b.start, None, settings)?);
        for mu in MUS {
            cases.extend(fall_from(d, alpha0, b.start, Some(mu), settings)?);
        }
    }
    Ok(Fall {
        bands,
        cases,
        across,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use numerics::linearize::eigenvalues;

    fn settings() -> Settings {
        Settings::dop853(1e-10, 1e-12)
    }

    /// The largest real part of the eigenvalues of eqs 23-25 linearized at $(\alpha_0, \beta a)$.
    fn growth(d: &Disk, alpha0: f64, beta: f64) -> f64 {
        let m = steady_motion(d, alpha0, beta * d.a).unwrap();
        let j = rolling::jacobian(d, &[m.alpha, m.alpha_dot, m.precession, m.spin]);
        eigenvalues(&j)
            .iter()
            .map(|z| z.re)
            .fold(f64::NEG_INFINITY, f64::max)
    }

    #[test]
    fn the_band_is_where_the_eigenvalues_grow() {
        let d = super::super::toy_disk();
        // The claim's onset is 71.4 deg (k = 1/4): no band below it, one above.
        assert!(band(&d, 71.0f64.to_radians()).is_none());
        assert!(band(&d, 72.0f64.to_radians()).is_some());
        for a in TILTS_DEG {
            let b = band(&d, a.to_radians()).unwrap();
            let g = |beta: f64| growth(&d, a.to_radians(), beta);
            assert!(
                g(b.lower * 0.99) < 1e-9 && g(b.upper * 1.01) < 1e-9,
                "{b:?}"
            );
            assert!(
                g(b.lower * 1.01) > 1e-6 && g(b.upper * 0.99) > 1e-6,
                "{b:?}"
            );
            assert!((g(b.start) - b.growth).abs() < 1e-6 * b.growth, "{b:?}");
            // The steady start needs the centripetal force of its centre: mu = b Omega0^2 / g.
            let need = b.start * d.a * b.precession.powi(2) / d.g;
            assert!((b.mu_needed - need).abs() < 1e-9, "{b:?}");
        }
    }

    #[test]
    fn a_start_in_the_band_falls_and_starts_outside_it_stay() {
        let d = super::super::toy_disk();
        let s = settings();
        let b80 = band(&d, 80f64.to_radians()).unwrap();
        // Outside: 65 deg (no band there) with the 80 deg start's b, and 80 deg above the band.
        for (a, beta) in [(65.0f64, b80.start), (80.0, 2.0 * b80.upper)] {
            for mu in [None, Some(1.0)] {
                let c = fall_from(&d, a.to_radians(), beta, mu, &s)
                    .unwrap()
                    .unwrap();
                assert!(c.fell_to_deg.is_none(), "{c:?}");
                assert!(c.swing.min_deg > a - 1.0, "{c:?}");
            }
        }
        let c = fall_from(&d, 80f64.to_radians(), b80.start, None, &s)
            .unwrap()
            .unwrap();
        assert!(c.fell_to_deg.unwrap() < 80.0 - LEFT, "{c:?}");
    }

    #[test]
    fn rolling_and_a_table_that_never_slips_agree_and_slipping_falls_further() {
        let d = super::super::toy_disk();
        let f = fall(&d, &settings()).unwrap();
        assert_eq!(f.bands.len(), TILTS_DEG.len());
        for b in &f.bands {
            let of = |mu: Option<f64>| {
                f.cases
                    .iter()
                    .find(|c| c.alpha0_deg == b.alpha0_deg && c.mu == mu)
                    .unwrap()
            };
            for mu in std::iter::once(None).chain(MUS.map(Some)) {
                let c = of(mu);
                eprintln!(
                    "{} deg mu {mu:?}: first dip {:?}, {:.2}-{:.2} mean {:.2}, late mean {:?}, swing {:?} -> {:?}, settles {}, slid {} lifted {}",
                    b.alpha0_deg, c.fell_to_deg, c.swing.min_deg, c.swing.max_deg, c.swing.mean_deg,
                    c.swing.late_mean_deg, c.swing.early_swing_deg, c.swing.late_swing_deg, c.swing.settles, c.slipped, c.lifted
                );
            }
            let (rolling, table) = (of(None), of(Some(1.0)));
            assert!(!table.slipped && table.slip_time == 0.0, "{table:?}");
            let gap = (rolling.fell_to_deg.unwrap() - table.fell_to_deg.unwrap()).abs();
            assert!(gap < 1e-6, "{rolling:?} {table:?}");
            assert!((rolling.end_deg - table.end_deg).abs() < 1e-5, "{table:?}");
            // The lowest table slides during the fall and, losing energy, falls further.
            let low = of(Some(MUS[0]));
            assert!(low.slipped && !low.lifted, "{low:?}");
            assert!(low.fell_to_deg.unwrap() < rolling.fell_to_deg.unwrap() - 10.0);
        }
    }

    #[test]
    fn the_tilt_it_falls_to_depends_on_b_across_the_band() {
        let d = super::super::toy_disk();
        let f = fall(&d, &settings()).unwrap();
        assert_eq!(f.across.len(), f.bands.len() * ACROSS.len());
        for a in [80.0, 85.0] {
            let to: Vec<f64> = f
                .across
                .iter()
                .filter(|c| c.alpha0_deg == a)
                .filter_map(|c| c.fell_to_deg)
                .collect();
            let spread = to.iter().copied().fold(f64::NEG_INFINITY, f64::max)
                - to.iter().copied().fold(f64::INFINITY, f64::min);
            assert!(to.len() == ACROSS.len() && spread > 15.0, "{a}: {to:?}");
        }
    }

    /// The swing the study reports from its 10 ms samples (refined between them) against a
    /// direct run of eqs 23-25 from the same start sampled every 0.1 ms, read with nothing but
    /// the samples' least, greatest and trapezoidal mean.
    #[test]
    fn the_swing_over_the_run_matches_a_direct_run() {
        let d = super::super::toy_disk();
        let s = settings();
        for a in TILTS_DEG {
            let alpha0 = a.to_radians();
            let b = band(&d, alpha0).unwrap();
            let c = fall_from(&d, alpha0, b.start, None, &s).unwrap().unwrap();
            let mut m = steady_motion(&d, alpha0, b.start * d.a).unwrap();
            m.alpha -= NUDGE;
            let model = Rolling::<4>::new(d, Extras::default(), None);
            let sol = solve(
                Problem::new(&model, 0.0, model.state(&m), DURATION).sampled(1e-4),
                &s,
            )
            .unwrap();
            let tilt: Vec<f64> = sol.y.iter().map(|y| y[0].to_degrees()).collect();
            let lo = tilt.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = tilt.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            let area: f64 = sol
                .t
                .windows(2)
                .zip(tilt.windows(2))
                .map(|(t, x)| 0.5 * (t[1] - t[0]) * (x[0] + x[1]))
                .sum();
            let mean = area / (sol.t.last().unwrap() - sol.t[0]);
            eprintln!(
                "{a} deg: study {:.4}-{:.4} mean {:.4} settles {}; direct {lo:.4}-{hi:.4} mean {mean:.4}; first dip {:?}",
                c.swing.min_deg, c.swing.max_deg, c.swing.mean_deg, c.swing.settles, c.fell_to_deg
            );
            assert!((c.swing.min_deg - lo).abs() < 1e-3, "{c:?} {lo}");
            assert!((c.swing.max_deg - hi).abs() < 1e-3, "{c:?} {hi}");
            assert!((c.swing.mean_deg - mean).abs() < 1e-3, "{c:?} {mean}");
            // Without dissipation the rolling disk nutates on: it never settles.
            assert!(!c.swing.settles, "{c:?}");
        }
    }

    #[test]
    #[ignore = "a timing: prints what the study costs"]
    fn cost() {
        let d = super::super::toy_disk();
        let t0 = std::time::Instant::now();
        let f = fall(&d, &settings()).unwrap();
        let runs = f.cases.len() + f.across.len();
        eprintln!("fall study: {:?} for {runs} runs", t0.elapsed());
    }
}
