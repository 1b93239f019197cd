//! Validation of a scene file: every value checked for physical meaning, errors located.

use super::spec::{MotionSpec, SceneSpec, StartSpec, StopSpec};
use super::{
    budget, locate, message, range, rolling_straight, steady_motion, vertical_spin, Disk,
    DiskError, Method, ModelKind, Motion, PowerLaw, Projection, Quantity, Scene, SceneError,
    Settings, SteadyError, Stop, PI,
};
use crate::model::sliding::Solid;
use crate::model::steady_solid::{RollingSolid, SolidSteadyError};

/// The fewest steps an adaptive method takes per turn of the disk's fastest rate (DOP853
/// with the default settings takes about 32 on a vertical spin at 1.5e7 rad/s).
const STEPS_PER_TURN_LEAST: f64 = 4.0;

/// The steps per turn a suggested stop time allows.
const STEPS_PER_TURN_SUGGESTED: f64 = 64.0;

/// The largest exponent of eq 75's law a scene may give: well above the paper's mechanisms
/// (beta from 0 to 4); a steeper law ends the spin-down within the first steps.
const BETA_MOST: f64 = 10.0;

pub(super) struct Validator<'s> {
    pub(super) src: &'s str,
    pub(super) file: &'s str,
}

impl Validator<'_> {
    /// The refusal of `key` in a scene whose model has no `what`, naming the model that has.
    pub(super) fn absent_from_model(
        &self,
        s: &super::SceneSpec,
        key: &str,
        what: &str,
        has_it: super::ModelKind,
    ) -> SceneError {
        self.err(
            &[key],
            format!(
                "the {} model has no {what}: remove `{key}`, or use model: {has_it}",
                s.model
            ),
        )
    }

    pub(super) fn err(&self, path: &[&str], message: impl Into<String>) -> SceneError {
        SceneError {
            file: self.file.to_string(),
            line: locate::line_of(self.src, path),
            column: None,
            message: message::compact_numbers(&message.into()),
        }
    }

    /// Values beyond the supported physical ranges ([`range`]) and budgets ([`budget`]).
    pub(super) fn limits(
        &self,
        s: &SceneSpec,
        disk: &Disk,
        start: &Motion,
    ) -> Result<(), SceneError> {
        let d = &s.disk;
        for (r, x) in [
            (range::RADIUS, d.radius),
            (range::INERTIA_FACTOR, disk.k),
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
        if let Some(slip) = s.start.slip {
            for (key, v) in [("forward", slip.forward), ("sideways", slip.sideways)] {
                if let Some(m) = range::refuse_slip(key, v, disk.a, disk.g) {
                    return Err(self.err(&["start", "slip", key], m));
                }
            }
        }
        let time = s.stop.time.unwrap_or(0.0);
        if let Some(dt) = s.sample {
            let rows = (time / dt).floor() + 2.0;
            let limit = budget::streamed_rows();
            if rows > limit as f64 {
                return Err(self.err(
                    &["sample"],
                    format!(
                        "sample: {dt:e} s over stop.time = {time} s records {rows:.3e} rows, more \
                         than the limit of {limit} that the wall-time budget of {} s allows (at \
                         most {} rows a second): raise sample to {:.3e} s or more, or the budget \
                         with --max-seconds",
                        budget::wall_seconds(),
                        budget::ROWS_PER_SECOND,
                        budget::round_up_3(time / (limit as f64 - 2.0))
                    ),
                ));
            }
        }
        let sv = &s.solver;
        if sv.method != Method::Rk4 && !s.model.is_spin_down_law() {
            let rows = s.sample.is_none().then_some(budget::MAX_ROWS);
            self.turns(start, time, u64::from(sv.max_steps), rows)?;
        }
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
                        budget::round_up_3(time / f64::from(sv.max_steps))
                    ),
                ));
            }
        }
        Ok(())
    }

    /// The steps a run needs at the least, from its fastest rate $w$ = max($|\Omega|$,
    /// $|\omega_1|$): an adaptive step resolves each turn with [`STEPS_PER_TURN_LEAST`] steps
    /// or more, so $w\,t/(2\pi)$ turns that need more steps than `max_steps` (or, unsampled,
    /// more rows than `rows`) are refused before integrating. The stop time it suggests allows
    /// [`STEPS_PER_TURN_SUGGESTED`] a turn, twice what DOP853 takes with the default settings.
    fn turns(
        &self,
        start: &Motion,
        time: f64,
        max_steps: u64,
        rows: Option<u64>,
    ) -> Result<(), SceneError> {
        let rate = start.precession.abs().max(start.spin.abs());
        let per_s = rate / std::f64::consts::TAU;
        let least = per_s * time * STEPS_PER_TURN_LEAST;
        let (limit, what) = match rows {
            Some(r) if r < max_steps => (r, "rows (an unsampled run records every step)"),
            _ => (max_steps, "steps (solver.max_steps)"),
        };
        if least <= limit as f64 {
            return Ok(());
        }
        Err(self.err(
            &["start"],
            format!(
                "start: a rate of {rate:.3e} rad/s over stop.time = {time} s is {:.3e} turns, which \
                 need at least {least:.3e} steps ({STEPS_PER_TURN_LEAST} a turn), more than the \
                 limit of {limit} {what}: lower stop.time to {:.3e} s or less, or start slower",
                per_s * time,
                limit as f64 / (per_s * STEPS_PER_TURN_SUGGESTED)
            ),
        ))
    }

    pub(super) fn scene(&self, s: SceneSpec) -> Result<Scene, SceneError> {
        let (k, solid) = self.solid(&s)?;
        let disk = Disk::new(s.disk.radius, k, s.disk.mass, s.disk.g).map_err(|e| {
            let key = match e {
                DiskError::Radius(_) => "radius",
                DiskError::InertiaFactor(_) => "k",
                DiskError::Mass(_) => "mass",
                DiskError::Gravity(_) => "g",
            };
            self.err(&["disk", key], format!("disk: {e}"))
        })?;
        let dissipation = self.dissipation(&s)?;
        let mechanisms = self.mechanisms(&s)?;
        let (friction, slip) = self.friction(&s)?;
        let toy = self.toy(&s, solid)?;
        let start = self.start(&s.start, &disk, solid, s.model)?;
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
            mechanisms,
            friction,
            slip,
            toy,
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
    pub(super) fn projection(&self, s: &SceneSpec) -> Result<Option<Projection>, SceneError> {
        let Some(p) = s.solver.project else {
            return Ok(None);
        };
        let conservative = s.model.conserves_energy();
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

    pub(super) fn dissipation(&self, s: &SceneSpec) -> Result<Option<PowerLaw>, SceneError> {
        // The sliding model takes eq 75's law as a drag torque (a spin-down with friction).
        let allowed = s.model.takes_dissipation_law();
        // Mechanisms alone make a dissipative model too; the adiabatic model is eq 76, the law.
        let required = s.model.is_spin_down_law()
            || (s.model == ModelKind::Dissipative && s.mechanisms.is_empty());
        let Some(d) = s.dissipation else {
            if required {
                let or = if s.model == ModelKind::Dissipative {
                    ", or a list of `mechanisms`"
                } else {
                    ""
                };
                return Err(self.err(
                    &["model"],
                    format!(
                        "the {} model needs a dissipation law: add `dissipation: {{ epsilon: 1.0e-6, beta: 2 }}` (eq 75){or}",
                        s.model
                    ),
                ));
            }
            return Ok(None);
        };
        if !allowed {
            return Err(self.err(
                &["dissipation"],
                format!(
                    "the {} model does not dissipate: remove `dissipation`, or use model: \
                     dissipative (or sliding)",
                    s.model
                ),
            ));
        }
        if !(d.epsilon.is_finite() && d.epsilon > 0.0) {
            return Err(self.err(
                &["dissipation", "epsilon"],
                format!("dissipation: epsilon must be positive, got {}", d.epsilon),
            ));
        }
        if !(d.beta.is_finite() && d.beta > -2.0 && d.beta <= BETA_MOST) {
            return Err(self.err(
                &["dissipation", "beta"],
                format!(
                    "dissipation: beta must be a number above -2 (eq 79 has no finite-time \
                     end otherwise) and at most {BETA_MOST} (the paper's mechanisms have beta \
                     from 0 to 4, sec. 11), got {}",
                    d.beta
                ),
            ));
        }
        Ok(Some(d))
    }

    pub(super) fn start(
        &self,
        s: &StartSpec,
        disk: &Disk,
        solid: Option<Solid>,
        model: ModelKind,
    ) -> Result<Motion, SceneError> {
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
        let mut m = if let (Some(st), Some(_)) = (&s.steady, solid) {
            RollingSolid::of(disk, solid)
                .steady(st.alpha0, st.b)
                .map_err(|e| {
                    let key = match e {
                        SolidSteadyError::Radius { .. } => "b",
                        _ => "alpha0",
                    };
                    self.err(&["start", "steady", key], e.to_string())
                })?
        } else if let Some(st) = &s.steady {
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
        if let (Some(balance), true) = (
            RollingSolid::of(disk, solid).balance_tilt(),
            m.alpha == PI / 2.0,
        ) {
            let lean = PI / 2.0 - balance;
            return Err(self.err(
                &["start"],
                format!(
                    "start: a disk with a thickness upright (alpha = pi/2) stands on a line of its \
                     rim, which the point-contact model does not run, and tilted less than its \
                     balance ({lean:.3} rad from upright) gravity tips it back there: tilt it further, \
                     e.g. add perturb: {{ alpha: {:.2} }}",
                    -(2.0 * lean).max(0.01)
                ),
            ));
        }
        if model.is_spin_down_law() && m.alpha >= PI / 2.0 {
            return Err(self.err(
                &["start"],
                "start: eq 76 is a small-angle law; start it with alpha well below pi/2",
            ));
        }
        Ok(m)
    }

    pub(super) fn stop(
        &self,
        s: &StopSpec,
        start: &Motion,
        model: ModelKind,
    ) -> Result<Stop, SceneError> {
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
        if s.lift_off && model.is_spin_down_law() {
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

    pub(super) fn record(
        &self,
        r: &[Quantity],
        model: ModelKind,
    ) -> Result<Vec<Quantity>, SceneError> {
        let mut out: Vec<Quantity> = Vec::new();
        // The default records what every model has: the adiabatic law has no spin.
        let list = if r.is_empty() && model.is_spin_down_law() {
            &[Quantity::Alpha, Quantity::Precession][..]
        } else if r.is_empty() {
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
            if model.is_spin_down_law() && !adiabatic_ok {
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
