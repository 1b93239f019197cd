//! Small numerical tools shared by the checks: a seeded random source, fits, linearization,
//! oscillation frequencies measured on trajectories, bisection, references computed once per
//! process.

pub mod autocorrelation;
pub mod fit;
pub mod linearize;
pub mod memo;
pub mod minimize;
pub mod oscillation;
pub mod rng;
