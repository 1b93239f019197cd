//! Peak times of pulses whose shape drifts from one pulse to the next.
//!
//! The paper's half-height method times a pulse by the mean of its rising and falling crossings
//! of one level. That is the pulse's centre only while the pulse keeps its shape: in the light
//! signal the tilt $\alpha$ of eq 29 drifts with $\Omega$, so successive pulses differ in height,
//! in width and in their troughs, and each pulse changes while it is being recorded. Near pulse
//! $i$ (centre $t_i$, rate $\Omega_i$) write the signal in the heading offset
//! $\varphi = \Omega_i (t - t_i)$ as a pulse that is symmetric in $\varphi$ at each instant and
//! drifts slowly:
//! $$v(t) = S_i(\varphi) + (t - t_i)\,D_i(\varphi) + O\bigl((t - t_i)^2\bigr),
//!   \qquad S_i, D_i \text{ even in } \varphi.$$
//! The drift term is odd about $t_i$ and moves both crossings of a level the same way, which is
//! the bias (up to 19 us at 378 rad/s on the coverage study's traces). $S_i$ is unknown (a real
//! scope's pulses have a shape nobody wrote down), but $D_i$, the rate of change of the pulse
//! at a fixed heading offset, is measured by the neighbouring pulses: the same offset falls at
//! $t_{i\pm1} + \varphi/\Omega_{i\pm1}$ in them, and
//! $$D_i(\varphi) \approx \frac{v\bigl(t_{i+1} + \varphi/\Omega_{i+1}\bigr) -
//!   v\bigl(t_{i-1} + \varphi/\Omega_{i-1}\bigr)}{t_{i+1} - t_{i-1}}$$
//! (a one-sided difference at the first and the last peak), the samples between samples
//! interpolated by the cubic through four. The pulse with its drift removed,
//! $u(t) = v(t) - (t - t_i)\,D_i(\varphi)$, is symmetric about $t_i$ whatever $S_i$ is, and is
//! timed by the mean of its crossings of its own half height
//! $\tfrac12(\max u + \min u)$, as in [`peaks`](crate::light_analysis::peak_search). An error $\delta$ in a
//! neighbour's centre adds $S_i'(\varphi)\,\delta$ to $D_i$, odd in $\varphi$, hence an even
//! term to $u$: it does not move the centre to first order. A change of height alone is the
//! special case $D_i = \gamma_i (S_i - b)$.
//!
//! $D_i$ carries the noise of two samples: at a crossing $w$ from the centre it adds about
//! $\sigma_v^2 (w/T)^2/2$ to the signal's variance ($T$ the period), which is added to the
//! crossing's. Pulses whose periods on either side differ by more than the anomaly rule of
//! [`rates`](crate::light_analysis::rates) allows (0.6-1.6) are a missed or stray peak's
//! neighbours: they keep their plain times. So does a pulse whose neighbours disagree: re-timed
//! with the drift from the earlier neighbour alone and from the later one alone, it must land
//! at the same time within the noise (see [`MAX_DISAGREEMENT`]); where one neighbour is
//! spoiled (fading into the end of the record, or carrying what the artifacts leave) the
//! difference it makes would otherwise be taken for drift.

use crate::light_analysis::peak::{edge, Peak};

/// $v$ at time `x` by the cubic through the four samples around it (`None` outside).
fn interpolate(t: &[f64], v: &[f64], x: f64) -> Option<f64> {
    let n = t.len();
    let k = t.partition_point(|&s| s <= x);
    if k < 2 || k + 1 >= n {
        return None;
    }
    let s0 = k - 2;
    let mut sum = 0.0;
    for i in s0..s0 + 4 {
        let mut l = 1.0;
        for j in s0..s0 + 4 {
            if i != j {
                l *= (x - t[j]) / (t[i] - t[j]);
            }
        }
        sum += l * v[i];
    }
    Some(sum)
}

/// The largest difference between a pulse re-timed with the drift from its earlier neighbour
/// and with the drift from its later one, in the plain time's standard uncertainty, over half
/// the central re-timing's correction (which the one-sided differences leave a part of: the
/// drift's curvature). The difference is at most 3.6 uncertainties on 8
/// clean and 4.8 on 8 artifact-laden traces of the coverage study (about 1200 pulses each); on
/// the noise-free law trace of `experiment_bias` (uncertainty 0.2 us) at most 3.9 us against
/// corrections of 12-15 us on the kept peaks. At the last fitted pulse of the
/// `artifacts_leave_beta_and_t0_within_the_targets` trace (drift, hum, clipping and dropped
/// samples together), whose later neighbour fades into what the artifacts leave, it is 21.6
/// uncertainties against a correction of 15.8: re-timed there, the pulse moved by -0.94 ms and
/// took t0 1.2 ms early.
const MAX_DISAGREEMENT: f64 = 6.0;

