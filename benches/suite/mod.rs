//! The benchmarks, one module per subject; [`super`] runs them as one target.

pub mod check;
pub mod experiment;
pub mod report;
pub mod rhs;
pub mod sampling;
pub mod scenes;
pub mod scipy_reference;
pub mod scipy_sampled;
pub mod sliding;
pub mod solver;
pub mod solver_steps;
