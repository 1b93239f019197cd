//! The sliding model's slip-stick scene and the friction studies (`studies::sliding`), for the
//! paper's fitted record.

use super::{Observer, Study};
use crate::error::ReportError;
use checks::equations::Bench;
use experiment::law::Law;
use studies::slip_stick::SlipStick;

/// The slip-stick run and the friction studies.
pub struct Friction;

impl Study for Friction {
    type Output = SlipStick;
    const NAME: &'static str = "friction";

    fn compute(&self, bench: &Bench, _: &Observer) -> Result<SlipStick, ReportError> {
        let fit = &bench.paper.fit;
        let record = Law::from_fit(fit.beta, fit.c_inv_root);
        Ok(studies::slip_stick::compute(&record)?)
    }
}
