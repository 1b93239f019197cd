//! The smooth flow of one mode: Newton-Euler with the mode's contact force (module
//! documentation of [`super`]), and what a state of that mode records.

use super::{horizontal, Mode, Sliding, DISSIPATED};
use crate::model::lab_frame::Snapshot;
use crate::model::{Layout, Model, Motion, Quantity, RowShared};
use crate::solve::{Dynamics, State};
use nalgebra::{Quaternion, Vector3};

/// The sliding model in one mode.
#[derive(Debug, Clone, Copy)]
pub struct Flow<'a> {
    /// The model.
    pub model: &'a Sliding,
    /// The mode.
    pub mode: Mode,
}

impl Flow<'_> {
    /// The geometry of `y`.
    pub fn snapshot(&self, y: &State<14>) -> Snapshot {
        self.model.snapshot(y)
    }

    /// The contact force in this mode (lab, N).
    pub fn force(&self, y: &State<14>) -> Vector3<f64> {
        self.model
            .contact_force(&self.mode, &self.snapshot(y))
            .force
    }

    /// [`Model::record`] on the geometry `s` of `y`, the contact force solved into `force`
    /// and the paper's variables read into `motion` when a quantity needs them and they are
    /// not there yet.
    fn record_with(
        &self,
        s: &Snapshot,
        y: &State<14>,
        q: Quantity,
        (force, motion): (&mut Option<Vector3<f64>>, &mut Option<Motion>),
        out: &mut Vec<f64>,
    ) -> bool {
        let mut contact =
            || *force.get_or_insert_with(|| self.model.contact_force(&self.mode, s).force);
        match q {
            Quantity::Energy => out.push(self.model.energy_at(s)),
            Quantity::Lz => {
                let i = self.model.inertia();
                out.push((s.rotation * i.component_mul(&s.omega_body)).z);
            }
            Quantity::NormalForce => out.push(contact().z),
            Quantity::Friction => {
                let f = contact();
                out.extend_from_slice(&[f.dot(&s.r), f.dot(&s.e2)]);
            }
            Quantity::Dissipated => out.push(y[DISSIPATED]),
            geometric => return s.record_geometry_with(geometric, motion, out),
        }
        true
    }

    /// The drift control added to $\dot{\mathbf v}$ in this mode.
    fn drift_correction(&self, s: &Snapshot) -> Vector3<f64> {
        let lambda = self.model.stabilisation;
        let z = Vector3::z();
        let v = match self.mode {
            Mode::Stick => s.contact_velocity,
            Mode::Slip { .. } => s.contact_velocity.z * z,
            Mode::Flight => return Vector3::zeros(),
        };
        -2.0 * lambda * v - lambda * lambda * s.height * z
    }
}

impl Dynamics<14> for Flow<'_> {
    fn rhs(&self, y: &State<14>, dy: &mut State<14>) {
        let s = self.snapshot(y);
        let d = &self.model.disk;
        let cf = self.model.contact_force(&self.mode, &s);
        let f = cf.force;
        let drag = self.model.drag_torque(&s);
        let resist = f.z * cf.arm;
        let w_dot = self.model.body_angular_acceleration(&s, &f, &cf.arm);
        let q = Quaternion::new(y[0], y[1], y[2], y[3]);
        let q_dot = q * Quaternion::from_imag(0.5 * s.omega_body)
            - q * (self.model.stabilisation * (q.norm_squared() - 1.0));
        let acc = f / d.m - d.g * Vector3::z() + self.drift_correction(&s);
        dy[0] = q_dot.w;
        dy[1] = q_dot.i;
        dy[2] = q_dot.j;
        dy[3] = q_dot.k;
        dy.fixed_rows_mut::<3>(4).copy_from(&w_dot);
        dy.fixed_rows_mut::<3>(7).copy_from(&s.velocity);
        dy.fixed_rows_mut::<3>(10).copy_from(&acc);
        dy[DISSIPATED] = -(drag + resist).dot(&s.omega)
            + match self.mode {
                Mode::Slip { .. } => -horizontal(&f).dot(&horizontal(&s.contact_velocity)),
                _ => 0.0,
            };
    }
}

impl Model<14> for Flow<'_> {
    fn layout(&self) -> &Layout {
        self.model.layout()
    }

    fn motion(&self, y: &State<14>) -> Motion {
        self.snapshot(y).motion()
    }

    fn energy(&self, y: &State<14>) -> f64 {
        self.model.energy(y)
    }

    fn record(&self, y: &State<14>, q: Quantity, out: &mut Vec<f64>) -> bool {
        self.record_with(&self.snapshot(y), y, q, (&mut None, &mut None), out)
    }

    /// The model's start state (rolling plus its start slip).
    fn state(&self, m: &Motion) -> State<14> {
        self.model.start_state(m)
    }

    /// The row with the geometry made once, the contact force (one contact problem) solved
    /// at most once and the paper's variables read at most once.
    fn record_row(
        &self,
        y: &State<14>,
        quantities: &[Quantity],
        normal_force: bool,
        out: &mut Vec<f64>,
    ) -> RowShared {
        let s = self.snapshot(y);
        let energy = self.model.energy_at(&s);
        let mut force = None;
        let normal = normal_force.then(|| {
            force
                .get_or_insert_with(|| self.model.contact_force(&self.mode, &s).force)
                .z
        });
        let mut motion = None;
        for &q in quantities {
            if q == Quantity::Energy {
                out.push(energy);
            } else {
                self.record_with(&s, y, q, (&mut force, &mut motion), out);
            }
        }
        RowShared {
            energy,
            normal_force: normal,
        }
    }
}
