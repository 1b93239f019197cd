//! A sound recording analysed: what the analysis
//! ([`analysis`](crate::sound_analysis::analysis)) holds, whichever fit is its result.

use crate::fit::law_choice::Comparison;
use crate::fit::plausibility::Verdict;
use crate::sound_analysis::phase_fit::PhaseFit;
use crate::sound_analysis::track::FrequencyTrack;
use crate::sound_analysis::track_law::TrackFit;
use crate::sound_analysis::turn_count::TurnCount;
use crate::trace::Truth;
use serde::Serialize;

/// A sound recording analysed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SoundAnalysis {
    /// The recording.
    pub source: String,
    /// What the file is (format, rate, channels, length), when it was read from a file.
    pub recording: Option<crate::formats::channel::RecordingInfo>,
    /// The track.
    pub track: FrequencyTrack,
    /// Eq 79 fitted to the pitch track.
    pub fit: TrackFit,
    /// Eq 79's heading fitted to the sound's phase, started from `fit` (the analysis's result).
    pub phase: Option<PhaseFit>,
    /// Why the phase was not fitted, when it was not.
    pub phase_refused: Option<String>,
    /// The turns the phase's fit counts against the pitch track's, when the phase was fitted.
    pub turn_count: Option<TurnCount>,
    /// Model choice.
    pub models: Comparison,
    /// The spin-down checks.
    pub verdict: Verdict,
    /// The rate's rise over the phase's blocks, where the track's frames rose too little and the
    /// spin-down was judged on the phase instead ([`rise`](crate::sound_analysis::rise)).
    pub rise_on_phase: Option<f64>,
    /// Where the track's own fit is refused (too few frames of the line for it, or frames its
    /// checks refuse) and the phase's fit seeded from the track's frames is the result
    /// ([`short_spin`](crate::sound_analysis::short_spin)): the track's refusal it stands in for.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub short_spin: Option<String>,
    /// The truth, for synthetic recordings.
    pub truth: Option<Truth>,
}
