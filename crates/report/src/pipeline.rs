//! The report's one pipeline: a run configuration ([`RunConfig`]) -> every study computed once,
//! the independent ones in parallel on rayon's threads ([`compute`]) -> plain results
//! ([`Results`]) -> pure figure functions (`crate::figures`, results -> figure) -> renderers
//! (HTML, LaTeX, JSON in `super::render`).
//!
//! Nothing downstream of [`compute`] integrates: tests/architecture.rs forbids the figures and
//! the renderers to reach the solver, the scene runner, the simulations or the checks, and
//! [`Results::computed`] records how many times each study ran (once, for a full report).

use crate::error::ReportError;
use crate::results::{CorrectionsStudy, Results, Study};
use checks::check::{run_checks, Checked, Selection};
use checks::corrections;
use checks::equations::Bench;
use experiment::law::Law;
use physics::scene::Scene;
use std::time::Instant;
use studies::energy::EnergyDrift;
use studies::frequency::Measured;
use studies::lab_frame::Compared;
use studies::precision;
use studies::runs::{PathRun, SpinDown};
use studies::slip_stick::SlipStick;
use studies::synthetic::Synthetic;

/// What to compute, and how.
#[derive(Debug, Clone)]
pub struct RunConfig<'p> {
    /// The paper (built-in or `--paper DIR`) and the checks' accuracy.
    pub bench: Bench<'p>,
    /// The studies to compute (each once, whatever the list repeats).
    pub studies: Vec<Study>,
}

impl<'p> RunConfig<'p> {
    /// Everything a full report needs.
    pub fn report(bench: Bench<'p>) -> Self {
        Self {
            bench,
            studies: Study::ALL.to_vec(),
        }
    }

    /// What the named figures need, and nothing else (no checks); an unknown name is an error
    /// that lists the figures.
    pub fn figures(bench: Bench<'p>, names: &[&str]) -> Result<Self, ReportError> {
        let mut studies = Vec::new();
        for n in names {
            for s in crate::figures::needs(n)? {
                if !studies.contains(s) {
                    studies.push(*s);
                }
            }
        }
        Ok(Self { bench, studies })
    }
}

/// One study's result, before it is put in its place.
enum Output {
    Checks(Vec<Checked>),
    Experiment(Box<Synthetic>),
    Precision(Box<precision::Study>),
    EnergyDrift(EnergyDrift),
    Frequency(Measured),
    Paths(Vec<PathRun>),
    SpinDown(Box<SpinDown>),
    LabFrame(Vec<Compared>),
    Corrections(Box<CorrectionsStudy>),
    Friction(Box<SlipStick>),
}

fn corrections_study(bench: &Bench) -> Result<CorrectionsStudy, ReportError> {
    let corrections = bench.paper.corrections.clone();
    let threads = rayon::current_num_threads().max(1);
    let corrected = corrections::check_corrected(bench, &corrections, threads)?;
    let fixed = corrections::apply(bench.paper, &corrections)?;
    let disk = Scene::load("spin-down")?.disk;
    let downstream = corrections::downstream(bench.paper, &fixed, (disk.a, disk.k, disk.g));
    Ok(CorrectionsStudy {
        corrections,
        corrected,
        downstream,
        error: None,
    })
}

fn one(study: Study, bench: &Bench) -> Result<Output, ReportError> {
    Ok(match study {
        Study::Checks => {
            // The checks share the machine with the other studies: as many threads as cores.
            let threads = rayon::current_num_threads().max(1);
            Output::Checks(run_checks(
                bench,
                &Selection::default(),
                threads,
                &|_, _| {},
            )?)
        }
        Study::Experiment => Output::Experiment(Box::new(studies::synthetic::compute()?)),
        Study::Precision => Output::Precision(Box::new(precision::benchmark_study()?)),
        Study::EnergyDrift => Output::EnergyDrift(studies::energy::compute()?),
        Study::Frequency => Output::Frequency(studies::frequency::compute()?),
        Study::Paths => Output::Paths(studies::runs::paths()?),
        Study::SpinDown => Output::SpinDown(Box::new(studies::runs::spin_down()?)),
        Study::LabFrame => Output::LabFrame(studies::lab_frame::compute()?),
        Study::Friction => {
            let fit = &bench.paper.fit;
            let record = Law::from_fit(fit.beta, fit.c_inv_root);
            Output::Friction(Box::new(studies::slip_stick::compute(&record)?))
        }
        Study::Corrections => {
            Output::Corrections(Box::new(corrections_study(bench).unwrap_or_else(|e| {
                CorrectionsStudy {
                    corrections: Vec::new(),
                    corrected: Vec::new(),
                    downstream: None,
                    error: Some(e.to_string()),
                }
            })))
        }
    })
}

/// Computes every study of `config` once, in parallel; `progress` receives a line as each
/// finishes (with its wall time: progress goes to stderr, never into the report's files).
/// The results do not depend on the threads: each study is deterministic on its own.
pub fn compute(
    config: &RunConfig,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<Results, ReportError> {
    use rayon::prelude::*;
    let mut wanted: Vec<Study> = Vec::new();
    for s in &config.studies {
        if !wanted.contains(s) {
            wanted.push(*s);
        }
    }
    // The longest first, so that the short ones fill the other threads around it.
    wanted.sort_by_key(|s| *s != Study::Checks);
    let total = wanted.len();
    let done = std::sync::atomic::AtomicUsize::new(0);
    let outputs: Vec<(Study, Output)> = wanted
        .par_iter()
        .map(|&s| {
            let start = Instant::now();
            let out = one(s, &config.bench).map_err(|e| format!("the {s} study failed: {e}"))?;
            let n = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress(&format!(
                "computed {s} ({n}/{total}) in {:.2} s",
                start.elapsed().as_secs_f64()
            ));
            Ok((s, out))
        })
        .collect::<Result<_, ReportError>>()?;
    let mut r = Results {
        paper: Some(config.bench.paper.clone()),
        ..Results::default()
    };
    for (s, out) in outputs {
        *r.computed.entry(s).or_insert(0) += 1;
        match out {
            Output::Checks(c) => r.checks = Some(c),
            Output::Experiment(e) => r.experiment = Some(*e),
            Output::Precision(p) => r.precision = Some(*p),
            Output::EnergyDrift(e) => r.energy = Some(e),
            Output::Frequency(f) => r.frequency = Some(f),
            Output::Paths(p) => r.paths = Some(p),
            Output::SpinDown(s) => r.spin_down = Some(*s),
            Output::LabFrame(l) => r.lab_frame = Some(l),
            Output::Corrections(c) => r.corrections = Some(*c),
            Output::Friction(f) => r.friction = Some(*f),
        }
    }
    Ok(r)
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
            c.studies,
            vec![Study::Paths, Study::SpinDown, Study::Experiment]
        );
        assert!(RunConfig::figures(Bench::default(), &["fig99"]).is_err());
    }
}
