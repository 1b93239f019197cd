//! A resistance moment whose rotation stops: Coulomb stick for rolling and boring resistance.
//!
//! Each resistance moment of `toy.rs` has the form $\mathbf M_e = F_z\,c\,\hat{\mathbf e}$
//! along its axis ($\hat{\mathbf e} = \hat{\mathbf z}$ for boring, $\hat{\mathbf r}$ for
//! rolling), with $c = -\ell\,\mathrm{sign}\,w$ while the rotation $w = \boldsymbol\omega\cdot
//! \hat{\mathbf e}$ turns. Where $w$ reaches zero, Coulomb's law for a moment is that of a
//! force: the moment takes any value $|c| \le \ell$ that keeps the rotation at rest, and the
//! rotation starts again only where the moment that holding it demands exceeds $\ell F_z$.
//! With the sign alone the moment flips at each crossing and an explicit integrator chatters on
//! $w = 0$ (two million steps on a boring stall).
//!
//! **The hold.** Within the band $|w| < \delta = 10^{-6}\sqrt{g/a}$ the coefficient $c$ is the
//! root of
//! $$ h(c) = \dot w(c) + \lambda w = \dot{\boldsymbol\omega}(c)\cdot\hat{\mathbf e} +
//!    \boldsymbol\omega\cdot\dot{\hat{\mathbf e}} + \lambda w,\qquad \lambda = \sqrt{g/a}, $$
//! where $\dot{\boldsymbol\omega}(c)$ is Euler's equation with the contact force of the mode
//! solved with that moment (the moment enters the contact condition, so the force changes with
//! $c$): the rotation is held and relaxes to zero at the model's drift-control rate. The root
//! is found by bisection on $[-\ell, \ell]$, on which $h$ increases. Where
//! $h(-\ell) > 0$ the largest moment cannot hold a rotation driven positive ($c = -\ell$), where
//! $h(\ell) < 0$ one driven negative ($c = \ell$): the rotation passes through zero as before,
//! resisted by $-\ell\,\mathrm{sign}\,w$. The rate of the rolling axis is
//! $\dot{\hat{\mathbf r}} = -(\dot{\mathbf n}_h - \hat{\mathbf r}(\hat{\mathbf r}\cdot\dot{\mathbf n}_h))/\sin\alpha$,
//! $\dot{\mathbf n}_h$ the horizontal part of $\boldsymbol\omega\times\hat{\mathbf n}$. The
//! boring component is held first, then the rolling one with it.

use super::toy::sign;
use super::{Mode, Sliding};
use crate::model::lab_frame::Snapshot;
use nalgebra::Vector3;

/// Bisection steps for a held coefficient: $2\ell/2^{60}$ is below round-off.
const BISECTIONS: usize = 60;

impl Sliding {
    /// $\delta$: the band of a resistance's rotation within which it may be held (rad/s).
    pub fn stall_band(&self) -> f64 {
        1e-6 * self.disk.g_over_a().sqrt()
    }

    /// The resistance arm per unit normal force in `mode` at `s` (lab, m): the signed one of
    /// `toy.rs` outside the band, with each rotation inside it held where its moment can hold
    /// it (module documentation). Zero without resistance and in flight.
    pub(crate) fn held_arm(&self, mode: &Mode, s: &Snapshot) -> Vector3<f64> {
        let Some(r) = self.toy.resistance else {
            return Vector3::zeros();
        };
        if matches!(mode, Mode::Flight) {
            return Vector3::zeros();
        }
        let band = self.stall_band();
        let boring_w = s.omega.z;
        let rolling_w = s.omega.dot(&s.r);
        let mut boring = -r.boring * sign(boring_w);
        let mut rolling = -r.rolling * sign(rolling_w);
        let arm = |b: f64, rl: f64| rl * s.r + b * Vector3::z();
        if r.boring > 0.0 && boring_w.abs() < band {
            let z_dot = Vector3::zeros();
            boring = self.held(mode, s, r.boring, boring_w, |c| {
                (arm(c, rolling), Vector3::z(), z_dot)
            });
        }
        if r.rolling > 0.0 && rolling_w.abs() < band {
            let n_dot = s.omega.cross(&s.e1);
            let nh_dot = Vector3::new(n_dot.x, n_dot.y, 0.0);
            let r_dot = -(nh_dot - s.r * s.r.dot(&nh_dot)) / s.sin_alpha;
            rolling = self.held(mode, s, r.rolling, rolling_w, |c| {
                (arm(boring, c), s.r, r_dot)
            });
        }
        arm(boring, rolling)
    }

