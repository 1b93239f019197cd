//! The figures of section 11 (tek04, tek01, tek02, Omega, tek726, tek728, Odot), from a
//! SYNTHETIC experiment: the paper's data are not published. The built-in `spin-down` scene
//! (rolling without slipping, eqs 23-25, with eq 75's power as a torque, beta = 2,
//! epsilon = 1.2e-6) is seen through the default light model and scope (5 kS/s, 10 s, 5 mV
//! noise, 8 bits), then analysed as the paper did (peak times, $\Omega_i$, $d\Omega_i/dt$) and
//! fitted (eqs 84 and 85).

use crate::figures::chart::{Axis, Legend, Plot, Series, Style};
use crate::figures::FigureError;
use crate::figures::{min_max_decimate, Drawing, Figure};
use crate::number::{measured, significant, to_place_of};
use studies::synthetic::Synthetic;

pub use crate::figures::coverage::coverage;

const SYNTHETIC: &str = "Synthetic data (the paper's are not published): the built-in spin-down \
    scene, a uniform disk ($a$ = 37.5 mm) rolling without slipping (eqs 23-25) that loses energy at \
    eq 75's rate with $\\beta = 2$ and $\\epsilon$ = 1.2e-6 s (applied as a torque against the angular \
    velocity), seen by a phototransistor through the default light model and recorded at 5 kS/s \
    for 10 s with 5 mV noise and 8-bit quantisation.";

/// The seven figures of section 11 and the fit's residuals, from the experiment the report's pipeline simulated and
/// analysed once (no integration here).
pub fn figures(e: &Synthetic) -> Result<Vec<Figure>, FigureError> {
    Ok(vec![
        tek04(e)?,
        tek_zoom(e, "tek01", 0.25)?,
        tek_zoom(e, "tek02", 0.06)?,
        omega(e)?,
        inverse_omega(e, "tek726", 0.0)?,
        inverse_omega(e, "tek728", 0.02)?,
        odot(e)?,
        residuals(&e.analysis)?,
    ])
}

/// When the spin-down ends in record time: the model's stop (lift-off or the alpha floor) if
/// the trace knows it, else the fitted t0.
fn end_time(e: &Synthetic) -> f64 {
    e.trace
        .truth
        .as_ref()
        .map_or(e.analysis.eq84.t0, |t| t.t_stop)
}

/// What the mark at [`end_time`] is: the truth (the model stops), or without one the fit.
fn end_label(e: &Synthetic) -> &'static str {
    if e.trace.truth.is_some() {
        "truth: the model stops at"
    } else {
        "fit: eq 84's t₀ ="
    }
}

/// The model's singular time t0 (record time), or the fitted one without a truth.
fn true_t0(e: &Synthetic) -> f64 {
    e.trace.truth.as_ref().map_or(e.analysis.eq84.t0, |t| t.t0)
}

fn tek04(e: &Synthetic) -> Result<Figure, FigureError> {
    let pts: Vec<(f64, f64)> = e
        .trace
        .t
        .iter()
        .copied()
        .zip(e.trace.v.iter().copied())
        .collect();
    let shown = min_max_decimate(&pts, 900);
    let t_end = end_time(e);
    let plot = Plot::new(
        "Light signal, the whole 10 s record",
        "time t (s)",
        "phototransistor signal (V)",
    )
    .with(Series::new("signal envelope", shown, Style::Line))
    .mark(Axis::X, t_end, format!("{} {t_end:.3} s", end_label(e)))
    .legend_at(Legend::UpperLeft);
    // No fixed y range: the automatic one grows at the top just enough for the legend, at
    // every size the figure is drawn (the paper's 3 in included).
    Ok(Figure {
        name: "tek04",
        title: "The light signal over 10 s (the paper's tek04)".into(),
        caption: super::captions::caption(
            "tek04",
            &serde_json::json!({
                "SYNTHETIC": format!("{}", SYNTHETIC),
                "t_end": format!("{:.3}", t_end),
                "samples_per_column": format!("{}", e.trace.len().div_ceil(900)),
                "peaks": format!("{}", e.analysis.peaks.len()),
            }),
        )?,
        drawing: Drawing::Plot(plot),
    })
}

