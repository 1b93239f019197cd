//! The contact force from the contact condition $A\mathbf F = \mathbf b$ (see [`super`]).
//!
//! $A$ is diagonal in the triad $(\hat{\mathbf 1}, \hat{\mathbf 2}, \hat{\mathbf 3})$: those are
//! principal axes of the disk ($I_{22} = I_{33}$) and $\boldsymbol\rho = a\hat{\mathbf 3}$, so
//! $-[\boldsymbol\rho]_\times J[\boldsymbol\rho]_\times\mathbf F =
//! a^2\left(F_1\hat{\mathbf 1}/I_{22} + F_2\hat{\mathbf 2}/I_{11}\right)$ (a push across the disk
//! turns it about a diameter, a push along the rim's tangent turns it about its axis, a push to
//! the centre does not turn it):
//! $$ A = \mathrm{diag}\left(\tfrac1m + \tfrac{a^2}{I_{22}},\ \tfrac1m + \tfrac{a^2}{I_{11}},\ \tfrac1m\right). $$
//! The free angular acceleration needs no matrix either: with
//! $I = I_{22}\mathbb 1 + (I_{11} - I_{22})\hat{\mathbf 1}\hat{\mathbf 1}^T$,
//! $\boldsymbol\omega\times I\boldsymbol\omega = (I_{11} - I_{22})\,\omega_1\,\boldsymbol\omega\times\hat{\mathbf 1}$,
//! which is perpendicular to $\hat{\mathbf 1}$, so
//! $\dot{\boldsymbol\omega}_0 = -\frac{I_{11} - I_{22}}{I_{22}}\,\omega_1\,\boldsymbol\omega\times\hat{\mathbf 1}$.

use super::geometry::Snapshot;
use super::{Contact, LabFrame};
use crate::disk::Disk;
use nalgebra::{Matrix3, Vector3};

/// The contact condition $\dot{\mathbf v}_c = A\mathbf F - \mathbf b$ at one instant: the free
/// acceleration term $\mathbf b$ (lab) and the diagonal of $A$ in the triad. Shared with the
/// sliding model ([`crate::model::sliding`]), which solves the same condition under other laws.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ContactProblem {
    /// $\mathbf b = g\hat{\mathbf z} - \dot{\boldsymbol\omega}_0\times\boldsymbol\rho - \boldsymbol\omega\times\dot{\boldsymbol\rho}$ (m/s²).
    pub b: Vector3<f64>,
    /// $A_{11} = 1/m + a^2/I_{22}$ (along $\hat{\mathbf 1}$).
    pub a1: f64,
    /// $A_{22} = 1/m + a^2/I_{11}$ (along $\hat{\mathbf 2}$).
    pub a22: f64,
    /// $A_{33} = 1/m$ (along $\hat{\mathbf 3}$).
    pub a3: f64,
    /// The whole matrix $A$ in the lab, when it is not diagonal in the triad (a thick disk or
    /// contact moments, [`crate::model::sliding`]); then it replaces the diagonal.
    pub full: Option<Matrix3<f64>>,
}

impl ContactProblem {
    /// The contact condition of disk `d` in the geometry `s`.
    pub(crate) fn of(d: &Disk, s: &Snapshot) -> Self {
        let (i1, i2) = (d.i11(), d.i22());
        let spin = s.omega.dot(&s.e1);
        let w_dot_free = -(i1 - i2) / i2 * spin * s.omega.cross(&s.e1);
        let b = d.g * Vector3::z() - w_dot_free.cross(&s.rho) - s.omega.cross(&s.rho_dot);
        let a2 = d.a * d.a;
        let inv_m = 1.0 / d.m;
        Self {
            b,
            a1: inv_m + a2 / i2,
            a22: inv_m + a2 / i1,
            a3: inv_m,
            full: None,
        }
    }

    /// $A\mathbf x$ for a lab vector $\mathbf x$, with the triad of `s`.
    pub(crate) fn apply(&self, s: &Snapshot, x: &Vector3<f64>) -> Vector3<f64> {
        if let Some(a) = self.full {
            return a * x;
        }
        s.e1 * (self.a1 * x.dot(&s.e1))
            + s.e2 * (self.a22 * x.dot(&s.e2))
            + s.e3 * (self.a3 * x.dot(&s.e3))
    }

    /// $A^{-1}\mathbf x$ for a lab vector $\mathbf x$, with the triad of `s`.
    pub(crate) fn solve(&self, s: &Snapshot, x: &Vector3<f64>) -> Vector3<f64> {
        if let Some(a) = self.full {
            return a.lu().solve(x).unwrap_or_else(Vector3::zeros);
        }
        s.e1 * (x.dot(&s.e1) / self.a1)
            + s.e2 * (x.dot(&s.e2) / self.a22)
            + s.e3 * (x.dot(&s.e3) / self.a3)
    }
}

impl LabFrame {
    /// $\mathbf F$ in the lab for the geometry `s`, from the exact contact condition (the
    /// stabilisation acts on the translation only, see [`LabFrame::drift_correction`]).
    pub(super) fn force(&self, s: &Snapshot) -> Vector3<f64> {
        let ContactProblem { b, a1, a22, a3, .. } = ContactProblem::of(&self.disk, s);
        match self.contact {
            Contact::Rolling => {
                s.e1 * (b.dot(&s.e1) / a1)
                    + s.e2 * (b.dot(&s.e2) / a22)
                    + s.e3 * (b.dot(&s.e3) / a3)
            }
            Contact::Frictionless => {
                // A_zz, with z = -cos(alpha) 1 - sin(alpha) 3.
                let azz = a1 * s.cos_alpha * s.cos_alpha + a3 * s.sin_alpha * s.sin_alpha;
                Vector3::new(0.0, 0.0, b.z / azz)
            }
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
