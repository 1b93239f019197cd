//! Eqs 66-71: small oscillations about steady motion without friction, against the linearized Lagrangian and integrations.

use super::{
    angular_frequency, linear, printed_relations, relation_scale, solve, Bench, Bindings, Disk,
    Ending, Extras, Finding, Frictionless, Linear, Method, Problem, State, Tolerance, Verdict,
    Worst, KS, PI,
};
use physics::disk::toy_sized;

/// The steady tilts swept in the small-oscillation checks (0 < alpha_0 < pi/2).
pub(super) const ALPHA0S: [f64; 5] = [0.1, 0.4, 0.8, 1.2, 1.5];

/// Integrates the frictionless model from steady spinless motion at `alpha0` displaced along
/// the oscillating eigenvector by tilt `eps` (tilt `alpha0 + eps`, Omega `Omega0 + ratio eps`),
/// over `periods` periods sampled 40 times per period.
pub(super) fn oscillate(
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
pub(super) fn ansatz(b: &Bench, n: u32, amplitude: fn(f64, f64) -> f64) -> Finding {
    // Resolving this claim needs tight integrations whatever the preset (see Bench::resolving).
    let b = &b.resolving(1e-12);
    let eq = b.paper.equation(n);
    let fractions = [1e-2, 3e-3, 1e-3, 3e-4];
    let mut errors = vec![0.0f64; fractions.len()];
    for &k in &[0.25, 0.5] {
        let d = toy_sized(k);
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
             $\\varpi$ from its eigenvalue) on frictionless integrations, relative to the amplitude, \
             against the amplitude $\\epsilon/\\alpha_0$"
        ),
        &fractions,
        &errors,
        1.0,
    );
    f.at = format!(
        "{}; each amplitude's error the worst over $k = 1/4$, 1/2 and $\\alpha_0 = 0.3$, 0.9, 1.3 \
         (toy-sized disk, $a = 37.5$ mm)",
        f.at
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
pub(super) fn eq66(b: &Bench) -> Finding {
    ansatz(b, 66, |eps, _| eps)
}

/// Eq 67, the trial form $\Omega = \Omega_0 + \delta\cos\varpi t$, checked like eq 66 (same
/// frequency, in phase with the tilt), relative to $|\delta|$.
pub(super) fn eq67(b: &Bench) -> Finding {
    ansatz(b, 67, |_, delta| delta.abs())
}

pub(super) fn sweep_linear(mut f: impl FnMut(&Disk, f64, &Linear, &mut Worst)) -> Worst {
    let mut worst = Worst::default();
    for &k in &KS {
        let d = toy_sized(k);
        for &alpha0 in &ALPHA0S {
            let lin = linear(&d, alpha0);
            f(&d, alpha0, &lin, &mut worst);
        }
    }
    worst
}

/// The steady spinless motion's quantities of the small-oscillation equations.
pub(super) fn linear_bindings(d: &Disk, alpha0: f64, lin: &Linear) -> Bindings<f64> {
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
pub(super) fn eq68(b: &Bench) -> Finding {
    let worst = sweep_linear(|d, alpha0, lin, worst| {
        let at = || format!("$k = {}$, $\\alpha_0 = {alpha0}$", d.k);
        for eps in [0.3, -0.05] {
            let delta = lin.ratio.re * eps;
            let bind = linear_bindings(d, alpha0, lin)
                .scalar("epsilon", eps)
                .scalar("delta", delta);
            printed_relations(b, 68, &bind, delta.abs(), worst, &|| {
                format!("{}, $\\epsilon = {eps}$", at())
            });
        }
        worst.add(0.0, lin.ratio.im, lin.ratio.re.abs(), at);
    });
    Finding::from_worst(
        Method::Linearization,
        "eq 68 as printed, $\\delta$ from the eigenvector of the linearized Lagrangian reference",
        worst,
        Tolerance::roundoff(),
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
pub(super) fn eq69(b: &Bench) -> Finding {
    let worst = sweep_linear(|d, alpha0, lin, worst| {
        let (j_a, j_ad, j_om) = (lin.jac[(1, 0)], lin.jac[(1, 1)], lin.jac[(1, 2)]);
        let at = || format!("$k = {}$, $\\alpha_0 = {alpha0}$", d.k);
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
                format!("{}, $\\delta = {delta:.4}$", at())
            });
        }
        worst.add_in(0.0, j_ad, j_a.abs().sqrt(), "1/s", at);
    });
    Finding::from_worst(
        Method::Linearization,
        "eq 69 as printed, $\\varpi$ from the linear tilt equation of the Lagrangian reference at independent $\\epsilon$ and $\\delta$",
        worst,
        Tolerance::roundoff())
    .in_unit("rad/s^2")
}

/// Eq 70, $\varpi^2(k + \cos^2\alpha_0) = k\Omega_0^2(1 + 2\cos^2\alpha_0) - \frac ga\sin\alpha_0 = 3k\Omega_0^2\cos^2\alpha_0$:
/// both printed relations evaluated from the LaTeX with $\varpi$ the eigenvalue of the Lagrangian
/// reference linearized about its own steady spinless motion $\Omega_0$. Errors relative to the
/// size of the relation's terms (they cancel near $\alpha_0 = \pi/2$, where round-off is
/// relative to them, not to their small difference).
pub(super) fn eq70(b: &Bench) -> Finding {
    let eq = b.paper.equation(70);
    let worst = sweep_linear(|d, alpha0, lin, worst| {
        let bind = linear_bindings(d, alpha0, lin).scalar("varpi", lin.varpi);
        let scale = relation_scale(eq, &bind);
        printed_relations(b, 70, &bind, scale, worst, &|| {
            format!("$k = {}$, $\\alpha_0 = {alpha0}$", d.k)
        });
    });
    Finding::from_worst(
        Method::Linearization,
        "eq 70 as printed (both relations), $\\varpi$ and $\\Omega_0$ from the linearized Lagrangian reference",
        worst,
        Tolerance::roundoff())
    .in_unit("rad^2/s^2")
}

/// Eq 71, $\varpi/\Omega_0 = \sqrt{3k/(k + \cos^2\alpha_0)}\cos\alpha_0$, evaluated from its
/// LaTeX with $\varpi$ the frequency of the tilt measured on integrations of the frictionless
/// model over 10 periods, started along the oscillating mode at amplitudes
/// $\epsilon = 10^{-4}\alpha_0\cos\alpha_0$ and $2\epsilon$ (the motion's scales are $\alpha_0$
/// and, near the vertical, $\cos\alpha_0$), extrapolated to zero amplitude by Richardson
/// ($\varpi(\epsilon) = \varpi + c\epsilon^2 + O(\epsilon^4)$: the amplitude's shift is even in
/// $\epsilon$), and $\Omega_0$ the steady precession. Smaller amplitudes drown in the solver's
/// error on $\alpha$, which is relative to $\alpha_0$.
pub(super) fn eq71(b: &Bench) -> Finding {
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
            format!("$k = {}$, $\\alpha_0 = {alpha0}$", d.k)
        });
    });
    Finding::from_worst(
        Method::Integration,
        "eq 71 as printed, $\\varpi$ measured on small oscillations of the frictionless model",
        worst,
        Tolerance::solver(b.rtol),
    )
    .in_unit("1")
}
