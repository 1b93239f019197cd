//! What a tilt does over a whole run, not at one extreme of it: the least and greatest tilt, the
//! tilt's mean over the run, and whether the motion settles into a lower steady rolling.
//!
//! From a sampled run $(t_j, \alpha_j, \dot\alpha_j)$ started at the steady tilt $\alpha_0$:
//! - the least and greatest $\alpha$: the samples' extremes, each refined where $\dot\alpha$
//!   changes sign on the cubic Hermite interpolant through $(\alpha, \dot\alpha)$ at both ends
//!   of the interval (error $O(\Delta t^4)$);
//! - the mean $\bar\alpha = \frac{1}{t_n - t_0}\int_{t_0}^{t_n}\alpha\,dt$ (trapezoids);
//! - *fallen*: from the first sample with $\alpha < \alpha_0 - 5°$ ([`FALLEN`]) on, the rest of
//!   the run is cut into an early and a late half; the *swing* of each is its
//!   $\max\alpha - \min\alpha$;
//! - *settles* (a lower steady rolling is reached): it has fallen, the late swing is at most
//!   [`DECAY`] of the early swing, and the late half's mean is below $\alpha_0 - 5°$. A
//!   conservative nutation (the rolling disk without dissipation) swings as far late as early
//!   and does not settle, whatever its least tilt.

use numerics::oscillation::bisect;
use serde::{Deserialize, Serialize};

/// The tilt is fallen once this far below the start's steady tilt (deg).
pub const FALLEN: f64 = 5.0;
/// The late swing must be at most this fraction of the early one for the motion to settle.
pub const DECAY: f64 = 0.5;

/// A run's tilt over the whole run (module documentation).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
pub struct Swing {
    /// Least tilt over the run (deg).
    pub min_deg: f64,
    /// Greatest tilt over the run (deg).
    pub max_deg: f64,
    /// Mean tilt over the run (deg).
    pub mean_deg: f64,
    /// Swing $\max\alpha - \min\alpha$ over the early half after the fall (deg); `None` when it
    /// never fell.
    pub early_swing_deg: Option<f64>,
    /// The same over the late half (deg).
    pub late_swing_deg: Option<f64>,
    /// Mean tilt over the late half after the fall (deg).
    pub late_mean_deg: Option<f64>,
    /// A lower steady rolling is reached: fallen, the swing decays to [`DECAY`] or less, and the
    /// late mean is below $\alpha_0 - 5°$.
    pub settles: bool,
}

/// The trapezoidal time mean of `x` over `t` (a single sample is its own mean).
fn mean(t: &[f64], x: &[f64]) -> f64 {
    let span = t.last().copied().unwrap_or(0.0) - t.first().copied().unwrap_or(0.0);
    if span <= 0.0 {
        return x.first().copied().unwrap_or(f64::NAN);
    }
    let area = t
        .windows(2)
        .zip(x.windows(2))
        .fold(0.0, |s, (t, x)| s + 0.5 * (t[1] - t[0]) * (x[0] + x[1]));
    area / span
}

/// The least and greatest of `alpha`, refined between samples where `alpha_dot` turns.
fn extremes(t: &[f64], alpha: &[f64], alpha_dot: &[f64]) -> (f64, f64) {
    let lo = alpha.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = alpha.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let mut out = (lo, hi);
    for j in 0..t.len().saturating_sub(1) {
        let (h, m0, m1) = (t[j + 1] - t[j], alpha_dot[j], alpha_dot[j + 1]);
        let (a0, a1) = (alpha[j], alpha[j + 1]);
        if m0 < 0.0 && m1 >= 0.0 {
            if let Some((_, a)) = hermite_minimum(a0, m0 * h, a1, m1 * h) {
                out.0 = out.0.min(a);
            }
        } else if m0 > 0.0 && m1 <= 0.0 {
            if let Some((_, a)) = hermite_minimum(-a0, -m0 * h, -a1, -m1 * h) {
                out.1 = out.1.max(-a);
            }
        }
    }
    out
}

impl Swing {
    /// The swing of a run sampled at times `t` with tilts `alpha` (rad) and tilt rates
    /// `alpha_dot` (rad/s), started from the steady tilt `alpha0` (rad).
    pub fn of(t: &[f64], alpha: &[f64], alpha_dot: &[f64], alpha0: f64) -> Swing {
        let (lo, hi) = extremes(t, alpha, alpha_dot);
        let fell = alpha.iter().position(|&a| a < alpha0 - FALLEN.to_radians());
        let halves = fell.filter(|&i| t.len() - i >= 4).map(|i| {
            let mid = i + (t.len() - i) / 2;
            let part = |r: std::ops::Range<usize>| {
                let (l, h) = extremes(&t[r.clone()], &alpha[r.clone()], &alpha_dot[r.clone()]);
                (
                    (h - l).to_degrees(),
                    mean(&t[r.clone()], &alpha[r]).to_degrees(),
                )
            };
            (part(i..mid + 1), part(mid..t.len()))
        });
        let early = halves.map(|h| h.0 .0);
        let late = halves.map(|h| h.1);
        let settles = match (early, late) {
            (Some(e), Some((l, m))) => l <= DECAY * e && m < alpha0.to_degrees() - FALLEN,
            _ => false,
        };
        Swing {
            min_deg: lo.to_degrees(),
            max_deg: hi.to_degrees(),
            mean_deg: mean(t, alpha).to_degrees(),
            early_swing_deg: early,
            late_swing_deg: late.map(|l| l.0),
            late_mean_deg: late.map(|l| l.1),
            settles,
        }
    }
}

