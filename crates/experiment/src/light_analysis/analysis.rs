//! The analysis of a trace, the paper's method plus fits: peaks, $\Omega_i$, $d\Omega_i/dt$, the
//! fitting window, the fits of eqs 84 and 85, and (for a synthetic trace) how far they land
//! from the truth.

use crate::error::ExperimentError;
use crate::fit::crossover::{fit_crossover, CrossoverFit};
use crate::fit::eq84_85::{fit_eq84, fit_eq85, Eq84Fit, Eq85Fit};
use crate::fit::law_choice::{compare_laws, Comparison};
use crate::fit::law_stability::{later_half, LawStability};
use crate::fit::plausibility::{Evidence, Verdict};
use crate::light_analysis::clean::{remove_glitches, remove_hum};
use crate::light_analysis::early_end::{early_end, EarlyEnd};
use crate::light_analysis::peak::Peak;
use crate::light_analysis::peak_search::{find_peaks, noise_level, PeakSettings};
use crate::light_analysis::rates::{accelerations, cycles, Acceleration, Cycle};
pub use crate::light_analysis::settings::AnalysisSettings;
use crate::light_analysis::window::fitting_window;
pub use crate::light_analysis::window::Window;
use crate::trace::{Trace, Truth};
use files::output::write_set_file;
use physics::budget::Work;
use serde::Serialize;
use std::fmt;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// How far the fits land from a synthetic trace's truth, in their own uncertainties.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Score {
    /// (beta_84 - beta) / sigma.
    pub beta84_pull: f64,
    /// (t0_84 - t0) / sigma.
    pub t0_pull: f64,
    /// t0_84 - t0 in sample periods.
    pub t0_error_samples: f64,
    /// (beta_85 - beta) / sigma.
    pub beta85_pull: f64,
    /// (beta_84 - beta) / sigma with the law's systematic uncertainty added in quadrature
    /// ([`LawStability`]).
    pub beta84_pull_with_law: f64,
    /// (t0_84 - t0) / sigma with the law's systematic uncertainty added in quadrature.
    pub t0_pull_with_law: f64,
}

/// Everything the analysis found.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Analysis {
    /// The trace's source.
    pub source: String,
    /// Samples.
    pub samples: usize,
    /// Median sample interval (s).
    pub sample_interval: f64,
    /// Estimated noise (V rms).
    pub noise: f64,
    /// Isolated one-sample glitches replaced before timing.
    pub glitches: usize,
    /// The largest mains-hum amplitude subtracted before timing (V; 0 if none was found).
    pub hum: f64,
    /// The settings used.
    pub settings: AnalysisSettings,
    /// Peaks found.
    pub peaks: Vec<Peak>,
    /// $\Omega_i$.
    pub cycles: Vec<Cycle>,
    /// $d\Omega_i/dt$.
    pub accelerations: Vec<Acceleration>,
    /// The fitting window.
    pub window: Window,
    /// Eq 84's fit.
    pub eq84: Eq84Fit,
    /// Eq 85's fit.
    pub eq85: Eq85Fit,
    /// Eq 84 with beta free against beta fixed at 1, 2, 3, 4 and the two-mechanism law.
    pub models: Comparison,
    /// The two-mechanism law's fit ([`crossover`](crate::fit::crossover)), when it converged.
    pub crossover: Option<CrossoverFit>,
    /// Eq 84 on the later half of the window: whether the law drifts, and its systematic
    /// uncertainty if it does.
    pub law_stability: Option<LawStability>,
    /// Set when the fitted $t_0$ lies before the last detected pulse (physically impossible).
    pub early_end: Option<EarlyEnd>,
    /// The plausibility checks (passed, or the analysis would have been refused).
    pub verdict: Verdict,
    /// The truth, if the trace carries one.
    pub truth: Option<Truth>,
    /// The fits against the truth.
    pub score: Option<Score>,
}

