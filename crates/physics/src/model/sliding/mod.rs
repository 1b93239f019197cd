//! The disk with Coulomb friction and a unilateral contact: the lab-frame Newton-Euler model of
//! [`crate::model::lab_frame`] in which the contact point may stick, slip or leave the table.
//!
//! **State** (14): the lab-frame model's 13 (quaternion, body angular velocity, centre of mass
//! and its velocity) and the energy $W$ the contact has taken out so far (friction work while
//! slipping plus impact losses), so that $E(t) + W(t) = E(0)$ is a check of the integration.
//!
//! **Equations.** As in the lab-frame model, the contact force $\mathbf F$ at the lowest rim
//! point $\boldsymbol\rho$ enters $m\dot{\mathbf v} = \mathbf F - mg\hat{\mathbf z}$ and
//! Euler's equations, and the contact point's velocity $\mathbf v_c = \mathbf v +
//! \boldsymbol\omega\times\boldsymbol\rho$ obeys $\dot{\mathbf v}_c = A\mathbf F - \mathbf b$
//! ([`crate::model::lab_frame::ContactProblem`]). The friction law picks $\mathbf F$ in each
//! [`Mode`]:
//! - **stick** (rolling): $\dot{\mathbf v}_c = 0$, $\mathbf F = A^{-1}\mathbf b$, valid while
//!   $|\mathbf F_t| \le \mu F_z$ and $F_z \ge 0$ (Coulomb's static law);
//! - **slip**: $\mathbf F = F_z(\hat{\mathbf z} - \mu\hat{\mathbf s})$ with
//!   $\hat{\mathbf s} = \mathbf v_{c,t}/|\mathbf v_{c,t}|$ (the friction opposes the slip) and
//!   $F_z$ from $\ddot h = 0$: $F_z = b_z / \hat{\mathbf z}\cdot A(\hat{\mathbf z} - \mu\hat{\mathbf s})$.
//!   The friction does work $\dot W = -\mathbf F_t\cdot\mathbf v_{c,t} = \mu F_z|\mathbf v_{c,t}|$.
//!   For the disk the denominator is $\frac1m\left[1 + \frac{\cos^2\alpha}{k} - \frac{\mu}{k}\sin\alpha\cos\alpha\,(\hat{\mathbf r}\cdot\hat{\mathbf s})\right]$,
//!   which vanishes for $\mu > (k + \cos^2\alpha)/(\sin\alpha\cos\alpha)$ (at least 1.12 for
//!   $k = 1/4$) with the slip along $+\hat{\mathbf r}$: Painlevé's paradox, where Coulomb's law
//!   has no solution; the run then halts with that reason;
//! - **flight**: $\mathbf F = 0$, the disk a free rigid body, until the rim's lowest point
//!   reaches the table again.
//!
//! **Switching** by located events ([`crate::events`]), never by smoothing the law:
//! slip -> stick when $\mathbf v_{c,t}$ passes through zero (if then $|A^{-1}\mathbf b|_t \le \mu F_z$;
//! otherwise the slip restarts in the consistent direction, see `law.rs`); stick -> slip when
//! $|\mathbf F_t|$ reaches $\mu F_z$; contact -> flight when $F_z$ reaches 0; flight -> contact
//! at the landing, an impact (`impact.rs`).
//!
//! **The slip direction at small speeds.** Coulomb's direction law $\hat{\mathbf s} =
//! \mathbf v_{c,t}/|\mathbf v_{c,t}|$ is singular where a slip starts or ends: a deviation of
//! the slip velocity across its direction relaxes at the rate $\mu F_z A_t/|\mathbf v_{c,t}|$,
//! which diverges, so an explicit integrator stalls (`ode_solvers` declares the problem stiff)
//! on every slip that starts from rest at the edge of the cone. The model therefore holds the
//! direction fixed, at the consistent direction the slip started in (`law.rs`) or the one it
//! had, while the slip is slower than $v_h = 10^{-6}\sqrt{ga}$ (0.6 µm/s for the toy disk), and
//! lets it follow $\mathbf v_{c,t}$ above $2v_h$ (located events with hysteresis). Within that
//! band the friction direction is off by at most the angle the slip turns while slower than
//! 1.2 µm/s; its work is still booked exactly ($\dot W = -\mathbf F_t\cdot\mathbf v_{c,t}$).
//! Nothing else is regularized: stick and slip are exact Coulomb phases.
//!
//! **Drift control** as in the lab-frame model, $\lambda = \sqrt{g/a}$ on the translation: the
//! whole $\mathbf v_c$ and $h$ while sticking, the vertical part while slipping, none in flight.

