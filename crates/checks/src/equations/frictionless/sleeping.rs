//! Eqs 64-65: the disk spinning about a vertical diameter without friction, and when it is stable.

use super::{
    add_threshold, bisect, printed_relations, printed_threshold, reference_jacobian, solve, Bench,
    Bindings, Ending, Event, Extras, Finding, Frictionless, Method, Problem, State, Tolerance,
    Worst, FRAC_PI_2, KS,
};
use physics::disk::toy_sized;

/// Eq 64, $\ddot\epsilon + (\Omega^2 - g/ak)\epsilon = 0$ for $\alpha = \pi/2 - \epsilon$.
///
/// The Jacobian of the Lagrangian reference at $\alpha = \pi/2$, $\dot\alpha = 0$,
/// $\omega_1 = 0$ gives the linear tilt equation $\ddot\epsilon = (\partial\ddot\alpha/\partial\alpha)\,\epsilon$;
/// the printed relation is evaluated from its LaTeX with that $\ddot\epsilon$ at amplitudes
/// $\epsilon$ = 0.3 and -0.05 (two, so that a changed power of $\epsilon$ shows), over several
/// spin rates of both signs, below and above the threshold. The couplings of $\ddot\alpha$ to
/// $\dot\alpha$ and $\Omega$, absent from the printed form, must vanish.
pub(super) fn eq64(b: &Bench) -> Finding {
    let mut worst = Worst::default();
    for &k in &KS {
        let d = toy_sized(k);
        for f in [-3.0, -1.2, 0.3, 0.8, 1.7, 3.0] {
            let om = f * d.g_over_a().sqrt();
            let jac = reference_jacobian(&d, [FRAC_PI_2, 0.0, om], 0.0);
            let scale = om * om + d.g / (d.a * k);
            let at = || format!("$k = {k}$, $\\Omega = {om:.3}$");
            for eps in [0.3, -0.05] {
                let bind = Bindings::new()
                    .scalar("tilt_from_vertical", eps)
                    .scalar("tilt_from_vertical_ddot", jac[(1, 0)] * eps)
                    .scalar("Omega", om)
                    .scalar("g", d.g)
                    .scalar("a", d.a)
                    .scalar("k", k);
                printed_relations(b, 64, &bind, scale * eps.abs(), &mut worst, &|| {
                    format!("{}, $\\epsilon = {eps}$", at())
                });
            }
            // d(alpha_ddot)/d(alpha_dot) and d(alpha_ddot)/d(Omega), both in 1/s, must vanish.
            worst.add_in(0.0, jac[(1, 1)], scale.sqrt(), "1/s", at);
            worst.add_in(0.0, jac[(1, 2)], scale.sqrt(), "1/s", at);
        }
    }
    Finding::from_worst(
        Method::Linearization,
        "eq 64 as printed with the linear tilt equation of the Lagrangian reference's Jacobian near the vertical",
        worst,
        Tolerance::roundoff())
    .in_unit("rad/s^2")
}

/// Eq 65, stable spinning about a vertical diameter for $|\Omega| > \sqrt{g/ak}$.
///
/// Threshold by bisection on integrations of the frictionless model started at
/// $\alpha = \pi/2 - 10^{-6}$, $\dot\alpha = 0$, $\omega_1 = 0$: unstable if the tilt from the
/// vertical doubles within $T = 120\sqrt{a/g}$. The bracket $[0.2, 20]\sqrt{g/a}$ does not use
/// the claim. A finite run cannot see growth slower than $\cosh(\sqrt{-\kappa}T) = 2$, which
/// shifts the located threshold by $(\mathrm{arccosh}\,2/T)^2/2\Omega^2$ relative (the
/// run's resolution): the tolerance is the bisection's plus twice that resolution.
pub(super) fn eq65(b: &Bench) -> Finding {
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
        let d = toy_sized(k);
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
            format!(
                "$k = {k}$, $\\Omega {}$",
                if sign > 0.0 { "> 0" } else { "< 0" }
            )
        });
    }
    let bis = Tolerance::bisection(width);
    let tolerance = Tolerance {
        value: bis.value + 2.0 * resolution,
        rule: format!(
            "{} plus twice the finite-run resolution $(\\operatorname{{arccosh}} 2 / T)^{{2}} / 2 \\Omega^{{2}} = {resolution:.1e}$",
            bis.rule
        ),
    };
    Finding::from_worst(
        Method::Threshold,
        "$\\sqrt{g/a k}$ against the spin rate below which a nearly vertical frictionless disk falls (bisection on integrations)",
        worst,
        tolerance)
    .in_unit("rad/s")
}
