//! Fits with uncertainties where the paper drew lines, shared by the light and the sound: eq 79's
//! parameters as every fit states them ([`law_fit`]); eqs 84 and 85 ([`eq84_85`]) by generalised nonlinear least squares ([`least_squares`]) with banded,
//! correlated errors ([`band`]); whether eq 79 holds across the window ([`law_stability`]); the
//! two-mechanism law ([`crossover`]); which dissipation law the data support ([`law_choice`],
//! calibrated by the stored study [`law_choice_record`]); whether the record is a spin-down at
//! all ([`plausibility`]); and what eq 79 says of a simulated motion itself ([`motion_law`]).

pub mod band;
pub mod crossover;
pub mod eq84_85;
pub mod law_choice;
pub mod law_choice_record;
pub mod law_fit;
pub mod law_stability;
pub mod least_squares;
pub mod motion_law;
pub mod plausibility;

pub use eq84_85::{fit_eq84, fit_eq84_fixed, fit_eq85, Eq84Fit, Eq85Fit, FitPoint, FixedFit};
