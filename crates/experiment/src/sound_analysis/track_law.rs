//! Eq 79 fitted to a pitch track's frames.
//!
//! Each frame $[a_k, b_k]$ gives $\Omega_k$, the mean of the rate over the frame weighted by the
//! window's energy $w^2$, $w$ the Hann window (a spectrum's centroid is the instantaneous
//! frequency's mean weighted by the windowed signal's energy); the law's own weighted mean
//! $$\bar\Omega_k = \frac{\int_{a_k}^{b_k} w^2(t)\,\Omega(t)\,dt}{\int_{a_k}^{b_k} w^2(t)\,dt}, \qquad
//!   \Omega(t) = \left(\frac{C}{t_0 - t}\right)^{1/(\beta+2)} \quad (79),$$
//! (32 midpoints) is fitted to it, so the rate's change within a frame costs no bias.
//! Frames do not overlap and their errors are taken as independent, each with its own
//! variance $\sigma_k^2$ from the track (noise and the pitch's motion) as the weight; the
//! covariance is $s^2 (J^{\mathsf T}J)^{-1}$ of the whitened problem with $s^2$ the reduced
//! $\chi^2$ ([`least_squares`](crate::fit::least_squares), [`Scale::Unknown`]), so a
//! common misstatement of the $\sigma_k$ is measured by the residuals.

use crate::fit::band::Row;
use crate::fit::law_fit::LawFit;
use crate::fit::least_squares::Problem;
use nalgebra::SVector;
use serde::Serialize;
use std::f64::consts::PI;

/// Midpoints per frame of the law's weighted mean.
const MIDPOINTS: usize = 32;

/// Eq 79's frame means weighted by the Hann window's square.
pub(crate) struct TrackLaw<'a> {
    /// Frame starts and ends (s), and the frames' rates (rad/s).
    pub a: &'a [f64],
    /// (see `a`)
    pub b: &'a [f64],
    /// (see `a`)
    pub y: &'a [f64],
}

impl Problem<3> for TrackLaw<'_> {
    fn y(&self) -> &[f64] {
        self.y
    }
    fn model(&self, p: &SVector<f64, 3>, i: usize) -> (f64, SVector<f64, 3>) {
        let q = 1.0 / (p[0] + 2.0);
        let (mut sw, mut m) = (0.0, 0.0);
        let mut g = SVector::<f64, 3>::zeros();
        for j in 0..MIDPOINTS {
            let u = (j as f64 + 0.5) / MIDPOINTS as f64;
            let w = (PI * u).sin().powi(4);
            let t = self.a[i] + u * (self.b[i] - self.a[i]);
            let ln_tau = (p[1] - t).ln();
            let om = (q * (p[2] - ln_tau)).exp();
            sw += w;
            m += w * om;
            g += w * SVector::<f64, 3>::new(
                -q * q * om * (p[2] - ln_tau),
                -q * om / (p[1] - t),
                q * om,
            );
        }
        (m / sw, g / sw)
    }
    fn rows(&self, _p: &SVector<f64, 3>) -> Vec<Row> {
        (0..self.y.len())
            .map(|i| Row {
                start: i,
                coef: vec![1.0],
            })
            .collect()
    }
    fn admissible(&self, p: &SVector<f64, 3>) -> bool {
        let bmax = self.b.iter().copied().fold(f64::MIN, f64::max);
        p.iter().all(|v| v.is_finite()) && p[0] > -0.9 && p[0] < 50.0 && p[1] > bmax
    }
}

/// Eq 79 fitted to a frequency track.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TrackFit {
    /// Eq 79's $\beta$, $t_0$ and $\ln C$ with their uncertainties, read as this fit's own
    /// fields.
    #[serde(flatten)]
    pub parameters: LawFit,
    /// The rms residual (rad/s).
    pub rms: f64,
    /// The reduced $\chi^2$ of the weighted residuals.
    pub chi2_dof: f64,
    /// Frames fitted.
    pub n: usize,
    /// The law's frame means (rad/s), one per track point.
    pub model: Vec<f64>,
}

crate::fit::law_fit::reads_law_fit!(TrackFit);
