//! Eqs 47-51: the frequency of small oscillations and the ratios of their amplitudes, against the model.

use super::{
    at, eq50_claim, measured_frequency, mode, printed_relations, printed_varpi2, rolling, scale,
    state, steady_bindings, sweep, varpi2, Bench, Finding, Method, Motion, Tolerance, Worst,
    EPSILON, FRAC_PI_2, KS,
};
use nalgebra::Complex;
use physics::disk::{toy_sized, Disk};

/// Eq 50: the squared frequency of small oscillations about a general steady motion.
///
/// Linearization and integration: compared with $\varpi^2 = e_2(J)$ of the model's exact
/// Jacobian over k in {0.1, 0.25, 0.5, 0.9}, tilts 0.05-1.5 and b/a in {negative, 0, 0.5, 2}
/// (relative to $\Omega_0^2 + \omega_{10}^2 + g/a$, round-off rule); and, at the stable points
/// of k = 1/4 (tilts below 1.5, b/a below 1), with the frequency of $\alpha(t)$ measured on integrations of
/// amplitudes $\epsilon = 10^{-5}\alpha_0$ and $2\epsilon$ along the mode, extrapolated to zero
/// amplitude (Richardson in $\epsilon^2$; relative, solver rule).
pub(super) fn eq50(b: &Bench) -> Finding {
    let mut lin = Worst::default();
    let mut int = Worst::default();
    sweep(|k, d, alpha0, rho, m| {
        let reference = varpi2(d, &state(m));
        let claimed = eq50_claim(b, d, m);
        lin.add(claimed, reference, scale(d, m), || at(k, alpha0, rho));
        if k == 0.25 && rho < 1.0 && reference > 1e-2 * scale(d, m) && alpha0 < 1.5 {
            let varpi = reference.sqrt();
            let eps = 1e-5 * alpha0;
            let w1 = measured_frequency(b, d, m, varpi, eps);
            let w2 = measured_frequency(b, d, m, varpi, 2.0 * eps);
            // Richardson: the amplitude shifts the frequency by O(eps^2).
            let measured = w1
                .zip(w2)
                .map_or(f64::NAN, |(w1, w2)| (4.0 * w1 - w2) / 3.0);
            let cl = claimed.max(0.0).sqrt();
            int.add(cl, measured, measured, || {
                format!(
                    "{} (frequency measured on integrations)",
                    at(k, alpha0, rho)
                )
            });
        }
    });
    let a = Finding::from_worst(
        Method::Linearization,
        "$\\varpi^{2}$ against e2 of the model's Jacobian, relative to $\\Omega_0^{2} + \\omega_{10}^{2} + g/a$",
        lin,
        Tolerance::roundoff(),
    )
    .in_unit("rad^2/s^2");
    let bfind = Finding::from_worst(
        Method::Integration,
        "$\\varpi$ against the frequency of $\\alpha$ measured on small-amplitude integrations",
        int,
        Tolerance::solver(b.rtol),
    )
    .in_unit("rad/s");
    worse(a, bfind)
}

/// The worse of two findings (a failure first, then the larger error relative to tolerance).
pub(super) fn worse(a: Finding, b: Finding) -> Finding {
    let ra = a.error / a.tolerance.value;
    let rb = b.error / b.tolerance.value;
    match (a.verdict.passes(), b.verdict.passes()) {
        (true, false) => b,
        (false, true) => a,
        _ if rb > ra => b,
        _ => a,
    }
}

/// Eq 47, $\delta = -\dfrac{2\epsilon}{\sin\alpha_0}(\Omega_0\cos\alpha_0 + \omega_{10})$.
///
/// Linearization: $\delta/\epsilon$ is the $\Omega$ entry of the oscillation mode's eigenvector
/// of the model's Jacobian normalised to $\alpha$ entry 1 (real: in phase). Sweep as eq 50,
/// stable points; relative to $|\Omega_0|/\sin\alpha_0 + |\omega_{10}|$.
pub(super) fn eq47(b: &Bench) -> Finding {
    ratio_check(b, 47)
}

/// Eq 48, $\gamma = -\epsilon\dfrac{\Omega_0\sin\alpha_0}{2k+1}$.
///
/// Linearization: the $\omega_1$ entry of the oscillation mode's eigenvector, as for eq 47.
pub(super) fn eq48(b: &Bench) -> Finding {
    ratio_check(b, 48)
}

