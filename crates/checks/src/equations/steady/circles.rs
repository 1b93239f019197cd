//! Eqs 27-32 and 38-40: steady motion's rates, radii and thresholds, against motions solved and measured on the model.

use super::super::steady_reference::{
    measure_b_r, rho_edge, rhos, steady_bindings, steady_drift, steady_exists, steady_ref, ALPHAS,
    KS,
};
use super::{
    add_threshold, at, contact_force, printed_relations, printed_threshold, rates, solve,
    solve_printed, solve_printed_with, Bench, Bindings, Disk, Extras, Finding, Method, Model,
    Motion, Problem, Rolling, Tolerance, Worst, PI,
};
use physics::disk::toy_sized;

/// Eq 27, the steady balance
/// $k\Omega_0^2\sin\alpha_0\cos\alpha_0 + (2k+1)\omega_{10}\Omega_0\sin\alpha_0 = \frac{g}{a}\cos\alpha_0$.
///
/// Integration: at each tilt and ratio $\omega_{10}/\Omega_0$, the $\Omega_0$ that eq 27 gives
/// is the start of an integration of the rolling model over two precession periods; the claim
/// holds if $\alpha$, $\Omega$ and $\omega_1$ stay constant to the solver's accuracy (a wrong
/// $\Omega_0$ makes the disk nutate with an amplitude proportional to the error).
pub(super) fn eq27(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for k in KS {
        let d = toy_sized(k);
        for alpha0 in [0.1, 0.5, 1.0] {
            for rho in rhos(&d, alpha0) {
                // Eq 27 as printed, solved for Omega_0 with omega_10 = rho Omega_0.
                let sign = if rho < 0.0 { -1.0 } else { 1.0 };
                let unit = d.g_over_a().sqrt();
                let eq = b.paper.equation(27);
                let bind_at = |x: f64| {
                    steady_bindings(&d, alpha0)
                        .scalar("Omega_0", x)
                        .scalar("omega_10", rho * x)
                };
                let om = eq
                    .relations()
                    .first()
                    .and_then(|rel| {
                        solve_printed_with(eq, rel, &bind_at, sign * 1e-3 * unit, sign * 1e3 * unit)
                    })
                    .map_or(f64::NAN, |x| b.claim(x));
                let m = Motion {
                    alpha: alpha0,
                    alpha_dot: 0.0,
                    precession: om,
                    spin: rho * om,
                };
                let drift = steady_drift(b, &d, &m, 2.0);
                w.add(drift, 0.0, 1.0, || {
                    format!(
                        "{}; largest relative drift of ($\\alpha$, $\\Omega$, $\\omega_1$) over 2 precession periods",
                        at(k, alpha0, rho)
                    )
                });
            }
        }
    }
    Finding::from_worst(
        Method::Integration,
        "drift of $\\alpha$, $\\Omega$, $\\omega_1$ started at eq 27's steady state",
        w,
        Tolerance::solver(b.rtol),
    )
    .in_unit("1")
}

/// Every steady motion of the sweep (the inertia factors [`KS`], the tilts [`ALPHAS`], the
/// ratios of `rhos`) that the model has, with $b$ and $r$ measured on its integrated path:
/// `visit(disk, k, alpha0, rho, motion, b, r)`.
fn measured_steady(b: &Bench, mut visit: impl FnMut(&Disk, f64, f64, f64, &Motion, f64, f64)) {
    for k in KS {
        let d = toy_sized(k);
        for alpha0 in ALPHAS {
            for rho in rhos(&d, alpha0) {
                let Some(m) = steady_ref(&d, alpha0, rho) else {
                    continue;
                };
                let (bb, r) = measure_b_r(b, &d, &m);
                visit(&d, k, alpha0, rho, &m, bb, r);
            }
        }
    }
}

