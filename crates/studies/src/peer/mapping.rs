//! The one place where the peer program's variables meet this tool's state.
//!
//! **The peer's frames** (M. Batista's Euler disk program). The lab $(X, Y, Z)$ has $Z$ up.
//! Frame (1) is the lab turned by $\psi$ about $Z$:
//! $\mathbf x_1 = (\cos\psi, \sin\psi, 0)$, $\mathbf y_1 = (-\sin\psi, \cos\psi, 0)$,
//! $\mathbf z_1 = \hat{\mathbf Z}$. Frame (2) is frame (1) turned by $\theta$ about $\mathbf x_1$:
//! $\mathbf p_1 = \mathbf x_1$, $\mathbf p_2 = \cos\theta\,\mathbf y_1 + \sin\theta\,\hat{\mathbf Z}$
//! (the symmetry axis), $\mathbf p_3 = -\sin\theta\,\mathbf y_1 + \cos\theta\,\hat{\mathbf Z}$.
//! The body is frame (2) turned by $\phi$ about $\mathbf p_2$; its axes are
//! $\mathbf b_1 = \cos\phi\,\mathbf p_1 - \sin\phi\,\mathbf p_3$, $\mathbf p_2$,
//! $\mathbf b_3 = \sin\phi\,\mathbf p_1 + \cos\phi\,\mathbf p_3$. So $\theta = 0$ is the disk
//! upright, $\theta = \pm\pi/2$ flat. Its angular velocity is written in frame (2),
//! $\boldsymbol\omega = \omega_1\mathbf p_1 + \omega_2\mathbf p_2 + \omega_3\mathbf p_3$, whence
//! $\dot\theta = \omega_1$, $\dot\psi = \omega_3/\cos\theta$, $\dot\phi = \omega_2 - \omega_3\tan\theta$.
//! The centre's velocity is written in frame (1), $\mathbf v = v_x\mathbf x_1 + v_y\mathbf y_1 +
//! v_z\hat{\mathbf Z}$, and the contact point is $\boldsymbol\rho = -h_p\mathbf p_2 - r_p\mathbf p_3$
//! with $h_p = c - f(1 - \sin\theta)$, $r_p = a - f(1 - \cos\theta)$ for $\theta > 0$ ($c$ the
//! half thickness, $f$ the fillet). Units are SI, angles in radians (degrees in its input).
//!
//! **This tool's triad** (`physics::model::lab_frame`): the body axis $\mathbf e_x$ is the symmetry
//! axis $\hat{\mathbf 1}$, $\cos\alpha = -\hat{\mathbf 1}\cdot\hat{\mathbf Z}$, and the contact is
//! $\boldsymbol\rho = p\hat{\mathbf 1} + q\hat{\mathbf 3}$ with $p = c - f(1 - \cos\alpha) > 0$ while
//! $\alpha < \pi/2$ (`model::sliding`'s `toy.rs`).
//!
//! **The map.** The two contacts coincide when $\hat{\mathbf 1} = -\mathbf p_2$ and
//! $\hat{\mathbf 3} = -\mathbf p_3$: then $p = h_p$, $q = r_p$ term by term exactly when
//! $\cos\alpha = \sin\theta$ and $\sin\alpha = \cos\theta$, i.e.
//! $$ \alpha = \frac\pi2 - \theta. $$
//! The rest of the triad follows: $\hat{\mathbf r} = -\hat{\mathbf 1}_h/|\hat{\mathbf 1}_h| = \mathbf y_1$,
//! $\hat{\mathbf 2} = \hat{\mathbf Z}\times\hat{\mathbf r} = -\mathbf x_1$, so the heading of
//! $\hat{\mathbf 2}$ is $\psi + \pi$ and the precession rate is $\dot\psi$. The body axes are
//! taken as $\mathbf e_x = -\mathbf p_2$, $\mathbf e_y = -\mathbf b_1$ and
//! $\mathbf e_z = \mathbf e_x\times\mathbf e_y = \mathbf p_2\times\mathbf b_1$ (at $\phi = 0$:
//! $\mathbf e_y = \hat{\mathbf 2}$, $\mathbf e_z = -\mathbf p_3 = \hat{\mathbf 3}$; the face angle
//! is not compared). The triad turns about the vertical at $\dot\psi$ (from
//! $\dot{\hat{\mathbf 1}} = -\dot{\mathbf p}_2 = -\dot\theta\,\mathbf p_3 + \dot\psi\cos\theta\,\mathbf x_1
//! = -\Omega\sin\alpha\,\hat{\mathbf 2} - \dot\alpha\,\hat{\mathbf 3}$), so the precession rate
//! is $\Omega = \dot\psi = \omega_3/\cos\theta$. The
//! spin about the symmetry axis is $\boldsymbol\omega\cdot\hat{\mathbf 1} = -\omega_2$ and
//! $\dot\alpha = -\omega_1$. The centre is the same point in both: $(x_c, y_c, z_c)$.

use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};
use physics::solve::State;

