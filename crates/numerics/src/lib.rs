//! Small numerical tools shared by the checks: a seeded random source, fits, linearization,
//! oscillation frequencies measured on trajectories, bisection, references computed once per
//! process, a sine and cosine over many angles at once, the C library's sine and cosine of one angle together, and the run-time choice of the wider
//! vector build that computes it.

pub mod autocorrelation;
pub mod fit;
pub mod libm;
pub mod linearize;
pub mod memo;
pub mod minimize;
pub mod oscillation;
pub mod rng;
pub mod trig;
pub mod wider;
