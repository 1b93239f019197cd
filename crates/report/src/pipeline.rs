//! The report's one pipeline: a run configuration ([`RunConfig`]) -> every study computed once,
//! the independent ones in parallel on rayon's threads ([`compute`]) -> plain results
//! ([`Results`]) -> pure figure functions (`crate::figures`, results -> figure) -> renderers
//! (HTML, LaTeX, JSON in `super::render`).
//!
//! Nothing downstream of [`compute`] integrates: tests/architecture.rs forbids the figures and
//! the renderers to reach the solver, the scene runner, the simulations or the checks, and
//! [`Results::computed`] records how many times each study ran (once, for a full report).

use crate::cache::Cache;
use crate::error::ReportError;
use crate::results::Results;
use crate::study::{self, Run, Source, Step};
use crate::timing::{Timing, Timings};
use checks::equations::Bench;
use std::time::Instant;

/// What to compute, and how.
#[derive(Clone)]
pub struct RunConfig<'p> {
    /// The paper (built-in or `--paper DIR`) and the checks' accuracy.
    pub bench: Bench<'p>,
    /// The studies to compute (each once, whatever the list repeats).
    pub studies: Vec<&'static dyn Run>,
    /// Where the results that depend on nothing but the program are kept between runs
    /// ([`crate::cache`]); `None`: every study is computed.
    pub cache: Option<Cache>,
}

impl<'p> RunConfig<'p> {
    /// Everything a full report needs.
    pub fn report(bench: Bench<'p>) -> Self {
        Self {
            bench,
            studies: study::ALL.to_vec(),
            cache: None,
        }
    }

    /// The same, with the results that may be kept read from and written to `cache`.
    pub fn with_cache(self, cache: Option<Cache>) -> Self {
        Self { cache, ..self }
    }

    /// What the named figures need, and nothing else (no checks); an unknown name is an error
    /// that lists the figures.
    pub fn figures(bench: Bench<'p>, names: &[&str]) -> Result<Self, ReportError> {
        let mut studies: Vec<&'static dyn Run> = Vec::new();
        for n in names {
            for s in crate::figures::needs(n)? {
                if !studies.iter().any(|t| t.name() == s.name()) {
                    studies.push(*s);
                }
            }
        }
        Ok(Self {
            bench,
            studies,
            cache: None,
        })
    }

    /// The names of the studies to compute, in order.
    pub fn study_names(&self) -> Vec<&'static str> {
        study::names(&self.studies)
    }
}

