//! The reduced model against the lab-frame model (eqs 23-25).

use super::{Observer, Study};
use crate::error::ReportError;
use checks::equations::Bench;
use studies::lab_frame::Compared;

/// The lab-frame comparisons.
pub struct LabFrame;

impl Study for LabFrame {
    type Output = Vec<Compared>;
    const NAME: &'static str = "lab-frame";

    fn compute(&self, _: &Bench, _: &Observer) -> Result<Vec<Compared>, ReportError> {
        Ok(studies::lab_frame::compute()?)
    }
}
