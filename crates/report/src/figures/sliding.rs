//! Friction and contact: the built-in slip-stick scene run by the sliding model (Coulomb stick
//! and slip, unilateral contact; `physics::model::sliding`), drawn from the run the report's
//! friction study made. Two figures: the contact's state against time (slip speed, normal
//! force, energy and the work the contact took), and the paths of the centre and of the
//! contact point on the table.

use crate::figures::chart::{Legend, Plot, Series, Style};
use crate::figures::FigureError;
use crate::figures::{min_max_decimate, Drawing, Figure, Panels};
use crate::number::measured;
use physics::run::Run;
use studies::slip_stick::SlipStick;

/// A column of the run, or an error naming it.
fn column(run: &Run, name: &str) -> Result<Vec<f64>, FigureError> {
    run.column(name)
        .ok_or_else(|| format!("the slip-stick run did not record {name}").into())
}

fn series(t: &[f64], v: &[f64], f: impl Fn(f64) -> f64) -> Vec<(f64, f64)> {
    t.iter().zip(v).map(|(t, v)| (*t, f(*v))).collect()
}

/// The slip-stick run against time: slip speed, normal force, energy and dissipated work.
pub fn slip_stick(r: &SlipStick) -> Result<Figure, FigureError> {
    let run = &r.slip_stick;
    let t = column(run, "t_s")?;
    let slip = column(run, "slip_speed_m_per_s")?;
    let fz = column(run, "normal_force_N")?;
    let e = column(run, "energy_J")?;
    let w = column(run, "dissipated_J")?;
    let t_end = t.last().copied().unwrap_or(0.0);
    // Sticking points have no slip to draw on a log axis: the slipping ones only.
    let slipping: Vec<(f64, f64)> = series(&t, &slip, |v| v)
        .into_iter()
        .filter(|p| p.1 > 1e-9)
        .collect();
    let stick_from = t
        .iter()
        .zip(&slip)
        .find(|(_, v)| **v <= 1e-9)
        .map(|(t, _)| *t);
    let normal = series(&t, &fz, |v| v / r.weight);
    let (fz_lo, fz_hi) = normal
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |a, p| {
            (a.0.min(p.1), a.1.max(p.1))
        });
    // The slip is over within a fraction of the run: the panels show it and as long again
    // of rolling (the nutation of the force over the whole run would fill the panel).
    let shown = stick_from.map_or(t_end, |ts| (2.0 * ts).clamp(0.05, t_end));
    let window = |p: Vec<(f64, f64)>| -> Vec<(f64, f64)> {
        let kept: Vec<(f64, f64)> = p.into_iter().filter(|q| q.0 <= shown).collect();
        min_max_decimate(&kept, 400)
    };
    let total: Vec<f64> = e.iter().zip(&w).map(|(e, w)| e + w).collect();
    let e0 = total.first().copied().unwrap_or(0.0);
    let balance = total
        .iter()
        .map(|x| (x - e0).abs() / e0.abs())
        .fold(0.0, f64::max);
    let speed = Plot::new(
        "Slip speed",
        "time t (s)",
        "|v_c| of the contact point (m/s)",
    )
    .log(false, true)
    .legend_at(Legend::Hidden)
    .with(Series::new("slip speed", window(slipping), Style::Line));
    let force = Plot::new(
        "Normal force",
        "time t (s)",
        "normal force over weight F_z / m g (dimensionless)",
    )
    .legend_at(Legend::Hidden)
    .with(Series::new("F_z / mg", window(normal), Style::Line));
    let energy = Plot::new("Energy", "time t (s)", "energy (J)")
        .legend_at(Legend::UpperRight)
        .y_range(0.0, 1.4 * e0)
        .with(Series::new("E", window(series(&t, &e, |v| v)), Style::Line))
        .with(Series::new(
            "W",
            window(series(&t, &w, |v| v)),
            Style::Dashed,
        ))
        .with(Series::new(
            "E + W",
            window(series(&t, &total, |v| v)),
            Style::Dotted,
        ));
    Ok(Figure {
        name: "slip-stick",
        title: "A slipping disk comes to roll (sliding model)".into(),
        caption: super::captions::caption(
            "slip-stick",
            &serde_json::json!({
                "mu": format!("{}", r.mu),
                "t_end": format!("{:.0}", t_end),
                "shown": format!("{:.2}", shown),
                "stick": format!("{}", stick_from.map_or("nowhere".into(), |t| format!("{t:.3} s"))),
                "fz_lo": format!("{:.3}", fz_lo),
                "fz_hi": format!("{:.3}", fz_hi),
                "balance": format!("{:.1e}", balance),
                "events": format!("{}", run.contact_events.len()),
            }),
        )?,
        drawing: Drawing::Panels(Panels {
            title: format!("Slip-stick scene, μ = {}", r.mu),
            plots: vec![speed, force, energy],
        }),
    })
}