fn tek_zoom(e: &Synthetic, name: &'static str, span: f64) -> Result<Figure, FigureError> {
    let t_end = end_time(e);
    let (from, to) = (t_end - span, t_end + 0.1 * span);
    let pts: Vec<(f64, f64)> = e
        .trace
        .t
        .iter()
        .copied()
        .zip(e.trace.v.iter().copied())
        .filter(|(t, _)| *t >= from && *t <= to)
        .collect();
    if pts.len() < 4 {
        return Err(format!("{name}: the record holds no samples before its end").into());
    }
    let peaks: Vec<(f64, f64)> = e
        .analysis
        .peaks
        .iter()
        .filter(|p| p.t >= from && p.t <= to)
        .map(|p| {
            // The signal at the peak time, by the nearest sample.
            let i = e
                .trace
                .t
                .partition_point(|t| *t < p.t)
                .min(e.trace.len() - 1);
            (p.t, e.trace.v[i])
        })
        .collect();
    let n_peaks = peaks.len();
    let fit_t0 = e.analysis.eq84.t0;
    let mut plot = Plot::new(
        format!("Light signal, the last {span} s"),
        "time t (s)",
        "phototransistor signal (V)",
    )
    .with(Series::new("signal", pts, Style::Line))
    .with(Series::new("peak times tᵢ", peaks, Style::Triangles))
    .mark(Axis::X, t_end, format!("{} {t_end:.3} s", end_label(e)))
    .legend_at(Legend::UpperLeft);
    if fit_t0 > from && fit_t0 < to {
        plot = plot.mark(Axis::X, fit_t0, format!("fit: eq 84's t₀ = {fit_t0:.3} s"));
    }
    // No fixed y range (see tek04).
    let paper = if name == "tek01" { "tek01" } else { "tek02" };
    Ok(Figure {
        name,
        title: format!("The last {span} s of the light signal (the paper's {paper})"),
        caption: super::captions::caption(
            "tek-zoom",
            &serde_json::json!({
                "SYNTHETIC": format!("{}", SYNTHETIC),
                "span": span.to_string(),
                "t_end": format!("{:.4}", t_end),
                "n_peaks": n_peaks.to_string(),
                "fit_t0": format!("{:.4}", fit_t0),
                "fit_before_ms": format!("{:.1}", 1e3 * (true_t0(e) - fit_t0)),
                "model_t0": format!("{}", format_args!("{:.4} s", true_t0(e))),
            }),
        )?,
        drawing: Drawing::Plot(plot),
    })
}

fn omega(e: &Synthetic) -> Result<Figure, FigureError> {
    let a = &e.analysis;
    let in_fit: Vec<bool> = {
        let mut v = vec![false; a.cycles.len()];
        for &i in &a.window.cycles {
            if i < v.len() {
                v[i] = true;
            }
        }
        v
    };
    let fitted: Vec<(f64, f64)> = a
        .cycles
        .iter()
        .filter(|c| in_fit[c.i])
        .map(|c| (c.t, c.omega))
        .collect();
    let left_out: Vec<(f64, f64)> = a
        .cycles
        .iter()
        .filter(|c| !in_fit[c.i])
        .map(|c| (c.t, c.omega))
        .collect();
    let f = &a.eq84;
    let p = 1.0 / (f.beta + 2.0);
    let c = f.ln_c.exp();
    let t_first = a.cycles.first().map_or(0.0, |c| c.t);
    let t_last = a.window.t_last;
    let law: Vec<(f64, f64)> = (0..=300)
        .map(|i| t_first + (t_last - t_first) * i as f64 / 300.0)
        .filter(|t| *t < f.t0)
        .map(|t| (t, (c / (f.t0 - t)).powf(p)))
        .collect();
    if fitted.is_empty() {
        return Err("Omega: no cycle in the fitting window".into());
    }
    let plot = Plot::new(
        "Precession rate per cycle",
        "time t (s)",
        "Ωᵢ = 2π / (tᵢ₊₁ − tᵢ) (rad/s)",
    )
    .with(Series::new("Ωᵢ, fitted cycles", fitted, Style::Points))
    .with(Series::new(
        "Ωᵢ, left out (last peaks)",
        left_out.clone(),
        Style::Crosses,
    ))
    .with(Series::new(
        format!("eq 79 fitted: β = {:.3}, t₀ = {:.4} s", f.beta, f.t0),
        law,
        Style::Dashed,
    ))
    .legend_at(Legend::UpperLeft);
    Ok(Figure {
        name: "Omega",
        title: "Omega against t (the paper's Omega)".into(),
        caption: super::captions::caption(
            "Omega",
            &serde_json::json!({
                "SYNTHETIC": format!("{}", SYNTHETIC),
                "cycles": format!("{}", a.cycles.len()),
                "drop_last": format!("{}", a.settings.drop_last),
                "omega_last": format!("{:.0}", a.window.omega_last),
                "beta": format!("{}", measured(f.beta, a.stated_sigmas().0)),
                "t0": format!("{}", measured(f.t0, a.stated_sigmas().1)),
                "message": format!("{}", a.early_end.as_ref().map_or(String::new(), |e| format!(
                " Impossible end: {}.",
                e.message
            ))),
            }),
        )?,
        drawing: Drawing::Plot(plot),
    })
}