/// Computes every study of `config` once, in parallel; `progress` receives a line as each
/// finishes (with its wall time: progress goes to stderr, never into the report's files).
/// The results do not depend on the threads: each study is deterministic on its own.
pub fn compute(
    config: &RunConfig,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<Results, ReportError> {
    crate::kept_film::around(config.cache.as_ref(), &cache_warning, || {
        compute_all(config, progress)
    })
}

/// [`compute`] with the film's $I$ as the process has it.
fn compute_all(
    config: &RunConfig,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<Results, ReportError> {
    use rayon::prelude::*;
    let wanted = wanted(config);
    let total = wanted.len();
    let done = std::sync::atomic::AtomicUsize::new(0);
    let outputs: Vec<(&'static str, study::Output)> = wanted
        .par_iter()
        .map(|s| {
            let start = Instant::now();
            let (out, source) = run_one(*s, config, progress)?;
            let n = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress(&format!(
                "{} {} ({n}/{total}) in {:.2} s",
                said(source),
                s.name(),
                start.elapsed().as_secs_f64()
            ));
            Ok((s.name(), out))
        })
        .collect::<Result<_, ReportError>>()?;
    Ok(results(config, outputs))
}

/// Computes every study of `config` once, one after another (each still on as many threads as
/// it uses alone), and records each one's wall and CPU time in `timings` (a study read from the
/// cache as `NAME (cached)`): the process's CPU time over a study is then that study's own. The
/// results are those of [`compute`].
pub fn compute_timed(
    config: &RunConfig,
    progress: &(dyn Fn(&str) + Sync),
    timings: &Timings,
) -> Result<Results, ReportError> {
    crate::kept_film::around(config.cache.as_ref(), &cache_warning, || {
        compute_all_timed(config, progress, timings)
    })
}

/// [`compute_timed`] with the film's $I$ as the process has it.
fn compute_all_timed(
    config: &RunConfig,
    progress: &(dyn Fn(&str) + Sync),
    timings: &Timings,
) -> Result<Results, ReportError> {
    let wanted = wanted(config);
    let total = wanted.len();
    let mut outputs = Vec::with_capacity(total);
    for (n, s) in wanted.iter().enumerate() {
        let start = (Instant::now(), crate::timing::cpu_seconds());
        let (out, source) = run_one(*s, config, progress)?;
        timings.record(Timing {
            name: match source {
                Source::Cached => format!("{} (cached)", s.name()),
                _ => s.name().to_string(),
            },
            wall: start.0.elapsed().as_secs_f64(),
            cpu: crate::timing::cpu_seconds() - start.1,
        });
        progress(&format!(
            "{} {} ({}/{total})",
            said(source),
            s.name(),
            n + 1
        ));
        outputs.push((s.name(), out));
    }
    Ok(results(config, outputs))
}

/// The studies of `config`, each once, the longest (the checks) first, so that the short ones
/// fill the other threads around it.
fn wanted(config: &RunConfig) -> Vec<&'static dyn Run> {
    let mut wanted: Vec<&'static dyn Run> = Vec::new();
    for s in &config.studies {
        if !wanted.iter().any(|t| t.name() == s.name()) {
            wanted.push(*s);
        }
    }
    wanted.sort_by_key(|s| s.name() != study::Checks.name());
    wanted
}

/// How a progress line says where a study's result came from.
fn said(source: Source) -> &'static str {
    match source {
        Source::Computed => "computed",
        Source::Stored => "computed and cached",
        Source::Cached => "read from the cache",
    }
}

/// Runs one study (or reads it from the cache), with a progress line at each quarter of the
/// steps it counts; a cache entry that is not trusted, or a cache that cannot be written, is a
/// warning on standard error (the report is the same without the cache).
fn run_one(
    s: &'static dyn Run,
    config: &RunConfig,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<(study::Output, Source), ReportError> {
    let name = s.name();
    let observe = |step: Step| {
        let quarter = |done: usize| done * 4 / step.total.max(1);
        if step.done > 0 && step.done < step.total && quarter(step.done) > quarter(step.done - 1) {
            progress(&format!("{name}: {} of {} done", step.done, step.total));
        }
    };
    physics::budget::in_stage(&format!("the {name} study"), || {
        let warn = |w: &str| eprintln!("warning: {w}");
        s.run(&study::RunContext {
            bench: &config.bench,
            observe: &observe,
            cache: config.cache.as_ref(),
            note: &warn,
        })
    })
    .map_err(|e| format!("the {name} study failed: {e}").into())
}

/// A cache entry that is not trusted, or a cache that cannot be written: a warning on standard
/// error.
fn cache_warning(w: &str) {
    eprintln!("warning: {w}");
}

/// The studies' outputs as the pipeline's results.
fn results(config: &RunConfig, outputs: Vec<(&'static str, study::Output)>) -> Results {
    let mut r = Results::of(Some(config.bench.paper.clone()));
    for (name, out) in outputs {
        r.insert(name, out);
    }
    r
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_figure_list_asks_for_its_studies_once_and_no_checks() {
        let c = RunConfig::figures(
            Bench::default(),
            &["path", "spin-down-alpha", "tek01", "tek02", "fig1"],
        )
        .unwrap();
        assert_eq!(
            c.study_names(),
            vec!["paths", "spin-down", "experiment", "steady-motion"]
        );
        assert!(RunConfig::figures(Bench::default(), &["fig99"]).is_err());
    }
}
