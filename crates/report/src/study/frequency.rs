//! The small-oscillation frequencies measured on integrations (eqs 54, 55, 71).

use super::{Observer, Study};
use crate::error::ReportError;
use checks::equations::Bench;
use studies::frequency::Measured;

/// The measured frequencies.
pub struct Frequency;

impl Study for Frequency {
    type Output = Measured;
    const NAME: &'static str = "frequency";

    fn compute(&self, _: &Bench, _: &Observer) -> Result<Measured, ReportError> {
        Ok(studies::frequency::compute()?)
    }
}
