//! An independent reference: the disk as a rigid body in lab coordinates, by Newton-Euler, with
//! the contact force solved from the contact condition at every evaluation. Nothing here uses the
//! paper's equations of motion (23-25, 60-62); it is their referee.
//!
//! **State** (13): the attitude quaternion $q = (w, i, j, k)$ (body to lab), the angular velocity
//! $\boldsymbol\omega_b$ in BODY axes ($\mathbf e_x$ = symmetry axis, so Euler's equations have a
//! constant diagonal inertia and $\omega_1 = \omega_{b,x}$ is a state), the centre of mass
//! $\mathbf x$ and its velocity $\mathbf v$ in the lab ($\hat{\mathbf z}$ up).
//!
//! **Equations.** With $I = \mathrm{diag}(2kma^2, kma^2, kma^2)$, the contact force $\mathbf F$ at
//! $\boldsymbol\rho = a\hat{\mathbf 3}$ (centre to the lowest rim point) and $R = R(q/|q|)$:
//! $$ m\dot{\mathbf v} = \mathbf F - mg\hat{\mathbf z} + m\mathbf c, \qquad
//!    I\dot{\boldsymbol\omega}_b + \boldsymbol\omega_b\times I\boldsymbol\omega_b = R^T(\boldsymbol\rho\times\mathbf F), $$
//! $$ \dot q = \tfrac12\, q\otimes(0, \boldsymbol\omega_b) - \lambda\,(|q|^2 - 1)\,q, \qquad \dot{\mathbf x} = \mathbf v, $$
//! where $\mathbf c$ and the $\lambda$ term are the drift control below (both zero on the constraint).
//!
//! **Contact force.** The material point at the contact moves at
//! $\mathbf v_c = \mathbf v + \boldsymbol\omega\times\boldsymbol\rho$. Since $\boldsymbol\rho$ is the
//! LOWEST rim point (its slide round the rim is horizontal), the contact height
//! $h = z_{cm} + \hat{\mathbf z}\cdot\boldsymbol\rho$ has $\dot h = \hat{\mathbf z}\cdot\mathbf v_c$.
//! Differentiating with the geometric rate $\dot{\boldsymbol\rho}$ of the contact point (see
//! [`Snapshot::of`]), $\dot{\boldsymbol\omega} = J(\boldsymbol\rho\times\mathbf F) + \dot{\boldsymbol\omega}_0$,
//! $J = RI^{-1}R^T$, $\dot{\boldsymbol\omega}_0 = -RI^{-1}(\boldsymbol\omega_b\times I\boldsymbol\omega_b)$:
//! $$ \dot{\mathbf v}_c = A\mathbf F - \mathbf b,\quad A = \tfrac1m\mathbb 1 - [\boldsymbol\rho]_\times J[\boldsymbol\rho]_\times,\quad
//!    \mathbf b = g\hat{\mathbf z} - \dot{\boldsymbol\omega}_0\times\boldsymbol\rho - \boldsymbol\omega\times\dot{\boldsymbol\rho}. $$
//! [`Contact::Rolling`]: $\dot{\mathbf v}_c = 0$, $\mathbf F = A^{-1}\mathbf b$.
//! [`Contact::Frictionless`]: $\mathbf F = F_z\hat{\mathbf z}$, $\ddot h = 0$, $F_z = b_z/A_{zz}$.
//! $A$ is diagonal in the triad (see `contact.rs`), so the solve costs three divisions.
//!
//! **Drift control.** $\mathbf F$ depends on the attitude and $\boldsymbol\omega$ only, so the
//! rotation is a closed system and the translation follows it. The constraint errors are
//! therefore corrected on the translation, $\mathbf c = -2\lambda\mathbf v_c - \lambda^2 h\hat{\mathbf z}$
//! (frictionless: its vertical part), which makes them decay critically damped at rate $\lambda$
//! and, unlike a Baumgarte term inside $\mathbf F$, never feeds the translation's integration
//! error back into the rotation. The quaternion term is radial: it changes $|q|$, never $q/|q|$,
//! from which $R$ is built, so it cannot touch the attitude dynamics. $\lambda = \sqrt{g/a}$
//! (16 s⁻¹ here), the problem's own rate: larger rates stiffen the problem (λ = 50 doubles the
//! steps, 3000 exhausts two million).
//!
//! Measured over 10 s, DOP853 at rtol 1e-12, atol 1e-14, toy disk (a = 37.5 mm, k = 1/4), rolling
//! perturbed steady motion ($\alpha_0 = 0.3$, b = 0.01 m, $\alpha$ + 1e-3) and a frictionless tilted
//! disk with spin (tests `drift_is_controlled`, `energy_*` in `tests/lab_frame.rs`):
//!
//! | scheme (rolling case)            | $\max\big||q|-1\big|$ | $\max|h|$ (m) | $\max|\mathbf v_c|$ (m/s) | energy drift | $\omega_1$ vs eqs 23-25 |
//! |----------------------------------|---------|---------|---------|---------|---------|
//! | none ($\lambda = 0$)             | 2.2e-14 | 2.3e-11 | 4.5e-12 | 9.4e-10 | 5.7e-12 |
//! | Baumgarte inside $\mathbf F$     | 4.4e-16 | 1.8e-15 | 3.8e-14 | 8.6e-13 | 7.0e-11 |
//! | on the translation (this model)  | 5.6e-16 | 2.7e-16 | 8.4e-15 | 1.7e-14 | 1.3e-12 |
//!
//! Frictionless case with this model: $\big||q|-1\big|$ 5.1e-15, $|h|$ 1.3e-13 m, $|\dot h|$
//! 1.2e-12 m/s (unstabilised 1.5e-12, 9.6e-10 m, 1.9e-10 m/s).

