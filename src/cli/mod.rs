//! The commands of the binary, one file per command: each has a clap `Args` (or, for a family
//! of subcommands, a `Command`) with `run()`. `lib.rs` holds the command line and calls
//! `run`. Errors are anyhow's here, and only here: the library's typed errors print their
//! sentence.

pub(crate) mod caching;
pub mod check;
pub(crate) mod choice;
pub mod completions;
pub mod exit;
pub mod experiment;
pub mod figures;
pub mod manual;
pub mod mutants;
pub mod paper_input;
pub mod peer;
pub mod precision;
pub mod quantities;
pub(crate) mod ranges;
pub mod report;
pub(crate) mod row_stream;
pub mod scenes;
pub mod simulate;
pub mod sound_figures;
pub(crate) mod stdin;
pub mod stdout;
pub(crate) mod trace_against;
pub(crate) mod utf8;
pub(crate) mod verdict_snapshot;

/// An error when an integration of this process ran past the wall-time budget: a command calls
/// it before it prints or writes a result computed from integrations, so that nothing cut short
/// is ever reported as a result.
pub(crate) fn within_budget() -> anyhow::Result<()> {
    match physics::budget::overrun() {
        Some(o) => Err(o.into()),
        None => Ok(()),
    }
}
