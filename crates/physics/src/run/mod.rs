//! Running a scene: build the model with only the states it needs, integrate, record.

pub mod sliding;
mod table;

pub use table::{ContactLost, Run};

use crate::budget;
use crate::dispatch::{dispatch, problem, Visit};
use crate::model::{Model, Quantity};
use crate::scene::Scene;
use crate::solve::{solve, Ending, SettingsError, Solution, State};

/// Runs a scene. `progress` receives the simulated time now and then. A run records at most
/// [`budget::MAX_ROWS`] rows: a scene that samples more finely is refused before integrating (by
/// [`solve`]), and an unsampled run that takes more steps is refused after it.
pub fn run(scene: &Scene, progress: Option<&dyn Fn(f64)>) -> Result<Run, SettingsError> {
    if scene.model.has_coulomb_friction() {
        return sliding::run(scene);
    }
    dispatch(scene, Integrate { progress })
}

/// Integrates and records whatever model the scene builds.
struct Integrate<'p> {
    progress: Option<&'p dyn Fn(f64)>,
}

impl Visit for Integrate<'_> {
    type Out = Result<Run, SettingsError>;

    fn visit<M: Model<N>, const N: usize>(self, model: &M, scene: &Scene) -> Self::Out {
        let y0 = model.state(&scene.start);
        let mut p = problem(model, scene, y0, scene.stop.time);
        p.progress = self.progress;
        p.sample = scene.sample;
        let sol = solve(p, &scene.settings)?;
        let rows = sol.t.len() as u64;
        if rows > budget::MAX_ROWS {
            return Err(SettingsError::Rows {
                rows,
                limit: budget::MAX_ROWS,
                suggest: scene.stop.time / (budget::MAX_ROWS as f64 / 10.0),
            });
        }
        Ok(record(model, scene, &y0, &sol))
    }
}

fn record<M: Model<N>, const N: usize>(
    model: &M,
    scene: &Scene,
    y0: &State<N>,
    sol: &Solution<N>,
) -> Run {
    let mut columns = vec!["t_s".to_string()];
    for q in &scene.record {
        columns.extend(q.columns().iter().map(|c| c.to_string()));
    }
    let mut rows = Vec::with_capacity(sol.t.len());
    let e0 = model.energy(y0);
    let mut energy_change: f64 = 0.0;
    let mut contact_lost = None;
    let mut force = Vec::with_capacity(1);
    // A run stopped by an event (lift_off: F_z = 0) ends on the located zero, whose sign is
    // the root finder's: that last row is not a loss of contact within the run.
    let checked = match sol.ending {
        Ending::Event { .. } => sol.t.len().saturating_sub(1),
        _ => sol.t.len(),
    };
    for (i, (t, y)) in sol.t.iter().zip(&sol.y).enumerate() {
        force.clear();
        if contact_lost.is_none()
            && i < checked
            && model.record(y, Quantity::NormalForce, &mut force)
            && force.first().is_some_and(|&n| n < 0.0)
        {
            contact_lost = Some(ContactLost {
                t: *t,
                normal_force: force[0],
            });
        }
        let mut row = Vec::with_capacity(columns.len());
        row.push(*t);
        for &q in &scene.record {
            let ok = model.record(y, q, &mut row);
            debug_assert!(ok, "validated scenes only record what their model provides");
        }
        rows.push(row);
        energy_change = energy_change.max(((model.energy(y) - e0) / e0).abs());
    }
    let (_, y_end) = sol.last();
    Run {
        scene: scene.name.clone(),
        model: scene.model,
        states: N,
        columns,
        rows,
        stats: sol.stats,
        ending: sol.ending.clone(),
        last: model.motion(&y_end),
        energy: (e0, model.energy(&y_end)),
        energy_change,
        contact_events: Vec::new(),
        contact_lost,
    }
}

impl Run {
    /// The run as CSV: a header of column names with units, then one row per recorded time.
    /// Numbers are printed with 17 significant digits so that they read back exactly.
    pub fn to_csv(&self) -> String {
        let mut s = self.columns.join(",");
        s.push('\n');
        for row in &self.rows {
            let cells: Vec<String> = row.iter().map(|v| format!("{v:.16e}")).collect();
            s.push_str(&cells.join(","));
            s.push('\n');
        }
        s
    }

    /// The values of one column.
    pub fn column(&self, name: &str) -> Option<Vec<f64>> {
        let i = self.columns.iter().position(|c| c == name)?;
        Some(self.rows.iter().map(|r| r[i]).collect())
    }
}
