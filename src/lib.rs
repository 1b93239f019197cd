//! `rolling-disk`: the equations of McDonald & McDonald (2001), "The Rolling Motion of a Disk on a
//! Horizontal Plane", as executable and checkable mathematics.

pub mod disk;
pub mod model;
pub mod solve;

pub use disk::Disk;