/// Eq 28, $\omega_{10} = \frac{b}{a}\Omega_0 = \Omega_0\left(\frac{r}{a} - \cos\alpha_0\right)$.
///
/// Integration: steady motions solved from the model (Newton on eq 24); $b$ and $r$ measured on
/// the integrated path of the centre of mass; both forms of the claim are compared with the
/// state's $\omega_{10}$ (relative to $|\Omega_0|$, since $\omega_{10}$ vanishes at $b = 0$).
pub(super) fn eq28(b: &Bench) -> Finding {
    let mut w = Worst::default();
    measured_steady(b, |d, k, alpha0, rho, m, bb, r| {
        let bind = steady_bindings(d, alpha0)
            .scalar("b", bb)
            .scalar("r", r)
            .scalar("Omega_0", m.precession)
            .scalar("omega_10", m.spin);
        printed_relations(b, 28, &bind, m.precession.abs(), &mut w, &|| {
            format!("{}; b and r measured on the path", at(k, alpha0, rho))
        });
    });
    Finding::from_worst(
        Method::Integration,
        "both printed relations of eq 28 at the model's steady spin and the measured b, r, relative to $|\\Omega_0|$",
        w,
        Tolerance::solver(b.rtol))
}

/// Eq 29, $\Omega_0^2 = \dfrac{g\cot\alpha_0}{k a\cos\alpha_0 + (2k+1)b}
/// = \dfrac{g\cot\alpha_0}{(2k+1)r - (k+1)a\cos\alpha_0}$.
///
/// Integration and derivation: the steady motion is solved from the model (Newton on eq 24 at a
/// ratio $\omega_{10}/\Omega_0$), $b$ and $r$ are measured on its integrated path, and both
/// forms of eq 29 at the measured $b$, $r$ are compared with the solved $\Omega_0^2$. Tilts
/// 0.1-1.4, $b$ negative (half way to eq 30's edge found numerically), zero and positive.
pub(super) fn eq29(b: &Bench) -> Finding {
    let mut w = Worst::default();
    measured_steady(b, |d, k, alpha0, rho, m, bb, r| {
        let bind = steady_bindings(d, alpha0)
            .scalar("b", bb)
            .scalar("r", r)
            .scalar("Omega_0", m.precession);
        let om2 = m.precession * m.precession;
        printed_relations(b, 29, &bind, om2, &mut w, &|| at(k, alpha0, rho));
    });
    Finding::from_worst(
        Method::Integration,
        "both printed forms of eq 29 at the measured b and r against the model's steady $\\Omega_0^{2}$",
        w,
        Tolerance::solver(b.rtol),
    )
    .in_unit("rad^2/s^2")
}

/// Eq 30, $b > -\dfrac{a k\cos\alpha_0}{2k+1}$.
///
/// Threshold: the most negative ratio $\rho = \omega_{10}/\Omega_0$ at which the model's eq 24
/// still has a real steady $\Omega_0$ is located by bisection (the coefficient of $\Omega^2$ in
/// $\ddot\alpha$ changes sign there and $\Omega_0^2$ diverges); $b = \rho a$ by the kinematics
/// verified in eq 28's check. Compared with the edge the printed inequality gives (solved for
/// $b$), and its direction with the model's at $b$ 0.1 % either side of the edge.
pub(super) fn eq30(b: &Bench) -> Finding {
    let width = 1e-10;
    let mut w = Worst::default();
    for k in KS {
        let d = toy_sized(k);
        for alpha0 in [0.1, 0.5, 1.0, 1.4, 1.55] {
            let edge = rho_edge(&d, alpha0, width) * d.a;
            let probes = [edge - 1e-3 * edge.abs(), edge + 1e-3 * edge.abs()];
            let bind = Bindings::new()
                .scalar("a", d.a)
                .scalar("k", k)
                .scalar("alpha_0", alpha0);
            let printed = printed_threshold(b, 30, "b", &bind, (-d.a, d.a), probes);
            let allowed = probes.map(|x| steady_exists(&d, alpha0, x / d.a));
            add_threshold(b, &mut w, &printed, edge, allowed, &|| {
                format!("$k = {k}$, $\\alpha_0 = {alpha0}$")
            });
        }
    }
    Finding::from_worst(
        Method::Threshold,
        "lower bound on b for a steady motion: the printed edge and direction against the model's edge found by bisection",
        w,
        Tolerance::bisection(width))
    .in_unit("m")
}

