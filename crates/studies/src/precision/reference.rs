//! The tight reference a scene's errors are measured against, and how it was validated.
//!
//! The reference is DOP853 at `rtol` = 1e-14, `atol` = 1e-16, a decade tighter than the tightest
//! tolerance the study measures. It is validated against three integrations that share none of
//! its error, or only part of it:
//! - DOP853 at `rtol` = 1e-13 (the same method one decade looser: a self-consistency check),
//! - DOPRI5 at `rtol` = 1e-14 (a different tableau, order 5),
//! - RK4 with a fixed step of `span / rk4_steps` (no error control at all; its error is
//!   $O(h^4)$).
//!
//! Each agreement is the error measure of [`crate::precision`] between the two solutions, at the
//! end and over the common sample times. The difference $d = |e_{\rm ref} - e_v|$ of two
//! independent errors bounds the larger of them unless they happen to cancel, so the reference's
//! `uncertainty` is the smallest agreement among the validators that use another method and
//! completed. The self-consistency agreement (DOP853 one decade looser) is reported but not used:
//! it shares the reference's systematic errors and only estimates the error of the looser run.
//!
//! Round-off, not truncation, limits the validators: a fixed-step or tight-tolerance run of $n$
//! steps accumulates up to $\sim n\varepsilon$ of rounding (measured on the benchmark scene:
//! RK4's error falls as $h^4$ down to about 1e-11 at $2^{16}$ steps, then grows again, to 1e-10
//! at $2^{19}$ steps; DOPRI5 stalls at 3e-11 below rtol 1e-12). Hence $2^{16}$ RK4 steps by
//! default. A power of two also keeps RK4's time exact: `ode_solvers` advances it by repeated
//! addition, which for a span with a short mantissa (10 s, 60 s) and a step of span / $2^m$ is
//! exact, while for other steps it drifts by up to $\sim n\varepsilon t$ (5e-11 s after
//! $4\times10^5$ steps of 10 s / $4\times10^5$), an error of (drift) x (rate) in the state.

use super::measure::{trace, Timing, Trace};
use physics::scene::Scene;
use physics::solve::{Ending, Method, Settings, SettingsError};
use serde::Serialize;

/// How to compute and validate a reference.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ReferenceOptions {
    /// The reference's settings.
    pub settings: Settings,
    /// Number of sample intervals over the scene's time span (the trajectory error is taken at
    /// these times).
    pub samples: u32,
    /// RK4 validator: number of fixed steps over the span.
    pub rk4_steps: u32,
    /// Whether to run the validators at all.
    pub validate: bool,
}

impl Default for ReferenceOptions {
    fn default() -> Self {
        Self {
            settings: Settings::dop853(1e-14, 1e-16),
            samples: 100,
            rk4_steps: 1 << 16,
            validate: true,
        }
    }
}

/// How closely one validating integration agrees with the reference.
#[derive(Debug, Clone, Serialize)]
pub struct Agreement {
    /// What it is ("dop853 rtol 1e-13", ...).
    pub label: String,
    /// Its settings.
    pub settings: Settings,
    /// Difference at the final time (see [`crate::precision`] for the measure).
    pub final_error: f64,
    /// Largest difference over the common sample times.
    pub trajectory_error: f64,
    /// Its right-hand-side evaluations (main pass).
    pub evaluations: u64,
    /// Why it ended.
    pub ending: Ending,
}

/// A reference solution of a scene.
#[derive(Debug, Clone, Serialize)]
pub struct Reference {
    /// The scene's name.
    pub scene: String,
    /// The reference integration.
    pub trace: Trace,
    /// Sample interval (s).
    pub sample_every: f64,
    /// Per component, the largest magnitude it reaches on the reference: the error scale.
    pub scale: Vec<f64>,
    /// The validating integrations.
    pub agreements: Vec<Agreement>,
    /// The smallest agreement among the validators that use another method and completed: the
    /// reference's error is taken to be below it. Infinite when validation was asked for and no
    /// independent validator completed; 0 when not validated.
    pub uncertainty: f64,
}

