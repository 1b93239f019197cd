//! The sliding model as a hybrid system: the guards of each mode and the jumps between them
//! (module documentation of [`super`]), run by [`crate::events::run_hybrid`].
//!
//! | mode        | guard (the flow ends where it reaches 0)                  | jump |
//! |-------------|-----------------------------------------------------------|------|
//! | stick       | $\mu F_z - |\mathbf F_t|$                                 | held slip in the consistent direction (`law.rs`) |
//! | stick       | $F_z$                                                     | flight |
//! | slip (free) | $|\mathbf v_{c,t}| - v_h$                                  | held slip along $\mathbf v_{c,t}$ |
//! | slip (held) | $\mathbf v_{c,t}\cdot\hat{\mathbf s}_0 + v_0$             | stopped: stick if the cone allows, else held slip from rest |
//! | slip (held) | $2v_h - |\mathbf v_{c,t}|$                                 | free slip |
//! | slip        | $F_z$                                                     | flight |
//! | slip        | $m\,\hat{\mathbf z}\cdot A(\hat{\mathbf z} - \mu\hat{\mathbf s})$ | halt: Painlevé's paradox |
//! | flight      | $h + 10^{-12}a$                                           | impact (`impact.rs`), then contact or flight |
//!
//! A held slip ends where its velocity passes through zero along the held direction
//! $\hat{\mathbf s}_0$ (offset by $v_0 = 10^{-10}\sqrt{ga}$ so that a slip starting from rest
//! starts with the guard positive).

use super::{horizontal, Mode, Sliding, DISSIPATED};
use crate::events::{run_hybrid, Hybrid, HybridProblem, HybridSolution, Jump, PointSink};
use crate::solve::{Event, Settings, SettingsError, State};
use nalgebra::Vector3;

/// A run of the sliding model.
pub type SlidingRun = HybridSolution<Mode, 14>;

impl SlidingRun {
    /// The time the run spent slipping (s): the steps that start in a slip mode.
    pub fn slip_time(&self) -> f64 {
        self.t
            .windows(2)
            .zip(&self.mode)
            .filter(|(_, m)| m.name() == "slip")
            .map(|(t, _)| t[1] - t[0])
            .sum()
    }
}

/// The names of the guards, as they appear in the switch log.
pub mod guard {
    /// Stick ends: the friction needed reaches the cone.
    pub const FRICTION_LIMIT: &str = "the friction needed reaches mu F_z";
    /// Contact ends.
    pub const CONTACT_LOST: &str = "the normal force reaches 0";
    /// A held slip stops.
    pub const SLIP_ENDS: &str = "the slip velocity passes through 0";
    /// A free slip slows to the hold speed.
    pub const HOLD: &str = "the slip slows below the hold speed";
    /// A held slip speeds up past twice the hold speed.
    pub const RELEASE: &str = "the slip speeds up past twice the hold speed";
    /// Coulomb's law has no solution.
    pub const PAINLEVE: &str = "Coulomb's law has no solution (Painleve)";
    /// Flight ends.
    pub const LANDING: &str = "the rim reaches the table";
}

impl Sliding {
    fn landing_margin(&self) -> f64 {
        1e-12 * self.disk.a
    }

    /// The mode and state the contact enters at `y`: slip along the contact point's velocity
    /// when it moves faster than $2v_h$, otherwise what Coulomb's law allows from rest (the
    /// contact point's residual velocity, below $2v_h$, projected to zero by [`Sliding::settle`],
    /// its energy booked in $W$).
    ///
    /// A slip slower than $2v_h$ is not continued along its own velocity: in the hold band the
    /// friction keeps its held direction, so the slip velocity may have turned far from the
    /// direction it would relax to under Coulomb's law (within microseconds, at the rate
    /// $\mu F_zA/|\mathbf v_{c,t}|$). Slipping on along that velocity re-entered the band with
    /// the same mismatch every few nanoseconds (10,000 switches within 0.2 s from the steady
    /// roll $\alpha_0 = 0.4$, $b = 0.02$ m with $\mu = 0.3$); restarting from rest takes the
    /// consistent direction instead (`law.rs`), or sticks where the cone allows.
    pub fn enter_contact(&self, y: &State<14>) -> (Mode, State<14>) {
        let s = self.snapshot(y);
        let vt = horizontal(&s.contact_velocity);
        let n = vt.norm();
        if n > 2.0 * self.hold_speed() {
            let dir = vt / n;
            let cp = self.contact_problem(&s);
            let f = self.slip_force(&cp, &s, &dir);
            let mode = if f.consistency <= 0.0 || f.force.z > 0.0 {
                Mode::Slip {
                    anchor: [dir.x, dir.y, 0.0],
                    held: false,
                }
            } else {
                Mode::Flight
            };
            return (mode, *y);
        }
        self.start_from_rest(y)
    }