/// Eq 31, $\Omega_0^2 = \dfrac{g}{a k\sin\alpha_0}$ for $b = 0$.
///
/// Integration: the centre of mass at rest means $\dot\alpha = 0$ and $\omega_1 = 0$ (eq 13's
/// velocity vanishes); the rolling model is started with eq 31's $\Omega_0$ and integrated
/// over two precession periods; $\alpha$, $\Omega$, $\omega_1$ must stay constant to the solver's
/// accuracy. Tilts 0.05-1.5.
pub(super) fn eq31(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for k in KS {
        let d = toy_sized(k);
        for alpha0 in [0.05, 0.3, 0.8, 1.2, 1.5] {
            let eq = b.paper.equation(31);
            let unit = d.g_over_a().sqrt();
            let bind = steady_bindings(&d, alpha0);
            let om = eq
                .relations()
                .first()
                .and_then(|rel| solve_printed(eq, rel, "Omega_0", &bind, 1e-3 * unit, 1e3 * unit))
                .map_or(f64::NAN, |x| b.claim(x));
            let m = Motion {
                alpha: alpha0,
                alpha_dot: 0.0,
                precession: om,
                spin: 0.0,
            };
            let drift = steady_drift(b, &d, &m, 2.0);
            w.add(drift, 0.0, 1.0, || {
                format!(
                    "$k = {k}$, $\\alpha_0 = {alpha0}$; relative drift over 2 precession periods"
                )
            });
        }
    }
    Finding::from_worst(
        Method::Integration,
        "drift of $\\alpha$, $\\Omega$, $\\omega_1$ started at eq 31's steady state $(b = 0)$",
        w,
        Tolerance::solver(b.rtol),
    )
    .in_unit("1")
}

/// The rate of the face angle (the disk's spin relative to the triad) measured on an
/// integration of `m` over one precession period: the face state's advance divided by the time.
/// The model advances the face angle at $\omega_1 + \Omega\cos\alpha$ (eq 11, checked with the
/// kinematics).
pub(super) fn measured_rel_spin(bench: &Bench, d: &Disk, m: &Motion) -> f64 {
    let extras = Extras {
        heading: false,
        path: false,
        face: true,
    };
    let model = Rolling::<5>::new(*d, extras, None);
    let t = 2.0 * PI / m.precession.abs();
    let sol = solve(
        Problem::new(&model, 0.0, model.state(m), t),
        &bench.settings(),
    )
    .expect("valid settings");
    let (t1, y1) = sol.last();
    y1[4] / t1
}

/// Shared by eqs 32 and 39: $\omega_{rel} = \Omega_0\cos\alpha_0$ at $b = 0$, against the face
/// angle's rate measured on an integration of the model's $b = 0$ steady motion.
pub(super) fn rel_spin_check(b: &Bench, n: u32) -> Finding {
    let mut w = Worst::default();
    for k in KS {
        let d = toy_sized(k);
        for alpha0 in ALPHAS {
            let Some(m) = steady_ref(&d, alpha0, 0.0) else {
                continue;
            };
            let measured = measured_rel_spin(b, &d, &m);
            let bind = steady_bindings(&d, alpha0)
                .scalar("Omega_0", m.precession)
                .scalar("omega_rel", measured);
            printed_relations(b, n, &bind, m.precession.abs(), &mut w, &|| {
                format!("$k = {k}$, $\\alpha_0 = {alpha0}$, $b = 0$")
            });
        }
    }
    Finding::from_worst(
        Method::Integration,
        "$\\omega_{\\mathrm{rel}} = \\Omega_0 \\cos(\\alpha_0)$ against the face angle's measured rate at $b = 0$, relative to $|\\Omega_0|$",
        w,
        Tolerance::solver(b.rtol))
}

/// Eq 32, $\omega_{rel} = \Omega_0\cos\alpha_0$ for $b = 0$.
///
/// Integration: the model's $b = 0$ steady motion (Newton on eq 24 at $\omega_{10} = 0$) is
/// integrated with the face angle over one precession period; its rate is the relative spin.
pub(super) fn eq32(b: &Bench) -> Finding {
    rel_spin_check(b, 32)
}

/// Eq 39, $\omega_{rel} = \Omega_0\cos\alpha_0$ (section 5's rederivation of eq 32).
///
/// Integration, as for eq 32.
pub(super) fn eq39(b: &Bench) -> Finding {
    rel_spin_check(b, 39)
}