/// The rising and falling crossings (time, uncertainty, slope) of pulse `i` with its drift
/// removed, the drift measured between peaks `a` and `b` (`a < b`; either may be `i`, for a
/// one-sided difference); `None` where the pulse or its neighbours run off the record or a
/// crossing is not found.
#[allow(clippy::too_many_arguments)]
fn retime_one(
    t: &[f64],
    v: &[f64],
    sigma_v: f64,
    c: &[f64],
    period: &[f64],
    peak: &Peak,
    i: usize,
    (a, b): (usize, usize),
) -> Option<[(f64, f64, f64); 2]> {
    let (ti, ti_period) = (c[i], period[i]);
    if !(ti_period > 0.0 && c[b] > c[a]) {
        return None;
    }
    // The pulse's samples: half a period either side of its centre.
    let lo = t.partition_point(|&s| s < ti - 0.5 * ti_period);
    let hi = t.partition_point(|&s| s <= ti + 0.5 * ti_period);
    if hi < lo + 8 {
        return None;
    }
    let mut u = Vec::with_capacity(hi - lo);
    for j in lo..hi {
        let x = t[j] - ti;
        let at = |k: usize| interpolate(t, v, c[k] + x * period[k] / ti_period);
        u.push(v[j] - x * (at(b)? - at(a)?) / (c[b] - c[a]));
    }
    let ts = &t[lo..hi];
    let m = ts.partition_point(|&s| s < ti).min(u.len() - 1);
    let (umax, umin) = u
        .iter()
        .fold((f64::MIN, f64::MAX), |(p, q), &x| (p.max(x), q.min(x)));
    let level = 0.5 * (umax + umin);
    let kr = (0..m).rev().find(|&k| u[k] <= level && u[k + 1] > level)?;
    let kf = (m..u.len() - 1).find(|&k| u[k] >= level && u[k + 1] < level)?;
    let last_fall = (kf..u.len() - 1)
        .rfind(|&k| u[k] >= level && u[k + 1] < level)
        .unwrap_or(kf);
    let w = 0.5 * (peak.fall - peak.rise);
    let sigma_u = sigma_v * (1.0 + 0.5 * (w / ti_period).powi(2)).sqrt();
    Some([
        edge(ts, &u, 0, kr, level, sigma_u, true),
        edge(ts, &u, kf, last_fall, level, sigma_u, false),
    ])
}

/// Re-times `peaks` (found on samples `v` at times `t`, noise `sigma_v`) with each pulse's
/// drift, measured by its neighbours, removed (see the module's documentation).
pub fn retime_drifting_pulses(t: &[f64], v: &[f64], sigma_v: f64, peaks: &mut [Peak]) {
    let n = peaks.len();
    if n < 3 || t.len() < 8 {
        return;
    }
    let c: Vec<f64> = peaks.iter().map(|p| p.t).collect();
    // Local periods: the mean of the two cycles around each peak.
    let period: Vec<f64> = (0..n)
        .map(|i| {
            let (a, b) = (i.saturating_sub(1), (i + 1).min(n - 1));
            (c[b] - c[a]) / (b - a) as f64
        })
        .collect();
    let centre = |r: &[(f64, f64, f64); 2]| 0.5 * (r[0].0 + r[1].0);
    for i in 0..n {
        let (a, b) = (i.saturating_sub(1), (i + 1).min(n - 1));
        let plain = peaks[i];
        if i > 0 && i + 1 < n {
            let r = (c[i + 1] - c[i]) / (c[i] - c[i - 1]);
            if !(0.6..=1.6).contains(&r) {
                continue;
            }
        }
        let Some(r) = retime_one(t, v, sigma_v, &c, &period, &plain, i, (a, b)) else {
            continue;
        };
        // The neighbours must agree: re-timed with the drift from either side alone, the pulse
        // lands within `MAX_DISAGREEMENT` of its plain uncertainty plus half the correction
        // (the one-sided differences also see the drift's curvature), or it keeps its plain
        // time.
        if i > 0 && i + 1 < n {
            let fwd = retime_one(t, v, sigma_v, &c, &period, &plain, i, (i, b));
            let bwd = retime_one(t, v, sigma_v, &c, &period, &plain, i, (a, i));
            match (fwd, bwd) {
                (Some(f), Some(g))
                    if (centre(&f) - centre(&g)).abs()
                        <= MAX_DISAGREEMENT * plain.sigma + 0.5 * (centre(&r) - plain.t).abs() => {}
                _ => continue,
            }
        }
        let [(tr, sr, gr), (tf, sf, gf)] = r;
        let p = &mut peaks[i];
        p.rise = tr;
        p.fall = tf;
        p.t = 0.5 * (tr + tf);
        p.sigma = 0.5 * (sr * sr + sf * sf).sqrt();
        p.slope = 0.5 * (gr + gf);
    }
}

#[cfg(test)]
mod tests {
    use crate::light_analysis::peak_search::{find_peaks, PeakSettings};
    use std::f64::consts::PI;

    /// Pulses of a shape unlike the light model's (Gaussian in the heading), at a constant rate
    /// of 20 turns/s, whose height triples, width grows by half and baseline rises over the
    /// record: the plain crossings are off the centres; with the drift removed they are not.
    #[test]
    fn drifting_pulses_of_any_shape_are_timed_at_their_centres() {
        let (dt, f) = (2e-4, 20.0);
        let t: Vec<f64> = (0..10_000).map(|j| j as f64 * dt).collect();
        let v: Vec<f64> = t
            .iter()
            .map(|&t| {
                let phi = (2.0 * PI * f * t + PI).rem_euclid(2.0 * PI) - PI;
                let width = 0.3 * (1.0 + 0.25 * t);
                0.1 + 0.05 * t + (1.0 + t) * (-0.5 * (phi / width).powi(2)).exp()
            })
            .collect();
        let worst = |drift: bool| {
            let s = PeakSettings {
                height_correction: drift,
                ..PeakSettings::default()
            };
            let p = find_peaks(&t, &v, dt, 1e-3, &s);
            assert!(p.len() >= 38, "{}", p.len());
            p[1..p.len() - 1]
                .iter()
                .map(|p| (p.t - (p.t * f).round() / f).abs())
                .fold(0.0, f64::max)
        };
        let (plain, fixed) = (worst(false), worst(true));
        println!(
            "worst offsets: plain {:.2} us, drift removed {:.3} us",
            1e6 * plain,
            1e6 * fixed
        );
        assert!(plain > 5e-6, "{plain}");
        assert!(fixed < 0.5e-6, "{fixed}");
    }
}
