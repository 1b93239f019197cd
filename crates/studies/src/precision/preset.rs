//! Accuracy presets (`--accuracy fast|standard|high`) and the accuracy each actually reaches.
//!
//! | preset   | method | rtol  | atol  |
//! |----------|--------|-------|-------|
//! | fast     | dopri5 | 1e-6  | 1e-8  |
//! | standard | dop853 | 1e-10 | 1e-12 |
//! | high     | dop853 | 1e-13 | 1e-15 |
//!
//! A tolerance is a request for local accuracy per step, not a promise about the global error,
//! which is why [`measure_preset`] measures what a preset reaches on a scene.

use super::measure::{trace, Timing};
use super::reference::Reference;
use physics::scene::Scene;
use physics::solve::{Ending, Method, Settings, SettingsError};
use serde::{Deserialize, Serialize};
use std::fmt;

/// An accuracy preset.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Accuracy {
    /// DOPRI5 at rtol 1e-6: figures and quick looks.
    Fast,
    /// DOP853 at rtol 1e-10, looser than the checks' default (rtol 1e-12).
    Standard,
    /// DOP853 at rtol 1e-13: near the limit of double precision.
    High,
}

impl Accuracy {
    /// Every preset, from the fastest.
    pub const ALL: [Accuracy; 3] = [Accuracy::Fast, Accuracy::Standard, Accuracy::High];

    /// The solver settings of this preset (with the default step limit).
    pub fn settings(self) -> Settings {
        let (method, rtol) = match self {
            Accuracy::Fast => (Method::Dopri5, 1e-6),
            Accuracy::Standard => (Method::Dop853, 1e-10),
            Accuracy::High => (Method::Dop853, 1e-13),
        };
        Settings {
            method,
            rtol,
            atol: rtol * 1e-2,
            ..Settings::default()
        }
    }

    /// `scene` with this preset's solver settings (its step limit kept).
    pub fn apply(self, scene: &Scene) -> Scene {
        let mut s = scene.clone();
        s.settings = Settings {
            max_steps: scene.settings.max_steps,
            ..self.settings()
        };
        s
    }
}

impl Accuracy {
    /// The preset's name, as `--accuracy` takes it.
    pub fn name(self) -> &'static str {
        match self {
            Accuracy::Fast => "fast",
            Accuracy::Standard => "standard",
            Accuracy::High => "high",
        }
    }

    /// What the preset is for, in one line.
    pub fn summary(self) -> &'static str {
        match self {
            Accuracy::Fast => "DOPRI5 at rtol 1e-6: figures and quick looks",
            Accuracy::Standard => {
                "DOP853 at rtol 1e-10, looser than the checks' default (rtol 1e-12)"
            }
            Accuracy::High => "DOP853 at rtol 1e-13: near the limit of double precision",
        }
    }
}

impl fmt::Display for Accuracy {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// What a preset reached on a scene.
#[derive(Debug, Clone, Serialize)]
pub struct PresetMeasurement {
    /// The preset.
    pub accuracy: Accuracy,
    /// Its settings.
    pub settings: Settings,
    /// Error at the final time against the reference.
    pub final_error: f64,
    /// Largest error over the reference's sample times.
    pub trajectory_error: f64,
    /// The reference's own uncertainty: errors below it are not resolved.
    pub reference_uncertainty: f64,
    /// Right-hand-side evaluations.
    pub evaluations: u64,
    /// Median wall time of one integration (s).
    pub wall_seconds: f64,
    /// Relative energy change from start to end.
    pub energy_change: f64,
    /// Why the run ended.
    pub ending: Ending,
}

/// Measures what `accuracy` reaches on `scene` against `reference` (computed for the same
/// scene), and how long one integration takes.
pub fn measure_preset(
    scene: &Scene,
    accuracy: Accuracy,
    reference: &Reference,
    timing: &Timing,
) -> Result<PresetMeasurement, SettingsError> {
    let settings = accuracy.apply(scene).settings;
    let t = trace(scene, &settings, Some(reference.sample_every), timing)?;
    let (final_error, trajectory_error) = reference.errors(&t);
    Ok(PresetMeasurement {
        accuracy,
        settings,
        final_error,
        trajectory_error,
        reference_uncertainty: reference.uncertainty,
        evaluations: t.stats.evaluations,
        wall_seconds: t.wall_seconds,
        energy_change: t.energy_change,
        ending: t.ending,
    })
}