    /// The coefficient $c \in [-\ell, \ell]$ of one rotation $w$ in the band (module
    /// documentation); `parts(c)` gives the whole arm with that coefficient, the axis and its
    /// rate.
    fn held(
        &self,
        mode: &Mode,
        s: &Snapshot,
        ell: f64,
        w: f64,
        parts: impl Fn(f64) -> (Vector3<f64>, Vector3<f64>, Vector3<f64>),
    ) -> f64 {
        let lambda = self.stabilisation;
        let h = |c: f64| {
            let (arm, axis, axis_dot) = parts(c);
            let f = self.contact_force_with(mode, s, &arm).force;
            let w_dot = s.rotation * self.body_angular_acceleration(s, &f, &arm);
            w_dot.dot(&axis) + s.omega.dot(&axis_dot) + lambda * w
        };
        let (lo, hi) = (h(-ell), h(ell));
        if !(lo <= 0.0 && hi >= 0.0) {
            // Not holdable: resisted against the rotation, or against the drive at w = 0.
            let drive = if w != 0.0 { w } else { lo + hi };
            return -ell * sign(drive);
        }
        let (mut a, mut b) = (-ell, ell);
        for _ in 0..BISECTIONS {
            let mid = 0.5 * (a + b);
            if h(mid) < 0.0 {
                a = mid;
            } else {
                b = mid;
            }
        }
        0.5 * (a + b)
    }

    /// $\dot{\boldsymbol\omega}_b$ (body axes) under the contact force `f`, the resistance
    /// `f.z * arm` and the drag: Euler's equations
    /// $I\dot{\boldsymbol\omega}_b = \mathbf N_b - \boldsymbol\omega_b\times I\boldsymbol\omega_b$.
    pub(crate) fn body_angular_acceleration(
        &self,
        s: &Snapshot,
        f: &Vector3<f64>,
        arm: &Vector3<f64>,
    ) -> Vector3<f64> {
        let i = self.inertia();
        let torque = s.rho.cross(f) + self.drag_torque(s) + f.z * arm;
        let torque_body = s.rotation.inverse_transform_vector(&torque);
        let w = s.omega_body;
        (torque_body - w.cross(&i.component_mul(&w))).component_div(&i)
    }
}

#[cfg(test)]
mod tests {
    use super::{Mode, Sliding};
    use crate::dispatch::sliding_model;
    use crate::run::sliding::integrate;
    use crate::scene::Scene;
    use nalgebra::Vector3;

    /// A thin disk rolling upright while turning at 2 rad/s under boring resistance of lever
    /// arm `boring`: the resistance stops the turn, and nothing drives it again.
    fn upright_turn(boring: f64) -> Scene {
        let text = format!(
            "name: boring-stall\nmodel: sliding\n\
             disk: {{ radius: 0.0375, mass: 0.4, k: 0.25, g: 9.8067 }}\n\
             friction: {{ mu: 1.0 }}\nresistance: {{ boring: {boring} }}\n\
             start: {{ explicit: {{ alpha: 1.5707963267948966, alpha_dot: 0.0, precession: 2.0, \
             spin: 30.0 }} }}\nstop: {{ time: 1.0 }}\nsample: 0.001\n\
             solver: {{ rtol: 1e-10, atol: 1e-10 }}\n"
        );
        Scene::parse(&text, "boring-stall.yaml").expect("the scene reads")
    }

    #[test]
    fn a_boring_stall_is_held_and_the_run_reaches_its_end() {
        let scene = upright_turn(3.75e-3);
        let m = sliding_model(&scene);
        let run = integrate(&m, &scene, scene.sample).expect("runs");
        assert!(run.ending.is_complete(), "{}", run.ending);
        let t_held = run
            .t
            .iter()
            .zip(&run.y)
            .find(|(_, y)| m.snapshot(y).omega.z.abs() < m.stall_band())
            .map_or(f64::NAN, |(t, _)| *t);
        println!(
            "boring stall: held from t = {t_held:.4} s, {:?}, omega_z at the end {:.3e} rad/s",
            run.stats,
            m.snapshot(run.y.last().expect("a state")).omega.z
        );
        assert!(run.stats.accepted < 20_000, "{:?}", run.stats);
        // docs/friction.md gives these figures.
        let docs = include_str!("../../../../../docs/friction.md").replace('\n', " ");
        let said = format!(
            "at rest from t = {t_held:.3} s and reaches the end of its second in {} accepted steps",
            run.stats.accepted
        );
        assert!(docs.contains(&said), "docs/friction.md lacks: {said}");
        let last = run.y.last().expect("a last state");
        let s = m.snapshot(last);
        assert!(s.omega.z.abs() < m.stall_band(), "omega_z {}", s.omega.z);
        // The held moment does no work beyond what is booked: E + W stays E(0).
        let e0 = m.energy(&run.y[0]) + run.y[0][super::super::DISSIPATED];
        let e1 = m.energy(last) + last[super::super::DISSIPATED];
        assert!((e1 - e0).abs() < 1e-8 * e0.abs(), "{e0} -> {e1}");
    }

