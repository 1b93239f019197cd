//! Eqs 59-63: the frictionless equations of motion and their constants, against the Lagrangian.

use super::{
    coordinate_rates, kinematics, printed_relations, reference_rates, relation_scale, solve,
    state_bindings, triad, Bench, Bindings, Disk, Event, Extras, Finding, Frictionless, Method,
    Model, Motion, Problem, Reference, Rng, State, Tolerance, Vector3, Worst, KS, PI, V3,
};
use physics::disk::toy_sized;

/// Eq 59, $\mathbf r_{cm} = a\sin\alpha\,\hat{\mathbf z}$: a model statement (no friction, so the
/// centre of mass moves only vertically; its height is fixed by the contact).
///
/// Consistency: the printed relation evaluated from its LaTeX with $\mathbf r_{cm}$ bound to the
/// centre's position above the lowest point of the rim, computed from the disk's orientation
/// alone (height $a\sqrt{u_z^2 + v_z^2}$ for any orthonormal $u, v$ spanning the disk's plane),
/// at the tilts visited by integrations of the frictionless model and at random tilts in
/// $(0, \pi)$.
pub(super) fn eq59(b: &Bench) -> Finding {
    let mut worst = Worst::default();
    let mut rng = Rng::new(59);
    let mut alphas: Vec<f64> = (0..40).map(|_| rng.uniform(0.01, PI - 0.01)).collect();
    for &k in &KS {
        let d = toy_sized(k);
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
        let v = e[0].cross(&u);
        let height = a * (u[2] * u[2] + v[2] * v[2]).sqrt();
        let bind = Bindings::new()
            .vector("r_cm", Vector3::new(0.0, 0.0, height))
            .vector("z_hat", Vector3::z())
            .scalar("a", a)
            .scalar("alpha", alpha);
        printed_relations(b, 59, &bind, a, &mut worst, &|| {
            format!("$\\alpha = {alpha:.4}$")
        });
    }
    Finding::definition(
        Method::Identity,
        "eq 59 as printed, $\\mathbf{r}_{\\mathrm{cm}}$ bound to the centre's height above the disk's lowest rim point (from the orientation)",
        worst,
        Tolerance::roundoff())
}