/// The paper's straight lines: slope `slope` in log-log through the point `(xm, ym)`, over
/// `[x0, x1]`.
fn line_through(xm: f64, ym: f64, slope: f64, x0: f64, x1: f64) -> Vec<(f64, f64)> {
    [x0, x1]
        .iter()
        .map(|&x| (x, ym * (x / xm).powf(slope)))
        .collect()
}

/// The median point in x of log-log data (the paper drew its lines through the data's middle).
fn mid_point(pts: &[(f64, f64)]) -> Option<(f64, f64)> {
    let mut s: Vec<(f64, f64)> = pts.to_vec();
    s.sort_by(|a, b| a.0.total_cmp(&b.0));
    s.get(s.len() / 2).copied()
}

fn inverse_omega(e: &Synthetic, name: &'static str, shift: f64) -> Result<Figure, FigureError> {
    let a = &e.analysis;
    let t0 = a.eq84.t0 + shift;
    let pts: Vec<(f64, f64)> = a
        .window
        .cycles
        .iter()
        .filter_map(|&i| a.cycles.get(i))
        .filter(|c| c.t < t0)
        .map(|c| (t0 - c.t, 1.0 / c.omega))
        .collect();
    let (xm, ym) =
        mid_point(&pts).ok_or_else(|| FigureError::from(format!("{name}: no cycle before t0")))?;
    let x0 = pts.iter().map(|p| p.0).fold(f64::INFINITY, f64::min);
    let x1 = pts.iter().map(|p| p.0).fold(f64::NEG_INFINITY, f64::max);
    let mut plot = Plot::new(
        format!("1/Ω against t₀ − t, t₀ = {t0:.3} s"),
        "t₀ − t (s)",
        "1/Ωᵢ (s)",
    )
    .log(true, true)
    .with(Series::new(
        "1/Ωᵢ (fitted cycles)",
        pts.clone(),
        Style::Points,
    ));
    for beta in 0..=4 {
        plot = plot.with(Series::new(
            format!("eq 84, β = {beta}"),
            line_through(xm, ym, 1.0 / (beta as f64 + 2.0), x0, x1),
            Style::Dashed,
        ));
    }
    plot = plot.legend_at(Legend::LowerRight);
    // The local slope over the last ten cycles: beta_apparent = 1/slope - 2.
    let mut tail: Vec<(f64, f64)> = pts.clone();
    tail.sort_by(|p, q| p.0.total_cmp(&q.0));
    let tail = &tail[..tail.len().min(10)];
    let slope = loglog_slope(tail);
    let apparent = 1.0 / slope - 2.0;
    let which = if shift == 0.0 {
        format!(
            "the fitted t0 = {t0:.4} s (true singular time of the model: {})",
            e.trace
                .truth
                .as_ref()
                .map_or("unknown".to_string(), |t| format!("{:.4} s", t.t0))
        )
    } else {
        format!(
            "t0 = {t0:.4} s, the fitted t0 plus {shift} s, as the paper's tek728 took 7.28 s \
             against tek726's 7.26 s"
        )
    };
    let paper = if shift == 0.0 { "tek726" } else { "tek728" };
    Ok(Figure {
        name,
        title: format!("1/Omega against t0 - t for t0 = {t0:.3} s (the paper's {paper})"),
        caption: super::captions::caption(
            "inverse-omega",
            &serde_json::json!({
                "SYNTHETIC": format!("{}", SYNTHETIC),
                "which": which.to_string(),
                "slope": format!("{:.3}", slope),
                "apparent": format!("{:.2}", apparent),
                "preferring": format!("{}", if shift == 0.0 {
                "With the right t0 the points follow the beta = 2 line down to the last cycles."
            } else {
                "A t0 too late bends the last cycles towards a flatter slope, a smaller apparent \
                 beta: the paper's argument for preferring 7.26 s."
            }),
            }),
        )?,
        drawing: Drawing::Plot(plot),
    })
}