/// Analyses a trace: the settings and the signal checked, glitches and mains hum removed, the
/// peaks timed, $\Omega_i$ and $d\Omega_i/dt$ formed, the fitting window chosen, eqs 84 and 85
/// and the other laws fitted, and (for a synthetic trace) the fits scored against the truth.
/// The work is held to the wall-time budget ([`physics::budget::wall_seconds`]).
pub fn analyze(trace: &Trace, s: &AnalysisSettings) -> Result<Analysis, ExperimentError> {
    let work = Work::start(format!("the analysis of {}", trace.source));
    analyze_within(trace, s, &work)
}

/// What the analysis measures before it fits any law: the trace cleaned, its peaks timed,
/// $\Omega_i$ and $d\Omega_i/dt$ formed and the fitting window chosen ([`timed`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Timed {
    /// Estimated noise (V rms).
    pub noise: f64,
    /// Isolated one-sample glitches replaced before timing.
    pub glitches: usize,
    /// The largest mains-hum amplitude subtracted before timing (V; 0 if none was found).
    pub hum: f64,
    /// Peaks found.
    pub peaks: Vec<Peak>,
    /// $\Omega_i$.
    pub cycles: Vec<Cycle>,
    /// $d\Omega_i/dt$.
    pub accelerations: Vec<Acceleration>,
    /// The fitting window.
    pub window: Window,
}

/// The analysis of [`analyze_within`] up to the fitting window, without the fits: the same
/// peaks, cycles and window, for a caller that reads no fit.
pub fn timed(
    trace: &Trace,
    s: &AnalysisSettings,
    work: &Work<'_>,
) -> Result<Timed, ExperimentError> {
    check_settings(trace, s)?;
    let dt = trace.sample_interval();
    work.stage("measuring the noise")?;
    let noise = noise_level(&trace.v);
    check_not_flat(trace, noise, &s.peaks)?;
    let mut v = trace.v.clone();
    work.stage("removing glitches and mains hum")?;
    let glitches = remove_glitches(&mut v, noise);
    let hum = remove_hum(&trace.t, &mut v, noise);
    work.stage("timing the peaks")?;
    let peaks = find_peaks(&trace.t, &v, dt, noise, &s.peaks);
    check_peak_count(trace, &peaks, s)?;
    work.stage("fitting the laws")?;
    let tp: Vec<f64> = peaks.iter().map(|p| p.t).collect();
    let cycles = cycles(&tp);
    let accelerations = accelerations(&tp);
    let window = fitting_window(
        &trace.source,
        &peaks,
        &cycles,
        accelerations.len(),
        dt,
        noise,
        s,
    )?;
    Ok(Timed {
        noise,
        glitches,
        hum,
        peaks,
        cycles,
        accelerations,
        window,
    })
}

/// [`analyze`] as part of `work`: each stage checks its budget and reports its progress.
pub fn analyze_within(
    trace: &Trace,
    s: &AnalysisSettings,
    work: &Work<'_>,
) -> Result<Analysis, ExperimentError> {
    let dt = trace.sample_interval();
    let timed = timed(trace, s, work)?;
    let peaks = &timed.peaks;
    let tp: Vec<f64> = peaks.iter().map(|p| p.t).collect();
    let w: Vec<f64> = peaks.iter().map(|p| p.sigma * p.sigma).collect();
    let fits = fit_laws(&trace.source, s, &tp, &w, &timed.cycles, &timed.window)?;
    let (beta_stated, t0_stated) = stated_sigmas(&fits.eq84, fits.law_stability.as_ref());
    let early_end = early_end(fits.eq84.t0, t0_stated, peaks, s.min_snr * timed.noise);
    let score = trace
        .truth
        .as_ref()
        .map(|tr| score(tr, &fits.eq84, &fits.eq85, dt, beta_stated, t0_stated));
    Ok(Analysis {
        source: trace.source.clone(),
        samples: trace.len(),
        sample_interval: dt,
        noise: timed.noise,
        glitches: timed.glitches,
        hum: timed.hum,
        settings: *s,
        peaks: timed.peaks,
        cycles: timed.cycles,
        accelerations: timed.accelerations,
        window: timed.window,
        eq84: fits.eq84,
        eq85: fits.eq85,
        models: fits.models,
        crossover: fits.crossover,
        law_stability: fits.law_stability,
        early_end,
        verdict: fits.verdict,
        truth: trace.truth.clone(),
        score,
    })
}

