//! Eqs 18-22: inertia, angular momentum and the equations of motion, against point-mass bodies.

use super::rolling::A;
use super::{
    at, identity, kin1, kin2, kin_bindings, lowest_rim_point, printed_relation, printed_relations,
    rate_scale, sample, Bench, Bindings, Cubic, Dual64, Finding, History, Kin, Method, Rng, Stated,
    Tolerance, Value, Vector3, Worst, D2, M, RATE, S, THREE, V,
};

/// A thin body as point masses in its body frame (plane z = 0, symmetry axis z), with the
/// inertia factor the paper states (uniform 1/4, ring 1/2) or derived here by hand
/// (annulus: $I_{22} = m(a^2 + c^2)/4$; a ring of radius $\rho$: $k = \rho^2 / 2a^2$).
pub(super) struct Body {
    pub(super) name: &'static str,
    pub(super) k: f64,
    pub(super) points: Vec<(V<f64>, f64)>,
}

pub(super) const MASS: f64 = 0.4;
pub(super) const G: f64 = 9.81;

/// Point masses of a thin annulus between radii `inner` and `outer` (3-point Gauss-Legendre in
/// the radius with weight r, exact to degree 5; 12 equal angles, exact for the quadratic
/// moments), or a ring when they are equal. Total mass `MASS`.
pub(super) fn plate(inner: f64, outer: f64) -> Vec<(V<f64>, f64)> {
    let gl = [
        (-(0.6f64).sqrt(), 5.0 / 9.0),
        (0.0, 8.0 / 9.0),
        ((0.6f64).sqrt(), 5.0 / 9.0),
    ];
    let radial: Vec<(f64, f64)> = if inner == outer {
        vec![(outer, 1.0)]
    } else {
        gl.iter()
            .map(|&(x, wt)| {
                let r = 0.5 * (outer + inner) + 0.5 * (outer - inner) * x;
                (r, wt * r)
            })
            .collect()
    };
    let n = 12;
    let total: f64 = radial.iter().map(|p| p.1).sum::<f64>() * n as f64;
    let mut out = Vec::new();
    for &(r, wt) in &radial {
        for j in 0..n {
            let th = 0.3 + 2.0 * std::f64::consts::PI * j as f64 / n as f64;
            out.push((V::new(r * th.cos(), r * th.sin(), 0.0), MASS * wt / total));
        }
    }
    out
}

pub(super) fn bodies() -> Vec<Body> {
    vec![
        Body {
            name: "uniform disk ($k = 1/4$)",
            k: 0.25,
            points: plate(0.0, A),
        },
        Body {
            name: "ring ($k = 1/2$)",
            k: 0.5,
            points: plate(A, A),
        },
        Body {
            name: "annulus $c = a/2$ ($k = 5/16$)",
            k: 5.0 / 16.0,
            points: plate(0.5 * A, A),
        },
        Body {
            name: "ring at radius $a \\sqrt{0.2}$ ($k = 0.1$)",
            k: 0.1,
            points: plate(A * 0.2f64.sqrt(), A * 0.2f64.sqrt()),
        },
    ]
}

/// The inertia tensor about the centre in body axes, summed over the point masses.
pub(super) fn inertia(points: &[(V<f64>, f64)]) -> M<f64> {
    points.iter().fold(M::zeros(), |i, (p, m)| {
        i + (M::identity() * p.dot(p) - p * p.transpose()) * *m
    })
}