/// The least-squares slope of log y against log x.
fn loglog_slope(pts: &[(f64, f64)]) -> f64 {
    let n = pts.len() as f64;
    let (mut sx, mut sy, mut sxx, mut sxy) = (0.0, 0.0, 0.0, 0.0);
    for (x, y) in pts {
        let (lx, ly) = (x.ln(), y.ln());
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
    }
    (n * sxy - sx * sy) / (n * sxx - sx * sx)
}

fn odot(e: &Synthetic) -> Result<Figure, FigureError> {
    let a = &e.analysis;
    let rows: Vec<(f64, f64)> = a
        .window
        .accelerations
        .iter()
        .filter_map(|&i| a.accelerations.get(i))
        .map(|r| (r.omega, r.omega_dot))
        .collect();
    let positive: Vec<(f64, f64)> = rows.iter().copied().filter(|p| p.1 > 0.0).collect();
    let dropped = rows.len() - positive.len();
    if positive.is_empty() {
        return Err("Odot: no positive dOmega/dt".into());
    }
    let x0 = positive.iter().map(|p| p.0).fold(f64::INFINITY, f64::min);
    let x1 = positive
        .iter()
        .map(|p| p.0)
        .fold(f64::NEG_INFINITY, f64::max);
    // The lines pass through the data's centre: the fitted curve at the middle of the data's
    // range of Omega (log scale), steadier than any single noisy point.
    let f = &a.eq85;
    let xm = (x0 * x1).sqrt();
    let ym = f.ln_k.exp() * (xm / f.omega_ref).powf(f.slope);
    let mut plot = Plot::new(
        "Rate of change of Ω against Ω",
        "Ω (rad/s)",
        "dΩ/dt (rad/s²)",
    )
    .log(true, true)
    .with(Series::new(
        "dΩᵢ/dt (fitted cycles)",
        positive.clone(),
        Style::Points,
    ));
    for beta in 0..=4 {
        plot = plot.with(Series::new(
            format!("eq 85, β = {beta}"),
            line_through(xm, ym, beta as f64 + 3.0, x0, x1),
            Style::Dashed,
        ));
    }
    plot = plot.legend_at(Legend::UpperLeft);
    Ok(Figure {
        name: "Odot",
        title: "dOmega/dt against Omega (the paper's Odot)".into(),
        caption: super::captions::caption(
            "Odot",
            &serde_json::json!({
                "SYNTHETIC": format!("{}", SYNTHETIC),
                "rows": format!("{}", rows.len()),
                "before_window": format!("{}", if dropped > 0 {
                format!(" ({dropped} with a negative difference, from timing noise, cannot be drawn on a log axis)")
            } else {
                String::new()
            }),
                "slope": format!("{}", measured(f.slope, f.slope_sigma)),
                "beta": format!("{}", to_place_of(f.beta, f.slope_sigma)),
            }),
        )?,
        drawing: Drawing::Plot(plot),
    })
}

/// $\Omega(t)$ of eq 79 with parameters $(\beta, t_0, \ln C)$ and its gradient in them.
fn law_and_gradient(p: [f64; 3], t: f64) -> (f64, [f64; 3]) {
    let q = 1.0 / (p[0] + 2.0);
    let tau = p[1] - t;
    let l = p[2] - tau.ln();
    let om = (q * l).exp();
    (om, [-q * q * om * l, -q * om / tau, q * om])
}

/// The rate per cycle with eq 79 fitted and its 95 % band, $\pm 1.96\sqrt{g^{\mathsf T}\Sigma g}$
/// with $g = \partial\Omega/\partial(\beta, t_0, \ln C)$ and $\Sigma$ the fit's stated covariance.
/// A pure function of the analysis.
pub fn omega_band(a: &experiment::Analysis) -> Result<Figure, FigureError> {
    let f = &a.eq84;
    let p = [f.beta, f.t0, f.ln_c];
    let pts: Vec<(f64, f64)> = a
        .window
        .cycles
        .iter()
        .filter_map(|&i| a.cycles.get(i))
        .map(|c| (c.t, c.omega))
        .collect();
    let (t_a, t_b) = (a.window.t_first, a.window.t_last);
    let mut law = Vec::new();
    let (mut lo, mut hi) = (Vec::new(), Vec::new());
    for k in 0..=200 {
        let t = t_a + (t_b - t_a) * k as f64 / 200.0;
        let (om, g) = law_and_gradient(p, t);
        let var: f64 = (0..3)
            .flat_map(|i| (0..3).map(move |j| (i, j)))
            .map(|(i, j)| g[i] * f.covariance[i][j] * g[j])
            .sum();
        let d = 1.96 * var.max(0.0).sqrt();
        law.push((t, om));
        lo.push((t, om - d));
        hi.push((t, om + d));
    }
    let plot = Plot::new("Ωᵢ with eq 79 and its 95 % band", "time t (s)", "Ω (rad/s)")
        .with(Series::new("Ωᵢ, fitted cycles", pts, Style::Points))
        .with(Series::new(
            format!("eq 79: β = {}", measured(f.beta, f.beta_sigma)),
            law,
            Style::Line,
        ))
        .with(Series::new("95 % band", lo, Style::Dotted))
        .with(Series::new("", hi, Style::Dotted))
        .legend_at(Legend::UpperLeft);
    Ok(Figure {
        name: "omega_band",
        title: "The frequency track with the fitted law and its band".into(),
        caption: super::captions::caption(
            "omega_band",
            &serde_json::json!({
                "source": format!("{}", a.source),
                "beta": format!("{}", measured(f.beta, a.stated_sigmas().0)),
                "t0": format!("{}", measured(f.t0, a.stated_sigmas().1)),
                "reduced_chi2": format!("{:.2}", f.reduced_chi2),
            }),
        )?,
        drawing: Drawing::Plot(plot),
    })
}

