//! The results layer: every study's result as plain data ([`Results`]), between the pipeline
//! that computes them (`crate::pipeline`) and the figures and renderers that only read them.

use checks::check::Checked;
use checks::corrections::Downstream;
use paper::Correction;
use std::collections::BTreeMap;
use std::fmt;
use studies::energy::EnergyDrift;
use studies::frequency::Measured;
use studies::lab_frame::Compared;
use studies::precision;
use studies::runs::{PathRun, SpinDown};
use studies::slip_stick::SlipStick;
use studies::synthetic::Synthetic;

/// One computation of the report.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Study {
    /// Every equation's and claim's check (`checks::check`).
    Checks,
    /// The synthetic experiment of section 11: the spin-down seen through the light model and
    /// scope, then analysed (eqs 84, 85).
    Experiment,
    /// The speed/accuracy study on the benchmark scene (`studies::precision`).
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
    /// The corrected forms of paper/corrections.yaml checked (`checks::corrections`).
    Corrections,
    /// The sliding model's slip-stick scene and the friction studies (`studies::sliding`).
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

/// Every study's result, present when it was computed.
#[derive(Debug, Clone, Default)]
pub struct Results {
    /// The checks.
    pub checks: Option<Vec<Checked>>,
    /// The synthetic experiment and its analysis.
    pub experiment: Option<Synthetic>,
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
    pub friction: Option<SlipStick>,
    /// The paper the results were computed from (the figures that draw its printed curves read
    /// it: the stability map, the frequency figure).
    pub paper: Option<paper::Paper>,
    /// How many times each study was computed to make these results.
    pub computed: BTreeMap<Study, usize>,
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
