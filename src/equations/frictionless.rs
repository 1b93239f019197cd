//! Checks of eqs 59-71: the disk on a frictionless table (sections 8 and 9 of the paper).
//!
//! The reference for the equations of motion (60-62) and for every linearization (64, 66-71) is
//! an independent Lagrangian of the frictionless disk, built here from geometry alone:
//! generalized coordinates $(\alpha, \psi, \phi)$ (tilt, heading of the horizontal diameter,
//! rotation of the disk about its axis), the triad constructed from them, its angular velocity
//! from $\vec\omega_{123} = \frac12\sum_i \hat{\mathbf e}_i\times\dot{\hat{\mathbf e}}_i$, the
//! centre of mass at the height of the disk's lowest rim point above the table, moving only
//! vertically, and
//! $$L = \tfrac12 m\dot h^2 + \tfrac12 k m a^2\left(|\vec\omega|^2 + (\vec\omega\cdot\hat{\mathbf 1})^2\right) - m g h.$$
//! Its Euler-Lagrange equations are evaluated numerically: the mass matrix
//! $\partial^2L/\partial\dot q\partial\dot q$, the mixed matrix $\partial^2L/\partial\dot q\partial q$
//! and the forces $\partial L/\partial q$ by hyper-dual numbers, exact to round-off, and the
//! paper's variables $\dot\alpha$, $\Omega = \vec\omega_{123}\cdot\hat{\mathbf z}$,
//! $\omega_1 = \vec\omega\cdot\hat{\mathbf 1}$ and their rates by dual numbers. Nothing of the
//! paper's eqs 60-62 enters it. The reference is generic over dual numbers, so its Jacobians (for
//! the linearizations) are exact too.

use super::{add_threshold, printed_relations, printed_threshold, term_scale, Bench, Equation};
use crate::disk::Disk;
use crate::finding::{Finding, Method, Tolerance, Verdict, Worst};
use crate::model::frictionless::Frictionless;
use crate::model::{Extras, Model, Motion};
use crate::numerics::linearize::{eigenvalues, jacobian};
use crate::numerics::oscillation::{angular_frequency, bisect};
use crate::numerics::rng::Rng;
use crate::paper::Bindings;
use crate::solve::{solve, Dynamics, Ending, Event, Problem, State};
use nalgebra::{Complex, SMatrix, Vector3};
use num_dual::{Dual, Dual64, DualNum, HyperDual};
use std::f64::consts::{FRAC_PI_2, PI};

/// The checks of this part of the paper.
pub const EQUATIONS: &[Equation] = &[
    Equation {
        number: 59,
        label: "e401",
        check: eq59,
    },
    Equation {
        number: 60,
        label: "e402",
        check: eq60,
    },
    Equation {
        number: 61,
        label: "e403",
        check: eq61,
    },
    Equation {
        number: 62,
        label: "e404",
        check: eq62,
    },
    Equation {
        number: 63,
        label: "e405",
        check: eq63,
    },
    Equation {
        number: 64,
        label: "e406",
        check: eq64,
    },
    Equation {
        number: 65,
        label: "e407",
        check: eq65,
    },
    Equation {
        number: 66,
        label: "e408",
        check: eq66,
    },
    Equation {
        number: 67,
        label: "e409",
        check: eq67,
    },
    Equation {
        number: 68,
        label: "e410",
        check: eq68,
    },
    Equation {
        number: 69,
        label: "e411",
        check: eq69,
    },
    Equation {
        number: 70,
        label: "e412",
        check: eq70,
    },
    Equation {
        number: 71,
        label: "e413",
        check: eq71,
    },
];

/// The inertia factors swept: thin shells to hoops, with the uniform disk (1/4) and hoop (1/2).
const KS: [f64; 4] = [0.1, 0.25, 0.5, 0.9];

fn disk(k: f64) -> Disk {
    Disk::new(0.0375, k, 0.4, 9.81).expect("a valid disk")
}

// ------------------------------------------------------------------ the Lagrangian reference

type V3<S> = [S; 3];

