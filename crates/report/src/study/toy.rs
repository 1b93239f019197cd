//! The real toy: the peer program's stored runs against this tool, and the toy's thickness
//! against the paper's thin-disk numbers (`studies::toy`).

use super::{Observer, Study};
use crate::error::ReportError;
use checks::equations::Bench;

/// The toy's studies.
pub struct Toy;

impl Study for Toy {
    type Output = studies::toy::Toy;
    const NAME: &'static str = "toy";

    fn compute(&self, _: &Bench, _: &Observer) -> Result<studies::toy::Toy, ReportError> {
        Ok(studies::toy::compute()?)
    }
}
