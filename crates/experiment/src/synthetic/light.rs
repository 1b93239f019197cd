//! The light model: a lamp and a detector at fixed directions, the disk's upper face a mirror
//! with a soft reflection lobe, read through a [`Scope`].
//!
//! The symmetry axis is $\hat{\mathbf 1} = -\sin\alpha\,\hat{\mathbf r} - \cos\alpha\,\hat{\mathbf z}$
//! with $\hat{\mathbf r} = (\sin\psi, -\cos\psi, 0)$ and $\psi$ the heading (the angle of
//! $\hat{\mathbf 2}$ from the lab's x axis, $\dot\psi = \Omega$), so the upper face's normal is
//! $$\hat{\mathbf n} = -\hat{\mathbf 1} = (\sin\alpha\sin\psi,\ -\sin\alpha\cos\psi,\ \cos\alpha).$$
//! It is tilted by $\alpha$ from the vertical and turns with the precession: one turn per cycle
//! of $\Omega$. A lamp in direction $\hat{\mathbf L}$ (from the disk) is mirrored into
//! $\hat{\mathbf m} = 2(\hat{\mathbf L}\cdot\hat{\mathbf n})\hat{\mathbf n} - \hat{\mathbf L}$,
//! and a detector in direction $\hat{\mathbf D}$ reads
//! $$V = V_0 + G\,\max(0, \hat{\mathbf m}\cdot\hat{\mathbf D})^{q}$$
//! ($V_0$ baseline, $G$ gain, $q$ the lobe's sharpness: its angular half-width is about
//! $1/\sqrt q$). With the detector a little off the flat mirror's reflection, the mirrored beam
//! sweeps a circle of radius $\approx 2\alpha$ past it once per turn: one pulse per cycle, sharp
//! while $\alpha$ is large, a shallow wave as $\alpha \to 0$. When the disk lies flat the signal is
//! the constant $V_0 + G(\hat{\mathbf m}_0\cdot\hat{\mathbf D})^q$.

use crate::error::ExperimentError;
use crate::synthetic::scope::Scope;
use serde::{Deserialize, Serialize};

/// A direction from the disk: elevation above the table and azimuth from the lab's x axis (rad).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Direction {
    /// Elevation above the horizontal (rad).
    pub elevation: f64,
    /// Azimuth from the lab's x axis, counter-clockwise seen from above (rad).
    pub azimuth: f64,
}

impl Direction {
    /// The unit vector.
    pub fn unit(&self) -> [f64; 3] {
        let (se, ce) = self.elevation.sin_cos();
        let (sa, ca) = self.azimuth.sin_cos();
        [ce * ca, ce * sa, se]
    }
}

/// Lamp, detector, lobe and scope.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct LightModel {
    /// Direction of the lamp from the disk.
    pub lamp: Direction,
    /// Direction of the detector from the disk.
    pub detector: Direction,
    /// Lobe exponent $q$ of $(\hat{\mathbf m}\cdot\hat{\mathbf D})^q$.
    pub lobe: f64,
    /// Gain $G$ (V at the lobe's centre).
    pub gain: f64,
    /// Baseline $V_0$ (V).
    pub baseline: f64,
    /// The scope that records it.
    pub scope: Scope,
}

impl Default for LightModel {
    /// A lamp at 60 degrees elevation from the -x side; the detector on the +x side at
    /// 60 - 6 = 54 degrees, 0.105 rad off the flat mirror's reflection; lobe $q = 300$
    /// (half-width about 3.3 degrees); 2 V gain on a 0.1 V baseline; the default [`Scope`].
    fn default() -> Self {
        let deg = std::f64::consts::PI / 180.0;
        Self {
            lamp: Direction {
                elevation: 60.0 * deg,
                azimuth: 180.0 * deg,
            },
            detector: Direction {
                elevation: 54.0 * deg,
                azimuth: 0.0,
            },
            lobe: 300.0,
            gain: 2.0,
            baseline: 0.1,
            scope: Scope::default(),
        }
    }
}

impl LightModel {
    /// Checks the settings, naming the first one that cannot be used.
    pub fn validate(&self) -> Result<(), ExperimentError> {
        let finite = [
            self.lamp.elevation,
            self.lamp.azimuth,
            self.detector.elevation,
            self.detector.azimuth,
            self.baseline,
        ];
        if !finite.iter().all(|x| x.is_finite()) {
            return Err(ExperimentError::Setting(
                "the light model's directions and baseline must be finite".into(),
            ));
        }
        if !(self.lobe.is_finite() && self.lobe >= 1.0) {
            return Err(ExperimentError::Setting(format!(
                "the lobe exponent q must be at least 1 (300 is a soft mirror), got {}",
                self.lobe
            )));
        }
        if !(self.gain.is_finite() && self.gain > 0.0) {
            return Err(ExperimentError::Setting(format!(
                "the gain must be positive volts, got {}",
                self.gain
            )));
        }
        self.scope.validate()
    }

    /// The upper face's normal $\hat{\mathbf n} = -\hat{\mathbf 1}$ at tilt `alpha` and heading `psi`.
    pub fn face_normal(alpha: f64, psi: f64) -> [f64; 3] {
        let (sa, ca) = alpha.sin_cos();
        let (sp, cp) = psi.sin_cos();
        [sa * sp, -sa * cp, ca]
    }

    /// The clean signal (V) at tilt `alpha` and heading `psi`, before the scope.
    pub fn intensity(&self, alpha: f64, psi: f64) -> f64 {
        let n = Self::face_normal(alpha, psi);
        let l = self.lamp.unit();
        let d = self.detector.unit();
        let ln = l[0] * n[0] + l[1] * n[1] + l[2] * n[2];
        let md: f64 = (0..3).map(|i| (2.0 * ln * n[i] - l[i]) * d[i]).sum();
        self.baseline + self.gain * md.max(0.0).powf(self.lobe)
    }
}
