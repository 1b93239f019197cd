//! Dissipation mechanisms side by side (beyond the paper): which of them gives the $\beta = 2$
//! that sec. 11 fits to its record, and over which rates each would dominate.
//!
//! **What the record needs.** Along steady rolling with $b = 0$ (eq 29,
//! $\Omega^2\sin\alpha = g/ka$) eq 26's energy is $E = \frac32 mga\sin\alpha = \frac{3mg^2}{2k\Omega^2}$
//! exactly, so a record that follows eq 79, $\Omega^{\beta+2} = C/(t_0 - t)$ (whence
//! $\dot\Omega = \Omega^{\beta+3}/(\beta+2)C$), needs the power
//! $$P_{\rm data}(\Omega) = \frac{dE}{dt} = -\frac{3mg^2}{k(\beta+2)C}\,\Omega^\beta .$$
//! With the paper's fit ($\beta = 2$, $C^{-1/4}$ = 5.5 ms) that is the line every mechanism is
//! held against. It uses eq 26, not eq 73's coefficient (which this tool finds wrong).
//!
//! **Spin-downs.** Each mechanism of [`physics::model::mechanism`], its coefficient set so that
//! it alone supplies $P_{\rm data}$ at the rate $\Omega_{\rm cal}$ where the paper's 10 s record
//! starts ($\Omega = (C/10\,{\rm s})^{1/(\beta+2)}$), drives the rolling model (eqs 23-25) from
//! steady motion at [`START_RATE`] until $\alpha$ falls to [`ALPHA_END`] (or [`MAX_TIME`]
//! passes). The last [`RECORD`] seconds are cut into turns at the heading's multiples of
//! $2\pi$ (the times a light peak would mark, located by cubic Hermite interpolation between
//! samples 1 ms apart) and handed to the experiment's own fits: eq 84 with $\beta$ free, its
//! plausibility checks, and the comparison of laws by BIC. A mechanism "gives $\beta = 2$" when
//! the fit says so, whatever its derivation claims.
//!
//! **Where each dominates.** The powers are drawn against $\Omega$ along the steady path: the
//! friction mechanisms at their calibrated coefficients, the air mechanisms with air's own
//! viscosity (no free coefficient; the boundary layer up to its factor of order one), with the
//! rate above which the film is thin enough for lubrication ([`Mechanisms::film_valid_above`]).

use crate::fit::crossover::fit_crossover;
use crate::fit::eq84_85::fit_eq84;
use crate::fit::law_choice::compare_laws;
use crate::fit::plausibility::Evidence;
use crate::light_analysis::analysis::AnalysisSettings;
use crate::light_analysis::rates::cycles;
use crate::synthetic::law::Law;
use numerics::oscillation::bisect;
use physics::disk::Disk;
use physics::model::air_film::SqueezeFilm;
use physics::model::mechanism::{Mechanism, AIR_KINEMATIC_VISCOSITY, AIR_VISCOSITY};
use physics::model::rolling::Rolling;
use physics::model::steady::{steady_motion, tilt_at_b0};
use physics::model::{Extras, Model, Motion};
use physics::solve::{solve, Ending, Event, Problem, Settings, SettingsError, Solution, State};
use serde::Serialize;
use std::f64::consts::TAU;

/// The length of the record fitted, as the paper's (s).
pub const RECORD: f64 = 10.0;
/// The rate each spin-down starts from, in steady motion with $b = 0$ (rad/s).
pub const START_RATE: f64 = 80.0;
/// The tilt that ends a spin-down (rad): $\Omega \approx 720$ rad/s for the toy disk.
pub const ALPHA_END: f64 = 2e-3;
/// The longest spin-down followed (s).
pub const MAX_TIME: f64 = 60.0;
/// The timing uncertainty given to each turn (s); the fits scale it by their $\chi^2$.
pub const TIMING: f64 = 1e-5;
/// The most turns fitted (disjoint, evenly spread).
const FITTED: usize = 40;
/// The sampling interval of the record (s).
const SAMPLE: f64 = 1e-3;