/// Eq 18, $I_{11} = 2kma^2$, $I_{22} = kma^2 = I_{33}$ (definition). Reference: the inertia
/// tensor summed over point masses of a uniform disk, a ring, an annulus and a smaller ring;
/// $k$ as the paper states it (1/4, 1/2) or derived by hand; off-diagonal entries must vanish.
pub(super) fn eq18(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for body in bodies() {
        let i = inertia(&body.points);
        let unit = body.k * MASS * A * A;
        // Body axes: symmetry axis z is 1-hat; x and y are diameters.
        let bind = Bindings::new()
            .scalar("I_11", i[(2, 2)])
            .scalar("I_22", i[(0, 0)])
            .scalar("I_33", i[(1, 1)])
            .scalar("k", body.k)
            .scalar("m", MASS)
            .scalar("a", A);
        printed_relations(b, 18, &bind, unit, &mut w, &|| {
            format!("the principal moments of the {}", body.name)
        });
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            w.add(0.0, i[(p, q)], unit, || {
                format!("off-diagonal I[{p}][{q}] of the {}", body.name)
            });
        }
    }
    identity(
        "the principal moments against quadratures of thin disks and rings",
        w,
        Stated::Definition,
    )
}

/// The inertia tensor in the lab, $R I_{body} R^T$.
pub(super) fn lab_tensor(rot: &M<f64>, i_body: &M<f64>) -> M<f64> {
    rot * i_body * rot.transpose()
}

/// The angular momentum about the centre in the lab, $R I_{body} R^T\vec\omega$.
pub(super) fn l_lab<T: S>(rot: &M<T>, i_body: &M<f64>, omega: &V<T>) -> V<T> {
    // I_body is of plain numbers: lifted entry by entry to the duals of the motion.
    rot * (i_body.map(T::from) * rot.tr_mul(omega))
}

/// Eq 19, $\mathbf L_{cm} = \mathbf I\cdot\vec\omega = kma^2(2\omega_1\hat{\mathbf 1} +
/// \dot\alpha\hat{\mathbf 2} - \Omega\sin\alpha\hat{\mathbf 3})$. Reference: $R I_{body} R^T
/// \vec\omega$ in the lab, $I_{body}$ summed over point masses, projected on the triad.
pub(super) fn eq19(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for (n, body) in bodies().iter().enumerate() {
        let i_body = inertia(&body.points);
        for (h, t) in sample(190 + n as u64, 50, RATE) {
            let k = kin1(&h, t);
            let l = l_lab(&k.rot, &i_body, &k.omega);
            let unit = body.k * MASS * A * A;
            let i_lab = lab_tensor(&k.rot, &i_body);
            let bind = kin_bindings(&k)
                .vector("L_cm", l)
                .value("I_tensor", Value::Tensor(i_lab))
                .scalar("k", body.k)
                .scalar("m", MASS);
            printed_relations(b, 19, &bind, unit * rate_scale(&k), &mut w, &|| {
                at(
                    &k,
                    &format!("$\\mathbf{{L}}_{{\\mathrm{{cm}}}}$ for the {}", body.name),
                )
            });
        }
    }
    identity(
        "the triad components of $\\mathbf{L}_{\\mathrm{cm}}$ against $R I_{\\mathrm{body}} R^{T} \\omega$ ($I_{\\mathrm{body}}$ by quadrature)",
        w,
        Stated::Relation,
    )
}

/// A random rigid motion of a body of point masses: its centre moving on a random cubic path.
/// Returns, at the sampled instant, the kinematics (with second derivatives), the centre's
/// acceleration and the point masses' lab offsets and accelerations.
pub(super) struct Particles {
    k: Kin<Dual64>,
    acc_cm: V<f64>,
    offsets: Vec<(V<f64>, V<f64>, f64)>,
}

pub(super) fn particles(h: &History, t: f64, rng: &mut Rng, body: &Body) -> Particles {
    let k = kin2(h, t);
    let acc_scale = G;
    let path: Vec<Cubic> = (0..3)
        .map(|_| {
            Cubic([
                0.0,
                rng.uniform(-1.0, 1.0),
                rng.uniform(-acc_scale, acc_scale),
                rng.uniform(-acc_scale, acc_scale),
            ])
        })
        .collect();
    let td = D2::new(Dual64::new(t, 1.0), Dual64::new(1.0, 0.0));
    let acc_cm: V<f64> = V::from_fn(|i, _| path[i].at(td).eps.eps);
    let rot: M<f64> = k.rot.map(|x| x.re);
    let rot_dd: M<f64> = k.rot_dot.map(|x| x.eps);
    let offsets = body
        .points
        .iter()
        .map(|(p, m)| (rot * p, acc_cm + rot_dd * p, *m))
        .collect();
    Particles { k, acc_cm, offsets }
}

