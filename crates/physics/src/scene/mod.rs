//! Scenes: YAML descriptions of a physical situation of the paper and of what to measure in it,
//! validated into a [`Scene`] before anything is integrated.
//!
//! ```yaml
//! name: nutating-coin
//! disk: { radius: 0.0375, k: 0.25, mass: 0.4, g: 9.81 }
//! model: rolling            # rolling | frictionless | dissipative | adiabatic | lab-frame | lab-frame-frictionless
//! start: { steady: { alpha0: 0.3, b: 0.0 }, perturb: { alpha: 1.0e-4 } }
//! stop: { time: 10.0 }      # plus, optionally, alpha_below: 0.01 and/or lift_off: true
//! record: [alpha, precession, spin]
//! solver: { method: dop853, rtol: 1.0e-10, atol: 1.0e-12 }   # optionally project: energy
//! ```
//! Every key is checked: an unknown one is an error, and so is every value with no physical
//! meaning; the error names the file, the line and what to change.

pub mod builtin;
pub mod depth;
mod friction;
pub mod locate;
mod mechanisms;
pub mod message;
mod model_kind;
pub mod range;
mod spec;
mod toy;
mod validate;

pub use model_kind::ModelKind;
use spec::SceneSpec;
use validate::Validator;

use crate::budget;
use crate::disk::{Disk, DiskError};
use crate::model::dissipation::PowerLaw;
use crate::model::mechanism::Mechanism;
use crate::model::sliding::{Friction, Slip, Toy};
use crate::model::steady::{rolling_straight, steady_motion, vertical_spin, SteadyError};
use crate::model::{Extras, Motion, Quantity};
use crate::solve::{Method, Projection, Settings};
use files::input;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;
use std::fmt;
use std::path::Path;

/// A scene file that cannot be used: where, and what to change.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneError {
    /// The file (or `builtin:NAME`).
    pub file: String,
    /// The 1-based line, when known.
    pub line: Option<usize>,
    /// The 1-based column, when known.
    pub column: Option<usize>,
    /// What is wrong and what to change.
    pub message: String,
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.line, self.column) {
            (Some(l), Some(c)) => write!(f, "{}:{l}:{c}: {}", self.file, self.message),
            (Some(l), None) => write!(f, "{}:{l}: {}", self.file, self.message),
            _ => write!(f, "{}: {}", self.file, self.message),
        }
    }
}

impl std::error::Error for SceneError {}

/// When a run stops.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Stop {
    /// The end time (s); always present, so that every run ends.
    pub time: f64,
    /// Stop when $\alpha$ falls below this (rad).
    pub alpha_below: Option<f64>,
    /// Stop when the disk leaves the table ($F_z \le 0$).
    pub lift_off: bool,
}

/// A validated scene.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Scene {
    /// Its name.
    pub name: String,
    /// What it shows.
    pub description: String,
    /// Where it came from (a path, or `builtin:NAME`).
    pub source: String,
    /// The disk.
    pub disk: Disk,
    /// The model.
    pub model: ModelKind,
    /// The dissipation law (dissipative and adiabatic models).
    pub dissipation: Option<PowerLaw>,
    /// Dissipation mechanisms from their physics (`crate::model::mechanism`), each a torque
    /// of the dissipative model besides or instead of eq 75's law.
    pub mechanisms: Vec<Mechanism>,
    /// The friction law (sliding model).
    pub friction: Option<Friction>,
    /// The contact point's velocity relative to rolling at the start (sliding model).
    pub slip: Slip,
    /// Finite thickness, a kinetic coefficient and resistance (sliding model; thin and plain
    /// when not asked for).
    #[serde(skip_serializing_if = "Toy::is_thin")]
    pub toy: Toy,
    /// The start, perturbation included.
    pub start: Motion,
    /// When to stop.
    pub stop: Stop,
    /// What to record, in this order.
    pub record: Vec<Quantity>,
    /// Record every `sample` seconds instead of at every step.
    pub sample: Option<f64>,
    /// Solver settings.
    pub settings: Settings,
    /// An invariant every step is projected back onto (`solver: { project: energy }`), for
    /// models without dissipation and the DOP853 method.
    pub projection: Option<Projection>,
}