/// Refuses a trace whose times and signal values differ in number, and settings out of range.
fn check_settings(trace: &Trace, s: &AnalysisSettings) -> Result<(), ExperimentError> {
    let file = &trace.source;
    let n = trace.len();
    if trace.v.len() != n {
        return Err(ExperimentError::Setting(format!(
            "{file}: {n} times but {} signal values",
            trace.v.len()
        )));
    }
    if !(s.min_samples_per_period.is_finite() && s.min_samples_per_period >= 2.0) {
        return Err(ExperimentError::Setting(format!(
            "min_samples_per_period must be at least 2, got {}",
            s.min_samples_per_period
        )));
    }
    let p = &s.peaks;
    let ok = |x: f64| x.is_finite() && x > 0.0;
    if !(ok(p.initial_window)
        && ok(p.window_periods)
        && p.hysteresis >= 0.0
        && p.hysteresis < 0.5
        && ok(p.min_span_sigmas))
    {
        return Err(ExperimentError::Setting(format!(
            "peak settings out of range: {p:?} (window > 0, 0 <= hysteresis < 0.5)"
        )));
    }
    Ok(())
}

/// Refuses a signal of fewer than 8 samples, or one whose span is not more than the peak
/// settings' `min_span_sigmas` times the noise `noise`: no pulses to time.
fn check_not_flat(trace: &Trace, noise: f64, p: &PeakSettings) -> Result<(), ExperimentError> {
    let (vmin, vmax) = trace
        .v
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    let span = vmax - vmin;
    if trace.len() < 8 || span.is_nan() || span <= p.min_span_sigmas * noise || span == 0.0 {
        return Err(ExperimentError::FlatSignal {
            file: trace.source.clone(),
            span: if span.is_finite() { span } else { 0.0 },
            noise,
            min_span_sigmas: p.min_span_sigmas,
        });
    }
    Ok(())
}

/// Refuses fewer peaks than six plus the `drop_last` left out at the end.
fn check_peak_count(
    trace: &Trace,
    peaks: &[Peak],
    s: &AnalysisSettings,
) -> Result<(), ExperimentError> {
    let needed = 6 + s.drop_last;
    if peaks.len() < needed {
        return Err(ExperimentError::TooFewPeaks {
            file: trace.source.clone(),
            what: "peaks found".into(),
            found: peaks.len(),
            needed,
            hint: "record more cycles, or check that the signal has one pulse per turn".into(),
        });
    }
    Ok(())
}

/// The laws fitted over the window, and the plausibility checks they passed.
struct Fits {
    /// Eq 84's fit.
    eq84: Eq84Fit,
    /// The two-mechanism law's fit, when it converged.
    crossover: Option<CrossoverFit>,
    /// The plausibility checks.
    verdict: Verdict,
    /// Eq 85's fit.
    eq85: Eq85Fit,
    /// Eq 84 with beta free against the other laws.
    models: Comparison,
    /// Eq 84 on the later half of the window.
    law_stability: Option<LawStability>,
}

