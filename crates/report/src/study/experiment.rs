//! The synthetic experiment of section 11: the spin-down seen through the light model and
//! scope, then analysed (eqs 84, 85).

use super::{Observer, Study};
use crate::error::ReportError;
use checks::equations::Bench;
use studies::synthetic::Synthetic;

/// The synthetic experiment and its analysis.
pub struct Experiment;

impl Study for Experiment {
    type Output = Synthetic;
    const NAME: &'static str = "experiment";

    fn compute(&self, _: &Bench, _: &Observer) -> Result<Synthetic, ReportError> {
        Ok(studies::synthetic::compute()?)
    }
}
