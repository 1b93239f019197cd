//! The speed/accuracy study on the benchmark scene (`studies::precision`).

use super::{Observer, Study};
use crate::error::ReportError;
use checks::equations::Bench;
use studies::precision;

/// The speed/accuracy study.
pub struct Precision;

impl Study for Precision {
    type Output = precision::Study;
    const NAME: &'static str = "precision";

    fn compute(&self, _: &Bench, _: &Observer) -> Result<precision::Study, ReportError> {
        Ok(precision::benchmark_study()?)
    }
}