    /// A thin disk rolling straight and upright at `spin` rad/s under rolling resistance of
    /// lever arm `rolling`: the moment $F_z\ell_r$ brings the rolling to rest at about
    /// $t = \dot\varphi_0\,\frac32 a^2/(g\ell_r)$ (the rolling disk's moment of inertia about
    /// its contact line), and nothing drives it again.
    fn upright_roll(rolling: f64, spin: f64) -> Scene {
        let text = format!(
            "name: rolling-stall\nmodel: sliding\n\
             disk: {{ radius: 0.0375, mass: 0.4, k: 0.25, g: 9.8067 }}\n\
             friction: {{ mu: 1.0 }}\nresistance: {{ rolling: {rolling} }}\n\
             start: {{ explicit: {{ alpha: 1.5707963267948966, alpha_dot: 0.0, precession: 0.0, \
             spin: {spin} }} }}\nstop: {{ time: 1.0 }}\nsample: 0.001\n\
             solver: {{ rtol: 1e-10, atol: 1e-10 }}\n"
        );
        Scene::parse(&text, "rolling-stall.yaml").expect("the scene reads")
    }

    #[test]
    fn a_rolling_stall_is_held_and_the_run_reaches_its_end() {
        let (ell, spin) = (1e-3, 2.0);
        let scene = upright_roll(ell, spin);
        let m = sliding_model(&scene);
        let run = integrate(&m, &scene, scene.sample).expect("runs");
        assert!(run.ending.is_complete(), "{}", run.ending);
        let rolling = |y: &crate::solve::State<14>| {
            let s = m.snapshot(y);
            s.omega.dot(&s.r)
        };
        let w0 = rolling(&run.y[0]);
        assert!((w0.abs() - spin).abs() < 1e-9, "rolling at the start {w0}");
        let t_held = run
            .t
            .iter()
            .zip(&run.y)
            .find(|(_, y)| rolling(y).abs() < m.stall_band())
            .map_or(f64::NAN, |(t, _)| *t);
        // Where the constant moment F_z l_r = m g l_r stops a rolling of (3/2) m a^2 w.
        let (a, g) = (0.0375, 9.8067);
        let expected = spin * 1.5 * a * a / (g * ell);
        let last = run.y.last().expect("a last state");
        println!(
            "rolling stall: held from t = {t_held:.4} s (expected {expected:.4} s), {:?}, \
             rolling at the end {:.3e} rad/s",
            run.stats,
            rolling(last)
        );
        assert!(
            (t_held - expected).abs() < 2.0 * scene.sample.expect("a sample"),
            "held from {t_held} s, expected {expected} s"
        );
        assert!(run.stats.accepted < 20_000, "{:?}", run.stats);
        assert!(rolling(last).abs() < m.stall_band(), "{}", rolling(last));
        // Held, not rocking: the disk stays upright.
        let alpha = m.snapshot(last).motion().alpha;
        assert!(
            (alpha - std::f64::consts::FRAC_PI_2).abs() < 1e-9,
            "{alpha}"
        );
        // E + W stays E(0): the held moment does no work, the rolling's energy is all in W.
        let e0 = m.energy(&run.y[0]) + run.y[0][super::super::DISSIPATED];
        let e1 = m.energy(last) + last[super::super::DISSIPATED];
        assert!((e1 - e0).abs() < 1e-8 * e0.abs(), "{e0} -> {e1}");
        let kinetic = e0 - m.energy(last);
        let booked = last[super::super::DISSIPATED] - run.y[0][super::super::DISSIPATED];
        assert!(booked > 0.0 && (booked - kinetic).abs() < 1e-8 * e0.abs());
    }

    #[test]
    fn a_moment_too_weak_to_hold_is_the_signed_one_and_a_held_one_stops_the_rotation() {
        let with = |boring: f64| sliding_model(&upright_turn(boring));
        let m = with(3e-2);
        let mut y = m.start_state(&crate::model::Motion {
            alpha: 1.0,
            alpha_dot: 5.0,
            precession: 5.0,
            spin: 20.0,
        });
        // Its vertical rotation taken out: the disk is still driven to turn.
        let s0 = m.snapshot(&y);
        let level = s0.omega - Vector3::z() * s0.omega.z;
        let body = s0.rotation.inverse_transform_vector(&level);
        for k in 0..3 {
            y[4 + k] = body[k];
        }
        let s = m.snapshot(&y);
        assert!(s.omega.z.abs() < m.stall_band(), "{}", s.omega.z);
        let mode = Mode::Stick;
        let rate = |m: &Sliding, arm: &Vector3<f64>| {
            let f = m.contact_force_with(&mode, &s, arm).force;
            (s.rotation * m.body_angular_acceleration(&s, &f, arm)).z
        };
        let free = rate(&m, &Vector3::zeros());
        assert!(free.abs() > 1.0, "not driven: {free}");
        // Too weak to hold: the signed moment, of its full size.
        let weak = with(1e-9);
        let arm = weak.held_arm(&mode, &s);
        assert!((arm.z.abs() - 1e-9).abs() < 1e-24, "{arm}");
        assert!(rate(&weak, &arm).signum() == free.signum());
        // Strong enough: held, the rotation's rate is -lambda omega_z, the moment within its bound.
        let arm = m.held_arm(&mode, &s);
        let held = rate(&m, &arm);
        assert!(
            (held + m.stabilisation * s.omega.z).abs() < 1e-9 * free.abs(),
            "{held} with arm {arm}"
        );
        assert!(arm.z.abs() < 3e-2, "{arm}");
    }
}
