//! `rolling-disk`: the equations of McDonald & McDonald (2001), "The Rolling Motion of a Disk on a
//! Horizontal Plane", as executable and checkable mathematics.
//!
//! Data flows one way: a [`scene::Scene`] (YAML) is validated, [`run::run`] builds the model with
//! only the states the scene needs and integrates it through [`solve`], the only door to
//! `ode_solvers`.

pub mod budget;
pub mod cause;
pub mod check;
pub mod compare;
pub mod corrections;
pub mod disk;
pub mod dispatch;
pub mod equations;
pub mod events;
pub mod experiment;
pub mod figures;
pub mod finding;
pub mod friction;
pub mod input;
pub mod model;
pub mod mutation;
pub mod numerics;
pub mod output;
pub mod output_file;
pub mod paper;
pub mod peer;
pub mod precision;
pub mod report;
pub mod run;
pub mod scene;
pub mod select;
pub mod solve;

pub use disk::Disk;
