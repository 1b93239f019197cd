//! Long-time behaviour: the energy drift of a conservative scene over many precession periods,
//! for every accuracy preset, as one pure result ([`DriftTable`]) for reports and figures.
//!
//! The rolling model (eqs 23-25) conserves the energy
//! $E = \tfrac12 m a^2 [(2k+1)\omega_1^2 + (k+1)\dot\alpha^2 + k\Omega^2\sin^2\alpha +
//! 2 (g/a)\sin\alpha]$ (`model::rolling::energy`); its drift over $10^4$ periods measures how
//! the integration's errors add up. The goal at the `high` preset is a relative drift below
//! $10^{-12}$.

use super::cost::{energy_drift, Drift};
use super::preset::Accuracy;
use super::PrecisionError;
use physics::scene::Scene;
use physics::solve::{Method, Projection};
use serde::Serialize;

/// The drift of one scene for every preset.
#[derive(Debug, Clone, Serialize)]
pub struct DriftTable {
    /// The scene.
    pub scene: String,
    /// Precession periods of the start integrated over.
    pub periods: f64,
    /// One row per preset, from the fastest.
    pub rows: Vec<DriftRow>,
    /// The same with every step projected back onto the start's energy
    /// (`solver: { project: energy }`), for the presets whose method can project (DOP853).
    pub projected: Vec<DriftRow>,
}

/// One preset's drift.
#[derive(Debug, Clone, Serialize)]
pub struct DriftRow {
    /// The preset.
    pub accuracy: Accuracy,
    /// What the run measured (settings, checkpoints, largest drift, work, time).
    pub drift: Drift,
}

/// Integrates `scene` over `periods` precession periods of its start with each preset, in
/// `checkpoints` chunks, and measures the energy drift of each; then again, projected onto the
/// energy after every step, with the presets that can project.
pub fn long_time_drift(
    scene: &Scene,
    periods: f64,
    checkpoints: u32,
) -> Result<DriftTable, PrecisionError> {
    let free = Scene {
        projection: None,
        ..scene.clone()
    };
    let projecting = Scene {
        projection: Some(Projection::Energy),
        ..scene.clone()
    };
    let run = |scene: &Scene, accuracy: Accuracy| {
        let settings = accuracy.apply(scene).settings;
        energy_drift(scene, &settings, periods, checkpoints)
            .map(|drift| DriftRow { accuracy, drift })
    };
    let rows = Accuracy::ALL
        .iter()
        .map(|&accuracy| run(&free, accuracy))
        .collect::<Result<Vec<_>, _>>()?;
    let projected = Accuracy::ALL
        .iter()
        .filter(|a| a.settings().method == Method::Dop853)
        .map(|&accuracy| run(&projecting, accuracy))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(DriftTable {
        scene: scene.name.clone(),
        periods,
        rows,
        projected,
    })
}