/// One mechanism's spin-down and what the experiment's fits make of it.
#[derive(Debug, Clone, PartialEq, Serialize, schemars::JsonSchema)]
pub struct MechanismSpinDown {
    /// The mechanism ([`Mechanism::name`]).
    pub mechanism: String,
    /// Its coefficient, calibrated to the record's need at $\Omega_{\rm cal}$.
    pub coefficient: f64,
    /// The coefficient's unit.
    pub unit: String,
    /// The $\beta$ its physics gives at small tilt ([`Mechanism::exponent`]).
    pub exponent: f64,
    /// How long the spin-down took to reach [`ALPHA_END`] (s; [`MAX_TIME`] if it did not).
    pub duration: f64,
    /// Turns in the record.
    pub turns: usize,
    /// Disjoint turns fitted, evenly spread over the record.
    pub fitted: usize,
    /// $\Omega$ of the first and last turn fitted (rad/s).
    pub omega_range: (f64, f64),
    /// Eq 84's $\beta$ with its standard uncertainty, when it could be fitted (also when the
    /// plausibility checks then refuse the fit).
    pub beta: Option<(f64, f64)>,
    /// The law the comparison chooses ([`Comparison::chosen`](crate::fit::law_choice::Comparison::chosen)), in words (not when refused).
    pub best_law: Option<String>,
    /// BIC of $\beta = 2$ above the best law's (0 when it is the best).
    pub delta_bic_beta_two: Option<f64>,
    /// Why the fit was refused, if it was.
    pub refused: Option<String>,
}

impl MechanismSpinDown {
    /// True when the fit was accepted and its $\beta$ agrees with `beta` within three standard
    /// uncertainties, and never more finely than 0.15 (the spread of the fitted exponents of
    /// single mechanisms over the record).
    pub fn gives(&self, beta: f64) -> bool {
        self.refused.is_none()
            && self
                .beta
                .is_some_and(|(b, s)| (b - beta).abs() < 3.0 * s.max(0.05))
    }
}

/// One mechanism's power along steady rolling, for the figure.
#[derive(Debug, Clone, PartialEq, Serialize, schemars::JsonSchema)]
pub struct PowerCurve {
    /// What it is.
    pub name: String,
    /// $(\Omega, |P|)$ in (rad/s, W).
    pub points: Vec<(f64, f64)>,
}

/// The study.
#[derive(Debug, Clone, PartialEq, Serialize, schemars::JsonSchema)]
pub struct Mechanisms {
    /// The record's law ($\beta$, $C$) the powers are held against.
    pub data_beta: f64,
    /// Its $C$ (s^-(beta+1)).
    pub data_c: f64,
    /// $\Omega_{\rm cal}$: where the 10 s record starts (rad/s).
    pub omega_cal: f64,
    /// Each mechanism's spin-down.
    pub spin_downs: Vec<MechanismSpinDown>,
    /// The record's need and each mechanism's power against $\Omega$.
    pub curves: Vec<PowerCurve>,
    /// The rate above which the squeeze film is thinner than the viscous layer (rad/s).
    pub film_valid_above: f64,
    /// Air's power over the record's need, at $\Omega_{\rm cal}$ and further on.
    pub air_over_need: Vec<AirOverNeed>,
}

/// Air's power, with air's own viscosity, over what the record needs at one rate.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, schemars::JsonSchema)]
pub struct AirOverNeed {
    /// $\Omega$ (rad/s).
    pub omega: f64,
    /// The boundary layer's power over the need (its factor of order one set to 1).
    pub layer: f64,
    /// The squeeze film's (lubrication) power over the need.
    pub film: f64,
}

/// The rates, besides $\Omega_{\rm cal}$, at which air is held against the record (rad/s).
pub const AIR_RATES: [f64; 2] = [300.0, 600.0];

/// $|P_{\rm data}|$ at $\Omega$ (module doc).
pub fn data_power(d: &Disk, law: &Law, omega: f64) -> f64 {
    3.0 * d.m * d.g * d.g * omega.powf(law.beta) / (d.k * (law.beta + 2.0) * law.c)
}

