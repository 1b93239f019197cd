//! The paper's experiment of section 11, reproduced at both ends.
//!
//! McDonald & McDonald lit a spinning Euler's Disk with a flashlight, recorded the light it
//! reflected onto a phototransistor with a scope at 5 kS/s (50,000 samples, the last 10 s of the
//! spin), took the time $t_i$ of each peak as the mean of the rising and falling edges at half
//! height, formed
//! $$\Omega_i = \frac{2\pi}{t_{i+1} - t_i}, \qquad
//!   \frac{d\Omega_i}{dt} = \frac{2(\Omega_{i+1} - \Omega_i)}{t_{i+2} - t_i},$$
//! and compared them, by drawing lines, with
//! $$\frac1\Omega = \left(\frac{t_0 - t}{C}\right)^{1/(\beta+2)} \quad (84), \qquad
//!   \frac{d\Omega}{dt} \propto \Omega^{\beta+3} \quad (85).$$
//!
//! This module does both ends:
//! - the **synthetic experiment** ([`simulate_trace`], [`law_trace`]): a spin-down (the
//!   dissipative rolling model, or the sliding model with friction and lift-off) seen through a
//!   [`LightModel`] (lamp, mirror-like face, detector, scope with noise and quantisation);
//! - the **analysis** ([`analyze`]) of any such trace, synthetic or a real scope's CSV
//!   ([`read_trace`]): peak times, $\Omega_i$, $d\Omega_i/dt$, and *fits* with uncertainties of
//!   $\beta$, $t_0$ and $C$ (eq 84) and of $\beta$ alone (eq 85), where the paper drew lines;
//! - the paper's own numbers recomputed from its constants ([`numbers::numbers`] with the fit the paper prints).
//!
//! The paper's "Hz" are angular frequencies, rad/s ($\Omega_i = 2\pi/\Delta t$); so are ours.

pub mod analysis;
pub mod analysis_settings;
pub mod artifacts;
pub mod audio;
pub mod band;
pub mod calibration;
pub mod channel;
pub mod clean;
pub mod coverage;
pub mod coverage_record;
pub mod crossover;
pub mod csv;
pub mod early_end;
pub mod error;
pub mod fit;
pub mod hum;
pub mod input;
pub mod law;
pub mod law_stability;
pub mod least_squares;
pub mod light;
pub mod line_power;
pub mod mains_drift;
pub mod mains_phase;
pub mod mechanism_record;
pub mod mechanisms;
pub mod model_choice;
pub mod models;
pub mod motion_law;
pub mod mp4_edit;
pub mod numbers;
pub mod peak;
pub mod peaks;
pub mod phase_blocks;
pub mod phase_fit;
pub mod plausibility;
pub mod pulse_drift;
pub mod rates;
pub mod recording;
pub mod scope;
pub mod simulate;
pub mod sliding_record;
pub mod sound;
pub mod sound_coverage;
pub mod sound_file;
pub mod spectrogram;
pub mod spectrum;
pub mod trace;
pub mod track;
pub mod turn_count;
pub mod wav;
pub mod window;

pub use analysis::{analyze, analyze_within, write_analysis, Analysis, AnalysisSettings};
pub use artifacts::Artifacts;
pub use audio::{
    analyze_sound, analyze_sound_within, write_sound_analysis, SoundAnalysis, SoundLaw,
};
pub use channel::{Channels, Recording, RecordingInfo};
pub use csv::{parse_trace, read_trace};
pub use error::ExperimentError;
pub use law::{law_trace, Law};
pub use light::{Direction, LightModel};
pub use recording::read_recording;
pub use scope::Scope;
pub use simulate::simulate_trace;
pub use sound::{law_sound, simulate_sound, Microphone};
pub use sound_file::{encode_sound, SoundFormat};
pub use trace::{Trace, Truth};
pub use track::TrackSettings;
pub use wav::{encode_wav, read_wav, wav_bytes, WavCoding};
