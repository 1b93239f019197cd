//! The symbols a check evaluated without a value, so that a claim that cannot be evaluated is
//! reported with the symbol that stopped it (eq 76 written with $\Omega^{\gamma}$: $\gamma$ has no
//! value in eq 76's check), never as a number that is not one.
//!
//! [`recording`] runs a check and returns, beside its result, every symbol an evaluation of the
//! paper's LaTeX looked up and found without a value while it ran, each as the evaluation's
//! message names it (the symbol, its column in its equation's LaTeX, its quantity). The record is
//! the running thread's, in frames: a check that waits on parallel work and meanwhile runs
//! another check on its thread keeps the two records apart. An evaluation that is a probe, whose
//! caller tries another side when one side has no value ([`crate::Paper::right_side`]), keeps
//! its record only when it fails ([`probing`]).

use std::cell::RefCell;
use std::collections::BTreeSet;

thread_local! {
    /// One frame per [`recording`] running on this thread, innermost last.
    static FRAMES: RefCell<Vec<BTreeSet<String>>> = const { RefCell::new(Vec::new()) };
}

/// Runs `f`, and returns its result with the symbols found without a value while it ran, in
/// their messages' order.
pub fn recording<R>(f: impl FnOnce() -> R) -> (R, Vec<String>) {
    FRAMES.with(|frames| frames.borrow_mut().push(BTreeSet::new()));
    let result = f();
    let noted = FRAMES.with(|frames| frames.borrow_mut().pop().unwrap_or_default());
    (result, noted.into_iter().collect())
}

/// Runs the probe `f`, and keeps what it noted only when `keep` says its result is a failure.
pub fn probing<R>(f: impl FnOnce() -> R, keep: impl FnOnce(&R) -> bool) -> R {
    let (result, noted) = recording(f);
    if keep(&result) {
        noted.into_iter().for_each(note);
    }
    result
}

/// Notes a symbol found without a value, in the innermost recording (none: nothing to keep).
pub(crate) fn note(symbol: String) {
    FRAMES.with(|frames| {
        if let Some(frame) = frames.borrow_mut().last_mut() {
            frame.insert(symbol);
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_recording_keeps_its_own_symbols_apart_from_an_inner_one() {
        let (inner, outer) = recording(|| {
            note("x".into());
            let ((), inner) = recording(|| note("y".into()));
            probing(|| note("z".into()), |_| false);
            probing(|| note("w".into()), |_| true);
            inner
        });
        assert_eq!(inner, ["y"]);
        assert_eq!(outer, ["w", "x"]);
        // Outside any recording, a note is dropped.
        note("v".into());
        assert_eq!(recording(|| ()).1, Vec::<String>::new());
    }
}
