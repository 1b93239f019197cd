//! Peak times by half-height crossings, the paper's method: the time of the peak of cycle $i$ is
//! the mean of the rising and the falling crossings of half height,
//! $t_i = \tfrac12(t_i^{\uparrow} + t_i^{\downarrow})$.
//!
//! "Half height" adapts to an amplitude that changes through the record: the level is
//! $L = \tfrac12(\max + \min)$ of the signal over a centred window of a few local periods
//! (a running min/max envelope). A first pass uses a fixed window; the second and third use
//! `window_periods` local periods, measured by the pass before. A crossing is counted only
//! when the signal leaves a hysteresis band $L \pm H$, and located inside its sample interval on
//! the cubic through the four samples around it. Where the envelope spans less than
//! `min_span_sigmas` noise deviations there is no signal, and no crossing.
//!
//! Each crossing's uncertainty follows from the noise $\sigma_v$ (estimated from the data), the
//! cubic's Lagrange weights $\ell_j$ at the root and the edge's slope $g$ (the least-squares line
//! through the six samples around the crossing, `peak::edge_slope`):
//! $\sigma_\times^2 = \sigma_v^2 \sum_j \ell_j^2 / g^2$, and
//! $\sigma_{t_i}^2 = \tfrac14(\sigma_\uparrow^2 + \sigma_\downarrow^2)$.
//!
//! The mean of two crossings is the centre of a pulse that keeps its shape; the light's pulses
//! drift (the tilt follows $\Omega$), so by default each pulse is then re-timed with its drift,
//! measured by its neighbours, removed ([`pulse_drift`](crate::light_analysis::pulse_drift)), and
//! last corrected for the change of $\Omega$ within the pulse ([`correct_chirp`]).

use crate::light_analysis::peak::{edge, Peak};
use crate::light_analysis::pulse_drift::retime_drifting_pulses;
use serde::{Deserialize, Serialize};

/// How peaks are found.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct PeakSettings {
    /// Width of the first pass's envelope window (s).
    pub initial_window: f64,
    /// Width of the later passes' windows, in local periods.
    pub window_periods: f64,
    /// Hysteresis half-band as a fraction of the envelope's span.
    pub hysteresis: f64,
    /// The envelope must span this many noise deviations for a crossing to count.
    pub min_span_sigmas: f64,
    /// Correct the mean of the crossings for the change of $\Omega$ within a pulse (see
    /// [`correct_chirp`]); false gives the paper's plain mean.
    pub chirp_correction: bool,
    /// Re-time each pulse with its drift (of height, width, troughs: the tilt's drift with
    /// $\Omega$), measured by its neighbours, removed (see
    /// [`pulse_drift`](crate::light_analysis::pulse_drift)); false gives the crossings of one level.
    #[serde(default)]
    pub height_correction: bool,
}

impl Default for PeakSettings {
    fn default() -> Self {
        Self {
            initial_window: 0.2,
            window_periods: 3.0,
            hysteresis: 0.15,
            min_span_sigmas: 10.0,
            chirp_correction: true,
            height_correction: true,
        }
    }
}

/// The noise of a signal: $\sigma_v$ from the median absolute second difference
/// ($\mathrm{Var}(v_{j+1} - 2v_j + v_{j-1}) = 6\sigma_v^2$ for white noise), floored at the
/// quantisation noise $\delta/\sqrt{12}$, $\delta$ the smallest step between samples.
pub fn noise_level(v: &[f64]) -> f64 {
    if v.len() < 3 {
        return 0.0;
    }
    let mut d2: Vec<f64> = v
        .windows(3)
        .map(|w| (w[2] - 2.0 * w[1] + w[0]).abs())
        .collect();
    let mid = d2.len() / 2;
    let (_, med, _) = d2.select_nth_unstable_by(mid, f64::total_cmp);
    let sigma = 1.4826 * *med / 6f64.sqrt();
    let lsb = v
        .windows(2)
        .map(|w| (w[1] - w[0]).abs())
        .filter(|d| *d > 0.0)
        .fold(f64::INFINITY, f64::min);
    if lsb.is_finite() {
        sigma.max(lsb / 12f64.sqrt())
    } else {
        sigma
    }
}