mod contact;
mod geometry;

pub(crate) use contact::ContactProblem;
pub(crate) use geometry::inertia;
#[cfg(test)]
mod tests;

pub use geometry::Snapshot;

use crate::disk::Disk;
use crate::model::{Extras, Layout, Model, Motion, Quantity, RowShared};
use crate::solve::{Dynamics, State};
use geometry::{Q, V, W, X};
use nalgebra::{Quaternion, Vector3};

/// What the table does at the contact point.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Contact {
    /// No slipping: the material point in contact is at rest (a 3-component force).
    Rolling,
    /// No friction: a vertical force only, keeping the lowest rim point on the table.
    Frictionless,
}

/// The disk in lab coordinates (see the module documentation).
#[derive(Debug, Clone)]
pub struct LabFrame {
    /// The disk.
    pub disk: Disk,
    /// The contact condition.
    pub contact: Contact,
    /// The stabilisation rate $\lambda$ (1/s) of the quaternion norm and the contact constraint;
    /// 0 switches it off.
    pub stabilisation: f64,
    layout: Layout,
}

impl LabFrame {
    /// The lab-frame model with the default stabilisation $\lambda = \sqrt{g/a}$.
    pub fn new(disk: Disk, contact: Contact) -> Self {
        Self {
            disk,
            contact,
            stabilisation: disk.g_over_a().sqrt(),
            layout: Layout::new(13, Extras::default()),
        }
    }

    /// The same model with stabilisation rate `rate` (1/s; 0 for none).
    pub fn with_stabilisation(mut self, rate: f64) -> Self {
        self.stabilisation = rate;
        self
    }

    /// The contact force $\mathbf F$ on the disk in state `y`, lab components (N).
    pub fn contact_force(&self, y: &State<13>) -> Vector3<f64> {
        self.force(&self.snapshot(y))
    }

    /// Total energy computed in the lab: $\frac12 m|\mathbf v|^2 + \frac12\boldsymbol\omega_b\cdot I\boldsymbol\omega_b + mg z_{cm}$ (J).
    pub fn energy(&self, y: &State<13>) -> f64 {
        self.energy_at(&self.snapshot(y))
    }

    /// [`LabFrame::energy`] of the geometry `s`.
    fn energy_at(&self, s: &Snapshot) -> f64 {
        let i = inertia(&self.disk);
        let w = s.omega_body;
        0.5 * self.disk.m * s.velocity.norm_squared()
            + 0.5 * w.dot(&i.component_mul(&w))
            + self.disk.m * self.disk.g * s.centre.z
    }

