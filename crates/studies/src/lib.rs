//! Studies: each computed once from the references, returning plain data (no drawing types).
//!
//! - [`sliding`]: the paper's claims that need Coulomb friction, run with the sliding model;
//! - [`precision`]: speed against accuracy, measured at equal error;
//! - [`peer`]: the thick toy against an independent program's stored runs;
//! - [`thickness`]: the toy's thickness against the paper's thin-disk numbers; [`toy`] both for
//!   the report, [`toy_steady`] its steady motions (eqs 29-30);
//! - [`compare`]: one scene run in two models side by side;
//! - the studies behind the report's figures: [`energy`] (drift of six methods), [`frequency`]
//!   (small oscillations measured, eqs 54, 55, 71), [`lab_frame`] (eqs 23-25 against the
//!   Newton-Euler model), [`runs`] (the path scenes and the one spin-down run), [`slip_stick`]
//!   (the sliding model's scene and the sliding studies), [`synthetic`] (the experiment of
//!   sec. 11 simulated and analysed).
//! - the Monte Carlo studies of the experiment's analysis, over many simulated records:
//!   [`coverage`] (do the light's stated intervals hold?), [`sound_coverage`] (the sound's),
//!   [`phone_coverage`] (the sound's on phones' recordings of real rooms, the realistic set),
//!   [`phone_bound`] (what those recordings can tell at best, their Cramér-Rao bounds),
//!   [`coverage_record`] (both as stored for the report), [`law_choice_study`] (how often the
//!   law choice takes one mechanism for two; stored as the calibration the choice states).

pub mod compare;
pub mod coverage;
pub mod coverage_record;
pub mod energy;
pub mod error;
pub mod frequency;
pub mod lab_frame;
pub mod law_choice_study;
pub mod peer;
pub mod phone_bound;
pub mod phone_coverage;
pub mod precision;
pub mod runs;
pub mod sliding;
pub mod slip_stick;
pub mod sound;
pub mod sound_coverage;
pub mod synthetic;
pub mod thickness;
pub mod toy;
pub mod toy_steady;

pub use error::StudyError;
