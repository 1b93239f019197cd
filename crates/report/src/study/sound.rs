//! The sound of the synthetic experiment: the spin-down as a phone records it, analysed, and its
//! spectrogram ([`studies::sound`]).

use super::{Observer, Study};
use crate::error::ReportError;
use checks::equations::Bench;
use studies::sound::SoundStudy;

/// The phone's recording of the spin-down and its analysis.
pub struct Sound;

impl Study for Sound {
    type Output = SoundStudy;
    const NAME: &'static str = "sound";

    fn compute(&self, _: &Bench, _: &Observer) -> Result<SoundStudy, ReportError> {
        Ok(studies::sound::compute()?)
    }
}