    /// Vertical angular momentum about the centre of mass, $\hat{\mathbf z}\cdot R\,I\boldsymbol\omega_b$ (kg m²/s).
    pub fn lz(&self, y: &State<13>) -> f64 {
        self.lz_at(&self.snapshot(y))
    }

    /// [`LabFrame::lz`] of the geometry `s`.
    fn lz_at(&self, s: &Snapshot) -> f64 {
        (s.rotation * inertia(&self.disk).component_mul(&s.omega_body)).z
    }
}

impl Dynamics<13> for LabFrame {
    fn rhs(&self, y: &State<13>, dy: &mut State<13>) {
        let s = self.snapshot(y);
        let d = &self.disk;
        let f = self.force(&s);
        let i = inertia(d);
        let torque_body = s.rotation.inverse_transform_vector(&s.rho.cross(&f));
        let w = s.omega_body;
        let w_dot = (torque_body - w.cross(&i.component_mul(&w))).component_div(&i);
        let q = Quaternion::new(y[Q], y[Q + 1], y[Q + 2], y[Q + 3]);
        let q_dot = q * Quaternion::from_imag(0.5 * w)
            - q * (self.stabilisation * (q.norm_squared() - 1.0));
        let acc = f / d.m - d.g * Vector3::z() + self.drift_correction(&s);
        dy[Q] = q_dot.w;
        dy[Q + 1] = q_dot.i;
        dy[Q + 2] = q_dot.j;
        dy[Q + 3] = q_dot.k;
        dy.fixed_rows_mut::<3>(W).copy_from(&w_dot);
        dy.fixed_rows_mut::<3>(X).copy_from(&s.velocity);
        dy.fixed_rows_mut::<3>(V).copy_from(&acc);
    }
}

impl Model<13> for LabFrame {
    /// Thirteen core states; heading, path and face are read from the geometry, not stored.
    fn layout(&self) -> &Layout {
        &self.layout
    }

    fn motion(&self, y: &State<13>) -> Motion {
        self.snapshot(y).motion()
    }

    fn energy(&self, y: &State<13>) -> f64 {
        LabFrame::energy(self, y)
    }

    fn record(&self, y: &State<13>, q: Quantity, out: &mut Vec<f64>) -> bool {
        let s = self.snapshot(y);
        match q {
            Quantity::Energy => out.push(LabFrame::energy(self, y)),
            Quantity::Lz => out.push(self.lz(y)),
            Quantity::NormalForce => out.push(self.force(&s).z),
            Quantity::Friction => {
                let f = self.force(&s);
                out.extend_from_slice(&[f.dot(&s.r), f.dot(&s.e2)]);
            }
            Quantity::Dissipated => out.push(0.0),
            geometric => return s.record_geometry(geometric, out),
        }
        true
    }

    /// The lab state for `m` with heading 0, the centre above the origin and face angle 0.
    fn state(&self, m: &Motion) -> State<13> {
        self.state_from(m, 0.0, [0.0, 0.0], 0.0)
    }

    /// The row with the geometry made once and the contact force solved at most once.
    fn record_row(
        &self,
        y: &State<13>,
        quantities: &[Quantity],
        normal_force: bool,
        out: &mut Vec<f64>,
    ) -> RowShared {
        let s = self.snapshot(y);
        let energy = self.energy_at(&s);
        let mut force = None;
        let mut contact = || *force.get_or_insert_with(|| self.force(&s));
        let normal = normal_force.then(|| contact().z);
        let mut motion = None;
        for &q in quantities {
            match q {
                Quantity::Energy => out.push(energy),
                Quantity::Lz => out.push(self.lz_at(&s)),
                Quantity::NormalForce => out.push(contact().z),
                Quantity::Friction => {
                    let f = contact();
                    out.extend_from_slice(&[f.dot(&s.r), f.dot(&s.e2)]);
                }
                Quantity::Dissipated => out.push(0.0),
                geometric => {
                    let ok = s.record_geometry_with(geometric, &mut motion, out);
                    debug_assert!(ok, "validated scenes only record what their model provides");
                }
            }
        }
        RowShared {
            energy,
            normal_force: normal,
        }
    }
}
