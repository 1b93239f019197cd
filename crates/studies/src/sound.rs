//! The sound of the synthetic experiment: the built-in spin-down scene as a phone beside the
//! disk records it (48 kS/s, [`Microphone::phone`], 2 % of 50 Hz hum), analysed (the pitch track,
//! eq 79 on the pitch and on the phase), and its spectrogram for the eye.

use crate::error::StudyError;
use experiment::plausibility::Plausibility;
use experiment::spectrogram::{spectrogram, Spectrogram};
use experiment::{analyze_sound, simulate_sound, Artifacts, Microphone, SoundAnalysis};
use physics::scene::Scene;

/// The phone's recording analysed, and its spectrogram.
#[derive(Debug, Clone)]
pub struct SoundStudy {
    /// The analysis.
    pub analysis: SoundAnalysis,
    /// The spectrogram: frames of 0.2 s every 0.1 s, 80 bands of 5 Hz up to 400 Hz.
    pub spectrogram: Spectrogram,
}

/// Simulates and analyses the phone's recording of the built-in spin-down (noise seed 1).
pub fn compute() -> Result<SoundStudy, StudyError> {
    let scene = Scene::load("spin-down")?;
    let mic = Microphone::phone(48_000, 1);
    let art = Artifacts {
        hum: 0.02,
        seed: 1,
        ..Artifacts::none()
    };
    let trace = simulate_sound(&scene, &mic, &art)?;
    let analysis = analyze_sound(
        &trace,
        &experiment::TrackSettings::default(),
        &Plausibility::default(),
    )?;
    Ok(SoundStudy {
        spectrogram: spectrogram(&trace, 0.2, 0.1, 400.0, 80),
        analysis,
    })
}