/// Eq 38, $\omega = -\Omega_0\sin\alpha_0$: at $b = 0$ the disk turns about axis
/// $\hat{\mathbf 3}$ at rate $\omega$.
///
/// Derivation from the contact force: with the angular velocity $\omega\hat{\mathbf 3}$ the
/// angular momentum about the centre is $k m a^2\omega\hat{\mathbf 3}$ (eq 18's moments); the
/// torque of the model's contact force (`contact_force`, eq 20 through the model's
/// accelerations) about the centre, $a\hat{\mathbf 3}\times\mathbf F$, must turn it at the
/// precession: $\frac{d}{dt}(k m a^2\omega\hat{\mathbf 3}) = k m a^2\omega\Omega_0\cos\alpha_0
/// \hat{\mathbf 2}$ (eq 7 at $\dot\alpha = 0$), while $\mathbf N\cdot\hat{\mathbf 2} =
/// a\mathbf F\cdot\hat{\mathbf 1}$. So $\omega = a F_1/(k m a^2\Omega_0\cos\alpha_0)$ from the
/// model's force, the reference (and $F_2 = 0$, since $d\mathbf L/dt$ has no axis-1 part).
pub(super) fn eq38(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for k in KS {
        let d = toy_sized(k);
        for alpha0 in [0.1, 0.5, 1.0, 1.4] {
            let Some(m) = steady_ref(&d, alpha0, 0.0) else {
                continue;
            };
            let r = rates(&d, &m, [0.0; 3]);
            let [fz, fr, f2] = contact_force(&d, &m, &r);
            // F along axis 1: z = -c 1 - s 3, r = -s 1 + c 3.
            let (s, c) = alpha0.sin_cos();
            let f1 = -c * fz - s * fr;
            // N = a 3 x F has axis-2 component a F.1; dL/dt = k m a^2 omega d3/dt has axis-2
            // component k m a^2 omega Omega cos(alpha) (eq 7, alpha_dot = 0). The axis-1 parts
            // (a F.2 against 0) are compared too.
            let omega_ref = d.a * f1 / (d.i22() * m.precession * c);
            w.add(f2, 0.0, d.m * d.g, || {
                format!("$k = {k}$, $\\alpha_0 = {alpha0}$: $F_2 / (m g)$")
            });
            let bind = steady_bindings(&d, alpha0)
                .scalar("Omega_0", m.precession)
                .scalar("omega_3", omega_ref);
            printed_relations(b, 38, &bind, omega_ref.abs(), &mut w, &|| {
                format!("$k = {k}$, $\\alpha_0 = {alpha0}$, $b = 0$")
            });
        }
    }
    Finding::from_worst(
        Method::Derivation,
        "rate about axis 3 at $b = 0$: claimed against the rate the model's contact torque sustains",
        w,
        Tolerance::roundoff(),
    )
}

/// Eq 40, $\Omega_0^2 = \dfrac{g}{a k\sin\alpha_0}$ (section 5's rederivation of eq 31).
///
/// Derivation: compared with the $\Omega_0^2$ of the model's steady motion at $\omega_{10} = 0$
/// (Newton on eq 24), tilts 0.05-1.5.
pub(super) fn eq40(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for k in KS {
        let d = toy_sized(k);
        for alpha0 in [0.05, 0.3, 0.8, 1.2, 1.5] {
            let Some(m) = steady_ref(&d, alpha0, 0.0) else {
                continue;
            };
            let om2 = m.precession * m.precession;
            let bind = steady_bindings(&d, alpha0).scalar("Omega_0", m.precession);
            printed_relations(b, 40, &bind, om2, &mut w, &|| {
                format!("$k = {k}$, $\\alpha_0 = {alpha0}$")
            });
        }
    }
    Finding::from_worst(
        Method::Derivation,
        "$\\Omega_0^{2}$ at $b = 0$ against the model's steady state solved by Newton",
        w,
        Tolerance::roundoff(),
    )
    .in_unit("rad^2/s^2")
}

// ------------------------------------------------------------------------------------------
// Section 5, against the lab-frame model
// ------------------------------------------------------------------------------------------
