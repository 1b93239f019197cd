//! Every equation's and claim's check (`checks::check`).

use super::{Observer, Step, Study};
use crate::error::ReportError;
use checks::check::{run_checks, Checked, Selection};
use checks::equations::Bench;

/// The checks of every equation and claim.
pub struct Checks;

impl Study for Checks {
    type Output = Vec<Checked>;
    const NAME: &'static str = "checks";

    fn compute(&self, bench: &Bench, observe: &Observer) -> Result<Vec<Checked>, ReportError> {
        // The checks share the machine with the other studies: as many threads as cores.
        let threads = rayon::current_num_threads().max(1);
        let step = |done, total| observe(Step { done, total });
        Ok(run_checks(bench, &Selection::default(), threads, &step)?)
    }
}
