//! The report's one pipeline: a run configuration ([`RunConfig`]) -> every study computed once,
//! the independent ones in parallel on rayon's threads ([`compute`]) -> plain results
//! ([`Results`]) -> pure figure functions (`crate::figures`, results -> figure) -> renderers
//! (HTML, LaTeX, JSON in `super::render`).
//!
//! Nothing downstream of [`compute`] integrates: tests/architecture.rs forbids the figures and
//! the renderers to reach the solver, the scene runner, the simulations or the checks, and
//! [`Results::computed`] records how many times each study ran (once, for a full report).

use super::studies;
use crate::check::{run_checks, Checked, Selection};
use crate::corrections::{self, Downstream};
use crate::equations::Bench;
use crate::experiment::{self, AnalysisSettings, LightModel};
use crate::figures::energy::EnergyDrift;
use crate::figures::experiment::Experiment;
use crate::figures::frequency::Measured;
use crate::figures::lab_frame::Compared;
use crate::figures::path::PathRun;
use crate::figures::spin_down::SpinDown;
use crate::paper::Correction;
use crate::precision;
use crate::report::error::ReportError;
use crate::scene::Scene;
use std::collections::BTreeMap;
use std::fmt;
use std::time::Instant;

/// One computation of the report.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Study {
    /// Every equation's and claim's check (`crate::check`).
    Checks,
    /// The synthetic experiment of section 11: the spin-down seen through the light model and
    /// scope, then analysed (eqs 84, 85).
    Experiment,
    /// The speed/accuracy study on the benchmark scene (`crate::precision`).
    Precision,
    /// Energy drift of six methods on the benchmark scene.
    EnergyDrift,
    /// Small-oscillation frequencies measured on integrations (eqs 54, 55, 71).
    Frequency,
    /// The path scenes but the spin-down.
    Paths,
    /// The one run of the built-in spin-down (eqs 23-25 with eq 75), shared by two figures.
    SpinDown,
    /// The reduced model against the lab-frame model (eqs 23-25).
    LabFrame,
    /// The corrected forms of paper/corrections.yaml checked (`crate::corrections`).
    Corrections,
    /// The sliding model's slip-stick scene and the friction studies (`crate::friction`).
    Friction,
}

impl Study {
    /// Every study, in the order they are listed in the report.
    pub const ALL: [Study; 10] = [
        Study::Checks,
        Study::Experiment,
        Study::Precision,
        Study::EnergyDrift,
        Study::Frequency,
        Study::Paths,
        Study::SpinDown,
        Study::LabFrame,
        Study::Corrections,
        Study::Friction,
    ];
}

impl fmt::Display for Study {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Study::Checks => "checks",
            Study::Experiment => "experiment",
            Study::Precision => "precision",
            Study::EnergyDrift => "energy-drift",
            Study::Frequency => "frequency",
            Study::Paths => "paths",
            Study::SpinDown => "spin-down",
            Study::LabFrame => "lab-frame",
            Study::Corrections => "corrections",
            Study::Friction => "friction",
        })
    }
}

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

/// Every study's result, present when it was computed.
#[derive(Debug, Clone, Default)]
pub struct Results {
    /// The checks.
    pub checks: Option<Vec<Checked>>,
    /// The synthetic experiment and its analysis.
    pub experiment: Option<Experiment>,
    /// The speed/accuracy study.
    pub precision: Option<precision::Study>,
    /// The energy-drift runs.
    pub energy: Option<EnergyDrift>,
    /// The measured frequencies.
    pub frequency: Option<Measured>,
    /// The path runs (rolling-circle, nutating-coin).
    pub paths: Option<Vec<PathRun>>,
    /// The spin-down run.
    pub spin_down: Option<SpinDown>,
    /// The lab-frame comparisons.
    pub lab_frame: Option<Vec<Compared>>,
    /// The corrections and their checks on the corrected paper.
    pub corrections: Option<CorrectionsStudy>,
    /// The slip-stick run and the friction studies.
    pub friction: Option<crate::figures::friction::FrictionResults>,
    /// The paper the results were computed from (the figures that draw its printed curves read
    /// it: the stability map, the frequency figure).
    pub paper: Option<crate::paper::Paper>,
    /// How many times each study was computed to make these results.
    pub computed: BTreeMap<Study, usize>,
}

