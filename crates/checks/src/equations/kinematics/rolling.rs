//! Eqs 12-17: rolling without slipping, the centre's velocity and its circle, steady motion.

use super::{
    at, identity, kin1, kin2, kin_bindings, printed_kinematics, printed_relations, rate_scale,
    sample, Bench, Bindings, Cubic, Dual64, Finding, History, Kin, Rng, Stated, Vector3, Worst,
    ONE, POINTS, RATE, R_HAT, THREE, V,
};

/// Disk radius of the toy (m); rolling checks use it so that velocities have their real size.
pub(super) const A: f64 = 0.0375;

/// The centre of mass's velocity of a disk rolling without slipping: $\dot C - a\dot{\hat{\mathbf
/// 3}}$, the contact point advancing on the table as it advances along the rim.
pub(super) fn v_cm_rolling(k: &Kin<f64>) -> V<f64> {
    (k.contact_rate * A) - (k.rates[THREE] * A)
}

/// Eq 12, $\mathbf v_{contact} = \mathbf v_{cm} + \vec\omega\times\mathbf a = 0$. Reference: a disk
/// rolling without slipping built from the rim's geometry (no cross product): its contact point
/// is at rest and its $\mathbf v_{cm}$ measured.
pub(super) fn eq12(b: &Bench) -> Finding {
    let w = printed_kinematics(
        b,
        12,
        12,
        |k| A * rate_scale(k),
        "$\\mathbf{v}_{\\mathrm{contact}}$",
    );
    identity(
        "the printed contact velocity against a disk rolled along its rim",
        w,
        Stated::Relation,
    )
}

/// Eq 13, $\mathbf v_{cm} = d\mathbf r_{cm}/dt = a\hat{\mathbf 3}\times\vec\omega =
/// -a\dot\alpha\hat{\mathbf 1} + a\omega_1\hat{\mathbf 2}$. Reference: the velocity of the centre
/// of a disk rolled along its rim; every printed equality.
pub(super) fn eq13(b: &Bench) -> Finding {
    let w = printed_kinematics(
        b,
        13,
        13,
        |k| A * rate_scale(k),
        "$\\mathbf{v}_{\\mathrm{cm}}$",
    );
    identity(
        "the printed forms of $\\mathbf{v}_{\\mathrm{cm}}$ against a disk rolled along its rim",
        w,
        Stated::Relation,
    )
}

/// The centre of curvature of the contact point's path, from its velocity and acceleration
/// (relative to the contact point): $(\hat{\mathbf z}\times\dot C)\,|\dot C|^2/((\dot C\times
/// \ddot C)\cdot\hat{\mathbf z})$.
pub(super) fn curvature_centre(v: &V<f64>, acc: &V<f64>) -> V<f64> {
    let turn = v.cross(acc)[2];
    (V::z().cross(v)) * (v.dot(v) / turn)
}