/// One state of the peer: its Euler angles, body rates in frame (2), the centre and its
/// velocity in frame (1) (SI units, radians).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PeerState {
    /// $\psi$, about $Z$.
    pub psi: f64,
    /// $\theta$, the tilt from upright.
    pub theta: f64,
    /// $\phi$, about the symmetry axis.
    pub phi: f64,
    /// $(\omega_1, \omega_2, \omega_3)$ in frame (2).
    pub omega: [f64; 3],
    /// Centre $(x, y, z)$ in the lab.
    pub centre: [f64; 3],
    /// Centre velocity $(v_x, v_y, v_z)$ in frame (1).
    pub velocity: [f64; 3],
}

impl PeerState {
    /// Frame (1) and frame (2)'s axes in the lab: $(\mathbf x_1, \mathbf y_1, \mathbf p_2, \mathbf p_3)$.
    fn axes(&self) -> [Vector3<f64>; 4] {
        let (sp, cp) = self.psi.sin_cos();
        let (st, ct) = self.theta.sin_cos();
        let x1 = Vector3::new(cp, sp, 0.0);
        let y1 = Vector3::new(-sp, cp, 0.0);
        let z = Vector3::z();
        [x1, y1, ct * y1 + st * z, -st * y1 + ct * z]
    }

    /// This tool's 14-component sliding state for the peer state (the dissipated work 0).
    pub fn lab_state(&self) -> State<14> {
        let [x1, y1, p2, p3] = self.axes();
        let (sf, cf) = self.phi.sin_cos();
        let b1 = cf * x1 - sf * p3;
        let ex = -p2;
        let ey = -b1;
        let ez = ex.cross(&ey);
        let rotation = Rotation3::from_matrix_unchecked(Matrix3::from_columns(&[ex, ey, ez]));
        let q = UnitQuaternion::from_rotation_matrix(&rotation);
        let [w1, w2, w3] = self.omega;
        let omega = w1 * x1 + w2 * p2 + w3 * p3;
        let omega_body = rotation.inverse() * omega;
        let [vx, vy, vz] = self.velocity;
        let v = vx * x1 + vy * y1 + vz * Vector3::z();
        let mut y = State::<14>::zeros();
        let c = q.quaternion().coords;
        y[0] = c.w;
        y[1] = c.x;
        y[2] = c.y;
        y[3] = c.z;
        for i in 0..3 {
            y[4 + i] = omega_body[i];
            y[7 + i] = self.centre[i];
            y[10 + i] = v[i];
        }
        y
    }

    /// The peer's Euler angles and rates for this tool's start: $\theta = \pi/2 - \alpha$,
    /// $\omega_1 = -\dot\alpha$, $\omega_2 = -\omega_s$ (the spin), $\omega_3 = \Omega\cos\theta$, and
    /// $\psi$ from the heading $\psi_2$ of $\hat{\mathbf 2}$: $\psi = \psi_2 - \pi$; $\phi = 0$.
    pub fn from_paper(
        alpha: f64,
        alpha_dot: f64,
        precession: f64,
        spin: f64,
        heading: f64,
    ) -> Self {
        let theta = std::f64::consts::FRAC_PI_2 - alpha;
        Self {
            psi: heading - std::f64::consts::PI,
            theta,
            phi: 0.0,
            omega: [-alpha_dot, -spin, precession * theta.cos()],
            centre: [0.0; 3],
            velocity: [0.0; 3],
        }
    }

    /// The centre's velocity that puts the contact point $\boldsymbol\rho = -h_p\mathbf p_2 -
    /// r_p\mathbf p_3$ at rest, plus the slip `slip` (lab), in frame (1) components:
    /// $\mathbf v = -\boldsymbol\omega\times\boldsymbol\rho + \mathbf s$.
    pub fn rolling_velocity(&self, hp: f64, rp: f64, slip: Vector3<f64>) -> [f64; 3] {
        let [x1, y1, p2, p3] = self.axes();
        let [w1, w2, w3] = self.omega;
        let omega = w1 * x1 + w2 * p2 + w3 * p3;
        let rho = -hp * p2 - rp * p3;
        let v = -omega.cross(&rho) + slip;
        [v.dot(&x1), v.dot(&y1), v.z]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use physics::disk::Disk;
    use physics::model::lab_frame::Snapshot;

    #[test]
    fn the_map_carries_tilt_spin_heading_and_precession() {
        let (alpha, alpha_dot, prec, spin, heading) = (1.1, 0.3, 7.0, -4.0, 0.4);
        let mut p = PeerState::from_paper(alpha, alpha_dot, prec, spin, heading);
        p.phi = 0.7;
        let d = Disk::uniform(0.0375);
        let s = Snapshot::of(d.a, &p.lab_state());
        let m = s.motion();
        assert!((m.alpha - alpha).abs() < 1e-14);
        assert!((m.alpha_dot - alpha_dot).abs() < 1e-13);
        assert!((m.spin - spin).abs() < 1e-13);
        assert!((m.precession - prec).abs() < 1e-13);
        let dh = (s.heading() - heading + 3.0 * std::f64::consts::PI)
            .rem_euclid(2.0 * std::f64::consts::PI)
            - std::f64::consts::PI;
        assert!(dh.abs() < 1e-14, "{dh}");
        // The lowest rim point of the thin disk is -p3 * a in the peer's frames.
        let [_, _, _, p3] = p.axes();
        assert!((s.rho - (-d.a * p3)).norm() < 1e-15);
    }
}
