//! The report's studies, each a computation in the style of argmin's `Solver`: a [`Study`] names
//! itself and computes its result from the bench; the executor ([`crate::pipeline::compute`])
//! runs those a report or a figure needs, each once, and gives every one the same observer
//! ([`Observer`]). Adding a study is one file here and its row in [`ALL`]; the figures that read
//! it name it in their own row (`crate::figures::FAMILIES`).

use crate::cache::{Cache, Lookup};
use crate::error::ReportError;
use checks::equations::Bench;
use std::any::Any;
use std::sync::Arc;

mod checks_run;
mod corrections;
pub mod energy_drift;
mod experiment;
mod frequency;
mod friction;
mod lab_frame;
mod paths;
mod precision;
mod sound;
mod spin_down;
pub mod steady_motion;
mod toy;

pub use checks_run::Checks;
pub use corrections::{Corrections, CorrectionsStudy};
pub use energy_drift::EnergyDrift;
pub use experiment::Experiment;
pub use frequency::Frequency;
pub use friction::Friction;
pub use lab_frame::LabFrame;
pub use paths::Paths;
pub use precision::Precision;
pub use sound::Sound;
pub use spin_down::SpinDown;
pub use steady_motion::SteadyMotion;
pub use toy::Toy;

/// One step of a study that counts its work: `done` of `total`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Step {
    /// Steps done.
    pub done: usize,
    /// Steps in all.
    pub total: usize,
}

/// What every study reports its steps to.
pub type Observer<'a> = dyn Fn(Step) + Sync + 'a;

/// A computation of the report.
pub trait Study: Sync {
    /// Its result: plain data that the figures and renderers read.
    type Output: Send + Sync + 'static;
    /// Its name, in progress lines and errors.
    const NAME: &'static str;
    /// Computes the result for `bench`; `observe` hears each step the study counts.
    fn compute(&self, bench: &Bench, observe: &Observer) -> Result<Self::Output, ReportError>;

    /// How the result may be kept between runs ([`crate::cache`]), for a study whose result
    /// depends on nothing but the program and the inputs it names; `None` (the default): the
    /// study is computed every time.
    fn kept(&self, _bench: &Bench) -> Option<Kept<Self::Output>> {
        None
    }
}

/// A result kept between runs: every input it depends on besides the program, as bytes, and
/// its encoding, which must give back a result equal to the one encoded (every field, every
/// float to the bit).
pub struct Kept<T> {
    /// The inputs' bytes (hashed into the entry's key).
    pub inputs: Vec<u8>,
    /// The result as bytes.
    pub encode: fn(&T) -> Result<Vec<u8>, String>,
    /// The result read back.
    pub decode: fn(&[u8]) -> Result<T, String>,
}

/// Where a study's result came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Source {
    /// Computed, and not kept (no cache, or a study computed every time).
    Computed,
    /// Computed and written to the cache (none valid was there).
    Stored,
    /// Read from the cache.
    Cached,
}

/// A result of any study, kept under the study's name.
pub type Output = Arc<dyn Any + Send + Sync>;

/// What a study runs with: the bench, the observer of its steps, the cache its result may be
/// kept in, and where a note for the user goes.
pub struct RunContext<'a> {
    /// The paper, solver and settings the study computes with.
    pub bench: &'a Bench<'a>,
    /// Told of each step the study counts.
    pub observe: &'a Observer<'a>,
    /// Where the study's result is kept between runs, if anywhere.
    pub cache: Option<&'a Cache>,
    /// Where a note for the user goes (a cache that cannot be read or written).
    pub note: &'a (dyn Fn(&str) + Sync),
}

/// Any [`Study`] behind one face, for the executor's table.
pub trait Run: Sync {
    /// The study's name.
    fn name(&self) -> &'static str;
    /// Computes the study's result, or reads it from the context's cache when the study's
    /// result may be kept and a valid entry is there (an entry that is not is replaced by the
    /// computed result). A cache that cannot be written is said in the context's note, and the
    /// result is computed.
    fn run(&self, context: &RunContext) -> Result<(Output, Source), ReportError>;
}

impl<S: Study> Run for S {
    fn name(&self) -> &'static str {
        S::NAME
    }

    fn run(&self, context: &RunContext) -> Result<(Output, Source), ReportError> {
        let RunContext {
            bench,
            observe,
            cache,
            note,
        } = *context;
        let kept = self.kept(bench);
        let key = kept.as_ref().and_then(|k| Cache::key(S::NAME, &k.inputs));
        let (Some(cache), Some(kept), Some(key)) = (cache, kept, key) else {
            return Ok((Arc::new(self.compute(bench, observe)?), Source::Computed));
        };
        let (lookup, bytes) = cache.get(S::NAME, &key);
        if let Some(out) = bytes.and_then(|b| (kept.decode)(&b).ok()) {
            return Ok((Arc::new(out), Source::Cached));
        }
        if lookup != Lookup::Missing {
            note(&format!(
                "{}: the cached result in {} did not pass its checks; computing it again",
                S::NAME,
                cache.dir().display()
            ));
        }
        let out = self.compute(bench, observe)?;
        let stored = (kept.encode)(&out)
            .map_err(std::io::Error::other)
            .and_then(|bytes| cache.put(S::NAME, &key, &bytes));
        if let Err(e) = stored {
            note(&format!(
                "{}: could not keep the result in {} ({e}); it is computed every time",
                S::NAME,
                cache.dir().display()
            ));
            return Ok((Arc::new(out), Source::Computed));
        }
        Ok((Arc::new(out), Source::Stored))
    }
}

/// Every study, in the order the report lists them; the checks first, as the longest.
pub const ALL: &[&dyn Run] = &[
    &Checks,
    &Experiment,
    &Sound,
    &Precision,
    &EnergyDrift,
    &Frequency,
    &Paths,
    &SpinDown,
    &LabFrame,
    &SteadyMotion,
    &Corrections,
    &Friction,
    &Toy,
];

/// The names of `studies`, in order.
pub fn names(studies: &[&dyn Run]) -> Vec<&'static str> {
    studies.iter().map(|s| s.name()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_study_has_its_own_name() {
        let mut n = names(ALL);
        n.sort_unstable();
        n.dedup();
        assert_eq!(n.len(), ALL.len(), "{:?}", names(ALL));
    }
}