/// The minimum of the cubic Hermite interpolant on $s \in [0, 1]$ with values `p0`, `p1` and
/// end slopes `d0 < 0 <= d1` (per unit $s$): where
/// $p'(s) = (6p_0 + 3d_0 - 6p_1 + 3d_1)s^2 + (6p_1 - 6p_0 - 4d_0 - 2d_1)s + d_0$ crosses zero
/// upward, as $(s, p(s))$; `None` for a zero-length interval.
pub(crate) fn hermite_minimum(p0: f64, d0: f64, p1: f64, d1: f64) -> Option<(f64, f64)> {
    let (qa, qb, qc) = (
        6.0 * p0 + 3.0 * d0 - 6.0 * p1 + 3.0 * d1,
        6.0 * p1 - 6.0 * p0 - 4.0 * d0 - 2.0 * d1,
        d0,
    );
    let slope = |s: f64| (qa * s + qb) * s + qc;
    let end = slope(1.0);
    if d0 == 0.0 || end.is_nan() || end < 0.0 {
        return None;
    }
    let (lo, hi) = bisect(0.0, 1.0, 1e-12, |s| slope(s) >= 0.0);
    let s = 0.5 * (lo + hi);
    let (s2, s3) = (s * s, s * s * s);
    let p = (2.0 * s3 - 3.0 * s2 + 1.0) * p0
        + (s3 - 2.0 * s2 + s) * d0
        + (-2.0 * s3 + 3.0 * s2) * p1
        + (s3 - s2) * d1;
    Some((s, p))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Samples of $\alpha(t)$ and its rate every `dt` over `[0, end]`.
    fn sampled(end: f64, dt: f64, f: impl Fn(f64) -> (f64, f64)) -> [Vec<f64>; 3] {
        let n = (end / dt).round() as usize;
        let t: Vec<f64> = (0..=n).map(|i| i as f64 * dt).collect();
        let (a, d) = t.iter().map(|&t| f(t)).unzip();
        [t, a, d]
    }

    #[test]
    fn the_hermite_minimum_is_exact_for_a_cubic() {
        // f(s) = (s - 0.3)^2 (s + 1): minimum 0 at s = 0.3.
        let f = |s: f64| (s - 0.3) * (s - 0.3) * (s + 1.0);
        let df = |s: f64| 2.0 * (s - 0.3) * (s + 1.0) + (s - 0.3) * (s - 0.3);
        let (s, p) = hermite_minimum(f(0.0), df(0.0), f(1.0), df(1.0)).unwrap();
        assert!((s - 0.3).abs() < 1e-10 && p.abs() < 1e-12, "{s} {p}");
    }

    /// A steady nutation between 60 and 80 deg: least, greatest and mean are its own, and
    /// however low it dips it does not settle.
    #[test]
    fn a_nutation_that_keeps_its_swing_does_not_settle() {
        let (c, r, w) = (70f64.to_radians(), 10f64.to_radians(), 7.3);
        let [t, a, d] = sampled(3.0, 1e-2, |t| {
            (c + r * (w * t).cos(), -r * w * (w * t).sin())
        });
        let s = Swing::of(&t, &a, &d, 80f64.to_radians());
        assert!((s.min_deg - 60.0).abs() < 1e-6, "{s:?}");
        assert!((s.max_deg - 80.0).abs() < 1e-6, "{s:?}");
        // The mean of a cosine over 3 s is its centre up to r sin(3w)/(3w).
        let exact = 70.0 + 10.0 * (3.0 * w).sin() / (3.0 * w);
        assert!((s.mean_deg - exact).abs() < 1e-3, "{s:?} {exact}");
        assert!(!s.settles, "{s:?}");
        let (e, l) = (s.early_swing_deg.unwrap(), s.late_swing_deg.unwrap());
        assert!(l > 0.9 * e, "{s:?}");
    }

    /// A nutation that decays onto 55 deg settles; the same decay onto 78 deg (above the
    /// start's 80 less 5) does not, and neither does one that never fell.
    #[test]
    fn a_decaying_swing_settles_only_below_the_start() {
        let run = |centre: f64| {
            let (c, r, w, k) = (centre.to_radians(), 20f64.to_radians(), 7.3, 2.0);
            sampled(3.0, 1e-2, move |t| {
                let e = (-k * t).exp();
                let a = c + r * e * (w * t).cos();
                (a, -r * e * (k * (w * t).cos() + w * (w * t).sin()))
            })
        };
        let [t, a, d] = run(55.0);
        let s = Swing::of(&t, &a, &d, 80f64.to_radians());
        assert!(s.settles, "{s:?}");
        let [t, a, d] = run(78.0);
        assert!(!Swing::of(&t, &a, &d, 80f64.to_radians()).settles);
        let [t, a, d] = sampled(3.0, 1e-2, |_| (80f64.to_radians(), 0.0));
        let s = Swing::of(&t, &a, &d, 80f64.to_radians());
        assert!(!s.settles && s.early_swing_deg.is_none(), "{s:?}");
        assert!((s.mean_deg - 80.0).abs() < 1e-12, "{s:?}");
    }
}
