//! A trace that follows eq 79 exactly: for testing the analysis where the truth is known without
//! any model error, and fast enough to make a hundred of them.
//!
//! With $p = 1/(\beta+2)$, eq 79 $\Omega = (C/(t_0 - t))^{p}$ integrates to the heading
//! $$\psi(t) = -\frac{C^{p}\,(t_0 - t)^{1-p}}{1 - p} \qquad (t < t_0),$$
//! and the tilt follows from steady motion with $b = 0$ (eq 29):
//! $\sin\alpha = g / (k a \Omega^2)$. After $t_0$ the disk lies flat.

use crate::error::ExperimentError;
use crate::synthetic::light::LightModel;
use crate::trace::{Trace, Truth};
use physics::disk::Disk;
use physics::model::steady::tilt_at_b0;
use serde::{Deserialize, Serialize};

/// Eq 79's law: $\Omega = (C/(t_0 - t))^{1/(\beta + 2)}$, with $t_0$ the scope's `end_at`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Law {
    /// $\beta$, above -1 so that the heading stays finite at $t_0$.
    pub beta: f64,
    /// $C$ (units $s^{-(\beta+1)}$).
    pub c: f64,
}

impl Law {
    /// The law of a fit $(\beta, C^{-1/(\beta+2)})$, as the paper states its own (sec. 11,
    /// read from paper/claims.yaml by the paper module; this module never sees the paper).
    pub fn from_fit(beta: f64, c_inv_root: f64) -> Self {
        Self {
            beta,
            c: c_inv_root.powf(-(beta + 2.0)),
        }
    }

    /// $\Omega$ at $t_0 - t = \tau$ (rad/s).
    pub fn precession(&self, tau: f64) -> f64 {
        (self.c / tau).powf(1.0 / (self.beta + 2.0))
    }

    /// The heading at $t_0 - t = \tau$ (rad).
    pub fn heading(&self, tau: f64) -> f64 {
        let p = 1.0 / (self.beta + 2.0);
        -self.c.powf(p) * tau.powf(1.0 - p) / (1.0 - p)
    }
}

/// The trace of a disk that follows `law` exactly, seen through `light`.
pub fn law_trace(law: &Law, disk: &Disk, light: &LightModel) -> Result<Trace, ExperimentError> {
    light.validate()?;
    if !(law.beta.is_finite() && law.beta > -1.0 && law.c.is_finite() && law.c > 0.0) {
        return Err(ExperimentError::Setting(format!(
            "the law needs beta > -1 and C > 0, got beta = {}, C = {}",
            law.beta, law.c
        )));
    }
    let scope = &light.scope;
    let t0 = scope.end_at;
    let t = scope.times();
    let flat = light.intensity(0.0, 0.0);
    let mut v: Vec<f64> = t
        .iter()
        .map(|&t| {
            let tau = t0 - t;
            if tau <= 0.0 {
                return flat;
            }
            let om = law.precession(tau);
            light.intensity(tilt_at_b0(disk, om), law.heading(tau))
        })
        .collect();
    scope.record(&mut v);
    Ok(Trace {
        source: format!("law:beta={},C={:e}", law.beta, law.c),
        t,
        v,
        truth: Some(Truth {
            beta: law.beta,
            t0,
            t_stop: t0,
            tau_rem: 0.0,
            c: Some(law.c),
            origin: "eq 79 exactly".into(),
        }),
    })
}