/// Eq 14, $\mathbf r_{cm} = x_A\hat{\mathbf x} + y_A\hat{\mathbf y} + r\hat{\mathbf r} -
/// a\hat{\mathbf 3}$ (definition). Reference: a disk rolled along its rim; $(x_A, y_A)$ is the
/// centre of curvature of the contact point's path (measured from its exact velocity and
/// acceleration) and $r = (C - A)\cdot\hat{\mathbf r}$ (signed: in a general motion the contact
/// path may curve away from the lean, and then $r < 0$, although the paper writes $r \ge 0$; the
/// count is in `at`). The content: the contact point moves along $\hat{\mathbf 2}$, so its circle's
/// centre lies on $\hat{\mathbf r}$'s line through it.
pub(super) fn eq14(b: &Bench) -> Finding {
    let mut w = Worst::default();
    let mut negative = 0;
    let points = sample(14, POINTS, RATE);
    for (h, t) in &points {
        let k2 = kin2(h, *t);
        let v: V<f64> = k2.contact_rate.map(|x| x.re) * A;
        let acc: V<f64> = k2.contact_rate.map(|x| x.eps) * A;
        let k = kin1(h, *t);
        let contact = V::zeros();
        let centre = contact + curvature_centre(&v, &acc);
        let r = (contact - centre).dot(&k.axes[R_HAT]);
        if r < 0.0 {
            negative += 1;
        }
        let r_cm = contact - (k.axes[THREE] * A);
        let bind = kin_bindings(&k)
            .vector("r_cm", r_cm)
            .scalar("x_A", centre[0])
            .scalar("y_A", centre[1])
            .scalar("r", r)
            .vector("x_hat", Vector3::x())
            .vector("y_hat", Vector3::y());
        printed_relations(b, 14, &bind, A + r.abs(), &mut w, &|| {
            at(
                &k,
                &format!("$\\mathbf{{r}}_{{\\mathrm{{cm}}}} (r = {r:.4e} m)$"),
            )
        });
    }
    w.at = format!("{}; $r < 0$ at {negative} of {} points", w.at, points.len());
    identity(
        "$x_A \\hat{\\mathbf{x}} + y_A \\hat{\\mathbf{y}} + r \\hat{\\mathbf{r}} - a \\hat{\\mathbf{3}}$ against a rolled disk's centre, A the contact path's centre of curvature",
        w, Stated::Definition,
    )
}

/// Eq 15, $d\mathbf r_{cm}/dt = \dot x_A\hat{\mathbf x} + \dot y_A\hat{\mathbf y} + \dot r\hat{\mathbf
/// r} - a\dot\alpha\hat{\mathbf 1} + (r - a\cos\alpha)\Omega\hat{\mathbf 2}$: the derivative of
/// eq 14 for any smooth $x_A(t), y_A(t), r(t)$ (random cubics here). Reference: eq 14's vector
/// differentiated exactly (the triad's rates by dual numbers).
pub(super) fn eq15(b: &Bench) -> Finding {
    let mut w = Worst::default();
    let mut rng = Rng::new(15);
    for (h, t) in sample(15, POINTS, RATE) {
        let k = kin1(&h, t);
        let v_scale = A * RATE;
        let mut cubic = |x0: f64| {
            let v = rng.uniform(-v_scale, v_scale);
            Cubic::random(&mut rng, x0, v, 0.5)
        };
        let (xa, ya) = (cubic(0.1), cubic(-0.2));
        let r0 = rng.uniform(-0.1, 0.1);
        let rr = {
            let v = rng.uniform(-v_scale, v_scale);
            Cubic::random(&mut rng, r0, v, 0.5)
        };
        let d = |p: &Cubic| {
            let x = p.at(Dual64::new(t, 1.0));
            (x.re, x.eps)
        };
        let ((_, xa_dot), (_, ya_dot), (r, r_dot)) = (d(&xa), d(&ya), d(&rr));
        let reference = (V::new(xa_dot, ya_dot, 0.0) + (k.axes[R_HAT] * r_dot))
            + ((k.rates[R_HAT] * r) - (k.rates[THREE] * A));
        let sc = reference.norm() + (A + r.abs()) * rate_scale(&k);
        let bind = kin_bindings(&k)
            .vector("v_cm", reference)
            .scalar("x_A_dot", xa_dot)
            .scalar("y_A_dot", ya_dot)
            .scalar("r", r)
            .scalar("r_dot", r_dot)
            .vector("x_hat", Vector3::x())
            .vector("y_hat", Vector3::y());
        printed_relations(b, 15, &bind, sc, &mut w, &|| {
            at(&k, r"$d\mathbf{r}_{\mathrm{cm}}/dt$")
        });
    }
    identity(
        "the printed derivative against eq 14 differentiated exactly",
        w,
        Stated::Relation,
    )
}

/// A steady rolling motion: constant tilt, precession and relative spin; measured: the
/// contact point's circle (centre A, signed radius r along r-hat), the centre of mass's signed
/// horizontal distance b from the circle's axis, omega_1 and Omega.
pub(super) struct Steady {
    pub(super) alpha: f64,
    pub(super) precession: f64,
    pub(super) spin: f64,
    pub(super) r: f64,
    pub(super) b: f64,
}

