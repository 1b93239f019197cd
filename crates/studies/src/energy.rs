//! The energy-drift study: the benchmark scene integrated by classical RK4 at two fixed steps
//! and by DOPRI5 and DOP853 at two tolerances each, with the drift $|E(t) - E_0|/E_0$ of the
//! total energy of eq 26, which the rolling model conserves exactly; DOP853 at 1e-8 once more
//! with every step projected back onto the start's energy (`solver: { project: energy }`).

use crate::error::StudyError;
use physics::model::rolling::Rolling;
use physics::model::{Extras, Model};
use physics::scene::Scene;
use physics::solve::{onto_level, solve, Method, Problem, Settings, State};

/// One integration of the benchmark scene and its energy drift.
#[derive(Debug, Clone, PartialEq)]
pub struct DriftRun {
    /// Method and tolerance or step, for the legend.
    pub label: String,
    /// The integration method.
    pub method: Method,
    /// True when every step was projected back onto the start's energy.
    pub projected: bool,
    /// $(t, |E(t) - E_0|/E_0)$ at every step.
    pub drift: Vec<(f64, f64)>,
    /// Right-hand-side evaluations the run took.
    pub evaluations: u64,
}

/// The energy-drift study: one run per method and tolerance (computed by
/// [`compute`]).
#[derive(Debug, Clone, PartialEq)]
pub struct EnergyDrift {
    /// The runs, in the legend's order.
    pub runs: Vec<DriftRun>,
}

/// The runs: method, relative tolerance (0 for fixed steps), step (0 for adaptive), and
/// whether every step is projected back onto the start's energy (`project: energy`).
const RUNS: [(Method, f64, f64, bool); 7] = [
    (Method::Rk4, 0.0, 1e-2, false),
    (Method::Rk4, 0.0, 1e-3, false),
    (Method::Dopri5, 1e-6, 0.0, false),
    (Method::Dopri5, 1e-9, 0.0, false),
    (Method::Dop853, 1e-8, 0.0, false),
    (Method::Dop853, 1e-8, 0.0, true),
    (Method::Dop853, 1e-12, 0.0, false),
];

/// Integrates the benchmark scene by each of [`RUNS`].
pub fn compute() -> Result<EnergyDrift, StudyError> {
    let scene = Scene::load("benchmark")?;
    let model = Rolling::<4>::new(scene.disk, Extras::default(), None);
    let y0 = model.state(&scene.start);
    let e0 = model.energy(&y0);
    let mut runs = Vec::new();
    for (method, rtol, step, projected) in RUNS {
        let settings = Settings {
            method,
            rtol: if rtol > 0.0 { rtol } else { 1e-10 },
            atol: if rtol > 0.0 { rtol * 1e-2 } else { 1e-12 },
            step: if step > 0.0 { step } else { 1e-3 },
            ..Settings::default()
        };
        let mut problem = Problem::new(&model, 0.0, y0, scene.stop.time);
        if projected {
            problem.project = Some(Box::new(|y: &mut State<4>| {
                onto_level(|y| model.energy(y), e0, y)
            }));
        }
        let sol = solve(problem, &settings)?;
        let drift: Vec<(f64, f64)> = sol
            .t
            .iter()
            .zip(&sol.y)
            .map(|(t, y)| (*t, ((model.energy(y) - e0) / e0).abs()))
            .collect();
        let label = match method {
            Method::Rk4 => format!("rk4, step {} ms", step * 1e3),
            _ if projected => format!("{method}, rtol {rtol:.0e}, projected"),
            _ => format!("{method}, rtol {rtol:.0e}"),
        };
        runs.push(DriftRun {
            label,
            method,
            projected,
            drift,
            evaluations: sol.stats.total_evaluations(),
        });
    }
    Ok(EnergyDrift { runs })
}
