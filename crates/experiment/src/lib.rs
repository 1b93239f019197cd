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
//!
//! The rooms, in the order a recording flows through them:
//! - [`formats`]: the files read (a scope's CSV, sound in any format) and written;
//! - [`synthetic`]: the synthetic experiment, light and sound, with what a room adds;
//! - [`light_analysis`]: the light signal's peaks timed, its rates, the fitting window;
//! - [`sound_analysis`]: the sound's hum removed, its pitch tracked, its phase followed;
//! - [`fit`]: the fits of eqs 84 and 85 with their uncertainties, the law chosen, the checks;
//! - [`numbers`]: the paper's own numbers of section 11; [`trace`]: the record itself;
//!   [`error`]: what can go wrong.

pub mod error;
pub mod fit;
pub mod formats;
pub mod light_analysis;
pub mod numbers;
pub mod sound_analysis;
pub mod synthetic;
pub mod trace;

// The modules whose paths callers outside this crate name, at the root as before the rooms.
pub use fit::{motion_law, plausibility};
pub use formats::{recording, scope_layout, wav};
pub use sound_analysis::{refusal, spectrogram, track, turn_count};
pub use synthetic::{law, mechanisms, simulate, sound};

pub use error::ExperimentError;
pub use formats::channel::{Channels, Recording, RecordingInfo};
pub use formats::csv::{parse_trace, parse_trace_columns, read_trace, read_trace_columns};
pub use formats::recording::read_recording;
pub use formats::sound_file::{encode_sound, SoundFormat};
pub use formats::wav::{encode_wav, read_wav, wav_bytes, WavCoding};
pub use light_analysis::analysis::{
    analyze, analyze_within, timed, write_analysis, Analysis, Timed,
};
pub use light_analysis::settings::AnalysisSettings;
pub use sound_analysis::analysis::{
    analyze_sound, analyze_sound_keeping_track, analyze_sound_within, write_sound_analysis,
    SoundAnalysis,
};
pub use sound_analysis::result::{SoundLaw, SoundResult, Terms};
pub use sound_analysis::track::TrackSettings;
pub use synthetic::artifacts::Artifacts;
pub use synthetic::law::{law_trace, Law};
pub use synthetic::light::{Direction, LightModel};
pub use synthetic::scope::Scope;
pub use synthetic::simulate::simulate_trace;
pub use synthetic::sound::{law_sound, simulate_sound, Microphone};
pub use trace::{Trace, Truth};
