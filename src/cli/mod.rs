//! The commands of the binary, one file per family; `main.rs` holds the command line and the
//! dispatch. Errors are anyhow's here, and only here: the library's typed errors print their
//! sentence.

pub(crate) mod checks;
pub(crate) mod peer;
pub(crate) mod report;
pub(crate) mod section11;
pub(crate) mod simulate;
pub(crate) mod speed;
pub(crate) mod stdout;

pub(crate) use super::*;
pub(crate) use checks::*;
pub(crate) use peer::*;
pub(crate) use report::*;
pub(crate) use section11::*;
pub(crate) use simulate::*;
pub(crate) use speed::*;