/// Random states (alpha, alpha_dot, Omega, omega_1) over the physical domain, rates in units of
/// sqrt(g/a); one in four with omega_1 = 0.
pub(super) fn random_states(d: &Disk, rng: &mut Rng, n: usize) -> Vec<Motion> {
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

pub(super) fn squared_rate(d: &Disk, m: &Motion) -> f64 {
    d.g_over_a() + m.alpha_dot.powi(2) + m.precession.powi(2) + m.spin.powi(2)
}

pub(super) fn describe(k: f64, m: &Motion) -> String {
    format!(
        "$k = {k}$, $\\alpha = {:.3}$, $\\dot\\alpha = {:.3}$, $\\Omega = {:.3}$, $\\omega_1 = {:.3}$",
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
pub(super) fn eq60(b: &Bench) -> Finding {
    let mut worst = Worst::default();
    let mut rng = Rng::new(60);
    let eq = b.paper.equation(60);
    for &k in &[0.1, 0.25, 0.9] {
        let d = toy_sized(k);
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
                let s = Motion::from_state(y.as_slice(), y[3]);
                let rates = reference_rates(&d, &s);
                let bind = state_bindings(&d, &s, rates);
                let scale = rates[2].abs() + squared_rate(&d, &s);
                let at = || format!("{} at $t = {t:.4}$ s", describe(k, m));
                printed_relations(b, 60, &bind, scale, &mut worst, &at);
                for (r, (spin, prev)) in rels.iter().zip(implied.iter_mut()) {
                    if r.rel.is_inequality() {
                        continue;
                    }
                    let rate = crate::harness::solve_printed(
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
                    worst.add_in(b.claim(*spin), y[3], m.spin.abs(), "rad/s", || {
                        format!("spin implied by eq 60 {}: {}", r.name(), at())
                    });
                }
            }
        }
    }
    Finding::from_worst(
        Method::IndependentModel,
        "eq 60 as printed at states integrated from the Lagrangian reference (residual with its rate), and the spin it implies against the integrated $\\omega_1(t)$",
        worst,
        Tolerance::solver(b.rtol))
}

/// Eqs 61-62: each printed relation of eq `n` evaluated from its LaTeX at random states, with
/// the rates $(\ddot\alpha, \dot\Omega, \dot\omega_1)$ of the Lagrangian reference there; the
/// residual relative to the sum of the magnitudes of the relation's terms plus
/// $g/a + \dot\alpha^2 + \Omega^2 + \omega_1^2$.
pub(super) fn residuals(b: &Bench, n: u32, seed: u64) -> Worst {
    let mut worst = Worst::default();
    let mut rng = Rng::new(seed);
    let eq = b.paper.equation(n);
    for &k in &KS {
        let d = toy_sized(k);
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
pub(super) fn eq61(b: &Bench) -> Finding {
    Finding::from_worst(
        Method::IndependentModel,
        "eq 61 as printed at random states, its rates from the Euler-Lagrange equations of the frictionless disk",
        residuals(b, 61, 61),
        Tolerance::roundoff())
    .in_unit("1/s^2")
}

/// Eq 62, $\dot\Omega\sin\alpha + 2\dot\alpha\Omega\cos\alpha + 2\omega_1\dot\alpha = 0$, as
/// printed, at 160 random states with the Lagrangian reference's $\dot\Omega$.
pub(super) fn eq62(b: &Bench) -> Finding {
    Finding::from_worst(
        Method::IndependentModel,
        "eq 62 as printed at random states, its rates from the Euler-Lagrange equations of the frictionless disk",
        residuals(b, 62, 62),
        Tolerance::roundoff())
    .in_unit("rad/s^2")
}

/// The vertical angular momentum about the centre of mass from geometry:
/// $\hat{\mathbf z}\cdot\mathbf I\vec\omega$ with $\mathbf I\vec\omega = k m a^2(\vec\omega + (\vec\omega\cdot\hat{\mathbf 1})\hat{\mathbf 1})$,
/// the disk's angular velocity from the reference kinematics.
pub(super) fn lz_geometric(d: &Disk, m: &Motion) -> f64 {
    let q = V3::new(m.alpha, 0.4, 0.0);
    let kin = kinematics(q, coordinate_rates(q, m));
    let w = kin.w_disk;
    let w1 = w.dot(&kin.e[0]);
    d.i22() * (w[2] + w1 * kin.e[0][2])
}

/// Eq 63, $k m a^2(\Omega\sin^2\alpha - 2\omega_1\cos\alpha) = L_z$ = constant.
///
/// Along integrations of the frictionless model (eqs 60-62) from random states, each printed
/// relation evaluated from its LaTeX with $L_z$ bound to the geometric
/// $\hat{\mathbf z}\cdot\mathbf I\vec\omega$ at the current state and "constant" to its value at
/// the start: the first relation tests the formula (to round-off), the second the constancy.
/// Tolerance: the solver's.
pub(super) fn eq63(b: &Bench) -> Finding {
    let mut worst = Worst::default();
    let mut rng = Rng::new(63);
    for &k in &KS {
        let d = toy_sized(k);
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
                let bind = state_bindings(&d, &s, V3::repeat(f64::NAN))
                    .scalar("L_z", lz_geometric(&d, &s))
                    .scalar("L_z_initial", initial);
                printed_relations(b, 63, &bind, scale, &mut worst, &|| {
                    format!("{} at $t = {t:.4}$ s", describe(k, &m))
                });
            }
        }
    }
    Finding::from_worst(
        Method::Conservation,
        "eq 63 as printed along frictionless integrations, $L_z$ bound to $\\hat{\\mathbf{z}} \\cdot I \\boldsymbol\\omega$ from geometry (now and at the start)",
        worst,
        Tolerance::solver(b.rtol))
}
