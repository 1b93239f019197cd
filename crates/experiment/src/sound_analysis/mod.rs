//! The sound recording analysed: mains hum out ([`mains`]), the fundamental of each frame
//! ([`spectrum`]) followed into a pitch track ([`track`]), the spectrogram for the eye
//! ([`spectrogram`]), the phase followed turn by turn ([`phase_blocks`]) and eq 79's heading
//! fitted to it ([`phase_fit`]), its residuals tested for structure ([`residual_structure`]),
//! the harmonics fitted alone and their disagreement ([`harmonic_agreement`]),
//! with a phone's high-pass read from the harmonics ([`high_pass`]), the turns it counts checked
//! against the track's ([`turn_count`]), which fit is the result and what uncertainty it states
//! ([`result`]), the rise a spin-down is judged on ([`rise`]), a short spin's fit from its phase
//! where the track holds too few frames ([`short_spin`]), eq 79 fitted to the track's frames
//! ([`track_law`]), and the whole analysis ([`analysis`], what it holds [`analysed`])
//! or its refusal with the track it had made ([`refusal`]).

pub mod analysed;
pub mod analysis;
pub mod harmonic_agreement;
#[cfg(test)]
mod heading_departure;
pub mod high_pass;
pub mod mains;
pub mod phase_blocks;
pub mod phase_fit;
pub mod refusal;
pub mod residual_structure;
pub mod result;
pub mod rise;
pub mod short_spin;
pub mod spectrogram;
pub mod spectrum;
pub mod track;
pub mod track_law;
pub mod turn_count;
