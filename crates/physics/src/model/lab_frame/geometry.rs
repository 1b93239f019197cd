//! What a lab state says about the disk's geometry: attitude, the triad of the lowest rim point,
//! the contact point and its rates, and the two-way conversion to the paper's variables.
//!
//! Body axes: $\mathbf e_x$ is the symmetry axis, $\mathbf e_y, \mathbf e_z$ lie in the disk's
//! plane; the rotation $R(q)$ maps body to lab. The symmetry axis in the lab is
//! $\hat{\mathbf n} = R\,\mathbf e_x$ and the paper's $\hat{\mathbf 1}$ is $\hat{\mathbf n}$ itself
//! (its sense is set once, by the start state, and carried continuously by the motion).

use super::LabFrame;
use crate::disk::Disk;
use crate::model::{Motion, Quantity};
use crate::solve::State;
use nalgebra::{Matrix3, Quaternion, Rotation3, UnitQuaternion, Vector3};

/// Where the parts of the 13 lab states sit: quaternion $(w, i, j, k)$, body angular velocity,
/// centre of mass, its velocity.
pub(super) const Q: usize = 0;
pub(super) const W: usize = 4;
pub(super) const X: usize = 7;
pub(super) const V: usize = 10;

/// The disk's configuration and velocities read from a lab state, all vectors in the lab.
#[derive(Debug, Clone, Copy)]
pub struct Snapshot {
    /// Body to lab, from the normalised quaternion $q/|q|$.
    pub rotation: Rotation3<f64>,
    /// Angular velocity in body axes $\boldsymbol\omega_b$.
    pub omega_body: Vector3<f64>,
    /// Angular velocity in the lab, $\boldsymbol\omega = R\boldsymbol\omega_b$.
    pub omega: Vector3<f64>,
    /// Centre of mass.
    pub centre: Vector3<f64>,
    /// Velocity of the centre of mass.
    pub velocity: Vector3<f64>,
    /// $\hat{\mathbf 1} = \hat{\mathbf n} = R\,\mathbf e_x$, the symmetry axis.
    pub e1: Vector3<f64>,
    /// $\hat{\mathbf 2} = \hat{\mathbf z}\times\hat{\mathbf r}$, horizontal, in the disk's plane.
    pub e2: Vector3<f64>,
    /// $\hat{\mathbf 3}$: from the centre to the lowest point of the rim.
    pub e3: Vector3<f64>,
    /// $\hat{\mathbf r} = -\hat{\mathbf n}_h/|\hat{\mathbf n}_h|$, horizontal.
    pub r: Vector3<f64>,
    /// $\sin\alpha = |\hat{\mathbf n}_h|$.
    pub sin_alpha: f64,
    /// $\cos\alpha = -\hat{\mathbf n}\cdot\hat{\mathbf z}$.
    pub cos_alpha: f64,
    /// $\boldsymbol\rho = a\hat{\mathbf 3}$, centre to the lowest rim point.
    pub rho: Vector3<f64>,
    /// $\dot{\boldsymbol\rho}$: the rate of the lowest rim point as a GEOMETRIC point (it runs
    /// round the rim), not $\boldsymbol\omega\times\boldsymbol\rho$.
    pub rho_dot: Vector3<f64>,
    /// Velocity of the material point now at the contact: $\mathbf v + \boldsymbol\omega\times\boldsymbol\rho$.
    pub contact_velocity: Vector3<f64>,
    /// Height of the lowest rim point above the table, $h = z_{cm} + \boldsymbol\rho\cdot\hat{\mathbf z}$.
    pub height: f64,
}

fn vec3<const N: usize>(y: &State<N>, i: usize) -> Vector3<f64> {
    Vector3::new(y[i], y[i + 1], y[i + 2])
}

