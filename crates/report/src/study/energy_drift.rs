//! The energy drift of six methods on the benchmark scene.

use super::{Observer, Study};
use crate::error::ReportError;
use checks::equations::Bench;

/// The energy-drift runs.
pub struct EnergyDrift;

impl Study for EnergyDrift {
    type Output = studies::energy::EnergyDrift;
    const NAME: &'static str = "energy-drift";

    fn compute(&self, _: &Bench, _: &Observer) -> Result<Self::Output, ReportError> {
        Ok(studies::energy::compute()?)
    }
}