/// Running max and min of `v` over the windows $[j - h_j, j + h_j]$. `half` must change by at most
/// one from a sample to the next (so that both window ends move forward): O(n) with two
/// monotonic queues.
fn envelope(v: &[f64], half: &[usize]) -> (Vec<f64>, Vec<f64>) {
    use std::collections::VecDeque;
    let n = v.len();
    let (mut hi, mut lo) = (vec![0.0; n], vec![0.0; n]);
    let (mut qmax, mut qmin): (VecDeque<usize>, VecDeque<usize>) =
        (VecDeque::new(), VecDeque::new());
    let mut next = 0; // next index to enter
    for j in 0..n {
        let left = j.saturating_sub(half[j]);
        let right = (j + half[j]).min(n - 1);
        while next <= right {
            while qmax.back().is_some_and(|&b| v[b] <= v[next]) {
                qmax.pop_back();
            }
            qmax.push_back(next);
            while qmin.back().is_some_and(|&b| v[b] >= v[next]) {
                qmin.pop_back();
            }
            qmin.push_back(next);
            next += 1;
        }
        while qmax.front().is_some_and(|&f| f < left) {
            qmax.pop_front();
        }
        while qmin.front().is_some_and(|&f| f < left) {
            qmin.pop_front();
        }
        hi[j] = qmax.front().map_or(v[j], |&f| v[f]);
        lo[j] = qmin.front().map_or(v[j], |&f| v[f]);
    }
    (hi, lo)
}

/// Makes `half` change by at most one between neighbours, never raising a value.
fn lipschitz(half: &mut [usize]) {
    for j in 1..half.len() {
        half[j] = half[j].min(half[j - 1] + 1);
    }
    for j in (0..half.len().saturating_sub(1)).rev() {
        half[j] = half[j].min(half[j + 1] + 1);
    }
}

/// The peaks of one pass with envelope half-widths `half`.
fn pass(t: &[f64], v: &[f64], half: &[usize], sigma_v: f64, s: &PeakSettings) -> Vec<Peak> {
    let (hi, lo) = envelope(v, half);
    let min_span = s.min_span_sigmas * sigma_v;
    let mut peaks = Vec::new();
    #[derive(PartialEq, Clone, Copy)]
    enum State {
        Unknown,
        Low,
        High,
    }
    let mut state = State::Unknown;
    let mut entered = 0; // where the current state began
    let mut rise: Option<(f64, f64, f64, f64, f64)> = None;
    for j in 0..v.len() {
        let span = hi[j] - lo[j];
        if span <= min_span {
            state = State::Unknown;
            rise = None;
            continue;
        }
        let level = 0.5 * (hi[j] + lo[j]);
        let band = (s.hysteresis * span).max(3.0 * sigma_v);
        let lvl = |k: usize| 0.5 * (hi[k] + lo[k]);
        if v[j] > level + band && state != State::High {
            if state == State::Low {
                let mut k = j - 1;
                while k > entered && v[k] > lvl(k) {
                    k -= 1;
                }
                let l = 0.5 * (lvl(k) + lvl(k + 1));
                let (tr, sr, gr) = edge(t, v, entered, k, l, sigma_v, true);
                rise = Some((tr, sr, l, gr, lo[k]));
            }
            state = State::High;
            entered = j;
        } else if v[j] < level - band && state != State::Low {
            if state == State::High {
                if let Some((tr, sr, l, gr, lo_r)) = rise.take() {
                    // The same level as the rise, so that a symmetric pulse gives its centre
                    // even while the envelope changes.
                    let mut k = j - 1;
                    while k > entered && v[k] < l {
                        k -= 1;
                    }
                    let l = if v[k] >= l && v[k + 1] < l {
                        l
                    } else {
                        0.5 * (lvl(k) + lvl(k + 1))
                    };
                    let height = l - 0.5 * (lo_r + lo[k]);
                    let (tf, sf, gf) = edge(t, v, entered, k, l, sigma_v, false);
                    peaks.push(Peak {
                        t: 0.5 * (tr + tf),
                        sigma: 0.5 * (sr * sr + sf * sf).sqrt(),
                        rise: tr,
                        fall: tf,
                        span,
                        height,
                        slope: 0.5 * (gr + gf),
                    });
                }
            }
            state = State::Low;
            entered = j;
        }
    }
    peaks
}

/// Envelope half-widths of `periods` local periods, the local period interpolated between the
/// peaks found so far (the median of five neighbouring intervals, against stray peaks).
fn adaptive_half(t: &[f64], peaks: &[Peak], periods: f64, dt: f64, max_half: usize) -> Vec<usize> {
    let n = t.len();
    if peaks.len() < 3 {
        return vec![max_half; n];
    }
    let raw: Vec<(f64, f64)> = peaks
        .windows(2)
        .map(|w| (0.5 * (w[0].t + w[1].t), w[1].t - w[0].t))
        .collect();
    let med: Vec<(f64, f64)> = (0..raw.len())
        .map(|i| {
            let a = i.saturating_sub(2);
            let b = (i + 3).min(raw.len());
            let mut w: Vec<f64> = raw[a..b].iter().map(|x| x.1).collect();
            w.sort_by(f64::total_cmp);
            (raw[i].0, w[w.len() / 2])
        })
        .collect();
    let mut half = Vec::with_capacity(n);
    let mut k = 0;
    for &tj in t {
        while k + 1 < med.len() && med[k + 1].0 <= tj {
            k += 1;
        }
        let p = if tj <= med[0].0 {
            med[0].1
        } else if k + 1 >= med.len() {
            med[med.len() - 1].1
        } else {
            let (a, b) = (med[k], med[k + 1]);
            a.1 + (b.1 - a.1) * (tj - a.0) / (b.0 - a.0)
        };
        let h = (0.5 * periods * p / dt).ceil() as usize;
        half.push(h.clamp(2, max_half));
    }
    lipschitz(&mut half);
    half
}