/// One study's result, before it is put in its place.
enum Output {
    Checks(Vec<Checked>),
    Experiment(Box<Experiment>),
    Precision(Box<precision::Study>),
    EnergyDrift(EnergyDrift),
    Frequency(Measured),
    Paths(Vec<PathRun>),
    SpinDown(Box<SpinDown>),
    LabFrame(Vec<Compared>),
    Corrections(Box<CorrectionsStudy>),
    Friction(Box<crate::figures::friction::FrictionResults>),
}

/// The corrections study: the corrected forms, their checks on the paper with all of them
/// substituted, and the dissipation strength the paper's fit means before and after.
#[derive(Debug, Clone)]
pub struct CorrectionsStudy {
    /// paper/corrections.yaml.
    pub corrections: Vec<Correction>,
    /// The corrected equations' checks.
    pub corrected: Vec<Checked>,
    /// $\epsilon$ from the paper's fit, printed and corrected eq 79, for the built-in
    /// spin-down disk.
    pub downstream: Option<Downstream>,
    /// Why the corrections could not be checked on this paper (a `--paper DIR` whose symbols
    /// or equations no longer fit them): the report says so instead of failing.
    pub error: Option<String>,
}

fn corrections_study(bench: &Bench) -> Result<CorrectionsStudy, ReportError> {
    let corrections = bench.paper.corrections.clone();
    let threads = rayon::current_num_threads().max(1);
    let corrected = corrections::check_corrected(bench, &corrections, threads)
        .map_err(|e| ReportError::Input(e.to_string()))?;
    let fixed = corrections::apply(bench.paper, &corrections)
        .map_err(|e| ReportError::Input(e.to_string()))?;
    let disk = Scene::load("spin-down")
        .map_err(|e| ReportError::Input(e.to_string()))?
        .disk;
    let downstream = corrections::downstream(bench.paper, &fixed, (disk.a, disk.k, disk.g));
    Ok(CorrectionsStudy {
        corrections,
        corrected,
        downstream,
        error: None,
    })
}

fn experiment_study() -> Result<Experiment, ReportError> {
    let scene = Scene::load("spin-down").map_err(|e| ReportError::Input(e.to_string()))?;
    let light = LightModel::default();
    let scope = &light.scope;
    let motion = experiment::simulate::simulate_motion(
        &scene,
        scope.end_at,
        scope.sample_rate,
        scope.samples,
    )
    .map_err(|e| ReportError::Input(e.to_string()))?;
    let trace = experiment::simulate::trace_of_motion(&motion, &light, &scene.name);
    let analysis = experiment::analyze(&trace, &AnalysisSettings::default())
        .map_err(|e| ReportError::Input(e.to_string()))?;
    let motion_law = Some(
        experiment::motion_law::law_of_motion(&motion, &light, &analysis)
            .map_err(|e| ReportError::Input(e.to_string()))?,
    );
    Ok(Experiment {
        trace,
        analysis,
        motion_law,
    })
}

fn precision_study() -> Result<precision::Study, ReportError> {
    let scene = Scene::load("benchmark").map_err(|e| ReportError::Input(e.to_string()))?;
    let mut opts = precision::StudyOptions::quick();
    opts.timing = precision::Timing::ONCE;
    precision::study(&scene, &opts).map_err(|e| ReportError::Input(e.to_string()))
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
        Study::Experiment => Output::Experiment(Box::new(experiment_study()?)),
        Study::Precision => Output::Precision(Box::new(precision_study()?)),
        Study::EnergyDrift => Output::EnergyDrift(studies::energy::compute()?),
        Study::Frequency => Output::Frequency(studies::frequency::compute()?),
        Study::Paths => Output::Paths(studies::runs::paths()?),
        Study::SpinDown => Output::SpinDown(Box::new(studies::runs::spin_down()?)),
        Study::LabFrame => Output::LabFrame(studies::lab_frame::compute()?),
        Study::Friction => {
            Output::Friction(Box::new(studies::friction::compute(&bench.paper.fit)?))
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