pub mod contact_events;
mod flow;
mod impact;
mod law;
mod stall;
mod switching;
#[cfg(test)]
mod tests;
mod toy;

pub use flow::Flow;
pub use switching::{guard, SlidingRun};
pub use toy::{Resistance, Solid, Toy};

use crate::disk::Disk;
use crate::model::dissipation::PowerLaw;
use crate::model::lab_frame::{Contact, ContactProblem, LabFrame, Snapshot};
use crate::model::{Extras, Layout, Motion};
use crate::solve::State;
use nalgebra::Vector3;
use serde::{Deserialize, Serialize};

/// Where the dissipated energy sits in the state.
pub const DISSIPATED: usize = 13;

/// The friction law and the impact law at the contact.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Friction {
    /// Coulomb's coefficient $\mu \ge 0$ (the same for sticking and slipping).
    pub mu: f64,
    /// Newton's coefficient of restitution $e\in[0, 1]$ for the normal velocity at a landing.
    #[serde(default)]
    pub restitution: f64,
}

/// The contact point's velocity relative to rolling at the start (m/s).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Slip {
    /// Along $\hat{\mathbf 2}$, the direction a disk with positive spin rolls.
    #[serde(default)]
    pub forward: f64,
    /// Along $\hat{\mathbf r}$ (horizontal, in the disk's plane's normal plane, away from the
    /// side the disk leans to).
    #[serde(default)]
    pub sideways: f64,
}

/// What the contact does in a phase of the motion.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Mode {
    /// The contact point at rest: rolling.
    Stick,
    /// The contact point sliding.
    Slip {
        /// Unit horizontal vector (lab): the slip direction when the phase began.
        anchor: [f64; 3],
        /// True while the slip is slower than [`Sliding::hold_speed`] and the friction keeps
        /// the direction `anchor`; false when it opposes the slip velocity itself.
        held: bool,
    },
    /// No contact.
    Flight,
}

impl Mode {
    /// A short name: stick, slip or flight.
    pub fn name(&self) -> &'static str {
        match self {
            Mode::Stick => "stick",
            Mode::Slip { .. } => "slip",
            Mode::Flight => "flight",
        }
    }
}

/// The disk with friction and unilateral contact (see the module documentation).
#[derive(Debug, Clone)]
pub struct Sliding {
    /// The disk.
    pub disk: Disk,
    /// The contact laws.
    pub friction: Friction,
    /// Drift control rate $\lambda$ (1/s).
    pub stabilisation: f64,
    /// The slip added to the start.
    pub slip: Slip,
    /// End the run where the contact is lost instead of flying on (a scene's `lift_off`).
    pub stop_at_lift_off: bool,
    /// An optional drag: eq 75's power as a torque about the centre (see [`Sliding::drag_torque`]).
    pub drag: Option<PowerLaw>,
    /// The most switches a run may take before it halts (default 10,000).
    pub max_switches: usize,
    /// Finite thickness, a kinetic coefficient, resistance (`toy.rs`); thin and plain by default.
    pub toy: Toy,
    layout: Layout,
}

impl Sliding {
    /// The model with drift control $\lambda = \sqrt{g/a}$ and no start slip.
    pub fn new(disk: Disk, friction: Friction) -> Self {
        Self {
            disk,
            friction,
            stabilisation: disk.g_over_a().sqrt(),
            slip: Slip::default(),
            stop_at_lift_off: false,
            drag: None,
            max_switches: 10_000,
            toy: Toy::default(),
            layout: Layout::new(14, Extras::default()),
        }
    }

    /// The same model starting with slip `slip`.
    pub fn with_slip(mut self, slip: Slip) -> Self {
        self.slip = slip;
        self
    }

    /// The same model losing energy by eq 75's power law as well.
    pub fn with_drag(mut self, drag: PowerLaw) -> Self {
        self.drag = Some(drag);
        self
    }

    /// The drag torque about the centre (lab, N m): as in the dissipative rolling model
    /// ([`crate::model::dissipation`]), $\mathbf N = -\frac{\epsilon m a g|\Omega|^\beta}{|\boldsymbol\omega|^2}\boldsymbol\omega$,
    /// whose power is eq 75's $P = -\epsilon m a g|\Omega|^\beta$ ($\Omega$ the precession
    /// rate read from the geometry). Zero without a drag or without rotation. Its work is booked
    /// in $W$ with the friction's.
    pub fn drag_torque(&self, s: &Snapshot) -> Vector3<f64> {
        let Some(law) = self.drag else {
            return Vector3::zeros();
        };
        let w2 = s.omega.norm_squared();
        if w2 == 0.0 {
            return Vector3::zeros();
        }
        let power = law.power(&self.disk, s.motion().precession);
        s.omega * (power / w2)
    }

