//! How a trace is analysed: the fitting window's rules (cycles left out at the end, the least
//! samples per period and signal-to-noise ratio, an optional time range) and the peak finding.

use crate::fit::plausibility::Plausibility;
use crate::light_analysis::peak_search::PeakSettings;
use serde::{Deserialize, Serialize};

/// How to analyse.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct AnalysisSettings {
    /// Peak finding.
    pub peaks: PeakSettings,
    /// Cycles shorter than this many samples are left out of the fits (timing by interpolation
    /// between samples degrades as the period nears the sample interval).
    pub min_samples_per_period: f64,
    /// The last peaks before the signal ends are left out: there the law breaks (the disk
    /// leaves the table, or its tilt is too small to modulate the light).
    pub drop_last: usize,
    /// Cycles whose pulses span less than this many noise deviations are left out: timing
    /// from faint edges is biased by quantisation and by the nonlinearity of the crossing.
    pub min_snr: f64,
    /// Fit only cycles whose middle is at or after this time (s).
    pub t_from: Option<f64>,
    /// Fit only cycles whose middle is at or before this time (s).
    pub t_to: Option<f64>,
    /// The checks that a fit describes a spin-down (see [`Plausibility`]).
    pub plausibility: Plausibility,
}

impl Default for AnalysisSettings {
    fn default() -> Self {
        Self {
            peaks: PeakSettings::default(),
            min_samples_per_period: 10.0,
            drop_last: 3,
            min_snr: 20.0,
            t_from: None,
            t_to: None,
            plausibility: Plausibility::default(),
        }
    }
}