/// Fits eq 84 over the window's cycles (peak times `tp`, timing variances `w`) and the
/// two-mechanism law, refuses (for the trace `file`) what the plausibility checks find not a
/// spin-down, then fits eq 85, compares the laws, and fits eq 84 on the later half.
fn fit_laws(
    file: &str,
    s: &AnalysisSettings,
    tp: &[f64],
    w: &[f64],
    cyc: &[Cycle],
    window: &Window,
) -> Result<Fits, ExperimentError> {
    let cyc_idx = &window.cycles;
    let ta: Vec<f64> = cyc_idx.iter().map(|&i| tp[i]).collect();
    let tb: Vec<f64> = cyc_idx.iter().map(|&i| tp[i + 1]).collect();
    let refuse = |reason: String| ExperimentError::Refused {
        file: file.to_string(),
        reason,
    };
    let eq84 = match fit_eq84(&ta, &tb, cyc_idx, w) {
        Ok(f) => f,
        Err(m) => return Err(refuse(format!("eq 84 cannot be fitted ({m})"))),
    };
    let crossover = fit_crossover(&ta, &tb, cyc_idx, w, &eq84).ok();
    let verdict = judge(s, cyc, window, &eq84, crossover.as_ref());
    if !verdict.refusals.is_empty() {
        return Err(refuse(verdict.refusals.join("; ")));
    }
    let eq85 = fit_eq85(tp, &window.accelerations, w).map_err(|m| ExperimentError::Fit {
        file: file.to_string(),
        what: "eq 85".into(),
        message: m.to_string(),
    })?;
    let models = compare_laws(&ta, &tb, cyc_idx, w, &eq84, crossover.as_ref());
    let law_stability = later_half(&ta, &tb, cyc_idx, w, &eq84);
    Ok(Fits {
        eq84,
        crossover,
        verdict,
        eq85,
        models,
        law_stability,
    })
}

/// The plausibility checks ([`Plausibility`]) of eq 84's fit over the window's cycles.
fn judge(
    s: &AnalysisSettings,
    cyc: &[Cycle],
    window: &Window,
    eq84: &Eq84Fit,
    crossover: Option<&CrossoverFit>,
) -> Verdict {
    let cyc_idx = &window.cycles;
    let t_mid: Vec<f64> = cyc_idx.iter().map(|&i| cyc[i].t).collect();
    let om: Vec<f64> = cyc_idx.iter().map(|&i| cyc[i].omega).collect();
    let ys: Vec<f64> = eq84.points.iter().map(|p| p.y).collect();
    let rs: Vec<f64> = eq84.points.iter().map(|p| p.residual).collect();
    s.plausibility.judge(&Evidence {
        t: &t_mid,
        omega: &om,
        anomalous: window.anomalous,
        y: &ys,
        residual: &rs,
        crossover_residual_ss: crossover.map(|x| x.residual_ss),
        beta: eq84.beta,
        t0: eq84.t0,
        t_first: window.t_first,
        t_last: window.t_last,
    })
}

/// How far eqs 84 and 85's fits land from the truth `tr` of a synthetic trace (sample interval
/// `dt`), with eq 84's stated uncertainties `beta_stated` and `t0_stated`.
fn score(
    tr: &Truth,
    eq84: &Eq84Fit,
    eq85: &Eq85Fit,
    dt: f64,
    beta_stated: f64,
    t0_stated: f64,
) -> Score {
    Score {
        beta84_pull: (eq84.beta - tr.beta) / eq84.beta_sigma,
        t0_pull: (eq84.t0 - tr.t0) / eq84.t0_sigma,
        t0_error_samples: (eq84.t0 - tr.t0) / dt,
        beta85_pull: (eq85.beta - tr.beta) / eq85.beta_sigma,
        beta84_pull_with_law: (eq84.beta - tr.beta) / beta_stated,
        t0_pull_with_law: (eq84.t0 - tr.t0) / t0_stated,
    }
}

/// The uncertainties of eq 84's $\beta$ and $t_0$ the analysis states: the fit's, with the
/// law's systematic uncertainty ([`LawStability`]) in quadrature where the law drifts.
fn stated_sigmas(eq84: &Eq84Fit, law: Option<&LawStability>) -> (f64, f64) {
    let (beta_sys, t0_sys) = law.map_or((0.0, 0.0), |l| (l.beta_systematic(), l.t0_systematic()));
    (eq84.beta_sigma.hypot(beta_sys), eq84.t0_sigma.hypot(t0_sys))
}