    /// [`Sliding::mode_from_rest`] at `y`, projecting the contact point's residual velocity
    /// (at most $10v_0$) to zero when it sticks or slips from rest.
    fn start_from_rest(&self, y: &State<14>) -> (Mode, State<14>) {
        match self.mode_from_rest(&self.snapshot(y)) {
            Mode::Flight => (Mode::Flight, *y),
            m => (m, self.settle(y)),
        }
    }

    /// The landing at `y`: lift the state back onto the table (the landing is located at a
    /// penetration of $10^{-12}a$; the potential energy this adds is booked in $W$), apply the
    /// impact, then fly on after a bounce or enter the contact.
    pub(crate) fn land(&self, y: &State<14>) -> Jump<Mode, 14> {
        let d = &self.disk;
        let mut y = *y;
        let h = self.snapshot(&y).height;
        y[9] -= h;
        y[DISSIPATED] += d.m * d.g * h;
        let s = self.snapshot(&y);
        let vc = s.contact_velocity;
        // A rebound slower than the bounce floor is not flown: the landing is plastic.
        let e = if -vc.z * self.friction.restitution > self.bounce_floor() {
            self.friction.restitution
        } else {
            0.0
        };
        let p = self.impact_impulse(&s, &vc, e);
        let (after, lost) = self.apply_impulse(&y, &p);
        let scale = 0.5 * d.m * s.velocity.norm_squared() + d.m * d.g * d.a;
        if lost < -1e-12 * scale {
            return Jump::Halt(format!(
                "the impact law gained {:.3e} J at a landing (frozen slip direction reversed \
                 during the impact): lower mu or the restitution",
                -lost
            ));
        }
        let vz = self.snapshot(&after).contact_velocity.z;
        if vz > self.bounce_floor() {
            return Jump::To {
                mode: Mode::Flight,
                y: after,
                what: format!("impact, bounce at {vz:.3e} m/s, {lost:.3e} J lost"),
            };
        }
        let (mode, y) = self.enter_contact(&after);
        Jump::To {
            mode,
            y,
            what: format!("impact, {lost:.3e} J lost, then {}", mode.name()),
        }
    }

    /// Runs the model from `y0` (a contact state: the start mode is [`Sliding::enter_contact`]'s)
    /// to `t_end`, with the given stop events and sampling.
    pub fn run<'a>(
        &'a self,
        y0: &State<14>,
        t_end: f64,
        settings: &Settings,
        sample: Option<f64>,
        stops: &'a dyn Fn() -> Vec<Event<'a, 14>>,
    ) -> Result<SlidingRun, SettingsError> {
        self.run_into(y0, t_end, settings, sample, stops, None, true)
    }

    /// [`Sliding::run`] handing every point to `on_point` as it is made instead of holding it
    /// (the run then holds its first point and its last, see [`HybridProblem::on_point`]),
    /// its samples from the dense output when `dense` ([`HybridProblem::dense_samples`]).
    #[allow(clippy::too_many_arguments)]
    pub fn run_into<'a>(
        &'a self,
        y0: &State<14>,
        t_end: f64,
        settings: &Settings,
        sample: Option<f64>,
        stops: &'a dyn Fn() -> Vec<Event<'a, 14>>,
        on_point: Option<PointSink<'a, Mode, 14>>,
        dense: bool,
    ) -> Result<SlidingRun, SettingsError> {
        let (mode, y) = self.enter_contact(y0);
        let mut p = HybridProblem::new(self, mode, 0.0, y, t_end);
        p.sample = sample;
        p.stops = stops;
        p.max_switches = self.max_switches;
        p.dense_samples = dense;
        p.on_point = on_point;
        run_hybrid(p, settings)
    }
}

