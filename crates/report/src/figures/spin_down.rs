//! The tilt of the full dissipative spin-down against the paper's law (eq 78) and against the
//! same law with the factor the energy balance gives.
//!
//! Eq 76 writes $\dot\alpha = -\tfrac25\epsilon\Omega^\beta$, from $P \approx \tfrac52 mag\dot\alpha$
//! (eq 74), which assumes $\ddot\alpha \approx g/a$, true only at lift-off. With the adiabatic
//! energy $E \approx \tfrac32 mga\alpha$ (eq 73 without $\dot\alpha^2$), $dE/dt = P$ gives
//! $\dot\alpha = -\tfrac23\epsilon\Omega^\beta$. With $\Omega^2 = g/ak\alpha$ either integrates to
//! $$\alpha = \left(\frac{c\,\epsilon(\beta+2)}{2}\right)^{2/(\beta+2)}
//!   \left(\frac{g}{ak}\right)^{\beta/(\beta+2)}(t_0 - t)^{2/(\beta+2)},$$
//! eq 78 for $c = 2/5$.

use crate::figures::chart::{Legend, Plot, Series, Style};
use crate::figures::FigureError;
use crate::figures::{log_thin, Drawing, Figure};
use studies::runs::SpinDown;

/// Eq 78 with factor `c` in $\dot\alpha = -c\epsilon\Omega^\beta$: $\alpha$ at $t_0 - t = \tau$.
pub fn law(c: f64, epsilon: f64, beta: f64, g_ak: f64, tau: f64) -> f64 {
    let p = 2.0 / (beta + 2.0);
    (c * epsilon * (beta + 2.0) / 2.0).powf(p) * g_ak.powf(beta / (beta + 2.0)) * tau.powf(p)
}

/// The figure, from the spin-down's run (no integration here).
pub fn figure(sd: &SpinDown) -> Result<Figure, FigureError> {
    let r = &sd.run;
    let t_stop = sd.t_stop;
    let t = r.column("t_s").ok_or("no time column")?;
    let alpha = r.column("alpha_rad").ok_or("no alpha column")?;
    let alpha_dot = r
        .column("alpha_dot_rad_per_s")
        .ok_or("no alpha_dot column")?;
    if alpha.is_empty() {
        return Err("the spin-down run recorded no samples".into());
    }
    let n = alpha.len();
    let beta = sd.beta;
    // The time still missing to the singularity when the run stops, from the law's own
    // alpha ~ (t0 - t)^(2/(beta+2)) (as the experiment's truth defines t0).
    let tau_rem = 2.0 * alpha[n - 1] / ((beta + 2.0) * alpha_dot[n - 1].abs().max(1e-300));
    let t0 = t_stop + tau_rem;
    let pts: Vec<(f64, f64)> = t
        .iter()
        .zip(&alpha)
        .map(|(t, a)| (t0 - t, *a))
        .filter(|(x, _)| *x > 0.0)
        .collect();
    if pts.is_empty() {
        return Err("the spin-down run has no sample before its singular time".into());
    }
    let shown = log_thin(&pts, 300);
    let g_ak = sd.g_ak;
    let (x0, x1) = pts.iter().fold((f64::INFINITY, 0.0_f64), |(lo, hi), p| {
        (lo.min(p.0), hi.max(p.0))
    });
    let line = |c: f64| -> Vec<(f64, f64)> {
        (0..=60)
            .map(|i| {
                let x = x0 * (x1 / x0).powf(i as f64 / 60.0);
                (x, law(c, sd.epsilon, beta, g_ak, x))
            })
            .collect()
    };
    // How far each law is from the model, at the middle of the run in log time.
    let mid = pts[pts.len() / 2];
    let ratio = |c: f64| mid.1 / law(c, sd.epsilon, beta, g_ak, mid.0);
    let (r25, r23) = (ratio(0.4), ratio(2.0 / 3.0));
    // Where the model leaves the 2/3 law by more than 5 % (scanning from the start).
    let depart = pts
        .iter()
        .find(|p| (p.1 / law(2.0 / 3.0, sd.epsilon, beta, g_ak, p.0) - 1.0).abs() > 0.05)
        .map_or((0.0, 0.0), |p| (p.0, p.1));
    let plot = Plot::new(
        "Tilt during the spin-down against the law of eq 78",
        "t₀ − t (s)",
        "α (rad)",
    )
    .log(true, true)
    .with(Series::new(
        "dissipative model (eqs 23-25 + eq 75 torque)",
        shown,
        Style::Points,
    ))
    .with(Series::new(
        "eq 78, paper's factor 2/5 (eq 76)",
        line(0.4),
        Style::Dashed,
    ))
    .with(Series::new(
        "eq 78 with 2/3 (energy balance)",
        line(2.0 / 3.0),
        Style::Line,
    ))
    .legend_at(Legend::UpperLeft);
    Ok(Figure {
        name: "spin-down-alpha",
        title: "The spin-down's tilt against eq 78".into(),
        caption: super::captions::caption(
            "spin-down-alpha",
            &serde_json::json!({
                "beta": beta.to_string(),
                "epsilon": format!("{:.1e}", sd.epsilon),
                "t0": format!("{:.4}", t0),
                "t_stop": format!("{:.4}", t_stop),
                "ending": format!("{}", r.ending),
                "tau_rem": format!("{:.1e}", tau_rem),
                "slope": format!("{:.2}", 2.0 / (beta + 2.0)),
                "r23": format!("{:.3}", r23),
                "mid": format!("{:.2e}", mid.0),
                "r25": format!("{:.3}", r25),
                "depart": format!("{:.0}", 1e3 * depart.0),
                "depart_alpha": format!("{:.4}", depart.1),
            }),
        )?,
        drawing: Drawing::Plot(plot),
    })
}
