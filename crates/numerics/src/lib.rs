//! Small numerical tools shared by the checks: a seeded random source, fits, linearization,
//! oscillation frequencies measured on trajectories, bisection, references computed once per
//! process, a sine and cosine taken two at a time.

pub mod autocorrelation;
pub mod fit;
pub mod linearize;
pub mod memo;
pub mod minimize;
pub mod oscillation;
pub mod rng;
pub mod trig;
pub mod wider;