fn dot<S: DualNum<f64> + Copy>(a: V3<S>, b: V3<S>) -> S {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross<S: DualNum<f64> + Copy>(a: V3<S>, b: V3<S>) -> V3<S> {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn axpy<S: DualNum<f64> + Copy>(s: S, x: V3<S>, y: V3<S>) -> V3<S> {
    [s * x[0] + y[0], s * x[1] + y[1], s * x[2] + y[2]]
}

/// The triad of the disk at tilt `alpha` and heading `psi`, built from its verbal definition:
/// $\hat{\mathbf 2} = (\cos\psi, \sin\psi, 0)$ the horizontal diameter, $\hat{\mathbf 1}$ the
/// symmetry axis at angle $\alpha$ to the vertical, $\hat{\mathbf 3}$ in the disk's plane pointing
/// down (to the lowest rim point). Returns the vectors and their derivatives with respect to
/// alpha (a rotation by psi about z is differentiated as $\hat{\mathbf z}\times$).
fn triad<S: DualNum<f64> + Copy>(alpha: S, psi: S) -> ([V3<S>; 3], [V3<S>; 3]) {
    let (sp, cp) = psi.sin_cos();
    let (sa, ca) = alpha.sin_cos();
    let zero = S::zero();
    let e1 = [-(sa * sp), sa * cp, -ca];
    let e2 = [cp, sp, zero];
    let e3 = [ca * sp, -(ca * cp), -sa];
    let d1 = [-(ca * sp), ca * cp, sa];
    let d3 = [-(sa * sp), sa * cp, -ca];
    ([e1, e2, e3], [d1, [zero; 3], d3])
}

/// Angular velocities of the triad and of the disk, and the triad, at coordinates `q` and rates
/// `qd` (q = alpha, psi, phi).
struct Kinematics<S> {
    e: [V3<S>; 3],
    e1_dot: V3<S>,
    w_triad: V3<S>,
    w_disk: V3<S>,
}

fn kinematics<S: DualNum<f64> + Copy>(q: V3<S>, qd: V3<S>) -> Kinematics<S> {
    let (e, d_alpha) = triad(q[0], q[1]);
    let z = [S::zero(), S::zero(), S::one()];
    let rate = |i: usize| {
        axpy(qd[0], d_alpha[i], {
            let c = cross(z, e[i]);
            [qd[1] * c[0], qd[1] * c[1], qd[1] * c[2]]
        })
    };
    let dots = [rate(0), rate(1), rate(2)];
    let mut w = [S::zero(); 3];
    for i in 0..3 {
        let c = cross(e[i], dots[i]);
        w = axpy(S::from(0.5), c, w);
    }
    Kinematics {
        e,
        e1_dot: dots[0],
        w_triad: w,
        w_disk: axpy(qd[2], e[0], w),
    }
}

/// The Lagrangian divided by $m a^2$.
fn lagrangian<S: DualNum<f64> + Copy>(d: &Disk, q: V3<S>, qd: V3<S>) -> S {
    let kin = kinematics(q, qd);
    let nz = kin.e[0][2];
    let nz_dot = kin.e1_dot[2];
    // Lowest rim point: the disk's plane spans u, v with u_z^2 + v_z^2 = 1 - n_z^2, so the
    // centre is a sqrt(1 - n_z^2) above it.
    let h = (S::one() - nz * nz).sqrt(); // h / a
    let h_dot = -(nz * nz_dot) / h;
    let w = kin.w_disk;
    let w1 = dot(w, kin.e[0]);
    h_dot * h_dot * 0.5 + (dot(w, w) + w1 * w1) * (0.5 * d.k) - h * d.g_over_a()
}

/// The paper's variables $(\dot\alpha, \Omega, \omega_1)$ at coordinates `q` and rates `qd`.
fn paper_rates<S: DualNum<f64> + Copy>(q: V3<S>, qd: V3<S>) -> V3<S> {
    let kin = kinematics(q, qd);
    [qd[0], kin.w_triad[2], dot(kin.w_disk, kin.e[0])]
}

fn solve3<S: DualNum<f64> + Copy>(m: [[S; 3]; 3], r: V3<S>) -> V3<S> {
    let det3 = |c0: V3<S>, c1: V3<S>, c2: V3<S>| dot(c0, cross(c1, c2));
    let col = |j: usize| [m[0][j], m[1][j], m[2][j]];
    let d = det3(col(0), col(1), col(2));
    [
        det3(r, col(1), col(2)) / d,
        det3(col(0), r, col(2)) / d,
        det3(col(0), col(1), r) / d,
    ]
}

/// The Euler-Lagrange equations solved for $\ddot q$.
fn euler_lagrange<T: DualNum<f64> + Copy>(d: &Disk, q: V3<T>, qd: V3<T>) -> V3<T> {
    type H<T> = HyperDual<T, f64>;
    let lift = |x: V3<T>| x.map(H::<T>::from_re);
    let mut mass = [[T::zero(); 3]; 3];
    let mut mixed = [[T::zero(); 3]; 3];
    let mut force = [T::zero(); 3];
    for i in 0..3 {
        for j in 0..3 {
            if j >= i {
                let (qh, mut qdh) = (lift(q), lift(qd));
                qdh[i].eps1 = T::one();
                qdh[j].eps2 = T::one();
                mass[i][j] = lagrangian(d, qh, qdh).eps1eps2;
                mass[j][i] = mass[i][j];
            }
            let (mut qh, mut qdh) = (lift(q), lift(qd));
            qdh[i].eps1 = T::one();
            qh[j].eps2 = T::one();
            let l = lagrangian(d, qh, qdh);
            mixed[i][j] = l.eps1eps2;
            force[j] = l.eps2;
        }
    }
    let r = [0, 1, 2].map(|i| force[i] - dot(mixed[i], qd));
    solve3(mass, r)
}

/// The reference accelerations $(\ddot\alpha, \dot\Omega, \dot\omega_1)$ of the frictionless
/// disk from the Lagrangian, at the paper's variables `m` (heading and face angle are cyclic;
/// they are set to arbitrary values).
fn reference_rates<T: DualNum<f64> + Copy>(d: &Disk, m: &Motion<T>) -> V3<T> {
    let q = [m.alpha, T::from(0.7), T::from(-1.3)];
    // The paper's rates are linear in qd: columns of the map are its images of unit rates.
    let unit = |j: usize| {
        let mut u = [T::zero(); 3];
        u[j] = T::one();
        paper_rates(q, u)
    };
    let cols = [unit(0), unit(1), unit(2)];
    let a = [0, 1, 2].map(|i| [cols[0][i], cols[1][i], cols[2][i]]);
    let qd = solve3(a, [m.alpha_dot, m.precession, m.spin]);
    let qdd = euler_lagrange(d, q, qd);
    // d/dt of the paper's variables along (qd, qdd).
    let qdual = [0, 1, 2].map(|i| Dual::<T, f64>::new(q[i], qd[i]));
    let qddual = [0, 1, 2].map(|i| Dual::<T, f64>::new(qd[i], qdd[i]));
    paper_rates(qdual, qddual).map(|x| x.eps)
}

/// The Lagrangian reference as a model $(\alpha, \dot\alpha, \Omega, \omega_1)$.
struct Reference {
    disk: Disk,
}

impl Dynamics<4> for Reference {
    fn rhs(&self, y: &State<4>, dy: &mut State<4>) {
        let m = Motion {
            alpha: y[0],
            alpha_dot: y[1],
            precession: y[2],
            spin: y[3],
        };
        let r = reference_rates(&self.disk, &m);
        dy[0] = y[1];
        dy[1] = r[0];
        dy[2] = r[1];
        dy[3] = r[2];
    }
}

/// Jacobian of the reference (states alpha, alpha_dot, Omega at spin `spin`) at `y`.
fn reference_jacobian(d: &Disk, y: [f64; 3], spin: f64) -> SMatrix<f64, 3, 3> {
    jacobian(
        |y: &[Dual64; 3]| {
            let m = Motion {
                alpha: y[0],
                alpha_dot: y[1],
                precession: y[2],
                spin: Dual64::from(spin),
            };
            let r = reference_rates(d, &m);
            [y[1], r[0], r[1]]
        },
        &y,
    )
}

/// Steady motion without spin at tilt `alpha0`, derived from the reference: with omega_1 = 0
/// and no tilt rate, alpha_ddot is a quadratic in Omega without linear term (kinetic energy
/// quadratic in the rates, mirror symmetry Omega -> -Omega), so two evaluations give the Omega_0^2
/// at which it vanishes.
fn steady_precession(d: &Disk, alpha0: f64) -> f64 {
    let add = |om: f64| {
        reference_rates(
            d,
            &Motion {
                alpha: alpha0,
                alpha_dot: 0.0,
                precession: om,
                spin: 0.0,
            },
        )[0]
    };
    let (a0, a1) = (add(0.0), add(1.0));
    (-a0 / (a1 - a0)).sqrt()
}

/// Linear small oscillations about steady spinless motion at `alpha0`, from the reference:
/// Omega_0, the Jacobian, the angular frequency varpi and the complex eigenvector ratio
/// delta/epsilon (component Omega over component alpha of the eigenvector of i varpi).
struct Linear {
    omega0: f64,
    jac: SMatrix<f64, 3, 3>,
    varpi: f64,
    ratio: Complex<f64>,
}

fn linear(d: &Disk, alpha0: f64) -> Linear {
    let omega0 = steady_precession(d, alpha0);
    let jac = reference_jacobian(d, [alpha0, 0.0, omega0], 0.0);
    let ev = eigenvalues(&jac);
    let varpi = ev.iter().map(|c| c.im).fold(f64::NEG_INFINITY, f64::max);
    let l = Complex::new(0.0, varpi);
    let j = |r: usize, c: usize| Complex::new(jac[(r, c)], 0.0);
    // Rows 0 and 2 of (J - lambda I) v = 0 with v_alpha = 1.
    let (a11, a12, b1) = (j(0, 1), j(0, 2), l - j(0, 0));
    let (a21, a22, b2) = (j(2, 1), j(2, 2) - l, -j(2, 0));
    let det = a11 * a22 - a12 * a21;
    let ratio = (a11 * b2 - a21 * b1) / det;
    Linear {
        omega0,
        jac,
        varpi,
        ratio,
    }
}

// ------------------------------------------------------------------ checks

/// The paper's variables of the frictionless disk at state `m`, with the rates
/// `[alpha_ddot, Omega_dot, omega_1_dot]`, bound to the quantities of paper/symbols.yaml.
fn state_bindings(d: &Disk, m: &Motion, rates: [f64; 3]) -> Bindings<f64> {
    Bindings::new()
        .scalar("alpha", m.alpha)
        .scalar("alpha_dot", m.alpha_dot)
        .scalar("alpha_ddot", rates[0])
        .scalar("Omega", m.precession)
        .scalar("Omega_dot", rates[1])
        .scalar("omega_1", m.spin)
        .scalar("omega_1_dot", rates[2])
        .scalar("k", d.k)
        .scalar("g", d.g)
        .scalar("a", d.a)
        .scalar("m", d.m)
}

/// The largest sum of the magnitudes of the terms of a printed relation of `eq` at `bind`: the
/// round-off scale of its residual (its terms may cancel).
fn relation_scale(eq: &crate::paper::Equation, bind: &Bindings<f64>) -> f64 {
    eq.relations()
        .iter()
        .map(|r| term_scale(eq, r.lhs, bind) + term_scale(eq, r.rhs, bind))
        .fold(0.0, f64::max)
}

/// Eq 59, $\mathbf r_{cm} = a\sin\alpha\,\hat{\mathbf z}$: a model statement (no friction, so the
/// centre of mass moves only vertically; its height is fixed by the contact).
///
/// Consistency: the printed relation evaluated from its LaTeX with $\mathbf r_{cm}$ bound to the
/// centre's position above the lowest point of the rim, computed from the disk's orientation
/// alone (height $a\sqrt{u_z^2 + v_z^2}$ for any orthonormal $u, v$ spanning the disk's plane),
/// at the tilts visited by integrations of the frictionless model and at random tilts in
/// $(0, \pi)$.
pub fn eq59(b: &Bench) -> Finding {
    let mut worst = Worst::default();
    let mut rng = Rng::new(59);
    let mut alphas: Vec<f64> = (0..40).map(|_| rng.uniform(0.01, PI - 0.01)).collect();
    for &k in &KS {
        let d = disk(k);
        let model = Frictionless::<3>::new(d, 0.0, Extras::default());
        let start = Motion {
            alpha: 1.0,
            alpha_dot: 0.0,
            precession: 1.3 * d.g_over_a().sqrt(),
            spin: 0.0,
        };
        if let Ok(sol) = solve(
            Problem::new(&model, 0.0, model.state(&start), 0.5).sampled(0.05),
            &b.settings(),
        ) {
            alphas.extend(sol.y.iter().map(|y| y[0]));
        }
    }
    let a = 0.0375;
    for alpha in alphas {
        let psi = rng.uniform(-PI, PI);
        let (e, _) = triad(alpha, psi);
        // Any orthonormal pair in the disk's plane: the horizontal diameter and its normal in
        // the plane, n x u.
        let u = e[1];
        let v = cross(e[0], u);
        let height = a * (u[2] * u[2] + v[2] * v[2]).sqrt();
        let bind = Bindings::new()
            .vector("r_cm", Vector3::new(0.0, 0.0, height))
            .vector("z_hat", Vector3::z())
            .scalar("a", a)
            .scalar("alpha", alpha);
        printed_relations(b, 59, &bind, a, &mut worst, &|| {
            format!("alpha = {alpha:.4}")
        });
    }
    Finding::from_worst(
        Method::Identity,
        "eq 59 as printed, r_cm bound to the centre's height above the disk's lowest rim point (from the orientation)",
        worst,
        Tolerance::roundoff(),
        true,
    )
}

/// Random states (alpha, alpha_dot, Omega, omega_1) over the physical domain, rates in units of
/// sqrt(g/a); one in four with omega_1 = 0.
fn random_states(d: &Disk, rng: &mut Rng, n: usize) -> Vec<Motion> {
    let w = d.g_over_a().sqrt();
    (0..n)
        .map(|i| Motion {
            alpha: rng.uniform(0.05, PI - 0.05),
            alpha_dot: rng.uniform(-2.0, 2.0) * w,
            precession: rng.uniform(-4.0, 4.0) * w,
            spin: if i % 4 == 0 {
                0.0
            } else {
                rng.uniform(-3.0, 3.0) * w
            },
        })
        .collect()
}

fn squared_rate(d: &Disk, m: &Motion) -> f64 {
    d.g_over_a() + m.alpha_dot.powi(2) + m.precession.powi(2) + m.spin.powi(2)
}

fn describe(k: f64, m: &Motion) -> String {
    format!(
        "k = {k}, alpha = {:.3}, alpha_dot = {:.3}, Omega = {:.3}, omega_1 = {:.3}",
        m.alpha, m.alpha_dot, m.precession, m.spin
    )
}

/// Eq 60, $\dot\omega_1 = 0$: the spin stays constant.
///
/// On integrations of the Lagrangian reference (whose spin equation knows nothing of eq 60) from
/// random states with nonzero spin, over 2 natural times sqrt(a/g) (the reference is costly: 15
/// hyper-dual Lagrangians a step), two comparisons for each printed relation: its residual at
/// every step with the reference's own $\dot\omega_1$ (relative to $|\dot\omega_1| + g/a$ + the
/// squared rates), and the spin it implies, $\omega_1(0) + \int\dot\omega_1\,dt$ with
/// $\dot\omega_1$ solved from the printed relation at the reference's states (trapezoids over
/// the steps), against the integrated $\omega_1(t)$.
pub fn eq60(b: &Bench) -> Finding {
    let mut worst = Worst::default();
    let mut rng = Rng::new(60);
    let eq = b.paper.equation(60);
    for &k in &[0.1, 0.25, 0.9] {
        let d = disk(k);
        let model = Reference { disk: d };
        for m in random_states(&d, &mut rng, 2).iter().skip(1) {
            let y0 = State::<4>::new(m.alpha, m.alpha_dot, m.precession, m.spin);
            let t_end = 2.0 / d.g_over_a().sqrt();
            // Keep the tilt inside (0, pi): the Lagrangian's height is singular flat.
            let Ok(sol) = solve(
                Problem::new(&model, 0.0, y0, t_end)
                    .stop_when(Event::new("flat", |y: &State<4>| y[0].sin() - 0.02)),
                &b.settings(),
            ) else {
                continue;
            };
            let rels = eq.relations();
            // Per relation: the spin it implies so far, and the previous (t, rate).
            let mut implied: Vec<(f64, Option<(f64, f64)>)> = vec![(m.spin, None); rels.len()];
            for (t, y) in sol.t.iter().zip(&sol.y) {
                let s = Motion {
                    alpha: y[0],
                    alpha_dot: y[1],
                    precession: y[2],
                    spin: y[3],
                };
                let rates = reference_rates(&d, &s);
                let bind = state_bindings(&d, &s, rates);
                let scale = rates[2].abs() + squared_rate(&d, &s);
                let at = || format!("{} at t = {t:.4} s", describe(k, m));
                printed_relations(b, 60, &bind, scale, &mut worst, &at);
                for (r, (spin, prev)) in rels.iter().zip(implied.iter_mut()) {
                    if r.rel.is_inequality() {
                        continue;
                    }
                    let rate = super::solve_printed(
                        eq,
                        r,
                        "omega_1_dot",
                        &bind,
                        -1e3 * scale,
                        1e3 * scale,
                    )
                    .unwrap_or(f64::NAN);
                    if let Some((t0, r0)) = *prev {
                        *spin += 0.5 * (r0 + rate) * (t - t0);
                    }
                    *prev = Some((*t, rate));
                    worst.add(b.claim(*spin), y[3], m.spin.abs(), || {
                        format!("spin implied by eq 60 {}: {}", r.name(), at())
                    });
                }
            }
        }
    }
    Finding::from_worst(
        Method::IndependentModel,
        "eq 60 as printed at states integrated from the Lagrangian reference (residual with its rate), and the spin it implies against the integrated omega_1(t)",
        worst,
        Tolerance::solver(b.rtol),
        false,
    )
}

/// Eqs 61-62: each printed relation of eq `n` evaluated from its LaTeX at random states, with
/// the rates $(\ddot\alpha, \dot\Omega, \dot\omega_1)$ of the Lagrangian reference there; the
/// residual relative to the sum of the magnitudes of the relation's terms plus
/// $g/a + \dot\alpha^2 + \Omega^2 + \omega_1^2$.
fn residuals(b: &Bench, n: u32, seed: u64) -> Worst {
    let mut worst = Worst::default();
    let mut rng = Rng::new(seed);
    let eq = b.paper.equation(n);
    for &k in &KS {
        let d = disk(k);
        for m in random_states(&d, &mut rng, 40) {
            let bind = state_bindings(&d, &m, reference_rates(&d, &m));
            let scale = relation_scale(eq, &bind) + squared_rate(&d, &m);
            printed_relations(b, n, &bind, scale, &mut worst, &|| describe(k, &m));
        }
    }
    worst
}

/// Eq 61, the frictionless tilt equation,
/// $(k\Omega^2 + \dot\alpha^2)\sin\alpha\cos\alpha + 2k\omega_1\Omega\sin\alpha - (k + \cos^2\alpha)\ddot\alpha = \frac ga\cos\alpha$,
/// as printed, at 160 random states with the Lagrangian reference's $\ddot\alpha$.
pub fn eq61(b: &Bench) -> Finding {
    Finding::from_worst(
        Method::IndependentModel,
        "eq 61 as printed at random states, its rates from the Euler-Lagrange equations of the frictionless disk",
        residuals(b, 61, 61),
        Tolerance::roundoff(),
        false,
    )
}

/// Eq 62, $\dot\Omega\sin\alpha + 2\dot\alpha\Omega\cos\alpha + 2\omega_1\dot\alpha = 0$, as
/// printed, at 160 random states with the Lagrangian reference's $\dot\Omega$.
pub fn eq62(b: &Bench) -> Finding {
    Finding::from_worst(
        Method::IndependentModel,
        "eq 62 as printed at random states, its rates from the Euler-Lagrange equations of the frictionless disk",
        residuals(b, 62, 62),
        Tolerance::roundoff(),
        false,
    )
}

/// The vertical angular momentum about the centre of mass from geometry:
/// $\hat{\mathbf z}\cdot\mathbf I\vec\omega$ with $\mathbf I\vec\omega = k m a^2(\vec\omega + (\vec\omega\cdot\hat{\mathbf 1})\hat{\mathbf 1})$,
/// the disk's angular velocity from the reference kinematics.
fn lz_geometric(d: &Disk, m: &Motion) -> f64 {
    let q = [m.alpha, 0.4, 0.0];
    let unit = |j: usize| {
        let mut u = [0.0; 3];
        u[j] = 1.0;
        paper_rates(q, u)
    };
    let cols = [unit(0), unit(1), unit(2)];
    let a = [0, 1, 2].map(|i| [cols[0][i], cols[1][i], cols[2][i]]);
    let qd = solve3(a, [m.alpha_dot, m.precession, m.spin]);
    let kin = kinematics(q, qd);
    let w = kin.w_disk;
    let w1 = dot(w, kin.e[0]);
    d.i22() * (w[2] + w1 * kin.e[0][2])
}

/// Eq 63, $k m a^2(\Omega\sin^2\alpha - 2\omega_1\cos\alpha) = L_z$ = constant.
///
/// Along integrations of the frictionless model (eqs 60-62) from random states, each printed
/// relation evaluated from its LaTeX with $L_z$ bound to the geometric
/// $\hat{\mathbf z}\cdot\mathbf I\vec\omega$ at the current state and "constant" to its value at
/// the start: the first relation tests the formula (to round-off), the second the constancy.
/// Tolerance: the solver's.
pub fn eq63(b: &Bench) -> Finding {
    let mut worst = Worst::default();
    let mut rng = Rng::new(63);
    for &k in &KS {
        let d = disk(k);
        for m in random_states(&d, &mut rng, 3) {
            let model = Frictionless::<3>::new(d, m.spin, Extras::default());
            let initial = lz_geometric(&d, &m);
            let scale = d.i22() * (m.precession.abs() + 2.0 * m.spin.abs());
            let t_end = 8.0 / d.g_over_a().sqrt();
            let Ok(sol) = solve(
                Problem::new(&model, 0.0, model.state(&m), t_end)
                    .sampled(t_end / 40.0)
                    .stop_when(Event::new("flat", |y: &State<3>| y[0].sin() - 0.02)),
                &b.settings(),
            ) else {
                continue;
            };
            for (t, y) in sol.t.iter().zip(&sol.y) {
                let s = model.motion(y);
                let bind = state_bindings(&d, &s, [f64::NAN; 3])
                    .scalar("L_z", lz_geometric(&d, &s))
                    .scalar("L_z_initial", initial);
                printed_relations(b, 63, &bind, scale, &mut worst, &|| {
                    format!("{} at t = {t:.4} s", describe(k, &m))
                });
            }
        }
    }
    Finding::from_worst(
        Method::Conservation,
        "eq 63 as printed along frictionless integrations, L_z bound to z . I omega from geometry (now and at the start)",
        worst,
        Tolerance::solver(b.rtol),
        false,
    )
}

/// Eq 64, $\ddot\epsilon + (\Omega^2 - g/ak)\epsilon = 0$ for $\alpha = \pi/2 - \epsilon$.
///
/// The Jacobian of the Lagrangian reference at $\alpha = \pi/2$, $\dot\alpha = 0$,
/// $\omega_1 = 0$ gives the linear tilt equation $\ddot\epsilon = (\partial\ddot\alpha/\partial\alpha)\,\epsilon$;
/// the printed relation is evaluated from its LaTeX with that $\ddot\epsilon$ at amplitudes
/// $\epsilon$ = 0.3 and -0.05 (two, so that a changed power of $\epsilon$ shows), over several
/// spin rates of both signs, below and above the threshold. The couplings of $\ddot\alpha$ to
/// $\dot\alpha$ and $\Omega$, absent from the printed form, must vanish.
pub fn eq64(b: &Bench) -> Finding {
    let mut worst = Worst::default();
    for &k in &KS {
        let d = disk(k);
        for f in [-3.0, -1.2, 0.3, 0.8, 1.7, 3.0] {
            let om = f * d.g_over_a().sqrt();
            let jac = reference_jacobian(&d, [FRAC_PI_2, 0.0, om], 0.0);
            let scale = om * om + d.g / (d.a * k);
            let at = || format!("k = {k}, Omega = {om:.3}");
            for eps in [0.3, -0.05] {
                let bind = Bindings::new()
                    .scalar("tilt_from_vertical", eps)
                    .scalar("tilt_from_vertical_ddot", jac[(1, 0)] * eps)
                    .scalar("Omega", om)
                    .scalar("g", d.g)
                    .scalar("a", d.a)
                    .scalar("k", k);
                printed_relations(b, 64, &bind, scale * eps.abs(), &mut worst, &|| {
                    format!("{}, epsilon = {eps}", at())
                });
            }
            worst.add(0.0, jac[(1, 1)], scale.sqrt(), at);
            worst.add(0.0, jac[(1, 2)], scale.sqrt(), at);
        }
    }
    Finding::from_worst(
        Method::Linearization,
        "eq 64 as printed with the linear tilt equation of the Lagrangian reference's Jacobian near the vertical",
        worst,
        Tolerance::roundoff(),
        false,
    )
}

/// Eq 65, stable spinning about a vertical diameter for $|\Omega| > \sqrt{g/ak}$.
///
/// Threshold by bisection on integrations of the frictionless model started at
/// $\alpha = \pi/2 - 10^{-6}$, $\dot\alpha = 0$, $\omega_1 = 0$: unstable if the tilt from the
/// vertical doubles within $T = 120\sqrt{a/g}$. The bracket $[0.2, 20]\sqrt{g/a}$ does not use
/// the claim. A finite run cannot see growth slower than $\cosh(\sqrt{-\kappa}T) = 2$, which
/// shifts the located threshold by $(\mathrm{arccosh}\,2/T)^2/2\Omega^2$ relative (the
/// run's resolution): the tolerance is the bisection's plus twice that resolution.
pub fn eq65(b: &Bench) -> Finding {
    // Resolving this claim needs tight integrations whatever the preset (see Bench::resolving).
    let b = &b.resolving(1e-12);
    let mut worst = Worst::default();
    let width = 1e-5;
    let mut resolution: f64 = 0.0;
    for (k, sign) in [
        (0.1, 1.0),
        (0.25, 1.0),
        (0.25, -1.0),
        (0.5, 1.0),
        (0.9, 1.0),
    ] {
        let d = disk(k);
        let unit = d.g_over_a().sqrt();
        let t_end = 120.0 / unit;
        let eps0 = 1e-6;
        let unstable = |om: f64| {
            let model = Frictionless::<3>::new(d, 0.0, Extras::default());
            let y0 = State::<3>::new(FRAC_PI_2 - eps0, 0.0, sign * om);
            let sol = solve(
                Problem::new(&model, 0.0, y0, t_end)
                    .stop_when(Event::new("tilt doubled", move |y: &State<3>| {
                        2.0 * eps0 - (FRAC_PI_2 - y[0]).abs()
                    })),
                &b.settings(),
            );
            !matches!(sol.map(|s| s.ending), Ok(Ending::TimeReached))
        };
        let (lo, hi) = bisect(0.2 * unit, 20.0 * unit, width, unstable);
        let threshold = 0.5 * (lo + hi);
        resolution = resolution.max((2f64.acosh() / t_end).powi(2) / (2.0 * threshold.powi(2)));
        // The printed inequality read as a threshold on Omega (of this sign), and its direction
        // against the integrations 0.1 % either side.
        let probes = [threshold * (1.0 - 1e-3), threshold * (1.0 + 1e-3)];
        let allowed = probes.map(|x| !unstable(x));
        let bind = Bindings::new()
            .scalar("g", d.g)
            .scalar("a", d.a)
            .scalar("k", k);
        let mut printed = printed_threshold(
            b,
            65,
            "Omega",
            &bind,
            (sign * 0.2 * unit, sign * 20.0 * unit),
            probes.map(|x| sign * x),
        );
        printed.edge = printed.edge.abs();
        add_threshold(b, &mut worst, &printed, threshold, allowed, &|| {
            format!("k = {k}, Omega {}", if sign > 0.0 { "> 0" } else { "< 0" })
        });
    }
    let bis = Tolerance::bisection(width);
    let tolerance = Tolerance {
        value: bis.value + 2.0 * resolution,
        rule: format!(
            "{} plus twice the finite-run resolution (arccosh 2 / T)^2 / 2 Omega^2 = {resolution:.1e}",
            bis.rule
        ),
    };
    Finding::from_worst(
        Method::Threshold,
        "sqrt(g/ak) against the spin rate below which a nearly vertical frictionless disk falls (bisection on integrations)",
        worst,
        tolerance,
        false,
    )
}

/// The steady tilts swept in the small-oscillation checks (0 < alpha_0 < pi/2).
const ALPHA0S: [f64; 5] = [0.1, 0.4, 0.8, 1.2, 1.5];

/// Integrates the frictionless model from steady spinless motion at `alpha0` displaced along
/// the oscillating eigenvector by tilt `eps` (tilt `alpha0 + eps`, Omega `Omega0 + ratio eps`),
/// over `periods` periods sampled 40 times per period.
fn oscillate(
    b: &Bench,
    d: &Disk,
    lin: &Linear,
    alpha0: f64,
    eps: f64,
    periods: f64,
) -> Option<(Vec<f64>, Vec<State<3>>)> {
    let model = Frictionless::<3>::new(*d, 0.0, Extras::default());
    let y0 = State::<3>::new(alpha0 + eps, 0.0, lin.omega0 + lin.ratio.re * eps);
    let period = 2.0 * PI / lin.varpi;
    let sol = solve(
        Problem::new(&model, 0.0, y0, periods * period).sampled(period / 40.0),
        &b.settings(),
    )
    .ok()?;
    (sol.ending == Ending::TimeReached).then_some((sol.t, sol.y))
}

/// Eqs 66-67: the residual of the printed trial form of eq `n` (evaluated from its LaTeX) on
/// small-amplitude integrations, relative to its amplitude (`amplitude` picks epsilon or
/// |delta|), at shrinking amplitudes.
fn ansatz(b: &Bench, n: u32, amplitude: fn(f64, f64) -> f64) -> Finding {
    // Resolving this claim needs tight integrations whatever the preset (see Bench::resolving).
    let b = &b.resolving(1e-12);
    let eq = b.paper.equation(n);
    let fractions = [1e-2, 3e-3, 1e-3, 3e-4];
    let mut errors = vec![0.0f64; fractions.len()];
    for &k in &[0.25, 0.5] {
        let d = disk(k);
        for &alpha0 in &[0.3, 0.9, 1.3] {
            let lin = linear(&d, alpha0);
            for (i, f) in fractions.iter().enumerate() {
                let eps = f * alpha0;
                let delta = lin.ratio.re * eps;
                let Some((t, y)) = oscillate(b, &d, &lin, alpha0, eps, 3.0) else {
                    errors[i] = f64::INFINITY;
                    continue;
                };
                for (t, y) in t.iter().zip(&y) {
                    let bind = Bindings::new()
                        .scalar("alpha", y[0])
                        .scalar("Omega", y[2])
                        .scalar("alpha_0", alpha0)
                        .scalar("Omega_0", lin.omega0)
                        .scalar("epsilon", eps)
                        .scalar("delta", delta)
                        .scalar("varpi", lin.varpi)
                        .scalar("t", *t);
                    for r in eq.relations() {
                        let e = match (eq.scalar(r.lhs, &bind), eq.scalar(r.rhs, &bind)) {
                            (Ok(l), Ok(rr)) if !r.rel.is_inequality() => {
                                (b.claim(rr) - l).abs() / amplitude(eps, delta)
                            }
                            _ => f64::INFINITY,
                        };
                        if e.is_nan() || e > errors[i] {
                            errors[i] = if e.is_nan() { f64::INFINITY } else { e };
                        }
                    }
                }
            }
        }
    }
    let mut f = Finding::from_order(
        format!(
            "residual of eq {n}'s trial form as printed (amplitude from the reference eigenvector, \
             varpi from its eigenvalue) on frictionless integrations, relative to the amplitude, \
             against the amplitude epsilon/alpha0"
        ),
        &fractions,
        &errors,
        1.0,
    );
    if f.verdict.passes() {
        f.verdict = Verdict::Definition;
    }
    f
}

/// Eq 66, the trial form $\alpha = \alpha_0 + \epsilon\cos\varpi t$: a definition, checked for
/// consistency: on integrations of the frictionless model from steady spinless motion
/// ($\alpha_0$ = 0.3, 0.9, 1.3; k = 1/4, 1/2) started along the oscillating mode, the residual
/// of the printed form relative to $\epsilon$ must fall as $\epsilon$ (first-order ansatz).
pub fn eq66(b: &Bench) -> Finding {
    ansatz(b, 66, |eps, _| eps)
}

/// Eq 67, the trial form $\Omega = \Omega_0 + \delta\cos\varpi t$, checked like eq 66 (same
/// frequency, in phase with the tilt), relative to $|\delta|$.
pub fn eq67(b: &Bench) -> Finding {
    ansatz(b, 67, |_, delta| delta.abs())
}

fn sweep_linear(mut f: impl FnMut(&Disk, f64, &Linear, &mut Worst)) -> Worst {
    let mut worst = Worst::default();
    for &k in &KS {
        let d = disk(k);
        for &alpha0 in &ALPHA0S {
            let lin = linear(&d, alpha0);
            f(&d, alpha0, &lin, &mut worst);
        }
    }
    worst
}

/// The steady spinless motion's quantities of the small-oscillation equations.
fn linear_bindings(d: &Disk, alpha0: f64, lin: &Linear) -> Bindings<f64> {
    Bindings::new()
        .scalar("alpha_0", alpha0)
        .scalar("Omega_0", lin.omega0)
        .scalar("k", d.k)
        .scalar("g", d.g)
        .scalar("a", d.a)
}

/// Eq 68, $\delta = -2\epsilon\Omega_0\cot\alpha_0$, evaluated from its LaTeX with $\delta$
/// bound to $\epsilon$ times the ratio $\delta/\epsilon$ of the oscillating eigenvector of the
/// Lagrangian reference linearized about steady spinless motion (its steady precession derived
/// from the reference itself), at $\epsilon$ = 0.3 and -0.05; the ratio must be real.
pub fn eq68(b: &Bench) -> Finding {
    let worst = sweep_linear(|d, alpha0, lin, worst| {
        let at = || format!("k = {}, alpha0 = {alpha0}", d.k);
        for eps in [0.3, -0.05] {
            let delta = lin.ratio.re * eps;
            let bind = linear_bindings(d, alpha0, lin)
                .scalar("epsilon", eps)
                .scalar("delta", delta);
            printed_relations(b, 68, &bind, delta.abs(), worst, &|| {
                format!("{}, epsilon = {eps}", at())
            });
        }
        worst.add(0.0, lin.ratio.im, lin.ratio.re.abs(), at);
    });
    Finding::from_worst(
        Method::Linearization,
        "eq 68 as printed, delta from the eigenvector of the linearized Lagrangian reference",
        worst,
        Tolerance::roundoff(),
        false,
    )
}

/// Eq 69, the first-order part of the tilt equation:
/// $\epsilon\varpi^2(k + \cos^2\alpha_0) = \epsilon k\Omega_0^2(1 - 2\cos^2\alpha_0) - 2\delta k\Omega_0\sin\alpha_0\cos\alpha_0 - \epsilon\frac ga\sin\alpha_0$.
/// With $\alpha = \alpha_0 + \epsilon\cos\varpi t$, $\Omega = \Omega_0 + \delta\cos\varpi t$ the
/// reference's linear tilt equation reads $-\varpi^2\epsilon = J_{\alpha}\epsilon + J_{\Omega}\delta$
/// (and no $\dot\alpha$ term) for any amplitudes, not only the eigenvector's: the printed
/// relation is evaluated from its LaTeX at $\epsilon = 0.3$ and $\delta = \epsilon(\delta/\epsilon)_{\rm eig} + s\,\epsilon\Omega_0$,
/// $s \in \{0, \pm\frac12\}$, with $\varpi^2 = -(J_\alpha\epsilon + J_\Omega\delta)/\epsilon$
/// (pairs where that is not positive are skipped), so that the coefficients of $\epsilon$ and
/// $\delta$ are tested separately. Errors relative to the relation's terms.
pub fn eq69(b: &Bench) -> Finding {
    let worst = sweep_linear(|d, alpha0, lin, worst| {
        let (j_a, j_ad, j_om) = (lin.jac[(1, 0)], lin.jac[(1, 1)], lin.jac[(1, 2)]);
        let at = || format!("k = {}, alpha0 = {alpha0}", d.k);
        let eps = 0.3;
        let eq = b.paper.equation(69);
        for s in [0.0, 0.5, -0.5] {
            let delta = (lin.ratio.re + s * lin.omega0) * eps;
            let varpi2 = -(j_a * eps + j_om * delta) / eps;
            if varpi2 <= 0.0 {
                continue;
            }
            let bind = linear_bindings(d, alpha0, lin)
                .scalar("epsilon", eps)
                .scalar("delta", delta)
                .scalar("varpi", varpi2.sqrt());
            let scale = relation_scale(eq, &bind);
            printed_relations(b, 69, &bind, scale, worst, &|| {
                format!("{}, delta = {delta:.4}", at())
            });
        }
        worst.add(0.0, j_ad, j_a.abs().sqrt(), at);
    });
    Finding::from_worst(
        Method::Linearization,
        "eq 69 as printed, varpi from the linear tilt equation of the Lagrangian reference at independent epsilon and delta",
        worst,
        Tolerance::roundoff(),
        false,
    )
}

/// Eq 70, $\varpi^2(k + \cos^2\alpha_0) = k\Omega_0^2(1 + 2\cos^2\alpha_0) - \frac ga\sin\alpha_0 = 3k\Omega_0^2\cos^2\alpha_0$:
/// both printed relations evaluated from the LaTeX with $\varpi$ the eigenvalue of the Lagrangian
/// reference linearized about its own steady spinless motion $\Omega_0$. Errors relative to the
/// size of the relation's terms (they cancel near $\alpha_0 = \pi/2$, where round-off is
/// relative to them, not to their small difference).
pub fn eq70(b: &Bench) -> Finding {
    let eq = b.paper.equation(70);
    let worst = sweep_linear(|d, alpha0, lin, worst| {
        let bind = linear_bindings(d, alpha0, lin).scalar("varpi", lin.varpi);
        let scale = relation_scale(eq, &bind);
        printed_relations(b, 70, &bind, scale, worst, &|| {
            format!("k = {}, alpha0 = {alpha0}", d.k)
        });
    });
    Finding::from_worst(
        Method::Linearization,
        "eq 70 as printed (both relations), varpi and Omega0 from the linearized Lagrangian reference",
        worst,
        Tolerance::roundoff(),
        false,
    )
}

/// Eq 71, $\varpi/\Omega_0 = \sqrt{3k/(k + \cos^2\alpha_0)}\cos\alpha_0$, evaluated from its
/// LaTeX with $\varpi$ the frequency of the tilt measured on integrations of the frictionless
/// model over 10 periods, started along the oscillating mode at amplitudes
/// $\epsilon = 10^{-4}\alpha_0\cos\alpha_0$ and $2\epsilon$ (the motion's scales are $\alpha_0$
/// and, near the vertical, $\cos\alpha_0$), extrapolated to zero amplitude by Richardson
/// ($\varpi(\epsilon) = \varpi + c\epsilon^2 + O(\epsilon^4)$: the amplitude's shift is even in
/// $\epsilon$), and $\Omega_0$ the steady precession. Smaller amplitudes drown in the solver's
/// error on $\alpha$, which is relative to $\alpha_0$.
pub fn eq71(b: &Bench) -> Finding {
    // Resolving this claim needs tight integrations whatever the preset (see Bench::resolving).
    let b = &b.resolving(1e-12);
    let worst = sweep_linear(|d, alpha0, lin, worst| {
        let measure = |eps: f64| {
            oscillate(b, d, lin, alpha0, eps, 10.0).and_then(|(t, y)| {
                let x: Vec<f64> = y.iter().map(|y| y[0]).collect();
                angular_frequency(&t, &x)
            })
        };
        let eps = 1e-4 * alpha0 * alpha0.cos();
        let varpi = match (measure(eps), measure(2.0 * eps)) {
            (Some(w1), Some(w2)) => (4.0 * w1 - w2) / 3.0,
            _ => f64::NAN,
        };
        let bind = linear_bindings(d, alpha0, lin).scalar("varpi", varpi);
        printed_relations(b, 71, &bind, varpi / lin.omega0, worst, &|| {
            format!("k = {}, alpha0 = {alpha0}", d.k)
        });
    });
    Finding::from_worst(
        Method::Integration,
        "eq 71 as printed, varpi measured on small oscillations of the frictionless model",
        worst,
        Tolerance::solver(b.rtol),
        false,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::frictionless::accelerations;

    fn verdicts(f: fn(&Bench) -> Finding) -> (Finding, Finding) {
        let start = std::time::Instant::now();
        let ok = f(&Bench::default());
        eprintln!("{:?}", start.elapsed());
        let bad = f(&Bench::perturbed(1e-3));
        eprintln!(
            "{}: error {:.3e} (tol {:.1e}) at {}\n   perturbed: {} error {:.3e}",
            ok.verdict, ok.error, ok.tolerance.value, ok.at, bad.verdict, bad.error
        );
        assert_eq!(bad.verdict, Verdict::Fails, "perturbed must fail");
        (ok, bad)
    }

    /// For an equation printed as `... = 0` (eqs 62, 64), whose claimed side a relative
    /// perturbation cannot move: the printed form holds, and every mutant of its LaTeX fails.
    fn printed_holds_and_mutants_fail(n: u32, f: fn(&Bench) -> Finding) {
        let b = Bench::default();
        let ok = f(&b);
        assert_eq!(ok.verdict, Verdict::Holds, "eq {n}: {ok:?}");
        let ms = crate::paper::mutate::mutants(&b.paper.equation(n).chains);
        assert!(!ms.is_empty(), "eq {n} has no mutants");
        for m in ms {
            let paper = b.paper.with_chains(n, m.chains);
            let bad = f(&Bench::with_paper(&paper));
            assert_eq!(bad.verdict, Verdict::Fails, "eq {n}: {} survives", m.change);
        }
    }

    #[test]
    fn reference_agrees_with_itself_on_energy() {
        // The Lagrangian reference conserves its energy: a sanity check of the reference.
        let d = disk(0.25);
        let m = Motion {
            alpha: 0.8,
            alpha_dot: 3.0,
            precession: 20.0,
            spin: 5.0,
        };
        let r = reference_rates(&d, &m);
        let rates = accelerations(&d, &m);
        assert!((r[0] - rates.0).abs() < 1e-9 * (1.0 + rates.0.abs()));
        assert!((r[1] - rates.1).abs() < 1e-9 * (1.0 + rates.1.abs()));
        assert!(r[2].abs() < 1e-10);
    }

    #[test]
    fn eq59_is_a_consistent_definition() {
        assert_eq!(verdicts(eq59).0.verdict, Verdict::Definition);
    }

    #[test]
    fn eq60_holds() {
        assert_eq!(verdicts(eq60).0.verdict, Verdict::Holds);
    }

    #[test]
    fn eq61_holds() {
        assert_eq!(verdicts(eq61).0.verdict, Verdict::Holds);
    }

    #[test]
    fn eq62_holds() {
        printed_holds_and_mutants_fail(62, eq62);
    }

    #[test]
    fn eq63_holds() {
        assert_eq!(verdicts(eq63).0.verdict, Verdict::Holds);
    }

    #[test]
    fn eq64_holds() {
        printed_holds_and_mutants_fail(64, eq64);
    }

    #[test]
    fn eq65_holds() {
        assert_eq!(verdicts(eq65).0.verdict, Verdict::Holds);
    }

    #[test]
    fn eq66_is_a_consistent_definition() {
        assert_eq!(verdicts(eq66).0.verdict, Verdict::Definition);
    }

    #[test]
    fn eq67_is_a_consistent_definition() {
        assert_eq!(verdicts(eq67).0.verdict, Verdict::Definition);
    }

    #[test]
    fn eq68_holds() {
        assert_eq!(verdicts(eq68).0.verdict, Verdict::Holds);
    }

    #[test]
    fn eq69_holds() {
        assert_eq!(verdicts(eq69).0.verdict, Verdict::Holds);
    }

    #[test]
    fn eq70_holds() {
        assert_eq!(verdicts(eq70).0.verdict, Verdict::Holds);
    }

    #[test]
    fn eq71_holds() {
        assert_eq!(verdicts(eq71).0.verdict, Verdict::Holds);
    }
}