impl Analysis {
    /// The stated standard uncertainties of eq 84's $\beta$ and $t_0$ (s): the fit's, and the
    /// law's where it drifts over the window.
    pub fn stated_sigmas(&self) -> (f64, f64) {
        stated_sigmas(&self.eq84, self.law_stability.as_ref())
    }
}

impl fmt::Display for Analysis {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (a, b, w) = (&self.eq84, &self.eq85, &self.window);
        writeln!(f, "experiment: {}", self.source)?;
        writeln!(
            f,
            "  {} samples every {:.3e} s; noise {:.2e} V rms; {} peaks, {} cycles",
            self.samples,
            self.sample_interval,
            self.noise,
            self.peaks.len(),
            self.cycles.len()
        )?;
        writeln!(f, "  window: {}", w.rule)?;
        writeln!(
            f,
            "          t = {:.4} .. {:.4} s, {} cycles ({} anomalous, {} too short, {} too faint left out); \
             fastest fitted Omega = {:.0} rad/s",
            w.t_first,
            w.t_last,
            w.cycles.len(),
            w.anomalous,
            w.too_short,
            w.faint,
            w.omega_last
        )?;
        let (beta_total, t0_total) = self.stated_sigmas();
        writeln!(
            f,
            "  eq 84: beta = {:.4} +- {:.4}, t0 = {:.6} +- {:.6} s (total: statistical and the law's), \
             C^(-1/(beta+2)) = {:.6e} +- {:.1e} s (reduced chi2 {:.2}, n = {})",
            a.beta, beta_total, a.t0, t0_total, a.inv_omega_1s, a.inv_omega_1s_sigma, a.reduced_chi2, a.n
        )?;
        if let Some(e) = &self.early_end {
            writeln!(f, "  impossible end: {}", e.message)?;
        }
        writeln!(
            f,
            "  eq 85: slope = {:.4} +- {:.4}, so beta = {:.4} +- {:.4} (reduced chi2 {:.2}, n = {})",
            b.slope, b.slope_sigma, b.beta, b.beta_sigma, b.reduced_chi2, b.n
        )?;
        writeln!(
            f,
            "  model choice (eq 84 on {} cycles): {}",
            self.models.n, self.models.summary
        )?;
        for c in &self.models.candidates {
            writeln!(
                f,
                "    {:<12} {:<28} dAIC {:>9.1}  dBIC {:>9.1}  weight {:.3}",
                c.name, c.parameters, c.delta_aic, c.delta_bic, c.weight
            )?;
        }
        writeln!(
            f,
            "  spin-down checks: Kendall tau {:.3}, Omega rises x{:.2}, R^2 {:.6}, t0 gap {:.4} of the window",
            self.verdict.kendall, self.verdict.rise, self.verdict.r2, self.verdict.gap
        )?;
        writeln!(
            f,
            "  uncertainties: scaled by the whitened residuals' covariance (their scatter is {:.2} \
             of the peak-timing noise's, and their correlation)",
            self.eq84.reduced_chi2.sqrt()
        )?;
        if let Some(l) = &self.law_stability {
            writeln!(
                f,
                "  the law across the window: eq 84 on the later {} cycles (from t = {:.4} s): \
                 beta = {:.4} +- {:.4}, t0 = {:.6} +- {:.6} s; shifts beta {:+.4}, t0 {:+.3} ms \
                 ({:.1} and {:.1} times the later half's uncertainty, which bounds what noise moves them): {}",
                l.cycles,
                l.t_from,
                l.beta,
                l.beta_sigma,
                l.t0,
                l.t0_sigma,
                l.beta_shift,
                l.t0_shift * 1e3,
                l.beta_shift.abs() / l.beta_sigma,
                l.t0_shift.abs() / l.t0_sigma,
                if l.drifts {
                    format!(
                        "eq 79 drifts over the record, so the shifts are the law's systematic \
                         uncertainty: beta = {:.4} +- {:.4} (stat) +- {:.4} (law), t0 = {:.6} +- \
                         {:.6} (stat) +- {:.6} (law) s",
                        a.beta,
                        a.beta_sigma,
                        l.beta_systematic(),
                        a.t0,
                        a.t0_sigma,
                        l.t0_systematic()
                    )
                } else {
                    "eq 79 holds across the window as far as the noise can tell".to_string()
                }
            )?;
        }
        if let (Some(t), Some(s)) = (&self.truth, &self.score) {
            writeln!(
                f,
                "  truth: beta = {}, t0 = {:.6} s ({}); pulls: beta84 {:+.2}, t0 {:+.2} \
                 ({:+.2} samples), beta85 {:+.2}; with the law's uncertainty: beta84 {:+.2}, \
                 t0 {:+.2}",
                t.beta,
                t.t0,
                t.origin,
                s.beta84_pull,
                s.t0_pull,
                s.t0_error_samples,
                s.beta85_pull,
                s.beta84_pull_with_law,
                s.t0_pull_with_law
            )?;
        }
        Ok(())
    }
}