/// Steady motion with $b = 0$ at rate $\Omega$.
fn steady_at(d: &Disk, omega: f64) -> Motion {
    let Ok(m) = steady_motion(d, tilt_at_b0(d, omega), 0.0) else {
        unreachable!("b = 0 is inside eq 30's range at every tilt")
    };
    m
}

/// The mechanism scaled to supply the record's power at $\Omega_{\rm cal}$.
pub fn calibrated(d: &Disk, law: &Law, mech: &Mechanism, omega_cal: f64) -> Mechanism {
    let unit = -mech.power(d, &steady_at(d, omega_cal));
    mech.scaled(data_power(d, law, omega_cal) / unit)
}

/// Times at which the heading (index 4) passes a multiple of $2\pi$, by cubic Hermite
/// interpolation with $\dot\psi = \Omega$ (index 2) between samples.
fn turns(run: &Solution<5>) -> Vec<f64> {
    let mut out = Vec::new();
    for (w, tw) in run.y.windows(2).zip(run.t.windows(2)) {
        let (p0, p1) = (w[0][4], w[1][4]);
        let k = (p0 / TAU).floor() + 1.0;
        let target = k * TAU;
        if !(p1 >= target && p0 < target) {
            continue;
        }
        let h = tw[1] - tw[0];
        let (m0, m1) = (w[0][2] * h, w[1][2] * h);
        let hermite = |s: f64| {
            let (s2, s3) = (s * s, s * s * s);
            (2.0 * s3 - 3.0 * s2 + 1.0) * p0
                + (s3 - 2.0 * s2 + s) * m0
                + (-2.0 * s3 + 3.0 * s2) * p1
                + (s3 - s2) * m1
                - target
        };
        let (lo, hi) = bisect(0.0, 1.0, 1e-14, |s| hermite(s) >= 0.0);
        out.push(tw[0] + 0.5 * (lo + hi) * h);
    }
    out
}

