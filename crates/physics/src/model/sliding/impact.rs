//! The landing: an impact at the rim's lowest point, and the projection that puts a contact
//! point that has just stopped slipping exactly at rest.
//!
//! **Impact law.** An impulse $\mathbf P$ at $\boldsymbol\rho$ changes the contact point's
//! velocity by $A\mathbf P$ (the same Delassus matrix as the contact force,
//! [`crate::model::lab_frame::ContactProblem`]): $\mathbf v_c^+ = \mathbf v_c^- + A\mathbf P$,
//! $\Delta\mathbf v = \mathbf P/m$, $\Delta\boldsymbol\omega_b = I^{-1}R^T(\boldsymbol\rho\times\mathbf P)$.
//! Normal direction: Newton's kinematic restitution, $v_{c,z}^+ = -e\,v_{c,z}^-$. Tangent:
//! Coulomb for impulses, $|\mathbf P_t| \le \mu P_z$: the contact point is stopped
//! ($\mathbf v_{c,t}^+ = 0$) when the impulse that does so lies in the cone; otherwise it slides
//! through the impact with $\mathbf P_t = -\mu P_z\hat{\mathbf s}$, $\hat{\mathbf s}$ the
//! direction of $\mathbf v_{c,t}^-$ (of $-\mathbf P^{\rm stick}_t$ when it is zero), held for
//! the impact's duration, and
//! $P_z = -(1+e)v_{c,z}^- / \hat{\mathbf z}\cdot A(\hat{\mathbf z} - \mu\hat{\mathbf s})$.
//! This is the Newton-Coulomb law in the form of Glocker's set-valued impact laws
//! (Ch. Glocker, *Set-Valued Force Laws*, Springer 2001, ch. 8; also Pfeiffer & Glocker,
//! *Multibody Dynamics with Unilateral Contacts*, Wiley 1996) restricted to one contact with the
//! sliding direction frozen during the impact; that restriction can in principle gain energy
//! when the sliding would reverse during the impact, so the energy lost is computed from the
//! states, booked in $W$, and a gain ends the run ([`super::Sliding::land`]).
//!
//! Bounces below $v_b = 10^{-5}\sqrt{ga}$ (about 6 µm/s for the toy disk) are treated as plastic
//! ($e = 0$): without that floor, $e > 0$ gives Zeno's infinite sequence of ever shorter
//! flights.

use super::{horizontal, Sliding, DISSIPATED};
use crate::model::lab_frame::Snapshot;
use crate::solve::State;
use nalgebra::Vector3;

impl Sliding {
    /// The speed below which a landing does not bounce (m/s).
    pub fn bounce_floor(&self) -> f64 {
        1e-5 * (self.disk.g * self.disk.a).sqrt()
    }

    /// The impulse of the impact law for the contact velocity `vc` (module documentation).
    pub(crate) fn impact_impulse(&self, s: &Snapshot, vc: &Vector3<f64>, e: f64) -> Vector3<f64> {
        let cp = self.contact_problem(s);
        let dv = Vector3::new(-vc.x, -vc.y, -(1.0 + e) * vc.z);
        let stick = cp.solve(s, &dv);
        let mu = self.friction.mu;
        if horizontal(&stick).norm() <= mu * stick.z {
            return stick;
        }
        let vt = horizontal(vc);
        let dir = if vt.norm() > self.slip_floor() {
            vt / vt.norm()
        } else {
            let pt = horizontal(&stick);
            if pt.norm() > 0.0 {
                -pt / pt.norm()
            } else {
                s.e2
            }
        };
        let unit = Vector3::z() - self.mu_kinetic() * dir;
        let denom = cp.apply(s, &unit).z;
        if denom <= 0.0 {
            return stick;
        }
        unit * (-(1.0 + e) * vc.z / denom)
    }

    /// The state after impulse `p` at the contact of `y`, with the energy lost added to $W$.
    pub(crate) fn apply_impulse(&self, y: &State<14>, p: &Vector3<f64>) -> (State<14>, f64) {
        let d = &self.disk;
        let s = self.snapshot(y);
        let e0 = self.energy_at(&s);
        let mut out = *y;
        let dw =
            (s.rotation.inverse_transform_vector(&s.rho.cross(p))).component_div(&self.inertia());
        for i in 0..3 {
            out[4 + i] += dw[i];
            out[10 + i] += p[i] / d.m;
        }
        let lost = e0 - self.energy_at(&self.snapshot(&out));
        out[DISSIPATED] += lost;
        (out, lost)
    }

    /// The projection that puts the contact point of `y` exactly at rest: the impulse
    /// $\mathbf P = -A^{-1}\mathbf v_c$ (no cone: it removes a residue of size $v_0$ left by
    /// locating the end of a slip, always a loss, $\frac12\mathbf v_c\cdot A^{-1}\mathbf v_c$).
    pub(crate) fn settle(&self, y: &State<14>) -> State<14> {
        let s = self.snapshot(y);
        let cp = self.contact_problem(&s);
        let p = -cp.solve(&s, &s.contact_velocity);
        self.apply_impulse(y, &p).0
    }
}