pub(super) fn steady(alpha: f64, precession: f64, omega_rel: f64) -> Steady {
    // omega_rel about 1 = -n is -phi_dot.
    let h = History {
        heading: Cubic::linear(0.4, precession),
        nutation: Cubic::linear(alpha, 0.0),
        face: Cubic::linear(-0.7, -omega_rel),
    };
    let k2 = kin2(&h, 0.3);
    let k = kin1(&h, 0.3);
    let v: V<f64> = k2.contact_rate.map(|x| x.re) * A;
    let acc: V<f64> = k2.contact_rate.map(|x| x.eps) * A;
    let contact = V::zeros();
    let centre = contact + curvature_centre(&v, &acc);
    let r_cm = contact - (k.axes[THREE] * A);
    Steady {
        alpha,
        precession: k.precession,
        spin: k.omega.dot(&k.axes[ONE]),
        r: (contact - centre).dot(&k.axes[R_HAT]),
        b: (r_cm - centre).dot(&k.axes[R_HAT]),
    }
}

/// The steady motions swept: tilts from 0.1 to 2.8 rad (past the vertical too), both senses of
/// precession, and relative spins chosen so that $b/a \in \{-0.3, 0, 0.5, 2\}$ (through eq 11;
/// only to place the points, the b used is measured). Half of these have $\omega_1 < 0$, against
/// the paper's sign convention for axis 1: the relations are kinematic and hold either way.
pub(super) fn steady_sweep() -> Vec<Steady> {
    let mut out = Vec::new();
    for alpha in [0.1, 0.4, 0.8, 1.2, 1.5, 2.0, 2.8] {
        for precession in [7.0, -4.0] {
            for beta in [-0.3, 0.0, 0.5, 2.0] {
                out.push(steady(
                    alpha,
                    precession,
                    precession * (f64::cos(alpha) + beta),
                ));
            }
        }
    }
    out
}

pub(super) fn steady_at(s: &Steady) -> String {
    format!(
        "$\\alpha = {:.3}$, $\\Omega = {:+.3}$, $b = {:+.4e} m$, $r = {:.4e} m$",
        s.alpha, s.precession, s.b, s.r
    )
}

/// Eq 16, $\omega_1 = b\Omega/a$ in steady motion. Reference: a steady motion rolled along the
/// rim (constant tilt, precession and relative spin); $b$ measured as the centre of mass's signed
/// horizontal distance from the axis of the contact point's circle (its centre of curvature),
/// $\omega_1 = \vec\omega\cdot\hat{\mathbf 1}$ from $\dot R R^T$.
pub(super) fn eq16(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for s in steady_sweep() {
        let bind = Bindings::new()
            .scalar("omega_1", s.spin)
            .scalar("b", s.b)
            .scalar("a", A)
            .scalar("Omega", s.precession);
        printed_relations(
            b,
            16,
            &bind,
            s.precession.abs() + s.spin.abs(),
            &mut w,
            &|| steady_at(&s),
        );
    }
    identity(
        "$b \\Omega / a$ against $\\vec\\omega \\cdot \\hat{\\mathbf{1}}$ on steady rolling, b measured on the circle",
        w,
        Stated::Relation,
    )
}

/// Eq 17, $b = r - a\cos\alpha$ (definition). Reference: on steady rolling motions, $b$ and $r$
/// measured on the circles (see eq 16).
pub(super) fn eq17(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for s in steady_sweep() {
        let bind = Bindings::new()
            .scalar("b", s.b)
            .scalar("r", s.r)
            .scalar("a", A)
            .scalar("alpha", s.alpha);
        printed_relations(b, 17, &bind, A + s.b.abs(), &mut w, &|| steady_at(&s));
    }
    identity(
        "$r - a \\cos(\\alpha)$ against the measured b on steady rolling",
        w,
        Stated::Definition,
    )
}

// ------------------------------------------------------------------------------------------
// Eqs 18-22: inertia and the dynamics
// ------------------------------------------------------------------------------------------
