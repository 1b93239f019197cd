//! Coulomb's law at the contact: the force in each mode, the test for sticking, and the
//! direction a slip starts in.
//!
//! **Slip onset.** When the contact point is at rest and sticking would need more than
//! $\mu F_z$, Coulomb's law says the point starts to slide, with the friction opposing the
//! slip that develops. Its direction $\hat{\mathbf s}$ is the one that is consistent:
//! with $\mathbf F(\hat{\mathbf s}) = F_z(\hat{\mathbf s})(\hat{\mathbf z} - \mu\hat{\mathbf s})$
//! the contact point's acceleration $\dot{\mathbf v}_c = A\mathbf F - \mathbf b$ must point
//! along $+\hat{\mathbf s}$ (Filippov's sliding-onset condition for this law). $A$ is not
//! isotropic along the table, so the direction is found by the fixed point
//! $\hat{\mathbf s}\leftarrow\dot{\mathbf v}_{c,t}/|\dot{\mathbf v}_{c,t}|$, started from
//! $-\mathbf F_{t}^{\rm stick}/|\mathbf F_{t}^{\rm stick}|$ (the friction at its limit along the
//! force sticking needs). That start is itself the consistent direction in the limit of a
//! vanishing excess $\delta = |\mathbf F^{\rm stick}_t| - \mu F_z$: with
//! $\hat{\mathbf u} = \mathbf F^{\rm stick}_t/|\mathbf F^{\rm stick}_t|$, the direction
//! $\hat{\mathbf s} = -\hat{\mathbf u} + O(\delta)$ gives $\dot{\mathbf v}_{c,t} = \lambda\hat{\mathbf s}$ with
//! $\lambda = \delta/(\hat{\mathbf u}\cdot A^{-1}\hat{\mathbf u}) > 0$. A slip that starts at
//! the located edge of the cone ($\delta \approx 0$) therefore starts along $-\hat{\mathbf u}$,
//! and the iteration is used only while the acceleration is well above round-off.

use super::{horizontal, Mode, Sliding};
use crate::model::lab_frame::{ContactProblem, Snapshot};
use nalgebra::Vector3;

/// The contact force of one evaluation, with what the guards need.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ContactForce {
    /// $\mathbf F$ (lab, N).
    pub force: Vector3<f64>,
    /// The denominator $m\,\hat{\mathbf z}\cdot A(\hat{\mathbf z} - \mu\hat{\mathbf s})$ of the slip law
    /// (1 when not slipping); zero or below is Painlevé's paradox.
    pub consistency: f64,
}

impl Sliding {
    /// The slip direction of the flow: `anchor` while held, else $\mathbf v_{c,t}/|\mathbf v_{c,t}|$.
    pub(crate) fn slip_direction(
        &self,
        s: &Snapshot,
        anchor: &[f64; 3],
        held: bool,
    ) -> Vector3<f64> {
        let v = horizontal(&s.contact_velocity);
        let n = v.norm();
        if held || n == 0.0 {
            Vector3::from(*anchor)
        } else {
            v / n
        }
    }

    /// The force in `mode` for the geometry `s`.
    pub(crate) fn contact_force(&self, mode: &Mode, s: &Snapshot) -> ContactForce {
        match mode {
            Mode::Flight => ContactForce {
                force: Vector3::zeros(),
                consistency: 1.0,
            },
            Mode::Stick => {
                let cp = ContactProblem::of(&self.disk, s);
                ContactForce {
                    force: cp.solve(s, &cp.b),
                    consistency: 1.0,
                }
            }
            Mode::Slip { anchor, held } => {
                let cp = ContactProblem::of(&self.disk, s);
                let dir = self.slip_direction(s, anchor, *held);
                self.slip_force(&cp, s, &dir)
            }
        }
    }

    /// $\mathbf F = F_z(\hat{\mathbf z} - \mu\hat{\mathbf s})$ with $F_z$ from $\ddot h = 0$.
    pub(crate) fn slip_force(
        &self,
        cp: &ContactProblem,
        s: &Snapshot,
        dir: &Vector3<f64>,
    ) -> ContactForce {
        let unit = Vector3::z() - self.friction.mu * dir;
        let denom = cp.apply(s, &unit).z;
        let consistency = denom * self.disk.m;
        if consistency <= 0.0 {
            return ContactForce {
                force: Vector3::zeros(),
                consistency,
            };
        }
        ContactForce {
            force: unit * (cp.b.z / denom),
            consistency,
        }
    }

    /// What the contact does from rest at the geometry `s` (the contact point's velocity
    /// assumed zero): stick when $F^{\rm stick}_z > 0$ and $|\mathbf F^{\rm stick}_t| < \mu F^{\rm stick}_z$,
    /// flight when $F_z \le 0$ under either law, otherwise slip in the consistent direction.
    pub(crate) fn mode_from_rest(&self, s: &Snapshot) -> Mode {
        let cp = ContactProblem::of(&self.disk, s);
        let stick = cp.solve(s, &cp.b);
        if stick.z <= 0.0 {
            return Mode::Flight;
        }
        let ft = horizontal(&stick).norm();
        if ft < self.friction.mu * stick.z {
            return Mode::Stick;
        }
        let dir = self.onset_direction(&cp, s, &stick);
        let f = self.slip_force(&cp, s, &dir);
        if f.consistency <= 0.0 || f.force.z > 0.0 {
            Mode::Slip {
                anchor: [dir.x, dir.y, 0.0],
                held: true,
            }
        } else {
            Mode::Flight
        }
    }

    /// The consistent slip direction at rest (module documentation).
    pub(crate) fn onset_direction(
        &self,
        cp: &ContactProblem,
        s: &Snapshot,
        stick: &Vector3<f64>,
    ) -> Vector3<f64> {
        let ft = horizontal(stick);
        let mut dir = if ft.norm() > 0.0 {
            -ft / ft.norm()
        } else {
            s.e2
        };
        for _ in 0..50 {
            let f = self.slip_force(cp, s, &dir);
            if f.consistency <= 0.0 {
                break;
            }
            let acc = horizontal(&(cp.apply(s, &f.force) - cp.b));
            let n = acc.norm();
            // At the edge of the cone the slip starts with zero acceleration along
            // -F_t/|F_t| (the limit of the consistent direction as the excess vanishes); a
            // direction read from an acceleration of round-off size would be noise.
            if n < 1e-6 * self.disk.g {
                break;
            }
            let next = acc / n;
            let moved = (next - dir).norm();
            dir = next;
            if moved < 1e-14 {
                break;
            }
        }
        dir
    }
}