/// The whitened residuals of eq 84's fit against time: unit scatter, no structure, when the law
/// and the noise model hold.
pub fn residuals(a: &experiment::Analysis) -> Result<Figure, FigureError> {
    let pts: Vec<(f64, f64)> = a.eq84.points.iter().map(|p| (p.x, p.normalized)).collect();
    let lag = lag_one(&a.eq84.points);
    let plot = Plot::new(
        "Whitened residuals of eq 84",
        "time t (s)",
        "residual / σ (dimensionless)",
    )
    .with(Series::new("cycles", pts, Style::Points))
    .mark(Axis::Y, 0.0, "")
    .legend_at(Legend::Hidden);
    Ok(Figure {
        name: "residuals",
        title: "Residuals of eq 84's fit".into(),
        caption: super::captions::caption(
            "residuals",
            &serde_json::json!({
                "source": format!("{}", a.source),
                "reduced_chi2": format!("{:.2}", a.eq84.reduced_chi2),
                "r_squared": format!("{:.6}", a.verdict.r2),
                "lag": format!("{:.2}", lag),
                "verdict": format!("{}", if a.eq84.reduced_chi2 > 3.0 && lag > 0.5 {
                ": a slow wave far above the noise, so eq 79 itself misses the recorded motion \
                 (the fit's stated errors are widened by it, but a law that does not hold can \
                 still place t0 wrongly)."
            } else {
                "."
            }),
            }),
        )?,
        drawing: Drawing::Plot(plot),
    })
}

/// The correlation of neighbouring whitened residuals (lag one): near 0 for noise, near 1 for a
/// slow wave that the law does not follow.
fn lag_one(points: &[experiment::fit::FitPoint]) -> f64 {
    let r: Vec<f64> = points.iter().map(|p| p.normalized).collect();
    numerics::autocorrelation::lag_one(&r)
}

/// A sound recording's frequency track with eq 79's fitted frame means.
pub fn sound_track(s: &experiment::SoundAnalysis) -> Result<Figure, FigureError> {
    let mid = |p: &experiment::track::TrackPoint| 0.5 * (p.a + p.b);
    let pts: Vec<(f64, f64)> = s.track.points.iter().map(|p| (mid(p), p.omega)).collect();
    let fit: Vec<(f64, f64)> = s
        .track
        .points
        .iter()
        .zip(&s.fit.model)
        .map(|(p, m)| (mid(p), *m))
        .collect();
    let plot = Plot::new("The sound's fundamental, Ω", "time t (s)", "Ω (rad/s)")
        .with(Series::new("spectral track (frames)", pts, Style::Points))
        .with(Series::new(
            format!(
                "eq 79: β = {}, t₀ = {} s",
                measured(s.fit.beta, s.fit.beta_sigma),
                significant(s.fit.t0)
            ),
            fit,
            Style::Line,
        ))
        .legend_at(Legend::UpperLeft);
    Ok(Figure {
        name: "sound_track",
        title: "Frequency track of a sound recording".into(),
        caption: super::captions::caption(
            "sound_track",
            &serde_json::json!({
                "source": format!("{}", s.source),
                "frame_from_ms": format!("{:.1}", 1e3 * s.track.frame_span.0),
                "frame_to_ms": format!("{:.1}", 1e3 * s.track.frame_span.1),
            }),
        )?,
        drawing: Drawing::Plot(plot),
    })
}
