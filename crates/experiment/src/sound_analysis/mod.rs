//! The sound recording analysed: mains hum out ([`mains`]), the fundamental of each frame
//! ([`spectrum`]) followed into a pitch track ([`track`]), the spectrogram for the eye
//! ([`spectrogram`]), the phase followed turn by turn ([`phase_blocks`]) and eq 79's heading
//! fitted to it ([`phase_fit`]), its residuals tested for structure ([`residual_structure`]),
//! with a phone's high-pass read from the harmonics ([`high_pass`]), the turns it counts checked
//! against the track's ([`turn_count`]), which fit is the result and what uncertainty it states
//! ([`result`]), the rise a spin-down is judged on ([`rise`]), and the whole analysis
//! ([`analysis`]) or its refusal with the track it had made ([`refusal`]).

pub mod analysis;
pub mod high_pass;
pub mod mains;
pub mod phase_blocks;
pub mod phase_fit;
pub mod refusal;
pub mod residual_structure;
pub mod result;
pub mod rise;
pub mod spectrogram;
pub mod spectrum;
pub mod track;
pub mod turn_count;
