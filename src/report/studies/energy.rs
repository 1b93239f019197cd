//! The energy-drift study: the benchmark scene integrated by classical RK4 at two fixed steps
//! and by DOPRI5 and DOP853 at two tolerances each, with the drift $|E(t) - E_0|/E_0$ of the
//! total energy of eq 26, which the rolling model conserves exactly.

use crate::figures::energy::{DriftRun, EnergyDrift};
use crate::figures::Style;
use crate::model::rolling::Rolling;
use crate::model::{Extras, Model};
use crate::scene::Scene;
use crate::solve::{solve, Method, Problem, Settings};

/// The runs: method, relative tolerance (0 for fixed steps), step (0 for adaptive).
const RUNS: [(Method, f64, f64); 6] = [
    (Method::Rk4, 0.0, 1e-2),
    (Method::Rk4, 0.0, 1e-3),
    (Method::Dopri5, 1e-6, 0.0),
    (Method::Dopri5, 1e-9, 0.0),
    (Method::Dop853, 1e-8, 0.0),
    (Method::Dop853, 1e-12, 0.0),
];

/// Integrates the benchmark scene by each of [`RUNS`].
pub fn compute() -> Result<EnergyDrift, String> {
    let scene = Scene::load("benchmark").map_err(|e| e.to_string())?;
    let model = Rolling::<4>::new(scene.disk, Extras::default(), None);
    let y0 = model.state(&scene.start);
    let e0 = model.energy(&y0);
    let mut runs = Vec::new();
    for (method, rtol, step) in RUNS {
        let settings = Settings {
            method,
            rtol: if rtol > 0.0 { rtol } else { 1e-10 },
            atol: if rtol > 0.0 { rtol * 1e-2 } else { 1e-12 },
            step: if step > 0.0 { step } else { 1e-3 },
            ..Settings::default()
        };
        let sol = solve(Problem::new(&model, 0.0, y0, scene.stop.time), &settings)
            .map_err(|e| e.to_string())?;
        let drift: Vec<(f64, f64)> = sol
            .t
            .iter()
            .zip(&sol.y)
            .map(|(t, y)| (*t, ((model.energy(y) - e0) / e0).abs()))
            .collect();
        let label = match method {
            Method::Rk4 => format!("rk4, step {} ms", step * 1e3),
            _ => format!("{method}, rtol {rtol:.0e}"),
        };
        let style = match method {
            Method::Dopri5 => Style::Dashed,
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