    /// The contact condition at `s`, with the drag torque's angular acceleration
    /// $I^{-1}\mathbf N$ added to the free one (so that sticking, slipping and the guards all see it).
    pub(crate) fn contact_problem(&self, s: &Snapshot) -> ContactProblem {
        self.contact_problem_with(s, &self.resistance_arm(s))
    }

    /// The contact condition at `s` with the resistance arm `arm` ([`Sliding::held_arm`]).
    pub(crate) fn contact_problem_with(&self, s: &Snapshot, arm: &Vector3<f64>) -> ContactProblem {
        let mut cp = ContactProblem::of(&self.disk, s);
        if let Some(full) = self.full_contact_matrix(s, arm) {
            let i = self.inertia();
            let spin = s.omega.dot(&s.e1);
            let w_dot_free = -(i.x - i.y) / i.y * spin * s.omega.cross(&s.e1);
            cp.b =
                self.disk.g * Vector3::z() - w_dot_free.cross(&s.rho) - s.omega.cross(&s.rho_dot);
            cp.full = Some(full);
        }
        if self.drag.is_some() {
            let n = self.drag_torque(s);
            let (i1, i2) = (self.inertia().x, self.inertia().y);
            let w_dot = n / i2 + s.e1 * (n.dot(&s.e1) * (1.0 / i1 - 1.0 / i2));
            cp.b -= w_dot.cross(&s.rho);
        }
        cp
    }

    /// $v_0 = 10^{-10}\sqrt{ga}$: the offset of the guard that ends a held slip, and the
    /// residual speed a located stop leaves (m/s).
    pub fn slip_floor(&self) -> f64 {
        1e-10 * (self.disk.g * self.disk.a).sqrt()
    }

    /// $v_h = 10^{-6}\sqrt{ga}$: below it the slip direction is held (module documentation).
    pub fn hold_speed(&self) -> f64 {
        1e-6 * (self.disk.g * self.disk.a).sqrt()
    }

    /// The lab state for the paper's variables `m` rolling (heading 0, centre above the
    /// origin, face 0), plus the start slip: $\mathbf v \mathrel{+}= s_f\hat{\mathbf 2} + s_s\hat{\mathbf r}$.
    pub fn start_state(&self, m: &Motion) -> State<14> {
        let lab = LabFrame::new(self.disk, Contact::Rolling);
        let y13 = lab.state_from(m, 0.0, [0.0, 0.0], 0.0);
        let mut y = extend(&y13);
        if self.toy.solid.is_some() {
            // The thin start's attitude and rotation, the solid's contact at the origin at rest.
            let s = self.snapshot(&y);
            let v = -s.omega.cross(&s.rho);
            y[9] = -s.rho.z;
            for i in 0..3 {
                y[10 + i] = v[i];
            }
        }
        let s = self.snapshot(&y);
        let dv = self.slip.forward * s.e2 + self.slip.sideways * s.r;
        for i in 0..3 {
            y[10 + i] += dv[i];
        }
        y
    }

    /// Total energy $\frac12 m|\mathbf v|^2 + \frac12\boldsymbol\omega_b\cdot I\boldsymbol\omega_b + mgz$ (J).
    pub fn energy(&self, y: &State<14>) -> f64 {
        self.energy_at(&self.snapshot(y))
    }

    /// The layout (14 core states, no extras: heading, path and face are read geometrically).
    pub fn layout(&self) -> &Layout {
        &self.layout
    }
}

/// A 13-state lab-frame state with $W = 0$ appended.
pub fn extend(y13: &State<13>) -> State<14> {
    let mut y = State::<14>::zeros();
    y.fixed_rows_mut::<13>(0).copy_from(y13);
    y
}

impl Sliding {
    /// The total energy at the geometry `s` (J).
    pub(crate) fn energy_at(&self, s: &Snapshot) -> f64 {
        let d = &self.disk;
        let i = self.inertia();
        let w = s.omega_body;
        0.5 * d.m * s.velocity.norm_squared()
            + 0.5 * w.dot(&i.component_mul(&w))
            + d.m * d.g * s.centre.z
    }
}

pub(crate) fn horizontal(v: &Vector3<f64>) -> Vector3<f64> {
    Vector3::new(v.x, v.y, 0.0)
}