/// The spin-down of `mech` (already calibrated), fitted as the experiment would.
pub fn spin_down(
    d: &Disk,
    mech: &Mechanism,
    settings: &Settings,
) -> Result<MechanismSpinDown, SettingsError> {
    let extras = Extras {
        heading: true,
        path: false,
        face: false,
    };
    let model = Rolling::<5>::new(*d, extras, None).with_mechanisms(&[*mech]);
    let y0 = model.state(&steady_at(d, START_RATE));
    // One run sampled finely throughout: its length is known only at its end, and a second
    // run over the record would integrate the last seconds twice.
    let fine = solve(
        Problem::new(&model, 0.0, y0, MAX_TIME)
            .stop_when(Event::new("alpha_end", |y: &State<5>| y[0] - ALPHA_END))
            .sampled(SAMPLE),
        settings,
    )?;
    let duration = match fine.ending {
        Ending::Event { t, .. } => t,
        _ => MAX_TIME,
    };
    let from = (duration - RECORD).max(0.0);
    let tp: Vec<f64> = turns(&fine).into_iter().filter(|&t| t >= from).collect();
    let mut out = MechanismSpinDown {
        mechanism: mech.name().into(),
        coefficient: mech.coefficient(),
        unit: mech.unit().into(),
        exponent: mech.exponent(),
        duration,
        turns: tp.len().saturating_sub(1),
        fitted: 0,
        omega_range: (0.0, 0.0),
        beta: None,
        best_law: None,
        delta_bic_beta_two: None,
        refused: None,
    };
    let cyc = cycles(&tp);
    if cyc.len() < 10 {
        out.refused = Some(format!("only {} turns in the record", cyc.len()));
        return Ok(out);
    }
    out.omega_range = (cyc[0].omega, cyc[cyc.len() - 1].omega);
    // Disjoint turns, at most FITTED of them spread over the record: enough to fix an exponent
    // to about 0.01, and the fits' cost stays small.
    let stride = (cyc.len() / FITTED).max(2);
    let idx: Vec<usize> = (0..cyc.len()).step_by(stride).collect();
    let cyc: Vec<_> = idx.iter().map(|&i| cyc[i]).collect();
    let ta: Vec<f64> = idx.iter().map(|&i| tp[i]).collect();
    let tb: Vec<f64> = idx.iter().map(|&i| tp[i + 1]).collect();
    let (ta, tb) = (&ta[..], &tb[..]);
    out.fitted = idx.len();
    let w = vec![TIMING * TIMING; tp.len()];
    let eq84 = match fit_eq84(ta, tb, &idx, &w) {
        Ok(f) => f,
        Err(e) => {
            out.refused = Some(format!("eq 84 cannot be fitted ({e})"));
            return Ok(out);
        }
    };
    let t_mid: Vec<f64> = cyc.iter().map(|c| c.t).collect();
    let om: Vec<f64> = cyc.iter().map(|c| c.omega).collect();
    let ys: Vec<f64> = eq84.points.iter().map(|p| p.y).collect();
    let rs: Vec<f64> = eq84.points.iter().map(|p| p.residual).collect();
    let crossover = fit_crossover(ta, tb, &idx, &w, &eq84).ok();
    let verdict = AnalysisSettings::default().plausibility.judge(&Evidence {
        t: &t_mid,
        omega: &om,
        anomalous: 0,
        y: &ys,
        residual: &rs,
        crossover_residual_ss: crossover.as_ref().map(|x| x.residual_ss),
        beta: eq84.beta,
        t0: eq84.t0,
        t_first: ta[0],
        t_last: tb[tb.len() - 1],
    });
    out.beta = (eq84.beta.is_finite() && eq84.beta_sigma.is_finite())
        .then_some((eq84.beta, eq84.beta_sigma));
    if !verdict.refusals.is_empty() {
        out.refused = Some(verdict.refusals.join("; "));
        return Ok(out);
    }
    let models = compare_laws(ta, tb, &idx, &w, &eq84, crossover.as_ref());
    out.best_law = models
        .chosen()
        .map(|c| format!("{} ({})", c.name, c.parameters));
    out.delta_bic_beta_two = models
        .candidates
        .iter()
        .find(|c| c.name == "beta = 2")
        .map(|c| c.delta_bic);
    Ok(out)
}

/// Rates of the figure's curves (rad/s), log-spaced.
fn figure_rates() -> Vec<f64> {
    (0..=60)
        .map(|i| 50.0 * (2000.0f64 / 50.0).powf(i as f64 / 60.0))
        .collect()
}

