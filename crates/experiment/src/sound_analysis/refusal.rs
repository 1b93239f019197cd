//! A sound analysis refused, with what it had found: the reason, and the pitch track made before
//! the refusal, so that the user can see why (`experiment analyze FILE --out DIR` writes both,
//! and the spectrogram with the track and the reason on it).

use crate::error::ExperimentError;
use crate::sound_analysis::track::FrequencyTrack;
use std::path::{Path, PathBuf};

/// Why a sound analysis was refused, and the pitch track it had made, when it had made one.
#[derive(Debug)]
pub struct SoundRefusal {
    /// The refusal, as the user reads it.
    pub error: ExperimentError,
    /// The pitch track, when the refusal came after it was made.
    pub track: Option<FrequencyTrack>,
}

impl SoundRefusal {
    /// A refusal that came before a track was made.
    pub fn before_track(error: ExperimentError) -> Self {
        Self { error, track: None }
    }

    /// Writes `refusal.txt` (the reason) and, when a track was made, `track.csv` (its frames, as
    /// [`FrequencyTrack::csv`]) into `dir`, each atomically; returns the paths written.
    pub fn write(&self, dir: &Path) -> Result<Vec<PathBuf>, ExperimentError> {
        let io = |p: &Path, e: std::io::Error| ExperimentError::Io {
            file: p.display().to_string(),
            message: format!("cannot write ({e})"),
        };
        std::fs::create_dir_all(dir).map_err(|e| io(dir, e))?;
        let mut texts = vec![("refusal.txt", format!("{}\n", self.error))];
        if let Some(t) = &self.track {
            texts.push(("track.csv", t.csv()));
        }
        let mut out = Vec::new();
        for (name, text) in texts {
            let p = dir.join(name);
            files::output::write_set_file(&p, text.as_bytes()).map_err(|e| io(&p, e))?;
            out.push(p);
        }
        Ok(out)
    }
}
