//! The analysis of a trace, the paper's method plus fits: peaks, $\Omega_i$, $d\Omega_i/dt$, the
//! fitting window, the fits of eqs 84 and 85, and (for a synthetic trace) how far they land
//! from the truth.

use crate::clean::{remove_glitches, remove_hum};
use crate::crossover::{fit_crossover, CrossoverFit};
use crate::early_end::{early_end, EarlyEnd};
use crate::error::ExperimentError;
use crate::fit::{fit_eq84, fit_eq85, Eq84Fit, Eq85Fit};
use crate::law_stability::{later_half, LawStability};
use crate::least_squares::FitError;
use crate::models::{compare_laws, Comparison};
use crate::peak::Peak;
use crate::peaks::{find_peaks, noise_level, PeakSettings};
use crate::plausibility::{Evidence, Plausibility, Verdict};
use crate::rates::{accelerations, cycles, Acceleration, Cycle};
use crate::trace::{Trace, Truth};
use files::atomic::write_atomically;
use serde::{Deserialize, Serialize};
use std::fmt;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

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
    /// The two-mechanism law's fit ([`crossover`](crate::crossover)), when it converged.
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

/// Analyses a trace.
pub fn analyze(trace: &Trace, s: &AnalysisSettings) -> Result<Analysis, ExperimentError> {
    let file = trace.source.clone();
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
    let dt = trace.sample_interval();
    let noise = noise_level(&trace.v);
    let (vmin, vmax) = trace
        .v
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    let span = vmax - vmin;
    if n < 8 || span.is_nan() || span <= p.min_span_sigmas * noise || span == 0.0 {
        return Err(ExperimentError::FlatSignal {
            file,
            span: if span.is_finite() { span } else { 0.0 },
            noise,
            min_span_sigmas: p.min_span_sigmas,
        });
    }
    let mut v = trace.v.clone();
    let glitches = remove_glitches(&mut v, noise);
    let hum = remove_hum(&trace.t, &mut v, noise);
    let peaks = find_peaks(&trace.t, &v, dt, noise, p);
    let too_few =
        |what: &str, found: usize, needed: usize, hint: &str| ExperimentError::TooFewPeaks {
            file: trace.source.clone(),
            what: what.into(),
            found,
            needed,
            hint: hint.into(),
        };
    let needed = 6 + s.drop_last;
    if peaks.len() < needed {
        return Err(too_few(
            "peaks found",
            peaks.len(),
            needed,
            "record more cycles, or check that the signal has one pulse per turn",
        ));
    }
    let tp: Vec<f64> = peaks.iter().map(|p| p.t).collect();
    let w: Vec<f64> = peaks.iter().map(|p| p.sigma * p.sigma).collect();
    let cyc = cycles(&tp);
    let acc = accelerations(&tp);

    let last_usable = peaks.len() - 1 - s.drop_last;
    let min_period = s.min_samples_per_period * dt;
    let (mut anomalous, mut too_short, mut faint) = (0, 0, 0);
    let min_span = s.min_snr * noise;
    let mut in_window = vec![false; cyc.len()];
    // The end of the spin-down: the pulses fade as the tilt vanishes; after three faint cycles
    // in a row (past the first twenty) nothing later is the disk's (hum or noise at most).
    let mut run = 0;
    let mut last_usable = last_usable;
    for (k, c) in cyc.iter().enumerate().skip(20) {
        if peaks[c.i].span < min_span || peaks[c.i + 1].span < min_span {
            run += 1;
            if run == 3 {
                last_usable = last_usable.min(k.saturating_sub(2));
                break;
            }
        } else {
            run = 0;
        }
    }
    for c in &cyc {
        if c.i + 1 > last_usable
            || s.t_from.is_some_and(|a| c.t < a)
            || s.t_to.is_some_and(|b| c.t > b)
        {
            continue;
        }
        if c.anomalous {
            anomalous += 1;
        } else if c.period < min_period {
            too_short += 1;
        } else if peaks[c.i].span < min_span || peaks[c.i + 1].span < min_span {
            faint += 1;
        } else {
            in_window[c.i] = true;
        }
    }
    let cyc_idx: Vec<usize> = (0..cyc.len()).filter(|&i| in_window[i]).collect();
    let acc_idx: Vec<usize> = (0..acc.len())
        .filter(|&i| in_window[i] && in_window[i + 1])
        .collect();
    if cyc_idx.len() < 5 {
        return Err(too_few(
            "cycles in the fitting window",
            cyc_idx.len(),
            5,
            "widen the window (t_from, t_to), lower drop_last or min_samples_per_period",
        ));
    }
    let first_peak = cyc_idx[0];
    let last_peak = cyc_idx[cyc_idx.len() - 1] + 1;
    let ta: Vec<f64> = cyc_idx.iter().map(|&i| tp[i]).collect();
    let tb: Vec<f64> = cyc_idx.iter().map(|&i| tp[i + 1]).collect();
    let fit_err = |what: &str, message: FitError| ExperimentError::Fit {
        file: trace.source.clone(),
        what: what.into(),
        message: message.to_string(),
    };
    let refuse = |reason: String| ExperimentError::Refused {
        file: trace.source.clone(),
        reason,
    };
    let eq84 = match fit_eq84(&ta, &tb, &cyc_idx, &w) {
        Ok(f) => f,
        Err(m) => return Err(refuse(format!("eq 84 cannot be fitted ({m})"))),
    };
    let t_mid: Vec<f64> = cyc_idx.iter().map(|&i| cyc[i].t).collect();
    let om: Vec<f64> = cyc_idx.iter().map(|&i| cyc[i].omega).collect();
    let ys: Vec<f64> = eq84.points.iter().map(|p| p.y).collect();
    let rs: Vec<f64> = eq84.points.iter().map(|p| p.residual).collect();
    let crossover = fit_crossover(&ta, &tb, &cyc_idx, &w, &eq84).ok();
    let verdict = s.plausibility.judge(&Evidence {
        t: &t_mid,
        omega: &om,
        anomalous,
        y: &ys,
        residual: &rs,
        crossover_residual_ss: crossover.as_ref().map(|x| x.residual_ss),
        beta: eq84.beta,
        t0: eq84.t0,
        t_first: tp[cyc_idx[0]],
        t_last: tp[cyc_idx[cyc_idx.len() - 1] + 1],
    });
    if !verdict.refusals.is_empty() {
        return Err(refuse(verdict.refusals.join("; ")));
    }
    let eq85 = fit_eq85(&tp, &acc_idx, &w).map_err(|m| fit_err("eq 85", m))?;
    let models = compare_laws(&ta, &tb, &cyc_idx, &w, &eq84, crossover.as_ref());
    let law_stability = later_half(&ta, &tb, &cyc_idx, &w, &eq84);
    let window = Window {
        rule: format!(
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
        ),
        first_peak,
        last_peak,
        t_first: tp[first_peak],
        t_last: tp[last_peak],
        omega_last: cyc[cyc_idx[cyc_idx.len() - 1]].omega,
        cycles: cyc_idx,
        accelerations: acc_idx,
        anomalous,
        too_short,
        faint,
    };
    let (beta_stated, t0_stated) = stated_sigmas(&eq84, law_stability.as_ref());
    let early_end = early_end(eq84.t0, t0_stated, &peaks, min_span);
    let score = trace.truth.as_ref().map(|tr| Score {
        beta84_pull: (eq84.beta - tr.beta) / eq84.beta_sigma,
        t0_pull: (eq84.t0 - tr.t0) / eq84.t0_sigma,
        t0_error_samples: (eq84.t0 - tr.t0) / dt,
        beta85_pull: (eq85.beta - tr.beta) / eq85.beta_sigma,
        beta84_pull_with_law: (eq84.beta - tr.beta) / beta_stated,
        t0_pull_with_law: (eq84.t0 - tr.t0) / t0_stated,
    });
    Ok(Analysis {
        source: trace.source.clone(),
        samples: n,
        sample_interval: dt,
        noise,
        glitches,
        hum,
        settings: *s,
        peaks,
        cycles: cyc,
        accelerations: acc,
        window,
        eq84,
        eq85,
        models,
        crossover,
        law_stability,
        early_end,
        verdict,
        truth: trace.truth.clone(),
        score,
    })
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
        write_atomically(&p, text.as_bytes()).map_err(|e| io(&p, e))?;
        out.push(p);
    }
    Ok(out)
}
