//! Eqs 80-81: where the power law predicts loss of contact, against eq 79 as printed.

use super::{
    bisect, printed_relations, Bench, Bindings, Dual2_64, DualNum, Finding, Method, Tolerance,
    Worst,
};

/// The lift-off of eqs 80-81 derived from eq 79 AS PRINTED (its last form, $\Omega$ in terms of
/// $C$): the time before $t_0$, $\tau$, at which $d^2(1/\Omega^2)/dt^2 = -k$ (the loss of contact
/// the paper states), the second derivative exact by a second-order dual number through the
/// parsed expression, located by bisection to relative width `WIDTH`; returns
/// $(\tau, \Omega(\tau))$.
pub(super) const WIDTH: f64 = 1e-12;

pub(super) fn lift_off(b: &Bench, k: f64, beta: f64, c: f64) -> (f64, f64) {
    let eq = b.paper.equation(79);
    let omega = |tau: Dual2_64| -> Dual2_64 {
        let constant = Dual2_64::from_re;
        let bind = Bindings::<Dual2_64>::new()
            .scalar("C", constant(c))
            .scalar("beta", constant(beta))
            .scalar("k", constant(k))
            .scalar("t_0", constant(0.0))
            .scalar("t", -tau);
        eq.chains[0]
            .sides
            .last()
            .and_then(|e| eq.scalar(e, &bind).ok())
            .unwrap_or(constant(f64::NAN))
    };
    let below = |tau: f64| {
        let om = omega(Dual2_64::from_re(tau).derivative());
        (om * om).recip().v2 < -k
    };
    let (lo, hi) = bisect(1e-15, 1e3, WIDTH, below);
    let tau = 0.5 * (lo + hi);
    (tau, omega(Dual2_64::from_re(tau)).re)
}

/// The (k, beta, C) swept by eqs 80-81 (C in the units of eq 79 for each beta).
pub(super) fn lift_off_cases() -> Vec<(f64, f64, f64)> {
    let mut v = Vec::new();
    for k in [0.25, 0.5] {
        for beta in [1.0, 2.0, 2.5, 3.0, 4.0] {
            for c in [1e6, 1.09e9] {
                v.push((k, beta, c));
            }
        }
    }
    v
}

/// Eq 80, $\Omega_{max} = (k(\beta+2)^2/2\beta)^{1/2(\beta+1)} C^{1/(\beta+1)}$, against
/// $\Omega$ of eq 79 where $d^2(1/\Omega^2)/dt^2 = -k$ (bisection).
pub fn eq80(b: &Bench) -> Finding {
    lift_off_check(b, 80)
}

/// Eq 81, $t_0 - t_{max} = (2\beta/k(\beta+2)^2)^{(\beta+2)/2(\beta+1)} C^{-1/(\beta+1)}$, against
/// the $\tau$ where eq 79 gives $d^2(1/\Omega^2)/dt^2 = -k$ (bisection).
pub fn eq81(b: &Bench) -> Finding {
    lift_off_check(b, 81)
}

/// Eqs 80-81: the printed relation with $\Omega_{max}$, $t_0 = 0$ and $t_{max} = -\tau$ bound to
/// the lift-off derived from eq 79.
pub(super) fn lift_off_check(b: &Bench, n: u32) -> Finding {
    let mut worst = Worst::default();
    for (k, beta, c) in lift_off_cases() {
        let (tau, om) = lift_off(b, k, beta, c);
        let bind = Bindings::new()
            .scalar("k", k)
            .scalar("beta", beta)
            .scalar("C", c)
            .scalar("Omega_max", om)
            .scalar("t_0", 0.0)
            .scalar("t_max", -tau);
        let scale = if n == 80 { om } else { tau };
        printed_relations(b, n, &bind, scale, &mut worst, &|| {
            format!("$k = {k}$, $\\beta = {beta}$, $C = {c:e}$")
        });
    }
    Finding::from_worst(
        Method::Threshold,
        if n == 80 {
            "$\\Omega_{\\mathrm{max}}$ of eq 80 against eq 79 as printed at $d^{2}(1/\\Omega^{2})/dt^{2} = -k$ (bisection)"
        } else {
            "$t_0 - t_{\\mathrm{max}}$ of eq 81 against the time where eq 79 as printed gives $d^{2}(1/\\Omega^{2})/dt^{2} = -k$ (bisection)"
        },
        worst,
        Tolerance::bisection(WIDTH))
    .in_unit(if n == 80 { "rad/s" } else { "s" })
}
