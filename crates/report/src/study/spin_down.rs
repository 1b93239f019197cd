//! The one run of the built-in spin-down (eqs 23-25 with eq 75), shared by two figures.

use super::{Observer, Study};
use crate::error::ReportError;
use checks::equations::Bench;

/// The spin-down run.
pub struct SpinDown;

impl Study for SpinDown {
    type Output = studies::runs::SpinDown;
    const NAME: &'static str = "spin-down";

    fn compute(&self, _: &Bench, _: &Observer) -> Result<Self::Output, ReportError> {
        Ok(studies::runs::spin_down()?)
    }
}