impl Analysis {
    /// The analysis as pretty JSON.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }

    /// The peaks as CSV.
    pub fn peaks_csv(&self) -> String {
        let mut s = String::from("i,t_s,sigma_s,rise_s,fall_s,span_V\n");
        for (i, p) in self.peaks.iter().enumerate() {
            let _ = writeln!(
                s,
                "{i},{},{},{},{},{}",
                p.t, p.sigma, p.rise, p.fall, p.span
            );
        }
        s
    }

    /// $\Omega_i$, with eq 84's curve and residuals where fitted, as CSV.
    pub fn omega_csv(&self) -> String {
        let mut s = String::from(
            "i,t_mid_s,period_s,omega_rad_per_s,anomalous,fitted,fit_inv_omega_s,residual_s,normalized\n",
        );
        let mut k = 0;
        for c in &self.cycles {
            let _ = write!(
                s,
                "{},{},{},{},{}",
                c.i, c.t, c.period, c.omega, c.anomalous
            );
            if self.window.cycles.get(k) == Some(&c.i) {
                let p = &self.eq84.points[k];
                let _ = writeln!(s, ",true,{},{},{}", p.model, p.residual, p.normalized);
                k += 1;
            } else {
                s.push_str(",false,,,\n");
            }
        }
        s
    }

    /// $d\Omega_i/dt$, with eq 85's curve and residuals where fitted, as CSV.
    pub fn omega_dot_csv(&self) -> String {
        let mut s = String::from(
            "i,t_s,omega_rad_per_s,omega_dot_rad_per_s2,fitted,fit_omega_dot,residual,normalized\n",
        );
        let mut k = 0;
        for a in &self.accelerations {
            let _ = write!(s, "{},{},{},{}", a.i, a.t, a.omega, a.omega_dot);
            if self.window.accelerations.get(k) == Some(&a.i) {
                let p = &self.eq85.points[k];
                let _ = writeln!(s, ",true,{},{},{}", p.model, p.residual, p.normalized);
                k += 1;
            } else {
                s.push_str(",false,,,\n");
            }
        }
        s
    }
}

/// Writes `analysis.json`, `peaks.csv`, `omega.csv` and `omega_dot.csv` into `dir` (created if
/// needed), each atomically. Returns the paths written.
pub fn write_analysis(a: &Analysis, dir: &Path) -> Result<Vec<PathBuf>, ExperimentError> {
    let io = |p: &Path, e: std::io::Error| ExperimentError::Io {
        file: p.display().to_string(),
        message: format!("cannot write ({e})"),
    };
    std::fs::create_dir_all(dir).map_err(|e| io(dir, e))?;
    let files = [
        ("analysis.json", a.to_json()),
        ("peaks.csv", a.peaks_csv()),
        ("omega.csv", a.omega_csv()),
        ("omega_dot.csv", a.omega_dot_csv()),
    ];
    let mut out = Vec::new();
    for (name, text) in files {
        let p = dir.join(name);
        write_set_file(&p, text.as_bytes()).map_err(|e| io(&p, e))?;
        out.push(p);
    }
    Ok(out)
}
