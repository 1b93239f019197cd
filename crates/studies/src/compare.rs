//! Running one scene in two models and measuring how far apart they end up: above all, the
//! paper's reduced equations against the independent lab-frame Newton-Euler model.

use physics::run::{run, Run};
use physics::scene::{ModelKind, Scene};
use physics::solve::SettingsError;
use serde::Serialize;

/// Why two runs of a scene could not be compared.
#[derive(Debug, thiserror::Error)]
pub enum CompareError {
    /// A sliding scene has no reduced model to referee.
    #[error(
        "a sliding scene already runs in the lab frame; compare it with rolling and frictionless \
         runs by setting mu large or 0 (tests/sliding.rs does)"
    )]
    Sliding,
    /// The lab-frame model has no dissipation.
    #[error(
        "the lab-frame model has no dissipation, so a {0} scene cannot be compared with it: \
         compare a rolling or frictionless scene"
    )]
    Dissipative(ModelKind),
    /// One of the two runs was refused.
    #[error("{source_name}{model}: {error}")]
    Run {
        /// The scene's file or built-in name.
        source_name: String,
        /// " in the ... model" for the second run, empty for the scene's own.
        model: String,
        /// Why.
        error: SettingsError,
    },
    /// One of the two runs ended early.
    #[error("a run did not finish ({model}: {mine}; {other}: {theirs})")]
    Unfinished {
        /// The scene's model.
        model: ModelKind,
        /// How its run ended.
        mine: String,
        /// The other model.
        other: ModelKind,
        /// How that run ended.
        theirs: String,
    },
}

/// The largest difference of one recorded quantity between two runs.
#[derive(Debug, Clone, Serialize)]
pub struct Difference {
    /// The column (with its unit).
    pub column: String,
    /// Largest absolute difference over the common sample times.
    pub largest: f64,
    /// The same relative to the quantity's range in the second run (with a floor of 1e-3 of
    /// its largest magnitude, for a quantity that barely moves); `None` when the quantity is
    /// zero throughout the second run, so that no scale exists.
    pub relative: Option<f64>,
    /// Where.
    pub at_time: f64,
}

/// Two runs of one scene compared.
#[derive(Debug, Clone, Serialize)]
pub struct Comparison {
    /// The scene.
    pub scene: String,
    /// Its own model.
    pub model: ModelKind,
    /// The model it was compared with.
    pub other: ModelKind,
    /// One entry per recorded column.
    pub differences: Vec<Difference>,
}

/// The lab-frame model that referees a scene's model.
pub fn lab_frame_for(model: ModelKind) -> Result<ModelKind, CompareError> {
    match model.lab_frame_referee() {
        Some(referee) => Ok(referee),
        None if model.has_coulomb_friction() => Err(CompareError::Sliding),
        None => Err(CompareError::Dissipative(model)),
    }
}

/// Runs `scene` in its own model and in `other`, both sampled at the same times (the scene's
/// `sample`, or 1000 samples over its duration), and measures the differences of what it records.
pub fn compare(scene: &Scene, other: ModelKind) -> Result<Comparison, CompareError> {
    let mut mine = scene.clone();
    if mine.sample.is_none() {
        mine.sample = Some(mine.stop.time / 1000.0);
    }
    let theirs = Scene {
        model: other,
        ..mine.clone()
    };
    let refused = |model: String| {
        move |error| CompareError::Run {
            source_name: scene.source.to_string(),
            model,
            error,
        }
    };
    let a = run(&mine, None).map_err(refused(String::new()))?;
    let b = run(&theirs, None).map_err(refused(format!(" in the {other} model")))?;
    if !a.ending.is_complete() || !b.ending.is_complete() {
        return Err(CompareError::Unfinished {
            model: scene.model,
            mine: a.ending.to_string(),
            other,
            theirs: b.ending.to_string(),
        });
    }
    Ok(Comparison {
        scene: scene.name.clone(),
        model: scene.model,
        other,
        differences: differences(&a, &b),
    })
}

fn differences(a: &Run, b: &Run) -> Vec<Difference> {
    let n = a.rows.len().min(b.rows.len());
    let mut out = Vec::new();
    // Angles that the lab model reports wrapped to (-pi, pi] are not compared.
    for (j, column) in a.columns.iter().enumerate().skip(1) {
        if column == "heading_rad" || column == "face_rad" {
            continue;
        }
        let values: Vec<f64> = b.rows[..n].iter().map(|r| r[j]).collect();
        let hi = values.iter().copied().fold(f64::MIN, f64::max);
        let lo = values.iter().copied().fold(f64::MAX, f64::min);
        let scale = (hi - lo).max(1e-3 * hi.abs().max(lo.abs()));
        let (mut largest, mut at_time) = (0.0f64, 0.0);
        for (row, v) in a.rows[..n].iter().zip(&values) {
            let d = (row[j] - v).abs();
            if d > largest || d.is_nan() {
                largest = d;
                at_time = row[0];
            }
        }
        out.push(Difference {
            column: column.clone(),
            largest,
            relative: (scale > 0.0).then_some(largest / scale),
            at_time,
        });
    }
    out
}
