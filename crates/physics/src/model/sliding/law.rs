//! Coulomb's law at the contact: the force in each mode, the test for sticking, and the
//! direction a slip starts in.
//!
//! **Slip onset.** When the contact point is at rest and sticking would need more than
//! $\mu F_z$, Coulomb's law says the point starts to slide, with the friction opposing the
//! slip that develops. Its direction $\hat{\mathbf s}$ is the one that is consistent:
//! with $\mathbf F(\hat{\mathbf s}) = F_z(\hat{\mathbf s})(\hat{\mathbf z} - \mu\hat{\mathbf s})$
//! the contact point's acceleration $\dot{\mathbf v}_c = A\mathbf F - \mathbf b$ must point
//! along $+\hat{\mathbf s}$ (Filippov's sliding-onset condition for this law). $A$ is not
//! isotropic along the table, so the direction is found by a root search in the table's plane
//! (`onset_direction`) that starts from
//! $-\mathbf F_{t}^{\rm stick}/|\mathbf F_{t}^{\rm stick}|$ (the friction at its limit along the
//! force sticking needs). That start is itself the consistent direction in the limit of a
//! vanishing excess $\delta = |\mathbf F^{\rm stick}_t| - \mu F_z$: with
//! $\hat{\mathbf u} = \mathbf F^{\rm stick}_t/|\mathbf F^{\rm stick}_t|$, the direction
//! $\hat{\mathbf s} = -\hat{\mathbf u} + O(\delta)$ gives $\dot{\mathbf v}_{c,t} = \lambda\hat{\mathbf s}$ with
//! $\lambda = \delta/(\hat{\mathbf u}\cdot A^{-1}\hat{\mathbf u}) > 0$. A slip that starts at
//! the located edge of the cone ($\delta \approx 0$) therefore starts along $-\hat{\mathbf u}$,
//! and the search takes the consistent root nearest to it.

use super::{horizontal, Mode, Sliding};
use crate::model::lab_frame::{ContactProblem, Snapshot};
use nalgebra::Vector3;
use numerics::oscillation::bisect;

/// The contact force of one evaluation, with what the guards need.
#[derive(Debug, Clone, Copy)]
pub struct ContactForce {
    /// $\mathbf F$ (lab, N).
    pub force: Vector3<f64>,
    /// The denominator $m\,\hat{\mathbf z}\cdot A(\hat{\mathbf z} - \mu\hat{\mathbf s})$ of the slip law
    /// (1 when not slipping); zero or below is Painlevé's paradox.
    pub consistency: f64,
    /// The resistance arm it was solved with: the moment is `force.z * arm`
    /// ([`Sliding::held_arm`]).
    pub arm: Vector3<f64>,
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

    /// The force in `mode` for the geometry `s`, with the resistance held where its rotation
    /// stops (`stall.rs`).
    pub fn contact_force(&self, mode: &Mode, s: &Snapshot) -> ContactForce {
        let arm = self.held_arm(mode, s);
        self.contact_force_with(mode, s, &arm)
    }