impl Snapshot {
    /// Reads state `y` of a disk of radius `a`. Singular only with the disk flat ($\sin\alpha = 0$).
    ///
    /// The lowest rim point is along the downward vertical projected on the disk's plane:
    /// $\mathbf u = -\hat{\mathbf z} + (\hat{\mathbf z}\cdot\hat{\mathbf n})\hat{\mathbf n}$,
    /// $|\mathbf u| = \sin\alpha$, $\hat{\mathbf 3} = \mathbf u/|\mathbf u|$. Its rate follows from
    /// $\dot{\hat{\mathbf n}} = \boldsymbol\omega\times\hat{\mathbf n}$ alone:
    /// $\dot{\mathbf u} = (\hat{\mathbf z}\cdot\dot{\hat{\mathbf n}})\hat{\mathbf n} + (\hat{\mathbf z}\cdot\hat{\mathbf n})\dot{\hat{\mathbf n}}$,
    /// $\dot{\hat{\mathbf 3}} = \left(\dot{\mathbf u} - \hat{\mathbf 3}(\hat{\mathbf 3}\cdot\dot{\mathbf u})\right)/|\mathbf u|$.
    /// Only the first 13 states are read, so a model that carries more (the sliding model's
    /// dissipated work) reads its geometry here too.
    pub fn of<const N: usize>(a: f64, y: &State<N>) -> Self {
        let q = Quaternion::new(y[Q], y[Q + 1], y[Q + 2], y[Q + 3]);
        let rotation = UnitQuaternion::new_normalize(q).to_rotation_matrix();
        let omega_body = vec3(y, W);
        let omega = rotation * omega_body;
        let (centre, velocity) = (vec3(y, X), vec3(y, V));
        let z = Vector3::z();
        let e1 = rotation * Vector3::x();
        let horizontal = Vector3::new(e1.x, e1.y, 0.0);
        let sin_alpha = horizontal.norm();
        let cos_alpha = -e1.z;
        let r = -horizontal / sin_alpha;
        let e3 = cos_alpha * r - sin_alpha * z;
        let e2 = z.cross(&r);
        let rho = a * e3;
        let e1_dot = omega.cross(&e1);
        let u_dot = e1_dot.z * e1 + e1.z * e1_dot;
        let rho_dot = a * (u_dot - e3 * e3.dot(&u_dot)) / sin_alpha;
        Self {
            rotation,
            omega_body,
            omega,
            centre,
            velocity,
            e1,
            e2,
            e3,
            r,
            sin_alpha,
            cos_alpha,
            rho,
            rho_dot,
            contact_velocity: velocity + omega.cross(&rho),
            height: centre.z + rho.z,
        }
    }

    /// The paper's $\alpha\in[0,\pi]$, the angle of $\hat{\mathbf 1}$ to $-\hat{\mathbf z}$.
    pub fn alpha(&self) -> f64 {
        self.sin_alpha.atan2(self.cos_alpha)
    }

    /// The paper's variables, read geometrically. The triad turns with the symmetry axis, so
    /// $\dot{\hat{\mathbf 1}} = \boldsymbol\omega\times\hat{\mathbf 1} = -\Omega\sin\alpha\,\hat{\mathbf 2} - \dot\alpha\,\hat{\mathbf 3}$
    /// defines $\Omega$ (the rate of the triad about the vertical) and $\dot\alpha$;
    /// $\omega_1 = \boldsymbol\omega\cdot\hat{\mathbf 1}$.
    pub fn motion(&self) -> Motion {
        let e1_dot = self.omega.cross(&self.e1);
        Motion {
            alpha: self.alpha(),
            alpha_dot: -e1_dot.dot(&self.e3),
            precession: -e1_dot.dot(&self.e2) / self.sin_alpha,
            spin: self.omega.dot(&self.e1),
        }
    }

    /// The heading $\psi$ of $\hat{\mathbf 2} = (\cos\psi, \sin\psi, 0)$, in $(-\pi, \pi]$.
    pub fn heading(&self) -> f64 {
        self.e2.y.atan2(self.e2.x)
    }

    /// The face angle $\phi$: the body axis $\mathbf e_y$ is
    /// $\cos\phi\,\hat{\mathbf 2} + \sin\phi\,\hat{\mathbf 3}$; in $(-\pi, \pi]$.
    pub fn face(&self) -> f64 {
        let ey = self.rotation * Vector3::y();
        ey.dot(&self.e3).atan2(ey.dot(&self.e2))
    }

    /// Records quantity `q` read from the geometry alone (the paper's variables, heading, path,
    /// face, speeds, the contact's height and path); false for what needs the model (energy,
    /// $L_z$, forces, energy dissipated), which the model records itself.
    pub fn record_geometry(&self, q: Quantity, out: &mut Vec<f64>) -> bool {
        self.record_geometry_with(q, &mut None, out)
    }

    /// [`Snapshot::record_geometry`] with the paper's variables read into `motion` when a
    /// quantity needs them and they are not there yet, so that a row reads them once.
    pub fn record_geometry_with(
        &self,
        q: Quantity,
        motion: &mut Option<Motion>,
        out: &mut Vec<f64>,
    ) -> bool {
        let mut m = || *motion.get_or_insert_with(|| self.motion());
        match q {
            Quantity::Alpha => out.push(m().alpha),
            Quantity::AlphaDot => out.push(m().alpha_dot),
            Quantity::Precession => out.push(m().precession),
            Quantity::Spin => out.push(m().spin),
            Quantity::Heading => out.push(self.heading()),
            Quantity::Path => out.extend_from_slice(&[self.centre.x, self.centre.y]),
            Quantity::Face => out.push(self.face()),
            Quantity::SlipSpeed => out.push(self.contact_velocity.xy().norm()),
            Quantity::CmSpeed => out.push(self.velocity.norm()),
            Quantity::ContactGap => out.push(self.height),
            Quantity::ContactPath => {
                let c = self.centre + self.rho;
                out.extend_from_slice(&[c.x, c.y]);
            }
            Quantity::Energy
            | Quantity::Lz
            | Quantity::NormalForce
            | Quantity::Friction
            | Quantity::Dissipated => return false,
        }
        true
    }
}

