//! The exit statuses of `rolling-disk`, one meaning each, so that a script or a CI job can tell
//! an error from a finding:
//!
//! | status | meaning |
//! |---|---|
//! | 0 | done; nothing asked to fail did |
//! | 1 | error: the command could not do what was asked (bad input, a check that could not run) |
//! | 2 | usage: the command line itself is wrong (clap's own status) |
//! | 3 | changed: `--against` found a verdict changed, or a number moved beyond its tolerance |
//! | 4 | found: `check --fail-on` met a verdict of the kind it names |
//! | 141 | the reader of standard output closed it (`\| head`) |
//!
//! When both 3 and 4 apply, the status is 3 and both are said.

use std::fmt;

/// `--against` found a change.
pub const CHANGED: u8 = 3;

/// `--fail-on` found a verdict of its kind.
pub const FOUND: u8 = 4;

/// An ending with its own status (not the 1 of an error) and the sentence said on standard
/// error.
#[derive(Debug)]
pub struct Status {
    /// The exit status.
    pub code: u8,
    /// What is said, as `error: {message}`.
    pub message: String,
}

impl fmt::Display for Status {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for Status {}

/// The exit status of an error that ended a command: its own [`Status`], or 1.
pub fn code_of(e: &anyhow::Error) -> u8 {
    e.downcast_ref::<Status>().map_or(1, |s| s.code)
}
