//! A sound analysis refused, with what it had found: the reason, and the pitch track made before
//! the refusal, so that the user can see why (`experiment analyze FILE --out DIR` writes both,
//! and the spectrogram with the track and the reason on it).

use crate::error::ExperimentError;
use crate::sound_analysis::track::FrequencyTrack;
use std::f64::consts::TAU;
use std::path::{Path, PathBuf};

/// The span of the disk's line (s) below which a refusal advises recording more of the spin:
/// eq 79's rate must rise by half across the frames fitted, which takes a second or more of the
/// line at the paper's law.
const SHORT_LINE_S: f64 = 2.0;

/// The least rise of the line's pitch, last over first, that a disk's spin-down is taken to
/// have: 5 %, far below any spin-down's fitted (the plausibility check asks for 50 %), so that
/// only a line that holds its pitch or falls is called another sound.
pub const RISES: f64 = 1.05;

/// What the pitch track heard, for a refusal's message: where it followed a line (the disk's, or
/// another sound it took for the disk's, such as a mains line the hum's removal left; or that no
/// line stood out of the noise), the mains lines subtracted, and what to do. `end` is
/// the recording's last time (s): a line followed into the recording's last frame (its last
/// frame ends less than one frame of its own length, and a sample, before `end`; the frames
/// tile the record, and near a disk's end they shrink to a few hundredths of a second) was
/// still sounding when the recording stopped, and the advice is to record until the disk is
/// silent.
pub fn what_was_heard(track: &FrequencyTrack, end: f64) -> String {
    let hum = if track.hum.is_empty() {
        String::new()
    } else {
        let lines: Vec<String> = track.hum.iter().map(|h| format!("{h:.1}")).collect();
        format!("; mains hum at {} Hz was subtracted", lines.join(", "))
    };
    let (Some(p), Some(q)) = (track.points.first(), track.points.last()) else {
        return format!(
            "in none of the {} frames did a line of the disk stand out of the noise between 5 Hz \
             and 2 kHz{hum}: record closer to the disk in a quieter room, with the phone's noise \
             suppression off where it has the setting (a line far below a phone's high-pass, \
             often 50-200 Hz, is faint: an external microphone or a recorder app without it \
             hears it)",
            track.frames
        );
    };
    let span = q.b - p.a;
    let heard = format!(
        "the pitch track followed a line over {span:.2} s, from {:.1} Hz at {:.2} s to {:.1} Hz \
         at {:.2} s{hum}",
        p.omega / TAU,
        p.a,
        q.omega / TAU,
        q.b
    );
    let advice = if span < SHORT_LINE_S {
        "record the whole spin, starting before the disk is released, and spin it longer (a \
         heavier disk, a smoother and harder surface): the fit needs the line over a rise of \
         half its pitch"
    } else if q.omega < RISES * p.omega {
        "a line whose pitch does not rise is not a settling disk's (its pitch rises toward the \
         end): it is another sound, a motor, a fan or a tone; record the disk's own spin-down, \
         from its release until it is silent"
    } else if q.b + (q.b - q.a) + 1e-3 >= end {
        "the recording stops while the disk's line still sounds: record until the disk has \
         settled and is silent, so that the rate's rise to its end is heard"
    } else if !track.hum.is_empty() {
        "record closer to the disk, on battery and away from mains-powered devices, so that its \
         line stands above the hum"
    } else {
        "record closer to the disk, away from other sounds"
    };
    format!("{heard}: {advice}")
}

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