/// The peaks of a signal sampled at (strictly increasing) times `t` with noise `sigma_v`.
pub fn find_peaks(t: &[f64], v: &[f64], dt: f64, sigma_v: f64, s: &PeakSettings) -> Vec<Peak> {
    let n = t.len();
    if n < 8 || dt.is_nan() || dt <= 0.0 {
        return Vec::new();
    }
    let max_half = ((0.5 * s.initial_window / dt).ceil() as usize).clamp(2, n);
    let mut peaks = pass(t, v, &vec![max_half; n], sigma_v, s);
    for _ in 0..2 {
        let half = adaptive_half(t, &peaks, s.window_periods, dt, max_half);
        peaks = pass(t, v, &half, sigma_v, s);
    }
    if s.height_correction {
        retime_drifting_pulses(t, v, sigma_v, &mut peaks);
    }
    if s.chirp_correction {
        correct_chirp(&mut peaks);
    }
    peaks
}

/// Removes the bias a changing rate gives the mean of two crossings.
///
/// A pulse symmetric in the heading, crossing half height at $\psi_c \mp \delta$, is crossed at
/// times $t(\psi_c \mp \delta)$ whose mean is $t(\psi_c) + \tfrac12 t''(\psi_c)\delta^2$, with
/// $t'' = d^2t/d\psi^2 = -\dot\Omega/\Omega^3$. With the half-width in time
/// $w = \tfrac12(t^{\downarrow} - t^{\uparrow}) \approx \delta/\Omega$ the peak is
/// $t(\psi_c) = \bar t + \tfrac12 (\dot\Omega/\Omega)\,w^2$, where
/// $\dot\Omega/\Omega = -d\ln(t_{i+1} - t_i)/dt$ is taken from the neighbouring periods.
/// Near $t_0$ this is a shift of a sample or more, which would otherwise bias $t_0$ and $\beta$.
pub fn correct_chirp(peaks: &mut [Peak]) {
    let n = peaks.len();
    if n < 3 {
        return;
    }
    let t: Vec<f64> = peaks.iter().map(|p| p.t).collect();
    for (i, peak) in peaks.iter_mut().enumerate() {
        let j = i.clamp(1, n - 2);
        let (d0, d1) = (t[j] - t[j - 1], t[j + 1] - t[j]);
        if d0 <= 0.0 || d1 <= 0.0 {
            continue;
        }
        let rate = -(d1 / d0).ln() / (0.5 * (d0 + d1));
        let w = 0.5 * (peak.fall - peak.rise);
        peak.t += 0.5 * rate * w * w;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn envelope_matches_brute_force() {
        let v: Vec<f64> = (0..200).map(|i| ((i * 37 % 101) as f64).sin()).collect();
        let mut half: Vec<usize> = (0..200).map(|i| 3 + (i / 20) % 5).collect();
        lipschitz(&mut half);
        let (hi, lo) = envelope(&v, &half);
        for j in 0..200usize {
            let a = j.saturating_sub(half[j]);
            let b = (j + half[j]).min(199);
            let m = v[a..=b].iter().cloned().fold(f64::MIN, f64::max);
            let mn = v[a..=b].iter().cloned().fold(f64::MAX, f64::min);
            assert_eq!((hi[j], lo[j]), (m, mn));
        }
    }

    #[test]
    fn times_the_peaks_of_a_sine() {
        let dt = 2e-4;
        let w = 2.0 * std::f64::consts::PI * 37.0;
        let t: Vec<f64> = (0..5000).map(|j| j as f64 * dt).collect();
        let v: Vec<f64> = t.iter().map(|t| 1.0 + (w * t).cos()).collect();
        let p = find_peaks(&t, &v, dt, 1e-3, &PeakSettings::default());
        assert!(p.len() >= 35, "{}", p.len());
        for pk in &p {
            let cycles = pk.t * 37.0;
            assert!((cycles - cycles.round()).abs() < 1e-5, "{}", pk.t);
        }
    }
}
