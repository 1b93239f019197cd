//! Eqs 44-46: the small-oscillation ansatz, against integrations along the mode.

use super::{
    mode, rolling, solve, state, steady_bindings, steady_ref, varpi2, Bench, Extras, Finding,
    Method, Model, Problem, Rolling, Tolerance, Worst, PI,
};
use physics::disk::toy_sized;

/// The ansatz of eqs 44-46 checked on integrations: started from a stable steady motion
/// displaced by $\epsilon$ along the model's oscillation mode, the variable `which`
/// (0 = $\alpha$, 2 = $\Omega$, 3 = $\omega_1$) is compared over two periods with
/// steady value + amplitude $\cos\varpi t$ (amplitude and $\varpi$ from the model's
/// linearization). Its residual relative to the amplitude must shrink as $\epsilon^1$ (the
/// ansatz is the first-order solution); the fitted order's distance to 1 is compared with
/// [`Tolerance::order`], for $\epsilon/\alpha_0 = 10^{-3}\dots10^{-6}$.
pub(super) fn ansatz(b: &Bench, which: usize) -> Finding {
    // Resolving this claim needs tight integrations whatever the preset (see Bench::resolving).
    let b = &b.resolving(1e-12);
    let mut w = Worst::default();
    let eps_rel: Vec<f64> = (3..=6).map(|i| 10f64.powi(-i)).collect();
    for k in [0.25, 0.5] {
        let d = toy_sized(k);
        for (alpha0, rho) in [(0.3, 0.0), (0.8, 0.5), (1.2, -0.05)] {
            let Some(m) = steady_ref(&d, alpha0, rho) else {
                continue;
            };
            let y = state(&m);
            let v2 = varpi2(&d, &y);
            if v2 <= 0.0 {
                continue;
            }
            let varpi = v2.sqrt();
            let (dl, ga) = mode(&rolling::jacobian(&d, &y), varpi);
            let amp_per_eps = [1.0, 0.0, dl.re, ga.re][which];
            let model = Rolling::<4>::new(d, Extras::default(), None);
            let period = 2.0 * PI / varpi;
            let mut errs = Vec::new();
            for &er in &eps_rel {
                let eps = er * alpha0;
                let mut start = m;
                start.alpha += eps;
                start.precession += eps * dl.re;
                start.spin += eps * ga.re;
                let sol = solve(
                    Problem::new(&model, 0.0, model.state(&start), 2.0 * period)
                        .sampled(period / 50.0),
                    &b.settings(),
                );
                let Ok(sol) = sol else {
                    errs.push(f64::INFINITY);
                    continue;
                };
                let amp = eps * amp_per_eps;
                let n = [44, 0, 45, 46][which];
                let eq = b.paper.equation(n);
                let mut e: f64 = 0.0;
                for (t, s) in sol.t.iter().zip(&sol.y) {
                    let bind = steady_bindings(&d, &m)
                        .scalar("epsilon", eps)
                        .scalar("delta", eps * dl.re)
                        .scalar("gamma", eps * ga.re)
                        .scalar("varpi", varpi)
                        .scalar("t", *t);
                    let claimed = eq
                        .relations()
                        .first()
                        .and_then(|rel| eq.scalar(rel.rhs, &bind).ok())
                        .map_or(f64::NAN, |c| b.claim(c));
                    let here = (claimed - s[which]).abs() / amp.abs();
                    e = if here.is_nan() {
                        f64::INFINITY
                    } else {
                        e.max(here)
                    };
                }
                errs.push(e);
            }
            let order = numerics::fit::log_log_slope(&eps_rel, &errs);
            let shrinking = errs[errs.len() - 1] < errs[0];
            let order = if shrinking { order } else { f64::NAN };
            w.add(order, 1.0, 1.0, || {
                format!(
                    "$k = {k}$, $\\alpha_0 = {alpha0}$, $b/a = {rho}$: residual / amplitude {:.2e} at $\\epsilon/\\alpha_0 = 1e-6$",
                    errs[errs.len() - 1]
                )
            });
        }
    }
    Finding::definition(
        Method::Integration,
        "fitted order of the ansatz's residual (relative to its amplitude) in $\\epsilon$, against 1",
        w,
        Tolerance::order(),
    )
    .in_unit("order")
}

/// Eq 44, $\alpha = \alpha_0 + \epsilon\cos\varpi t$ (the ansatz; a definition).
///
/// Consistency: a small-amplitude integration along the model's mode follows it to first order
/// in $\epsilon$ (see `ansatz`).
pub(super) fn eq44(b: &Bench) -> Finding {
    ansatz(b, 0)
}

/// Eq 45, $\Omega = \Omega_0 + \delta\cos\varpi t$ (the ansatz; a definition): in phase with
/// $\alpha$, checked as eq 44.
pub(super) fn eq45(b: &Bench) -> Finding {
    ansatz(b, 2)
}

/// Eq 46, $\omega_1 = \omega_{10} + \gamma\cos\varpi t$ (the ansatz; a definition): in phase with
/// $\alpha$, checked as eq 44.
pub(super) fn eq46(b: &Bench) -> Finding {
    ansatz(b, 3)
}
