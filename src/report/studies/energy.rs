//! The energy-drift study: the benchmark scene integrated by classical RK4 at two fixed steps
//! and by DOPRI5 and DOP853 at two tolerances each, with the drift $|E(t) - E_0|/E_0$ of the
//! total energy of eq 26, which the rolling model conserves exactly; DOP853 at 1e-8 once more
//! with every step projected back onto the start's energy (`solver: { project: energy }`).

use crate::figures::energy::{DriftRun, EnergyDrift};
use crate::figures::Style;
use crate::model::rolling::Rolling;
use crate::model::{Extras, Model};
use crate::report::error::ReportError;
use crate::scene::Scene;
use crate::solve::{onto_level, solve, Method, Problem, Settings, State};

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
pub fn compute() -> Result<EnergyDrift, ReportError> {
    let scene = Scene::load("benchmark").map_err(|e| ReportError::Input(e.to_string()))?;
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
        let sol = solve(problem, &settings).map_err(|e| ReportError::Input(e.to_string()))?;
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
        let style = match method {
            Method::Dopri5 => Style::Dashed,
            Method::Dop853 if projected => Style::Dotted,
            Method::Rk4 | Method::Dop853 => Style::Line,
        };
        runs.push(DriftRun {
            label,
            style,
            drift,
            evaluations: sol.stats.total_evaluations(),
        });
    }
    Ok(EnergyDrift { runs })
}