impl LabFrame {
    /// The lab state for the paper's variables `m`, heading $\psi$ (the angle of
    /// $\hat{\mathbf 2}$ from the lab x axis), centre of mass $(x, y)$ on the table and face
    /// angle $\phi$:
    /// $\hat{\mathbf 2} = (\cos\psi, \sin\psi, 0)$, $\hat{\mathbf r} = (\sin\psi, -\cos\psi, 0)$,
    /// $\hat{\mathbf 1} = -\sin\alpha\,\hat{\mathbf r} - \cos\alpha\,\hat{\mathbf z}$,
    /// $\hat{\mathbf 3} = \cos\alpha\,\hat{\mathbf r} - \sin\alpha\,\hat{\mathbf z}$;
    /// $R = [\hat{\mathbf 1}\ \hat{\mathbf 2}\ \hat{\mathbf 3}]\,R_x(\phi)$;
    /// $\boldsymbol\omega = \omega_1\hat{\mathbf 1} + \dot\alpha\hat{\mathbf 2} - \Omega\sin\alpha\,\hat{\mathbf 3}$;
    /// the centre at height $a\sin\alpha$. Its velocity is what the contact allows:
    /// rolling, $\mathbf v = -\boldsymbol\omega\times a\hat{\mathbf 3}$ (the contact point at rest,
    /// eq 13); frictionless, $\mathbf v = a\dot\alpha\cos\alpha\,\hat{\mathbf z}$ (eq 59).
    pub fn state_from(&self, m: &Motion, heading: f64, centre: [f64; 2], face: f64) -> State<13> {
        let a = self.disk.a;
        let (s, c) = m.alpha.sin_cos();
        let (sp, cp) = heading.sin_cos();
        let z = Vector3::z();
        let e2 = Vector3::new(cp, sp, 0.0);
        let r = Vector3::new(sp, -cp, 0.0);
        let e1 = -s * r - c * z;
        let e3 = c * r - s * z;
        let triad = Rotation3::from_matrix_unchecked(Matrix3::from_columns(&[e1, e2, e3]));
        let rotation = triad * Rotation3::from_axis_angle(&Vector3::x_axis(), face);
        let q = UnitQuaternion::from_rotation_matrix(&rotation);
        let omega = m.spin * e1 + m.alpha_dot * e2 - m.precession * s * e3;
        let omega_body = rotation.inverse() * omega;
        let velocity = match self.contact {
            super::Contact::Rolling => -omega.cross(&(a * e3)),
            super::Contact::Frictionless => a * m.alpha_dot * c * z,
        };
        let mut y = State::<13>::zeros();
        let qc = q.quaternion().coords; // (i, j, k, w)
        y[Q] = qc.w;
        y[Q + 1] = qc.x;
        y[Q + 2] = qc.y;
        y[Q + 3] = qc.z;
        y.fixed_rows_mut::<3>(W).copy_from(&omega_body);
        y.fixed_rows_mut::<3>(X)
            .copy_from(&Vector3::new(centre[0], centre[1], a * s));
        y.fixed_rows_mut::<3>(V).copy_from(&velocity);
        y
    }

    /// The paper's variables, heading, centre of mass $(x, y)$ and face angle of a lab state:
    /// the inverse of [`LabFrame::state_from`] (angles in $(-\pi, \pi]$).
    pub fn to_paper(&self, y: &State<13>) -> (Motion, f64, [f64; 2], f64) {
        let s = self.snapshot(y);
        (s.motion(), s.heading(), [s.centre.x, s.centre.y], s.face())
    }

    /// The geometry of state `y`.
    pub fn snapshot(&self, y: &State<13>) -> Snapshot {
        Snapshot::of(self.disk.a, y)
    }
}

/// $\mathrm{diag}(I_{11}, I_{22}, I_{33})$ in body axes (eq 18's moments).
pub(crate) fn inertia(disk: &Disk) -> Vector3<f64> {
    Vector3::new(disk.i11(), disk.i22(), disk.i22())
}