/// The paths of the centre and of the contact point on the table.
pub fn paths(r: &SlipStick) -> Result<Figure, FigureError> {
    let run = &r.slip_stick;
    let t = column(run, "t_s")?;
    let slip = column(run, "slip_speed_m_per_s")?;
    let (x, y) = (column(run, "x_m")?, column(run, "y_m")?);
    let (cx, cy) = (column(run, "contact_x_m")?, column(run, "contact_y_m")?);
    let mm = |a: &[f64], b: &[f64]| -> Vec<(f64, f64)> {
        a.iter().zip(b).map(|(a, b)| (a * 1e3, b * 1e3)).collect()
    };
    let centre = mm(&x, &y);
    let contact = mm(&cx, &cy);
    let stuck = t
        .iter()
        .zip(&slip)
        .position(|(_, v)| *v <= 1e-9)
        .unwrap_or(t.len());
    // One second of rolling: over the whole run the nutating contact fills a band.
    let rolled = t.partition_point(|x| *x < t.get(stuck).copied().unwrap_or(0.0) + 1.0);
    let thin = |p: &[(f64, f64)]| -> Vec<(f64, f64)> {
        let step = (p.len() / 2000).max(1);
        p.iter().step_by(step).copied().collect()
    };
    let plot = Plot::new("Paths on the table", "x (mm)", "y (mm)")
        .equal_aspect()
        .legend_at(Legend::UpperRight)
        .with(Series::new(
            "contact point, slipping",
            thin(&contact[..stuck]),
            Style::Line,
        ))
        .with(Series::new(
            "contact point, rolling",
            thin(&contact[stuck..rolled]),
            Style::Dotted,
        ))
        .with(Series::new("centre of mass", thin(&centre), Style::Dashed))
        .with(Series::new("start", vec![centre[0]], Style::Points));
    let t_stick = t.get(stuck).copied().unwrap_or(f64::NAN);
    Ok(Figure {
        name: "slip-stick-path",
        title: "Where the slipping disk goes".into(),
        caption: super::captions::caption(
            "slip-stick-path",
            &serde_json::json!({
                "t_stick": format!("{:.3}", t_stick),
            }),
        )?,
        drawing: Drawing::Plot(plot),
    })
}

/// The power range of the mechanisms figure (W): curves are cut, not clamped, at its edges.
const LOWEST: f64 = 1e-6;
/// (W)
const HIGHEST: f64 = 10.0;

fn inside(p: &[(f64, f64)]) -> Vec<(f64, f64)> {
    p.iter()
        .copied()
        .filter(|(_, y)| (LOWEST..=HIGHEST).contains(y))
        .collect()
}

/// Dissipation mechanisms side by side: the power each takes along steady rolling with
/// $b = 0$ against $\Omega$ (log-log, so a mechanism's $\beta$ is its slope), with the power the
/// paper's record needs (eq 79 with its fit, through eq 26's energy).
pub fn mechanisms(r: &SlipStick) -> Result<Figure, FigureError> {
    let s = &r.studies.mechanisms;
    let (need, rest) = s
        .curves
        .split_first()
        .ok_or("the mechanisms study drew no curves")?;
    let styles = [
        Style::Dashed,
        Style::Dotted,
        Style::Dashed,
        Style::Dotted,
        Style::Line,
        Style::Line,
    ];
    let mut plot = Plot::new(
        "Dissipation mechanisms along the spin-down",
        "Ω (rad/s)",
        "|P| (W)",
    )
    .log(true, true)
    .y_range(LOWEST, HIGHEST)
    .with(Series::new(
        "the record's need",
        inside(&need.points),
        Style::Line,
    ));
    for (c, style) in rest.iter().zip(styles) {
        let label = c.name.split(" (").next().unwrap_or(&c.name).to_string();
        plot = plot.with(Series::new(label, inside(&c.points), style));
    }
    if s.film_valid_above.is_finite() {
        plot = plot.mark(
            crate::figures::chart::Axis::X,
            s.film_valid_above,
            "gap = viscous layer",
        );
    }
    let fits: Vec<String> = s
        .spin_downs
        .iter()
        .map(|m| match (m.beta, &m.refused) {
            (Some((b, e)), None) => format!("{}, beta = {}", m.mechanism, measured(b, e)),
            (_, Some(_)) => format!("{} refused", m.mechanism),
            (None, None) => format!("{} not fitted", m.mechanism),
        })
        .collect();
    Ok(Figure {
        name: "mechanisms",
        title: "Which mechanism gives beta = 2?".into(),
        caption: super::captions::caption(
            "mechanisms",
            &serde_json::json!({
                "data_beta": format!("{}", s.data_beta),
                "omega_cal": format!("{:.0}", s.omega_cal),
                "fits": format!("{}", fits.join("; ")),
            }),
        )?,
        drawing: Drawing::Plot(plot),
    })
}
