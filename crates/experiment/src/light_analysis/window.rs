//! The fitting window: the cycles eqs 84 and 85 are fitted on, and why the others are left
//! out (anomalous, too short, too faint, past the end of the spin-down, or outside the times
//! asked for).

use crate::error::ExperimentError;
use crate::light_analysis::peak::Peak;
use crate::light_analysis::rates::Cycle;
use crate::light_analysis::settings::AnalysisSettings;
use serde::Serialize;

/// Which cycles were fitted, and why the others were not.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Window {
    /// The rule, in words.
    pub rule: String,
    /// First peak used.
    pub first_peak: usize,
    /// Last peak used.
    pub last_peak: usize,
    /// Its time span (s).
    pub t_first: f64,
    /// (s)
    pub t_last: f64,
    /// Indices of the cycles fitted by eq 84.
    pub cycles: Vec<usize>,
    /// Indices of the accelerations fitted by eq 85.
    pub accelerations: Vec<usize>,
    /// Cycles left out as anomalous (missed or stray peak).
    pub anomalous: usize,
    /// Cycles left out as too short.
    pub too_short: usize,
    /// Cycles left out as too faint.
    pub faint: usize,
    /// The fastest cycle fitted (rad/s): the paper's "last analyzable cycle" was 680.
    pub omega_last: f64,
}

/// The cycles in the window (indexed like the cycles) and the counts of those left out.
struct Selection {
    /// Whether each cycle is fitted.
    in_window: Vec<bool>,
    /// Left out as anomalous.
    anomalous: usize,
    /// Left out as too short.
    too_short: usize,
    /// Left out as too faint.
    faint: usize,
}

/// The fitting window over the cycles `cyc` between the `peaks` of the trace `file` (sample
/// interval `dt`, noise `noise`), with `accelerations` accelerations; an error when it holds
/// fewer than five cycles.
pub(crate) fn fitting_window(
    file: &str,
    peaks: &[Peak],
    cyc: &[Cycle],
    accelerations: usize,
    dt: f64,
    noise: f64,
    s: &AnalysisSettings,
) -> Result<Window, ExperimentError> {
    let min_span = s.min_snr * noise;
    let last_usable = end_of_spin_down(peaks, cyc, min_span, peaks.len() - 1 - s.drop_last);
    let sel = select_cycles(
        peaks,
        cyc,
        last_usable,
        s.min_samples_per_period * dt,
        min_span,
        s,
    );
    let in_window = &sel.in_window;
    let cyc_idx: Vec<usize> = (0..cyc.len()).filter(|&i| in_window[i]).collect();
    let acc_idx: Vec<usize> = (0..accelerations)
        .filter(|&i| in_window[i] && in_window[i + 1])
        .collect();
    if cyc_idx.len() < 5 {
        return Err(ExperimentError::TooFewPeaks {
            file: file.to_string(),
            what: "cycles in the fitting window".into(),
            found: cyc_idx.len(),
            needed: 5,
            hint: "widen the window (t_from, t_to), lower drop_last or min_samples_per_period"
                .into(),
        });
    }
    let first_peak = cyc_idx[0];
    let last_peak = cyc_idx[cyc_idx.len() - 1] + 1;
    Ok(Window {
        rule: rule(s, first_peak, last_peak),
        first_peak,
        last_peak,
        t_first: peaks[first_peak].t,
        t_last: peaks[last_peak].t,
        omega_last: cyc[cyc_idx[cyc_idx.len() - 1]].omega,
        cycles: cyc_idx,
        accelerations: acc_idx,
        anomalous: sel.anomalous,
        too_short: sel.too_short,
        faint: sel.faint,
    })
}

/// The last peak the fits may use: at most `last_usable`, and before the end of the
/// spin-down. The pulses fade as the tilt vanishes; after three cycles in a row (past the
/// first twenty) with a pulse spanning less than `min_span`, nothing later is the disk's (hum
/// or noise at most).
fn end_of_spin_down(peaks: &[Peak], cyc: &[Cycle], min_span: f64, last_usable: usize) -> usize {
    let mut run = 0;
    for (k, c) in cyc.iter().enumerate().skip(20) {
        if peaks[c.i].span < min_span || peaks[c.i + 1].span < min_span {
            run += 1;
            if run == 3 {
                return last_usable.min(k.saturating_sub(2));
            }
        } else {
            run = 0;
        }
    }
    last_usable
}

/// The cycles up to peak `last_usable` and within the settings' times, each fitted unless it
/// is anomalous, shorter than `min_period` (s), or has a pulse spanning less than `min_span`.
fn select_cycles(
    peaks: &[Peak],
    cyc: &[Cycle],
    last_usable: usize,
    min_period: f64,
    min_span: f64,
    s: &AnalysisSettings,
) -> Selection {
    let mut sel = Selection {
        in_window: vec![false; cyc.len()],
        anomalous: 0,
        too_short: 0,
        faint: 0,
    };
    for c in cyc {
        if c.i + 1 > last_usable
            || s.t_from.is_some_and(|a| c.t < a)
            || s.t_to.is_some_and(|b| c.t > b)
        {
            continue;
        }
        if c.anomalous {
            sel.anomalous += 1;
        } else if c.period < min_period {
            sel.too_short += 1;
        } else if peaks[c.i].span < min_span || peaks[c.i + 1].span < min_span {
            sel.faint += 1;
        } else {
            sel.in_window[c.i] = true;
        }
    }
    sel
}

/// The window's rule in words, for the window from `first_peak` to `last_peak`.
fn rule(s: &AnalysisSettings, first_peak: usize, last_peak: usize) -> String {
    format!(
        "cycles between peaks {first_peak} and {last_peak}: all but the last {} peaks, \
         periods of at least {} samples, pulses spanning at least {} noise deviations \
         (none after the first three faint ones in a row), no anomalous period{}{}",
        s.drop_last,
        s.min_samples_per_period,
        s.min_snr,
        s.t_from
            .map_or(String::new(), |a| format!(", middle at or after {a} s")),
        s.t_to
            .map_or(String::new(), |b| format!(", middle at or before {b} s")),
    )
}
