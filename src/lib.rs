//! `rolling-disk`: the equations of McDonald & McDonald (2001), "The Rolling Motion of a Disk on a
//! Horizontal Plane", as executable and checkable mathematics.
//!
//! Data flows one way: a [`scene::Scene`] (YAML) is validated, [`run::run`] builds the model with
//! only the states the scene needs and integrates it through [`solve`], the only door to
//! `ode_solvers`.

pub mod catalogue;
pub mod check;
pub mod compare;
pub mod disk;
pub mod dispatch;
pub mod equations;
pub mod experiment;
pub mod figures;
pub mod finding;
pub mod model;
pub mod numerics;
pub mod output;
pub mod precision;
pub mod report;
pub mod run;
pub mod scene;
pub mod select;
pub mod solve;

pub use disk::Disk;
