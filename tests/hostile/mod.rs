//! Issue 48's hostile suite in one place: the tool used as a hostile user would. Every run goes
//! through [`sandbox::bounded`], which kills it and fails the test past its limit (2 s for a
//! refusal) and fails on a panic; the writers' runs are made in a sandbox folder recorded before
//! and compared after, so a file the tool did not create, changed or removed, fails them.
//!
//! - `writers`: every file-writing command against a device node, a FIFO, a read-only file, a
//!   symbolic link, a hard link, its own input and a user's `.NAME.tmp-PID` folders; a folder
//!   writer removing only a temporary it proves its own.
//! - `door`: `--out` through a link to a folder, a name shadowing a built-in scene, a `--paper`
//!   folder whose equations are a FIFO or endless, numeric options and `max_steps` out of range.
//! - `budgets`: budgets and step limits too small (refusals naming one that does, applied), a
//!   fillet at its limit, and property tests over budgets (the twin of the fuzz target
//!   `fuzz/fuzz_targets/budgets.rs`).
//! - `advice`: each wrong piece of advice of the issue, corrected and applied.
//! - `arguments`: a path argument that is not UTF-8, and `peer export`'s warnings of the peer's
//!   fixed floors.
//! - `precision`: a scene with mode switches measured over its whole run in under 5 s.
//! - `pairing`: `peer compare` pairing every mode change on the raw peer runs.

mod advice;
mod arguments;
mod budgets;
mod door;
mod pairing;
mod precision;
pub mod sandbox;
mod writers;
