//! Validation of a scene file: every value checked for physical meaning, errors located.

use super::spec::*;
use super::*;

pub(super) struct Validator<'s> {
    pub(super) src: &'s str,
    pub(super) file: &'s str,
}

impl Validator<'_> {
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

    pub(super) fn dissipation(&self, s: &SceneSpec) -> Result<Option<PowerLaw>, SceneError> {
        // The sliding model takes eq 75's law as a drag torque (a spin-down with friction).
        let allowed = matches!(
            s.model,
            ModelKind::Dissipative | ModelKind::Adiabatic | ModelKind::Sliding
        );
        // Mechanisms alone make a dissipative model too; the adiabatic model is eq 76, the law.
        let required = s.model == ModelKind::Adiabatic
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

    pub(super) fn start(
        &self,
        s: &StartSpec,
        disk: &Disk,
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

    pub(super) fn record(
        &self,
        r: &[Quantity],
        model: ModelKind,
    ) -> Result<Vec<Quantity>, SceneError> {
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