/// Eq 20, $m\,d^2\mathbf r_{cm}/dt^2 = \mathbf F - mg\hat{\mathbf z}$. Reference: a body of point
/// masses in a random rigid motion, each obeying Newton's law under gravity, internal forces
/// (which cancel in pairs) and its share of the external force; the external non-gravitational
/// force is then $\mathbf F = \sum_i m_i(\ddot{\mathbf x}_i + g\hat{\mathbf z})$. Claimed:
/// $m\ddot{\mathbf r}_{cm}$ of the body's centre against $\mathbf F - mg\hat{\mathbf z}$.
pub(super) fn eq20(b: &Bench) -> Finding {
    let mut w = Worst::default();
    let mut rng = Rng::new(20);
    for body in bodies() {
        for (h, t) in sample(200, 25, RATE) {
            let p = particles(&h, t, &mut rng, &body);
            let force: V<f64> = p
                .offsets
                .iter()
                .fold(V::zeros(), |s, (_, acc, m)| s + (acc + V::z() * G) * *m);
            let sc = MASS * (G + p.acc_cm.norm());
            let bind = Bindings::new()
                .scalar("m", MASS)
                .scalar("g", G)
                .vector("a_cm", p.acc_cm)
                .vector("F", force)
                .vector("z_hat", Vector3::z());
            printed_relations(b, 20, &bind, sc, &mut w, &|| {
                format!(
                    "$m \\, d^2\\mathbf{{r}}_{{\\mathrm{{cm}}}}/dt^2$ for the {}",
                    body.name
                )
            });
        }
    }
    identity(
        "$m \\, d^2\\mathbf{r}_{\\mathrm{cm}}/dt^2$ against $\\mathbf{F} - m g \\hat{\\mathbf{z}}$ summed over the point masses of a rigid body",
        w,
        Stated::Relation,
    )
    .in_unit("N")
}

