//! The energy drift of six methods on the benchmark scene, each run named by how it stepped
//! ([`Stepping`]), so that the figure reads the runs as plain data.

use super::{Observer, Study};
use crate::error::ReportError;
use checks::equations::Bench;
use physics::solve::Method;

/// The energy-drift runs.
pub struct EnergyDrift;

/// How a run of the energy-drift study stepped.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stepping {
    /// Classical RK4 at a fixed step.
    FixedStep,
    /// DOPRI5, adaptive.
    Dopri5,
    /// DOP853, adaptive.
    Dop853,
    /// DOP853 with every step projected back onto the start's energy.
    Dop853Projected,
}

/// One run: $(t, |E(t) - E_0|/E_0)$ at every step, with its label and work.
#[derive(Debug, Clone, PartialEq)]
pub struct DriftCurve {
    /// Method and tolerance or step, for the legend.
    pub label: String,
    /// How it stepped.
    pub stepping: Stepping,
    /// $(t, |E(t) - E_0|/E_0)$ at every step.
    pub drift: Vec<(f64, f64)>,
    /// Right-hand-side evaluations the run took.
    pub evaluations: u64,
}

impl Study for EnergyDrift {
    /// The runs, in the legend's order.
    type Output = Vec<DriftCurve>;
    const NAME: &'static str = "energy-drift";

    fn compute(&self, _: &Bench, _: &Observer) -> Result<Self::Output, ReportError> {
        let study = studies::energy::compute()?;
        Ok(study
            .runs
            .into_iter()
            .map(|run| DriftCurve {
                stepping: match run.method {
                    Method::Rk4 => Stepping::FixedStep,
                    Method::Dopri5 => Stepping::Dopri5,
                    Method::Dop853 if run.projected => Stepping::Dop853Projected,
                    Method::Dop853 => Stepping::Dop853,
                },
                label: run.label,
                drift: run.drift,
                evaluations: run.evaluations,
            })
            .collect())
    }
}