impl Reference {
    /// Computes the reference of `scene` and, if asked, validates it.
    pub fn compute(scene: &Scene, opts: &ReferenceOptions) -> Result<Reference, SettingsError> {
        let span = scene.stop.time;
        let every = span / f64::from(opts.samples.max(1));
        let tr = trace(scene, &opts.settings, Some(every), &Timing::ONCE)?;
        let n = tr.y_final.len();
        let mut scale = vec![0.0f64; n];
        for y in tr.samples.iter().chain(std::iter::once(&tr.y_final)) {
            for (s, v) in scale.iter_mut().zip(y) {
                *s = s.max(v.abs());
            }
        }
        for s in &mut scale {
            if !(s.is_finite() && *s > 0.0) {
                *s = 1.0;
            }
        }
        let mut reference = Reference {
            scene: scene.name.clone(),
            trace: tr,
            sample_every: every,
            scale,
            agreements: Vec::new(),
            uncertainty: 0.0,
        };
        if opts.validate {
            let s = opts.settings;
            let validators = [
                Settings {
                    rtol: s.rtol * 10.0,
                    atol: s.atol * 10.0,
                    ..s
                },
                Settings {
                    method: Method::Dopri5,
                    ..s
                },
                Settings {
                    method: Method::Rk4,
                    step: span / f64::from(opts.rk4_steps.max(1)),
                    max_steps: s.max_steps.max(opts.rk4_steps + 1),
                    ..s
                },
            ];
            for v in validators {
                let t = trace(scene, &v, Some(every), &Timing::ONCE)?;
                let (final_error, trajectory_error) = reference.errors(&t);
                reference.agreements.push(Agreement {
                    label: label(&v),
                    settings: v,
                    final_error,
                    trajectory_error,
                    evaluations: t.stats.evaluations,
                    ending: t.ending,
                });
            }
            reference.uncertainty = reference
                .agreements
                .iter()
                .filter(|a| a.ending.is_complete() && a.settings.method != s.method)
                .map(|a| a.trajectory_error.max(a.final_error))
                .fold(f64::INFINITY, f64::min);
        }
        Ok(reference)
    }

    /// The scaled error of state `y` against the reference state `r`.
    pub fn state_error(&self, y: &[f64], r: &[f64]) -> f64 {
        y.iter()
            .zip(r)
            .zip(&self.scale)
            .map(|((a, b), s)| (a - b).abs() / s)
            .fold(0.0, f64::max)
    }

    /// The errors of `t` against the reference: (at the final time, over the trajectory). The
    /// trajectory error is the largest over the sample times the two share, the final time
    /// included. A run that did not complete has infinite errors.
    pub fn errors(&self, t: &Trace) -> (f64, f64) {
        if !t.ending.is_complete() || t.y_final.iter().any(|v| !v.is_finite()) {
            return (f64::INFINITY, f64::INFINITY);
        }
        let r = &self.trace;
        let mut final_error = self.state_error(&t.y_final, &r.y_final);
        if matches!(r.ending, Ending::Event { .. }) || matches!(t.ending, Ending::Event { .. }) {
            final_error = final_error.max((t.t_final - r.t_final).abs() / r.t_final.abs());
        }
        let mut trajectory = final_error;
        let tol = 1e-9 * self.sample_every;
        let (mut i, mut j) = (0, 0);
        // Both sample lists are increasing; their last entries are the final points (compared
        // above), so compare the others at equal times.
        let (nt, nr) = (
            t.sample_t.len().saturating_sub(1),
            r.sample_t.len().saturating_sub(1),
        );
        while i < nt && j < nr {
            let (a, b) = (t.sample_t[i], r.sample_t[j]);
            if (a - b).abs() <= tol {
                trajectory = trajectory.max(self.state_error(&t.samples[i], &r.samples[j]));
                i += 1;
                j += 1;
            } else if a < b {
                i += 1;
            } else {
                j += 1;
            }
        }
        (final_error, trajectory)
    }
}

/// A short label for settings: "rk4 h 1e-3", "dop853 rtol 1e-10".
pub fn label(s: &Settings) -> String {
    match s.method {
        Method::Rk4 => format!("rk4 h {:.3e}", s.step),
        m => format!("{m} rtol {:.0e}", s.rtol),
    }
}
