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
pub mod message;
pub mod range;

use crate::budget;
use crate::disk::{Disk, DiskError};
use crate::input;
use crate::model::dissipation::PowerLaw;
use crate::model::sliding::{Friction, Slip};
use crate::model::steady::{rolling_straight, steady_motion, vertical_spin, SteadyError};
use crate::model::{Extras, Motion, Quantity};
use crate::solve::{Method, Projection, Settings};
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

/// The model a scene integrates.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ModelKind {
    /// Rolling without slipping, eqs 23-25.
    Rolling,
    /// No friction at the contact, eqs 60-62.
    Frictionless,
    /// Rolling with the power-law dissipation of eq 75 as a torque.
    Dissipative,
    /// The paper's one-state spin-down law, eq 76.
    Adiabatic,
    /// The independent Newton-Euler model in lab coordinates, rolling without slipping.
    LabFrame,
    /// The independent Newton-Euler model in lab coordinates, without friction.
    LabFrameFrictionless,
    /// The lab-frame model with Coulomb friction, stick/slip and flight (issue 14).
    Sliding,
}

impl fmt::Display for ModelKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            ModelKind::Rolling => "rolling",
            ModelKind::Frictionless => "frictionless",
            ModelKind::Dissipative => "dissipative",
            ModelKind::Adiabatic => "adiabatic",
            ModelKind::LabFrame => "lab-frame",
            ModelKind::LabFrameFrictionless => "lab-frame-frictionless",
            ModelKind::Sliding => "sliding",
        })
    }
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct SceneSpec {
    name: String,
    #[serde(default)]
    description: String,
    disk: DiskSpec,
    model: ModelKind,
    #[serde(default)]
    dissipation: Option<PowerLaw>,
    #[serde(default)]
    friction: Option<friction::FrictionSpec>,
    start: StartSpec,
    stop: StopSpec,
    #[serde(default)]
    record: Vec<Quantity>,
    #[serde(default)]
    sample: Option<f64>,
    #[serde(default)]
    solver: SolverSpec,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct DiskSpec {
    radius: f64,
    k: f64,
    mass: f64,
    #[serde(default = "earth_gravity")]
    g: f64,
}

fn earth_gravity() -> f64 {
    9.81
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct StartSpec {
    steady: Option<SteadySpec>,
    vertical_spin: Option<VerticalSpinSpec>,
    rolling_straight: Option<RollingStraightSpec>,
    explicit: Option<MotionSpec>,
    perturb: Option<MotionSpec>,
    slip: Option<friction::SlipSpec>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct SteadySpec {
    alpha0: f64,
    b: f64,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct VerticalSpinSpec {
    precession: f64,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RollingStraightSpec {
    spin: f64,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
struct MotionSpec {
    #[serde(default)]
    alpha: f64,
    #[serde(default)]
    alpha_dot: f64,
    #[serde(default)]
    precession: f64,
    #[serde(default)]
    spin: f64,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct StopSpec {
    time: Option<f64>,
    alpha_below: Option<f64>,
    #[serde(default)]
    lift_off: bool,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct SolverSpec {
    #[serde(default = "default_method")]
    method: Method,
    #[serde(default = "default_rtol")]
    rtol: f64,
    #[serde(default = "default_atol")]
    atol: f64,
    #[serde(default = "default_step")]
    step: f64,
    #[serde(default = "default_max_steps")]
    max_steps: u32,
    #[serde(default)]
    project: Option<Projection>,
}

fn default_method() -> Method {
    Settings::default().method
}
fn default_rtol() -> f64 {
    Settings::default().rtol
}
fn default_atol() -> f64 {
    Settings::default().atol
}
fn default_step() -> f64 {
    Settings::default().step
}
fn default_max_steps() -> u32 {
    Settings::default().max_steps
}

impl Default for SolverSpec {
    fn default() -> Self {
        Self {
            method: default_method(),
            rtol: default_rtol(),
            atol: default_atol(),
            step: default_step(),
            max_steps: default_max_steps(),
            project: None,
        }
    }
}

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
    /// The friction law (sliding model).
    pub friction: Option<Friction>,
    /// The contact point's velocity relative to rolling at the start (sliding model).
    pub slip: Slip,
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

    /// Reads a scene from a file path, or a built-in scene by name.
    pub fn load(name_or_path: &str) -> Result<Scene, SceneError> {
        if let Some(src) = builtin::source(name_or_path) {
            if !Path::new(name_or_path).exists() {
                return Scene::parse(src, &format!("builtin:{name_or_path}"));
            }
        }
        let path = Path::new(name_or_path);
        let src = input::read_text(path, input::MAX_SCENE_BYTES).map_err(|e| {
            let (line, hint) = match &e {
                input::InputError::NotText { line, .. } => (Some(*line), ""),
                input::InputError::Open { .. } => (
                    None,
                    "; give a path to a YAML file or the name of a built-in scene \
                     (`rolling-disk scenes` lists them)",
                ),
                _ => (None, ""),
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

struct Validator<'s> {
    src: &'s str,
    file: &'s str,
}

impl Validator<'_> {
    fn err(&self, path: &[&str], message: impl Into<String>) -> SceneError {
        SceneError {
            file: self.file.to_string(),
            line: locate::line_of(self.src, path),
            column: None,
            message: message::compact_numbers(&message.into()),
        }
    }

    /// Values beyond the supported physical ranges ([`range`]) and budgets ([`budget`]).
    fn limits(&self, s: &SceneSpec, disk: &Disk, start: &Motion) -> Result<(), SceneError> {
        let d = &s.disk;
        for (r, x) in [
            (range::RADIUS, d.radius),
            (range::INERTIA_FACTOR, d.k),
            (range::MASS, d.mass),
            (range::GRAVITY, d.g),
        ] {
            if let Some(m) = r.refuse(x) {
                return Err(self.err(r.key, m));
            }
        }
        for (key, w) in [
            ("alpha_dot", start.alpha_dot),
            ("precession", start.precession),
            ("spin", start.spin),
        ] {
            if let Some(m) = range::refuse_rate(key, w, disk.a, disk.g) {
                return Err(self.err(&["start"], m));
            }
        }
        let time = s.stop.time.unwrap_or(0.0);
        if let Some(dt) = s.sample {
            let rows = (time / dt).floor() + 2.0;
            if rows > budget::MAX_ROWS as f64 {
                return Err(self.err(
                    &["sample"],
                    format!(
                        "sample: {dt:e} s over stop.time = {time} s records {rows:.3e} rows, more \
                         than the limit of {}: raise sample to {:.3e} s or more",
                        budget::MAX_ROWS,
                        time / (budget::MAX_ROWS as f64 - 2.0)
                    ),
                ));
            }
        }
        let sv = &s.solver;
        if sv.method == Method::Rk4 && sv.step.is_finite() && sv.step > 0.0 {
            let needed = (time / sv.step).ceil();
            if needed > f64::from(sv.max_steps) {
                return Err(self.err(
                    &["solver", "step"],
                    format!(
                        "solver: rk4 with step {:e} s over stop.time = {time} s needs {needed:.3e} \
                         steps, more than max_steps = {}: raise step to {:.3e} s or more, or use \
                         method: dop853",
                        sv.step,
                        sv.max_steps,
                        time / f64::from(sv.max_steps)
                    ),
                ));
            }
        }
        Ok(())
    }

    fn scene(&self, s: SceneSpec) -> Result<Scene, SceneError> {
        let disk = Disk::new(s.disk.radius, s.disk.k, s.disk.mass, s.disk.g).map_err(|e| {
            let key = match e {
                DiskError::Radius(_) => "radius",
                DiskError::InertiaFactor(_) => "k",
                DiskError::Mass(_) => "mass",
                DiskError::Gravity(_) => "g",
            };
            self.err(&["disk", key], format!("disk: {e}"))
        })?;
        let dissipation = self.dissipation(&s)?;
        let (friction, slip) = self.friction(&s)?;
        let start = self.start(&s.start, &disk, s.model)?;
        let stop = self.stop(&s.stop, &start, s.model)?;
        let record = self.record(&s.record, s.model)?;
        if let Some(dt) = s.sample {
            if !(dt.is_finite() && dt > 0.0) {
                return Err(self.err(
                    &["sample"],
                    format!("sample must be a positive interval in seconds, got {dt}"),
                ));
            }
        }
        let settings = Settings {
            method: s.solver.method,
            rtol: s.solver.rtol,
            atol: s.solver.atol,
            step: s.solver.step,
            max_steps: s.solver.max_steps,
        };
        settings.validate().map_err(|e| {
            let key = match e {
                crate::solve::SettingsError::Atol(_) => "atol",
                crate::solve::SettingsError::Step(_) => "step",
                crate::solve::SettingsError::MaxSteps { .. } => "max_steps",
                _ => "rtol",
            };
            self.err(&["solver", key], format!("solver: {e}"))
        })?;
        self.limits(&s, &disk, &start)?;
        let projection = self.projection(&s)?;
        Ok(Scene {
            name: s.name,
            description: s.description,
            source: self.file.to_string(),
            disk,
            model: s.model,
            dissipation,
            friction,
            slip,
            start,
            stop,
            record,
            sample: s.sample,
            settings,
            projection,
        })
    }

    /// `solver: { project: energy }`: only where the energy is conserved and the step loop
    /// can project (DOP853, the crate's own engine).
    fn projection(&self, s: &SceneSpec) -> Result<Option<Projection>, SceneError> {
        let Some(p) = s.solver.project else {
            return Ok(None);
        };
        let conservative = matches!(
            s.model,
            ModelKind::Rolling
                | ModelKind::Frictionless
                | ModelKind::LabFrame
                | ModelKind::LabFrameFrictionless
        );
        if !conservative {
            return Err(self.err(
                &["solver", "project"],
                format!(
                    "solver: project: {p} needs a model that conserves the energy (rolling, frictionless, lab-frame or lab-frame-frictionless), and the {} model does not: remove `project`",
                    s.model
                ),
            ));
        }
        if s.solver.method != Method::Dop853 {
            return Err(self.err(
                &["solver", "project"],
                format!(
                    "solver: project: {p} needs method: dop853 (the projection is applied in its step loop), got {}: set method: dop853 or remove `project`",
                    s.solver.method
                ),
            ));
        }
        Ok(Some(p))
    }

    fn dissipation(&self, s: &SceneSpec) -> Result<Option<PowerLaw>, SceneError> {
        let needs = matches!(s.model, ModelKind::Dissipative | ModelKind::Adiabatic);
        match (needs, s.dissipation) {
            (true, None) => Err(self.err(
                &["model"],
                format!(
                    "the {} model needs a dissipation law: add `dissipation: {{ epsilon: 1.0e-6, beta: 2 }}` (eq 75)",
                    s.model
                ),
            )),
            (false, Some(_)) => Err(self.err(
                &["dissipation"],
                format!(
                    "the {} model does not dissipate: remove `dissipation`, or use model: dissipative",
                    s.model
                ),
            )),
            (true, Some(d)) => {
                if !(d.epsilon.is_finite() && d.epsilon > 0.0) {
                    return Err(self.err(
                        &["dissipation", "epsilon"],
                        format!("dissipation: epsilon must be positive, got {}", d.epsilon),
                    ));
                }
                if !(d.beta.is_finite() && d.beta > -2.0) {
                    return Err(self.err(
                        &["dissipation", "beta"],
                        format!(
                            "dissipation: beta must be a number above -2 (eq 79 has no finite-time \
                             end otherwise), got {}",
                            d.beta
                        ),
                    ));
                }
                Ok(Some(d))
            }
            (false, None) => Ok(None),
        }
    }

    fn start(&self, s: &StartSpec, disk: &Disk, model: ModelKind) -> Result<Motion, SceneError> {
        let forms = [
            s.steady.is_some(),
            s.vertical_spin.is_some(),
            s.rolling_straight.is_some(),
            s.explicit.is_some(),
        ];
        if forms.iter().filter(|&&f| f).count() != 1 {
            return Err(self.err(
                &["start"],
                "start needs exactly one of steady: { alpha0, b }, vertical_spin: { precession }, \
                 rolling_straight: { spin } or explicit: { alpha, alpha_dot, precession, spin } \
                 (plus an optional perturb)",
            ));
        }
        let mut m = if let Some(st) = &s.steady {
            steady_motion(disk, st.alpha0, st.b).map_err(|e| {
                let key = match e {
                    SteadyError::Angle(_) => "alpha0",
                    SteadyError::Radius { .. } => "b",
                };
                self.err(&["start", "steady", key], e.to_string())
            })?
        } else if let Some(v) = &s.vertical_spin {
            vertical_spin(v.precession)
        } else if let Some(r) = &s.rolling_straight {
            rolling_straight(r.spin)
        } else {
            let e = s
                .explicit
                .as_ref()
                .map_or_else(MotionSpec::default, |e| MotionSpec {
                    alpha: e.alpha,
                    alpha_dot: e.alpha_dot,
                    precession: e.precession,
                    spin: e.spin,
                });
            Motion {
                alpha: e.alpha,
                alpha_dot: e.alpha_dot,
                precession: e.precession,
                spin: e.spin,
            }
        };
        if let Some(p) = &s.perturb {
            m.alpha += p.alpha;
            m.alpha_dot += p.alpha_dot;
            m.precession += p.precession;
            m.spin += p.spin;
        }
        let values = [m.alpha, m.alpha_dot, m.precession, m.spin];
        if !values.iter().all(|v| v.is_finite()) {
            return Err(self.err(&["start"], "start: every value must be a finite number"));
        }
        if !(m.alpha > 0.0 && m.alpha < PI) {
            return Err(self.err(
                &["start"],
                format!(
                    "start: alpha = {} rad puts the disk flat on the table or through it; the \
                     paper's alpha lies strictly between 0 and pi",
                    m.alpha
                ),
            ));
        }
        if model == ModelKind::Adiabatic && m.alpha >= PI / 2.0 {
            return Err(self.err(
                &["start"],
                "start: eq 76 is a small-angle law; start it with alpha well below pi/2",
            ));
        }
        Ok(m)
    }

    fn stop(&self, s: &StopSpec, start: &Motion, model: ModelKind) -> Result<Stop, SceneError> {
        let Some(time) = s.time else {
            return Err(self.err(
                &["stop"],
                "stop needs a time bound so that every run ends: add `time: <seconds>` to stop",
            ));
        };
        if !(time.is_finite() && time > 0.0) {
            return Err(self.err(
                &["stop", "time"],
                format!("stop: time must be a positive number of seconds, got {time}"),
            ));
        }
        if let Some(b) = s.alpha_below {
            if !(b.is_finite() && b > 0.0) {
                return Err(self.err(
                    &["stop", "alpha_below"],
                    format!("stop: alpha_below must be a positive angle in radians, got {b}"),
                ));
            }
            if start.alpha <= b {
                return Err(self.err(
                    &["stop", "alpha_below"],
                    format!(
                        "stop: alpha_below = {b} already holds at the start (alpha = {}): lower it",
                        start.alpha
                    ),
                ));
            }
        }
        if s.lift_off && model == ModelKind::Adiabatic {
            return Err(self.err(
                &["stop", "lift_off"],
                "stop: the adiabatic law has no contact force, so lift_off cannot be detected: \
                 use alpha_below",
            ));
        }
        Ok(Stop {
            time,
            alpha_below: s.alpha_below,
            lift_off: s.lift_off,
        })
    }

    fn record(&self, r: &[Quantity], model: ModelKind) -> Result<Vec<Quantity>, SceneError> {
        let mut out: Vec<Quantity> = Vec::new();
        let list = if r.is_empty() {
            &[Quantity::Alpha, Quantity::Precession, Quantity::Spin][..]
        } else {
            r
        };
        for &q in list {
            if out.contains(&q) {
                return Err(self.err(&["record"], format!("record: {} is listed twice", q.name())));
            }
            let adiabatic_ok = matches!(
                q,
                Quantity::Alpha | Quantity::AlphaDot | Quantity::Precession | Quantity::Energy
            );
            if model == ModelKind::Adiabatic && !adiabatic_ok {
                return Err(self.err(
                    &["record"],
                    format!(
                        "record: the adiabatic law (eq 76) has only alpha as a state; it can record \
                         alpha, alpha_dot, precession and energy, not {}",
                        q.name()
                    ),
                ));
            }
            self.contact_quantity(q, model)?;
            out.push(q);
        }
        Ok(out)
    }
}