impl Scene {
    /// The optional states this scene's recordings need.
    pub fn extras(&self) -> Extras {
        Extras {
            heading: self.record.contains(&Quantity::Heading),
            path: self.record.contains(&Quantity::Path),
            face: self.record.contains(&Quantity::Face),
        }
    }

    /// Reads a scene from a file path, or a built-in scene by name (`NAME` or `builtin:NAME`);
    /// a file whose name is that of a built-in scene is refused, naming both ways to say which.
    pub fn load(name_or_path: &str) -> Result<Scene, SceneError> {
        if let Some(src) = name_or_path
            .strip_prefix("builtin:")
            .and_then(builtin::source)
        {
            return Scene::parse(src, name_or_path);
        }
        if let Some(src) = builtin::source(name_or_path) {
            if std::fs::symlink_metadata(name_or_path).is_err() {
                return Scene::parse(src, &format!("builtin:{name_or_path}"));
            }
            // A file here shadows the built-in scene of the same name: say so rather than pick.
            return Err(SceneError {
                file: name_or_path.to_string(),
                line: None,
                column: None,
                message: format!(
                    "is both a built-in scene and a file in this directory: write \
                     ./{name_or_path} for the file or builtin:{name_or_path} for the built-in scene"
                ),
            });
        }
        let path = Path::new(name_or_path);
        let src = input::read_text(path, input::MAX_SCENE_BYTES).map_err(|e| {
            let (line, hint) = match &e {
                input::InputError::NotText { line, .. } => (Some(*line), String::new()),
                input::InputError::Open { .. } => (
                    None,
                    format!(
                        "; {}give a path to a YAML file or the name of a built-in scene \
                         (`rolling-disk scenes` lists them)",
                        builtin::nearest(name_or_path)
                            .map_or(String::new(), |n| format!("did you mean {n}? ")),
                    ),
                ),
                _ => (None, String::new()),
            };
            SceneError {
                file: name_or_path.to_string(),
                line,
                column: None,
                message: format!("{}{hint}", e.reason()),
            }
        })?;
        Scene::parse(&src, &path.display().to_string())
    }

    /// Parses and validates a scene from YAML text; `file` names it in errors. A byte-order
    /// mark and CR or CRLF line ends are accepted; nesting deeper than [`depth::MAX_DEPTH`] is
    /// refused before the YAML reader sees it.
    pub fn parse(src: &str, file: &str) -> Result<Scene, SceneError> {
        let src = &*input::normalize(src);
        if let Err((line, column)) = depth::check(src) {
            return Err(SceneError {
                file: file.to_string(),
                line: Some(line),
                column: Some(column),
                message: format!(
                    "the scene nests deeper than {} levels here; a scene needs at most four \
                     (for example start: {{ steady: {{ alpha0: 0.3 }} }})",
                    depth::MAX_DEPTH
                ),
            });
        }
        let spec: SceneSpec = serde_yaml::from_str(src).map_err(|e| {
            let raw = e.to_string();
            let raw = raw.find(" at line ").map_or(raw.as_str(), |i| &raw[..i]);
            let (line, column) = match e.location() {
                Some(l) => (Some(l.line()), Some(l.column())),
                None => (None, None),
            };
            // The reader places a top-level duplicate at the mapping's start: name the line
            // that repeats the key instead.
            let (line, column) = match message::repeated_top_key(raw, src) {
                Some(l) => (Some(l), Some(1)),
                None => (line, column),
            };
            let at = line.zip(column).and_then(|(l, c)| {
                let text = src.lines().nth(l.checked_sub(1)?)?;
                text.chars().nth(c.checked_sub(1)?)
            });
            let mut message = message::translate(raw);
            if at == Some('\t') && !message.contains("tab") {
                message = "a tab character here: YAML indents with spaces only: replace the tab \
                           with spaces"
                    .to_string();
            } else if raw.contains("cannot start any token") {
                message.push_str(
                    ": `@` and the backtick are reserved in YAML: put such a value in quotes",
                );
            }
            SceneError {
                file: file.to_string(),
                line,
                column,
                message,
            }
        })?;
        Validator { src, file }.scene(spec)
    }
}
