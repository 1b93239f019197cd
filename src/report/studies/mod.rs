//! The studies behind the figures, each computed once per report by
//! [`super::pipeline::compute`]: every integration the figures show happens here, none in
//! `crate::figures`.
//!
//! | study | what | file |
//! |---|---|---|
//! | energy drift | the benchmark scene by six methods and tolerances | `energy.rs` |
//! | frequency | 51 nudged steady motions, rolling and frictionless (eqs 54, 55, 71) | `frequency.rs` |
//! | lab frame | two scenes by the reduced and the lab-frame model (eqs 23-25) | `lab_frame.rs` |
//! | scene runs | the path scenes and the one spin-down run | `runs.rs` |
//! | friction | the slip-stick scene (sliding model) and the friction studies of `crate::friction` | `friction.rs` |
//!
//! The precision study, the experiment and the checks have their own modules
//! (`crate::precision`, `crate::experiment`, `crate::check`); the pipeline calls them.

pub mod energy;
pub mod frequency;
pub mod friction;
pub mod lab_frame;
pub mod runs;
