//! What can stop a study: the lower layer's own error, carried whole, or a result the study
//! cannot use (a run that did not record what the study reads).

use experiment::ExperimentError;
use physics::model::steady::SteadyError;
use physics::scene::SceneError;
use physics::solve::SettingsError;

/// A study that could not be computed.
#[derive(Debug, thiserror::Error)]
pub enum StudyError {
    /// A built-in scene could not be loaded.
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// An integration's settings were refused.
    #[error(transparent)]
    Settings(#[from] SettingsError),
    /// A steady motion the study starts from does not exist.
    #[error(transparent)]
    Steady(#[from] SteadyError),
    /// The synthetic experiment could not be simulated or analysed.
    #[error(transparent)]
    Experiment(#[from] ExperimentError),
    /// A run ended or recorded otherwise than the study needs.
    #[error("{0}")]
    Unusable(String),
}

impl From<String> for StudyError {
    fn from(s: String) -> Self {
        StudyError::Unusable(s)
    }
}

impl From<&str> for StudyError {
    fn from(s: &str) -> Self {
        StudyError::Unusable(s.to_string())
    }
}
