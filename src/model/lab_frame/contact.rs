//! The contact force from the contact condition (see the module documentation of
//! [`super`]): $A\mathbf F = \mathbf b + $ stabilisation, solved without allocating.

use super::geometry::{inertia, Snapshot};
use super::{Contact, LabFrame};
use nalgebra::{Matrix3, Vector3};

impl LabFrame {
    /// $\mathbf F$ in the lab for the geometry `s`. A NaN state gives a NaN force (the solver
    /// then reports it) rather than a panic.
    pub(super) fn force(&self, s: &Snapshot) -> Vector3<f64> {
        let d = &self.disk;
        let z = Vector3::z();
        let inv_i = inertia(d).map(|v| 1.0 / v);
        let r = s.rotation.matrix();
        let j = r * Matrix3::from_diagonal(&inv_i) * r.transpose();
        let rho_x = s.rho.cross_matrix();
        let a = Matrix3::identity() / d.m - rho_x * j * rho_x;
        let w = s.omega_body;
        let w_dot_free =
            s.rotation * (-w.cross(&inertia(d).component_mul(&w))).component_mul(&inv_i);
        let b = d.g * z - w_dot_free.cross(&s.rho) - s.omega.cross(&s.rho_dot);
        match self.contact {
            Contact::Rolling => a
                .cholesky()
                .map_or(Vector3::repeat(f64::NAN), |c| c.solve(&b)),
            Contact::Frictionless => Vector3::new(0.0, 0.0, b.z / a[(2, 2)]),
        }
    }

    /// The stabilisation added to $\dot{\mathbf v}$: $-2\lambda\mathbf v_c - \lambda^2 h\hat{\mathbf z}$
    /// when rolling, its vertical part $-(2\lambda\dot h + \lambda^2 h)\hat{\mathbf z}$ without
    /// friction. Zero on the constraint manifold.
    pub(super) fn drift_correction(&self, s: &Snapshot) -> Vector3<f64> {
        let lambda = self.stabilisation;
        let z = Vector3::z();
        let v = match self.contact {
            Contact::Rolling => s.contact_velocity,
            Contact::Frictionless => s.contact_velocity.z * z,
        };
        -2.0 * lambda * v - lambda * lambda * s.height * z
    }
}