/// Eq 21, $d\mathbf L_{cm}/dt = \mathbf N_{cm} = \mathbf a\times\mathbf F$. Reference: the same
/// point-mass body; the torque about the centre of the external forces is $\sum_i m_i\boldsymbol
/// \rho_i\times\ddot{\mathbf x}_i$ (internal central forces give none; gravity's,
/// $-\sum_i m_i\boldsymbol\rho_i\times g\hat{\mathbf z}$, vanishes about the centre of mass and is
/// kept in the sum). Claimed: the rate of $\mathbf L_{cm} = R I_{body}R^T\vec\omega$, exact by
/// dual numbers.
///
/// The second equality, $\mathbf N_{cm} = \mathbf a\times\mathbf F$, is the torque of the one
/// force the table exerts, at the contact point. Reference, without a cross product of
/// $\mathbf a$ and $\mathbf F$: the torque is the generalized force of a rotation, the gradient
/// in $\vec\omega$ of the power $\mathbf F\cdot\mathbf v_P$ that the force delivers at the body
/// point $P$ it acts on, whose velocity relative to the centre is $\vec\omega\times\mathbf r_P$;
/// $P$ is found on the rim (its lowest point, [`lowest_rim_point`]), and $\mathbf F = m(\ddot
/// {\mathbf r}_{cm} + g\hat{\mathbf z})$ on rolling motions (eq 20's reference). The gradient is
/// taken by dual numbers, one seed per component of $\vec\omega$.
pub(super) fn eq21(b: &Bench) -> Finding {
    let mut w = Worst::default();
    let mut rng = Rng::new(21);
    for body in bodies() {
        let i_body = inertia(&body.points);
        for (h, t) in sample(210, 25, RATE) {
            let p = particles(&h, t, &mut rng, &body);
            let torque = p.offsets.iter().fold(V::zeros(), |s, (rho, acc, m)| {
                s + rho.cross(&(acc + V::z() * G)) * *m
            });
            let gravity = p.offsets.iter().fold(V::zeros(), |s, (rho, _, m)| {
                s + rho.cross(&V::z()) * (-*m * G)
            });
            let reference = torque + gravity;
            let l = l_lab(&p.k.rot, &i_body, &p.k.omega);
            let l_dot: V<f64> = l.map(|x| x.eps);
            let omega: V<f64> = p.k.omega.map(|x| x.re);
            let omega_dot: V<f64> = p.k.omega.map(|x| x.eps);
            let rates = omega.norm();
            let sc = body.k * MASS * A * A * (rates * rates + omega_dot.norm()) + reference.norm();
            let bind = Bindings::new()
                .vector("L_cm_rate", l_dot)
                .vector("N_cm", reference);
            printed_relation(b, 21, 0, &bind, sc, &mut w, &|| {
                format!(
                    "$d\\mathbf{{L}}_{{\\mathrm{{cm}}}}/dt$ for the {}",
                    body.name
                )
            });
        }
    }
    for (h, t) in sample(211, 25, RATE) {
        let k = kin1(&h, t);
        let k2 = kin2(&h, t);
        let acc: V<f64> = (k2.contact_rate - k2.rates[THREE]).map(|x| x.eps) * A;
        let force = (acc + V::z() * G) * MASS;
        let r_p = lowest_rim_point(&k);
        let torque = power_gradient(&force, &r_p);
        let bind = Bindings::new()
            .vector("N_cm", torque)
            .vector("a_vec", r_p)
            .vector("F", force);
        let sc = A * force.norm();
        printed_relation(b, 21, 1, &bind, sc, &mut w, &|| {
            format!(
                "$\\mathbf{{N}}_{{\\mathrm{{cm}}}}$ of the contact force, $\\alpha = {:.3}$",
                k.alpha
            )
        });
    }
    identity(
        "$d\\mathbf{L}_{\\mathrm{cm}}/dt$ of $R I R^{T} \\vec\\omega$ against the torque summed over point masses; the contact \
         force's torque against the gradient in $\\omega$ of the power it delivers",
        w,
        Stated::Relation,
    )
}

/// The torque of a force `f` acting at the body point `r_p` (from the centre): the gradient in
/// $\vec\omega$ of the power $\mathbf f\cdot(\vec\omega\times\mathbf r_P)$, by dual numbers.
fn power_gradient(f: &Vector3<f64>, r_p: &Vector3<f64>) -> Vector3<f64> {
    Vector3::from_fn(|i, _| {
        let omega: V<Dual64> = V::from_fn(|j, _| Dual64::new(0.0, if i == j { 1.0 } else { 0.0 }));
        let r: V<Dual64> = r_p.map(Dual64::from);
        omega.cross(&r).dot(&f.map(Dual64::from)).eps
    })
}

