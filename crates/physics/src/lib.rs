//! The references: the disk, its models (rolling, frictionless, dissipative, lab-frame, sliding),
//! the one door to the integrators ([`solve`]), events, budgets, and scenes.
//!
//! Data flows one way: a [`scene::Scene`] (YAML) is validated, [`run::run`] builds the model with
//! only the states the scene needs and integrates it through [`solve`], the only door to
//! `ode_solvers`. Nothing here sees the paper or a check: this crate depends on neither.

pub mod budget;
pub mod disk;
pub mod dispatch;
pub mod events;
pub mod model;
pub mod nearest;
pub mod run;
pub mod scene;
pub mod solve;

pub use disk::Disk;