    /// The force in `mode` for the geometry `s` with the resistance arm `arm`.
    pub(crate) fn contact_force_with(
        &self,
        mode: &Mode,
        s: &Snapshot,
        arm: &Vector3<f64>,
    ) -> ContactForce {
        match mode {
            Mode::Flight => ContactForce {
                force: Vector3::zeros(),
                consistency: 1.0,
                arm: Vector3::zeros(),
            },
            Mode::Stick => {
                let cp = self.contact_problem_with(s, arm);
                ContactForce {
                    force: cp.solve(s, &cp.b),
                    consistency: 1.0,
                    arm: *arm,
                }
            }
            Mode::Slip { anchor, held } => {
                let cp = self.contact_problem_with(s, arm);
                let dir = self.slip_direction(s, anchor, *held);
                ContactForce {
                    arm: *arm,
                    ..self.slip_force(&cp, s, &dir)
                }
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
        let unit = Vector3::z() - self.mu_kinetic() * dir;
        let denom = cp.apply(s, &unit).z;
        let consistency = denom * self.disk.m;
        if consistency <= 0.0 {
            return ContactForce {
                force: Vector3::zeros(),
                consistency,
                arm: Vector3::zeros(),
            };
        }
        ContactForce {
            force: unit * (cp.b.z / denom),
            consistency,
            arm: Vector3::zeros(),
        }
    }

    /// What the contact does from rest at the geometry `s` (the contact point's velocity
    /// assumed zero): stick when $F^{\rm stick}_z > 0$ and $|\mathbf F^{\rm stick}_t| < \mu F^{\rm stick}_z$,
    /// flight when $F_z \le 0$ under either law, otherwise slip in the consistent direction.
    pub(crate) fn mode_from_rest(&self, s: &Snapshot) -> Mode {
        let cp = self.contact_problem(s);
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

    /// The consistent slip direction at rest (module documentation): the direction
    /// $\hat{\mathbf s}(\theta) = (\cos\theta, \sin\theta, 0)$ nearest to
    /// $-\hat{\mathbf u}$ at which the contact point's acceleration $\dot{\mathbf v}_{c,t}$ has
    /// no component across $\hat{\mathbf s}$ and none against it.
    ///
    /// Found by bracketing the across component $(\dot{\mathbf v}_{c,t}\times\hat{\mathbf s})_z$
    /// in steps of 5 degrees outward from $-\hat{\mathbf u}$ and bisecting each bracket, keeping the
    /// first root whose along component is not negative. Not by the fixed point
    /// $\hat{\mathbf s}\leftarrow\dot{\mathbf v}_{c,t}/|\dot{\mathbf v}_{c,t}|$: near the edge
    /// of the cone the acceleration along $\hat{\mathbf s}$ is of the size of the excess $\delta$
    /// while its across component changes by $O(|\mathbf b|)$ per radian, so that map has a gain
    /// of order $|\mathbf b|/\delta$ and runs away from the consistent direction (it did, at
    /// $\delta = 1.4\times10^{-5}$ N with $\mu = 0.05$, to a direction the contact point
    /// decelerated along: ten thousand held slips of $10^{-10}$ s each).
    pub(crate) fn onset_direction(
        &self,
        cp: &ContactProblem,
        s: &Snapshot,
        stick: &Vector3<f64>,
    ) -> Vector3<f64> {
        let ft = horizontal(stick);
        let start = if ft.norm() > 0.0 {
            -ft / ft.norm()
        } else {
            s.e2
        };
        let theta0 = start.y.atan2(start.x);
        let direction = |phi: f64| {
            let th = theta0 + phi;
            Vector3::new(th.cos(), th.sin(), 0.0)
        };
        // (along, across) components of the contact point's acceleration for direction phi;
        // None where the slip law has no solution (Painleve).
        let components = |phi: f64| {
            let dir = direction(phi);
            let f = self.slip_force(cp, s, &dir);
            if f.consistency <= 0.0 {
                return None;
            }
            let acc = horizontal(&(cp.apply(s, &f.force) - cp.b));
            Some((acc.dot(&dir), acc.cross(&dir).z))
        };
        // The along component at a root is about delta / m; round-off in it is ~1e-12 g.
        let tiny = 1e-9 * self.disk.g;
        let step = 5f64.to_radians();
        for j in 0..36 {
            for (lo, hi) in [
                (j as f64 * step, (j + 1) as f64 * step),
                (-((j + 1) as f64) * step, -(j as f64) * step),
            ] {
                let (Some((_, c_lo)), Some((_, c_hi))) = (components(lo), components(hi)) else {
                    continue;
                };
                if c_lo == 0.0 || (c_lo > 0.0) != (c_hi > 0.0) {
                    let positive_at_lo = c_lo > 0.0;
                    let (a, b) = if c_lo == 0.0 {
                        (lo, lo)
                    } else {
                        bisect(lo, hi, 1e-14, |phi| {
                            components(phi).is_some_and(|(_, c)| c > 0.0) != positive_at_lo
                        })
                    };
                    let root = 0.5 * (a + b);
                    if components(root).is_some_and(|(along, _)| along >= -tiny) {
                        return direction(root);
                    }
                }
            }
        }
        start
    }
}