/// Eq 22, $\frac{1}{ma}\frac{d\mathbf L_{cm}}{dt} + \frac{d^2\mathbf r_{cm}}{dt^2}\times
/// \hat{\mathbf 3} = g\hat{\mathbf 3}\times\hat{\mathbf z}$: eqs 20 and 21 with the force
/// eliminated. For ANY motion of a rolling disk (built along its rim, second derivatives by
/// nested duals, $\mathbf L_{cm} = R I_{body}R^T\vec\omega$), eq 20 defines the contact force
/// $\mathbf F = m(\ddot{\mathbf r}_{cm} + g\hat{\mathbf z})$ and the residual of eq 21 is
/// $\boldsymbol\rho = \dot{\mathbf L}_{cm} - a\hat{\mathbf 3}\times\mathbf F$; eq 22's residual
/// (its left side minus its right) must equal $\boldsymbol\rho/ma$, so that eq 22 holds exactly
/// when eq 21 does. Claimed: eq 22's left side.
///
/// The sides are read in either order, and the relation up to its sign: `b = a` and `-a = -b`
/// are the same equation as `a = b`, so the side that holds $d\mathbf L_{cm}/dt$ is taken as the
/// claimed one ([`eq22_oriented`]) and the residual is signed so that its coefficient of
/// $d\mathbf L_{cm}/dt$ is positive, as printed.
pub(super) fn eq22(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for body in bodies() {
        let i_body = inertia(&body.points);
        for (h, t) in sample(220, 50, RATE) {
            let k = kin2(&h, t);
            let three: V<f64> = k.axes[THREE].map(|x| x.re);
            let acc: V<f64> = (k.contact_rate - k.rates[THREE]).map(|x| x.eps) * A;
            let l = l_lab(&k.rot, &i_body, &k.omega);
            let l_dot: V<f64> = l.map(|x| x.eps);
            let force = (acc + V::z() * G) * MASS;
            let residual21 = l_dot - (three * A).cross(&force);
            let bind = |l: V<f64>| {
                Bindings::new()
                    .scalar("m", MASS)
                    .scalar("a", A)
                    .scalar("g", G)
                    .vector("L_cm_rate", l)
                    .vector("a_cm", acc)
                    .vector("e3", three)
                    .vector("z_hat", Vector3::z())
            };
            let (lhs, rhs) = eq22_oriented(b, l_dot, &bind);
            let sc = G + lhs.norm();
            for i in 0..3 {
                w.add(
                    b.claim(lhs[i]) - rhs[i],
                    residual21[i] / (MASS * A),
                    sc,
                    || {
                        format!(
                            "component {} of eq 22's residual for the {}, $\\alpha = {:.3}$",
                            ["x", "y", "z"][i],
                            body.name,
                            k.alpha.re
                        )
                    },
                );
            }
        }
    }
    Finding::from_worst(
        Method::Derivation,
        "eq 22's residual against eq 21's residual / (m a), F from eq 20, on rolling motions",
        w,
        Tolerance::roundoff(),
    )
    .in_unit("m/s^2")
}

/// Eq 22's two sides at `bind(l_dot)`, `l_dot` the rate $d\mathbf L_{cm}/dt$, the side that holds $d\mathbf L_{cm}/dt$ first (the
/// left side where both or neither do), each multiplied by the sign that makes the coefficient
/// of $d\mathbf L_{cm}/dt$ in first minus second positive (+1 where it is zero). Either order of
/// the printed sides, and both sides negated, give the same two vectors to the bit; a side that
/// cannot be evaluated is NaN.
fn eq22_oriented(
    b: &Bench,
    l_dot: V<f64>,
    bind: &dyn Fn(V<f64>) -> Bindings<f64>,
) -> (V<f64>, V<f64>) {
    let eq = b.paper.equation(22);
    let Some(rel) = eq.relations().into_iter().next() else {
        return (V::repeat(f64::NAN), V::repeat(f64::NAN));
    };
    let at = |l: V<f64>| {
        let bound = bind(l);
        let side = |e| {
            eq.eval(e, &bound)
                .and_then(|v| v.vector())
                .unwrap_or(V::repeat(f64::NAN))
        };
        (side(rel.lhs), side(rel.rhs))
    };
    let (lhs, rhs) = at(l_dot);
    // The change of each side when dL_cm/dt changes by one unit along x.
    let (lhs_x, rhs_x) = at(l_dot + V::x());
    let (dl, dr) = ((lhs_x - lhs).x, (rhs_x - rhs).x);
    let (claimed, other, slope) = if dl == 0.0 && dr != 0.0 {
        (rhs, lhs, dr - dl)
    } else {
        (lhs, rhs, dl - dr)
    };
    if slope < 0.0 {
        (-claimed, -other)
    } else {
        (claimed, other)
    }
}