/// Runs the study for disk `d` against the record's law (the paper's fit).
pub fn mechanisms(d: &Disk, law: &Law, settings: &Settings) -> Result<Mechanisms, SettingsError> {
    use rayon::prelude::*;
    let omega_cal = (law.c / RECORD).powf(1.0 / (law.beta + 2.0));
    let mechs: Vec<Mechanism> = Mechanism::all_unit()
        .iter()
        .map(|m| calibrated(d, law, m, omega_cal))
        .collect();
    let spin_downs: Result<Vec<_>, _> = mechs
        .par_iter()
        .map(|m| spin_down(d, m, settings))
        .collect();
    let rates = figure_rates();
    let curve = |name: String, p: &dyn Fn(f64) -> f64| PowerCurve {
        name,
        points: rates.iter().map(|&om| (om, p(om))).collect(),
    };
    let mut curves = vec![curve(
        format!(
            "what the record needs (eq 79, beta = {}, C^-1/(beta+2) = {} ms)",
            law.beta,
            1e3 * law.c.powf(-1.0 / (law.beta + 2.0))
        ),
        &|om| data_power(d, law, om),
    )];
    for m in mechs.iter().filter(|m| m.unit() != "Pa s") {
        curves.push(curve(format!("{} (calibrated)", m.name()), &|om| {
            -m.power(d, &steady_at(d, om))
        }));
    }
    let air = [
        Mechanism::AirFilm {
            viscosity: AIR_VISCOSITY,
        },
        Mechanism::AirLayer {
            viscosity: AIR_VISCOSITY,
            kinematic: AIR_KINEMATIC_VISCOSITY,
        },
    ];
    for m in &air {
        curves.push(curve(format!("{} (air's viscosity)", m.name()), &|om| {
            -m.power(d, &steady_at(d, om))
        }));
    }
    let gap = |om: f64| {
        SqueezeFilm::gap_over_layer(d, AIR_KINEMATIC_VISCOSITY, steady_at(d, om).alpha, om) - 1.0
    };
    let film_valid_above =
        numerics::oscillation::bisect_to_width(10.0, 1e5, 1e-3, |om| Some(gap(om) < 0.0))
            .unwrap_or(f64::NAN);
    let air_over_need = std::iter::once(omega_cal)
        .chain(AIR_RATES)
        .map(|om| {
            let need = data_power(d, law, om);
            let m = steady_at(d, om);
            AirOverNeed {
                omega: om,
                layer: -air[1].power(d, &m) / need,
                film: -air[0].power(d, &m) / need,
            }
        })
        .collect();
    Ok(Mechanisms {
        data_beta: law.beta,
        data_c: law.c,
        omega_cal,
        spin_downs: spin_downs?,
        curves,
        film_valid_above,
        air_over_need,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The paper's fit, as paper/claims.yaml states it.
    fn paper_law() -> Law {
        Law::from_fit(2.0, 0.0055)
    }

    /// The record's need is what eq 79 takes from eq 26's energy: integrating
    /// $dE/dt = P_{\rm data}$ between two rates reproduces the law's time between them.
    #[test]
    fn the_record_need_reproduces_the_law_it_came_from() {
        let d = physics::disk::toy_disk();
        let law = paper_law();
        let (w1, w2) = (150.0f64, 400.0f64);
        // t(w) = t0 - C / w^(beta+2); dt = dE / P.
        let exact = law.c / w1.powi(4) - law.c / w2.powi(4);
        // dE/dOmega along steady b = 0 motion from the model's eq 26, not from the closed form.
        let e = |w: f64| physics::model::rolling::energy(&d, &steady_at(&d, w));
        let n = 20_000;
        let mut t = 0.0;
        for i in 0..n {
            let w = w1 + (w2 - w1) * (i as f64 + 0.5) / n as f64;
            let h = 1e-4 * w;
            let de_dw = -(e(w + h) - e(w - h)) / (2.0 * h);
            t += de_dw / data_power(&d, &law, w) * (w2 - w1) / n as f64;
        }
        assert!((t - exact).abs() < 1e-6 * exact, "{t} vs {exact}");
    }

    /// The spin-downs give back, through the experiment's fit, the exponent each mechanism's
    /// physics predicts, where eq 79 has a finite-time singularity ($\beta > -2$), even where
    /// the experiment's plausibility checks refuse it (rolling resistance, $\beta < -0.5$);
    /// pivoting ($\beta = -3$) has none and is refused. Only viscous rolling friction gives
    /// the paper's 2 and is accepted.
    #[test]
    fn each_mechanism_spins_down_with_its_own_exponent() {
        let d = physics::disk::toy_disk();
        let settings = Settings::dop853(1e-10, 1e-12);
        let s = mechanisms(&d, &paper_law(), &settings).unwrap();
        for r in &s.spin_downs {
            println!("{r:?}");
            if r.exponent > -2.0 {
                let (beta, _) = r.beta.unwrap_or_else(|| panic!("{r:?}"));
                assert!((beta - r.exponent).abs() < 0.15, "{r:?}");
            } else {
                assert!(r.refused.is_some(), "{r:?}");
            }
            assert_eq!(r.refused.is_some(), r.exponent < -0.5, "{r:?}");
            let gives_two = r.refused.is_none()
                && r.beta
                    .is_some_and(|(b, s)| (b - 2.0).abs() < 3.0 * s.max(0.05));
            assert_eq!(gives_two, r.exponent == 2.0, "{r:?}");
        }
        assert!(
            s.film_valid_above > 300.0 && s.film_valid_above < 5000.0,
            "{s:?}"
        );
    }
}