/// The small oscillation about the steady motion `m` of disk `d`: $\varpi^2 = e_2(J)$ and the
/// $\Omega$ and $\omega_1$ entries of the mode's eigenvector relative to $\alpha$'s; `None` where
/// the motion is unstable ($\varpi^2 \le 0$).
fn oscillation_mode(d: &Disk, m: &Motion) -> Option<(f64, Complex<f64>, Complex<f64>)> {
    let v2 = varpi2(d, &state(m));
    if v2 <= 0.0 {
        return None;
    }
    let j = rolling::jacobian(d, &state(m));
    let (dl, ga) = mode(&j, v2.sqrt());
    Some((v2, dl, ga))
}

pub(super) fn ratio_check(b: &Bench, which: u32) -> Finding {
    let mut w = Worst::default();
    sweep(|k, d, alpha0, rho, m| {
        let Some((_, dl, ga)) = oscillation_mode(d, m) else {
            return;
        };
        let (om, w10) = (m.precession, m.spin);
        let sc = om.abs() / alpha0.sin() + w10.abs();
        // delta and gamma: the mode's entries relative to alpha's, times epsilon.
        let bind = steady_bindings(d, m)
            .scalar("delta", EPSILON * dl.re)
            .scalar("gamma", EPSILON * ga.re);
        printed_relations(b, which, &bind, EPSILON * sc, &mut w, &|| {
            at(k, alpha0, rho)
        });
    });
    Finding::from_worst(
        Method::Linearization,
        if which == 47 {
            "$\\delta/\\epsilon$ against the mode's eigenvector of the model's Jacobian"
        } else {
            "$\\gamma/\\epsilon$ against the mode's eigenvector of the model's Jacobian"
        },
        w,
        Tolerance::roundoff(),
    )
}

/// Eq 49, the first-order part of eq 24:
/// $\epsilon\varpi^2(k+1) = -(2k+1)(\epsilon\omega_{10}\Omega_0\cos\alpha_0 + \gamma\Omega_0\sin\alpha_0
/// + \delta\omega_{10}\sin\alpha_0) + \epsilon k\Omega_0^2(1 - 2\cos^2\alpha_0)
/// - 2\delta k\Omega_0\sin\alpha_0\cos\alpha_0 - \epsilon\frac{g}{a}\sin\alpha_0$.
///
/// Linearization: with $\epsilon = 1$ and $\delta$, $\gamma$ from the model's eigenvector (not
/// from eqs 47-48), the right-hand side divided by $k+1$ is compared with $\varpi^2 = e_2(J)$.
pub(super) fn eq49(b: &Bench) -> Finding {
    let mut w = Worst::default();
    sweep(|k, d, alpha0, rho, m| {
        let Some((v2, dl, ga)) = oscillation_mode(d, m) else {
            return;
        };
        let bind = steady_bindings(d, m)
            .scalar("delta", EPSILON * dl.re)
            .scalar("gamma", EPSILON * ga.re);
        let claimed = printed_varpi2(b, 49, &bind);
        w.add(claimed, v2, scale(d, m), || at(k, alpha0, rho));
    });
    Finding::from_worst(
        Method::Linearization,
        "$\\varpi^{2}$ from the $\\alpha$ row with the eigenvector's $\\delta$, $\\gamma$, against e2 of the Jacobian",
        w,
        Tolerance::roundoff())
    .in_unit("rad^2/s^2")
}

/// Eq 51, $\varpi^2(k+1) = 2(2k+1)\omega_{10}^2 - \frac{g}{a}$ for a wheel rolling straight
/// ($\alpha_0 = \pi/2$, $\Omega_0 = 0$).
///
/// Linearization: $e_2$ of the model's Jacobian at the upright rolling state, for
/// $\omega_{10}^2$ from 0.1 to 10 times $g/a$.
pub(super) fn eq51(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for k in KS {
        let d = toy_sized(k);
        for f in [0.1, 0.3, 1.0, 3.0, 10.0] {
            let w10 = (f * d.g_over_a()).sqrt();
            let y = [FRAC_PI_2, 0.0, 0.0, w10];
            let reference = varpi2(&d, &y);
            let m = Motion {
                alpha: FRAC_PI_2,
                alpha_dot: 0.0,
                precession: 0.0,
                spin: w10,
            };
            let claimed = printed_varpi2(b, 51, &steady_bindings(&d, &m));
            w.add(claimed, reference, w10 * w10 + d.g_over_a(), || {
                format!("$k = {k}$, $\\omega_{{10}}^{{2}} = {f} g/a$")
            });
        }
    }
    Finding::from_worst(
        Method::Linearization,
        "$\\varpi^{2}$ of the straight wheel against e2 of the Jacobian, relative to $\\omega_{10}^{2} + g/a$",
        w,
        Tolerance::roundoff(),
    )
    .in_unit("rad^2/s^2")
}
