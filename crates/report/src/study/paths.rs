//! The path scenes but the spin-down (rolling-circle, nutating-coin).

use super::{Observer, Study};
use crate::error::ReportError;
use checks::equations::Bench;
use studies::runs::PathRun;

/// The path runs.
pub struct Paths;

impl Study for Paths {
    type Output = Vec<PathRun>;
    const NAME: &'static str = "paths";

    fn compute(&self, _: &Bench, _: &Observer) -> Result<Vec<PathRun>, ReportError> {
        Ok(studies::runs::paths()?)
    }
}