impl Hybrid<14> for Sliding {
    type Mode = Mode;
    type Flow<'a> = super::Flow<'a>;

    fn flow(&self, mode: &Mode) -> super::Flow<'_> {
        super::Flow {
            model: self,
            mode: *mode,
        }
    }

    fn guards<'a>(&'a self, mode: &Mode) -> Vec<Event<'a, 14>> {
        let mu = self.friction.mu;
        match *mode {
            Mode::Stick => vec![
                Event::new(guard::FRICTION_LIMIT, move |y: &State<14>| {
                    let f = self.contact_force(&Mode::Stick, &self.snapshot(y)).force;
                    mu * f.z - horizontal(&f).norm()
                }),
                Event::new(guard::CONTACT_LOST, move |y: &State<14>| {
                    self.contact_force(&Mode::Stick, &self.snapshot(y)).force.z
                }),
            ],
            Mode::Slip { anchor, held } => {
                let mode = Mode::Slip { anchor, held };
                let mut g = vec![
                    if held {
                        let floor = self.slip_floor();
                        let s0 = Vector3::from(anchor);
                        Event::new(guard::SLIP_ENDS, move |y: &State<14>| {
                            horizontal(&self.snapshot(y).contact_velocity).dot(&s0) + floor
                        })
                    } else {
                        let vh = self.hold_speed();
                        Event::new(guard::HOLD, move |y: &State<14>| {
                            horizontal(&self.snapshot(y).contact_velocity).norm() - vh
                        })
                    },
                    Event::new(guard::CONTACT_LOST, move |y: &State<14>| {
                        self.contact_force(&mode, &self.snapshot(y)).force.z
                    }),
                    Event::new(guard::PAINLEVE, move |y: &State<14>| {
                        self.contact_force(&mode, &self.snapshot(y)).consistency
                    }),
                ];
                if held {
                    let vh2 = 2.0 * self.hold_speed();
                    g.push(Event::new(guard::RELEASE, move |y: &State<14>| {
                        vh2 - horizontal(&self.snapshot(y).contact_velocity).norm()
                    }));
                }
                g
            }
            Mode::Flight => {
                let margin = self.landing_margin();
                vec![Event::new(guard::LANDING, move |y: &State<14>| {
                    self.snapshot(y).height + margin
                })]
            }
        }
    }

    fn jump(&self, mode: &Mode, guard: usize, y: &State<14>) -> Jump<Mode, 14> {
        let s = self.snapshot(y);
        match (*mode, guard) {
            (Mode::Stick, 0) => {
                let cp = self.contact_problem(&s);
                let stick = cp.solve(&s, &cp.b);
                let dir = self.onset_direction(&cp, &s, &stick);
                Jump::To {
                    mode: Mode::Slip {
                        anchor: [dir.x, dir.y, 0.0],
                        held: true,
                    },
                    y: *y,
                    what: "stick -> slip".into(),
                }
            }
            (Mode::Stick, _) | (Mode::Slip { .. }, 1) => {
                if self.stop_at_lift_off {
                    return Jump::Stop;
                }
                Jump::To {
                    mode: Mode::Flight,
                    y: *y,
                    what: "lift-off".into(),
                }
            }
            (Mode::Slip { held: true, .. }, 0) => {
                // Stopped, or only turned away from the held direction.
                let (mode, y) = self.enter_contact(y);
                Jump::To {
                    mode,
                    y,
                    what: format!("slip -> {}", mode.name()),
                }
            }
            (Mode::Slip { held, .. }, 0 | 3) => {
                let vt = horizontal(&s.contact_velocity);
                let dir = vt / vt.norm();
                Jump::To {
                    mode: Mode::Slip {
                        anchor: [dir.x, dir.y, 0.0],
                        held: !held,
                    },
                    y: *y,
                    what: if held {
                        "slip direction released"
                    } else {
                        "slip direction held"
                    }
                    .into(),
                }
            }
            (Mode::Slip { .. }, _) => Jump::Halt(format!(
                "Coulomb's law with mu = {} has no solution in this slip (Painleve's paradox, \
                 possible for mu above (k + cos^2 alpha)/(sin alpha cos alpha)): lower mu",
                self.friction.mu
            )),
            (Mode::Flight, _) => self.land(y),
        }
    }
}
