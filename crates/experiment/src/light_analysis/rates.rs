//! The paper's rates from the peak times $t_i$:
//! $$\Omega_i = \frac{2\pi}{t_{i+1} - t_i}, \qquad
//!   \frac{d\Omega_i}{dt} = \frac{2(\Omega_{i+1} - \Omega_i)}{t_{i+2} - t_i}.$$
//! $\Omega_i$ is the mean rate over cycle $i$, placed at its middle
//! $\bar t_i = \tfrac12(t_i + t_{i+1})$ (exact to second order in the period); $d\Omega_i/dt$ is placed
//! at $t_{i+1}$ and paired with the mean rate over the two cycles, $4\pi/(t_{i+2} - t_i)$.

use serde::Serialize;
use std::f64::consts::PI;

/// One cycle: $\Omega_i$.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Cycle {
    /// Index $i$ of its first peak.
    pub i: usize,
    /// Its middle $\bar t_i$ (s).
    pub t: f64,
    /// Its period $t_{i+1} - t_i$ (s).
    pub period: f64,
    /// $\Omega_i$ (rad/s).
    pub omega: f64,
    /// Its period is out of line with its neighbours' (a missed or a stray peak).
    pub anomalous: bool,
}

/// Two cycles: $d\Omega_i/dt$.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Acceleration {
    /// Index $i$ of its first peak.
    pub i: usize,
    /// Its time $t_{i+1}$ (s).
    pub t: f64,
    /// The mean rate over the two cycles, $4\pi/(t_{i+2} - t_i)$ (rad/s).
    pub omega: f64,
    /// $d\Omega_i/dt$ (rad/s^2).
    pub omega_dot: f64,
}

/// $\Omega_i$ for every pair of consecutive peaks. A period outside 0.6-1.6 times the median of
/// its six neighbours marks the cycle anomalous.
pub fn cycles(t: &[f64]) -> Vec<Cycle> {
    let d: Vec<f64> = t.windows(2).map(|w| w[1] - w[0]).collect();
    (0..d.len())
        .map(|i| {
            let mut nb: Vec<f64> = (i.saturating_sub(3)..(i + 4).min(d.len()))
                .filter(|&j| j != i)
                .map(|j| d[j])
                .collect();
            nb.sort_by(f64::total_cmp);
            let anomalous = !nb.is_empty() && {
                let r = d[i] / nb[nb.len() / 2];
                !(0.6..=1.6).contains(&r)
            };
            Cycle {
                i,
                t: 0.5 * (t[i] + t[i + 1]),
                period: d[i],
                omega: 2.0 * PI / d[i],
                anomalous,
            }
        })
        .collect()
}

/// $d\Omega_i/dt$ for every three consecutive peaks.
pub fn accelerations(t: &[f64]) -> Vec<Acceleration> {
    t.windows(3)
        .enumerate()
        .map(|(i, w)| {
            let (o1, o2) = (2.0 * PI / (w[1] - w[0]), 2.0 * PI / (w[2] - w[1]));
            Acceleration {
                i,
                t: w[1],
                omega: 4.0 * PI / (w[2] - w[0]),
                omega_dot: 2.0 * (o2 - o1) / (w[2] - w[0]),
            }
        })
        .collect()
}
