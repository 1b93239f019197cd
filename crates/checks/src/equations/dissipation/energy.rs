//! Eqs 72-73: the energy of the disk at small tilt and its rate, against the exact energy.

use super::{
    energy, last_side, steady_precession, Bench, Dual64, Finding, Headline, Motion, SMALL_ALPHAS,
};
use crate::equations::disk_runs::DiskRuns;
use crate::harness::disk_constants;
use physics::disk::toy_sized;

/// Eq 72 at states of the $b = 0$ family (steady precession at each tilt, $\omega_1 = 0$) with
/// tilt rate $\dot\alpha^2 = c_0\,g\alpha/a$: the claimed
/// $U \approx \frac12 m a^2\dot\alpha^2 + \frac32 m a g\alpha$ against the exact energy.
pub(super) fn eq72_at(b: &Bench, c0: f64) -> Finding {
    let mut headline = None;
    let mut errors = vec![0.0f64; SMALL_ALPHAS.len()];
    let mut runs = DiskRuns::default();
    let mut worst_form = vec![0usize; SMALL_ALPHAS.len()];
    for &k in &[0.25, 0.5] {
        let d = toy_sized(k);
        for (i, &alpha) in SMALL_ALPHAS.iter().enumerate() {
            let alpha_dot = -(c0 * d.g * alpha / d.a).sqrt();
            let m = Motion {
                alpha,
                alpha_dot,
                precession: steady_precession(&d, alpha),
                spin: 0.0,
            };
            let reference = energy(&d, &m);
            let bind = disk_constants(&d)
                .scalar("alpha", alpha)
                .scalar("alpha_dot", alpha_dot)
                .scalar("h", d.a * alpha.sin())
                .scalar("h_dot", d.a * alpha.cos() * alpha_dot)
                .scalar("I_22", k * d.m * d.a * d.a)
                .scalar("I_33", k * d.m * d.a * d.a)
                .scalar("omega_3", -m.precession * alpha.sin())
                .scalar("U", reference);
            for (form, side) in b.paper.equation(72).chains[0].sides.iter().enumerate() {
                let e = b
                    .paper
                    .equation(72)
                    .scalar(side, &bind)
                    .map_or(f64::INFINITY, |c| {
                        ((b.claim(c) - reference) / reference).abs()
                    });
                runs.add(k, None, SMALL_ALPHAS.len(), i, e);
                if e > errors[i] || e.is_nan() {
                    errors[i] = if e.is_nan() { f64::INFINITY } else { e };
                    worst_form[i] = form + 1;
                }
            }
            let eq = b.paper.equation(72);
            if k == 0.25 && i == SMALL_ALPHAS.len() - 1 {
                let unit = d.m * d.g * d.a * alpha;
                let printed = last_side(eq, &bind);
                headline = Some(Headline::new(
                    format!(
                        "$U / (m g a \\alpha)$ at $\\dot\\alpha^{{2}} = {c0} g \\alpha / a$ (eq 72's last form)"
                    ),
                    printed / unit,
                    "implied",
                    reference / unit,
                    "1",
                    format!("uniform disk $(k = 1/4)$, $\\alpha = {alpha}$, $b = 0$"),
                ));
            }
        }
    }
    let f = Finding::from_order(
        format!(
            "every printed form of U in eq 72 against the exact energy at $b = 0$ ($\\Omega^{{2}} = g/a k \\sin \\alpha$, $\\omega_1 = 0$), \
             $\\dot\\alpha^{{2}} = {c0} g \\alpha / a$, relative error against $\\alpha$"
        ),
        &SMALL_ALPHAS,
        &errors,
        b.paper.equation(72).entry.claimed_order.unwrap_or(2.0),
    );
    let alternatives = runs.alternatives(&SMALL_ALPHAS, f.claimed);
    let mut f = naming_the_worst_side(f, &worst_form, headline);
    f.at = format!(
        "{}; each error the worst over $k = 1/4$ and 1/2, $b = 0$",
        f.at
    );
    f.with_robustness(alternatives)
}

/// Eq 72, $U = \frac12 m\dot h^2 + \frac12 I_{33}\omega^2 + mgh \approx \frac12 m a^2\dot\alpha^2 + \frac32 m a g\alpha$.
///
/// FAILS. Measured where every term of the claim is of its own order: $\dot\alpha^2 = g\alpha/a$
/// (the kinetic term as large as the potential one, as near the loss of contact that eq 73
/// considers). The exact energy of the $b = 0$ disk is
/// $\frac12(k+1) m a^2\dot\alpha^2 + \frac32 m g a\sin\alpha$ (the same coefficient $(k +
/// \cos^2\alpha)/2 \to (k+1)/2$ without friction): the claim misses the rotation about the
/// horizontal diameter, $\frac12 I_{22}\dot\alpha^2$, which is not small in $\alpha$. Its relative
/// error tends to $k/(k+4)$, 5.9 % for $k = 1/4$ and 11 % for $k = 1/2$, instead of falling as
/// $\alpha^2$. With $\dot\alpha = 0$ (the adiabatic limit) the claim holds at order 2 (see the
/// tests).
///
/// The tilt rate is a choice the paper leaves open: the verdict is also given at
/// $\dot\alpha^2 = 0.01\,g\alpha/a$, a slow fall (eq 73's check uses
/// $\dot\alpha = -0.1\sqrt{g\alpha/a}$); the missing $\frac12 k m a^2\dot\alpha^2$ is then
/// smaller, but still of the order of the kept terms, so its relative error still does not fall
/// with $\alpha$.
pub fn eq72(b: &Bench) -> Finding {
    let slow = eq72_at(b, 0.01);
    eq72_at(b, 1.0).with_robustness(vec![crate::robustness::Alternative::new(
        "the point of evaluation",
        "$\\dot\\alpha^{2} = 0.01 g \\alpha / a$, a slow fall, in place of $g \\alpha / a$ ($k = 0.25$, 0.5)",
        slow.reference,
        slow.as_read(),
    )])
}

/// Eq 73, $P = dU/dt \approx m a^2\dot\alpha\ddot\alpha + \frac32 m a g\dot\alpha \approx \frac52 m a g\dot\alpha$,
/// the last form "when $F_z \approx 0$".
///
/// FAILS. Reference: the exact rate of the energy, $dE/dt$ by a dual number, at states of the
/// $b = 0$ family ($\omega_1 = 0$, $\Omega^2 = g/ak\sin\alpha$ followed adiabatically) where the
/// premise holds exactly: $F_z = m g + m\,d^2(a\sin\alpha)/dt^2 = 0$, i.e.
/// $\ddot\alpha = (\dot\alpha^2\sin\alpha - g/a)/\cos\alpha$, with $\dot\alpha = -0.1\sqrt{g\alpha/a}$.
/// There $dE/dt \to (\frac12 - k) m a g\dot\alpha$ (the paper's own first form gives
/// $\frac12 m a g\dot\alpha$: with $F_z = 0$, $m a\ddot\alpha \approx -m g$, not $+m g$); the
/// printed $\frac52$ needs $\ddot\alpha = +g/a$, i.e. $F_z \approx 2 m g$. Error in units of
/// $m a g|\dot\alpha|$: $2 + k$, not falling with $\alpha$. (Adiabatically, $\ddot\alpha \approx
/// 0$, the power is $\frac32 m a g\dot\alpha$, the relation eq 76 should have used.)
pub fn eq73(b: &Bench) -> Finding {
    let mut headline = None;
    let mut errors = vec![0.0f64; SMALL_ALPHAS.len()];
    let mut worst_form = vec![0usize; SMALL_ALPHAS.len()];
    let mut worst_k = vec![0.0f64; SMALL_ALPHAS.len()];
    let mut runs = DiskRuns::default();
    for &k in &[0.25, 0.5] {
        let d = toy_sized(k);
        for (i, &alpha) in SMALL_ALPHAS.iter().enumerate() {
            let alpha_dot = -0.1 * (d.g * alpha / d.a).sqrt();
            let (s, c) = alpha.sin_cos();
            let alpha_ddot = (alpha_dot * alpha_dot * s - d.g_over_a()) / c;
            // Along the motion: alpha' = alpha_dot, alpha_dot' = alpha_ddot, Omega follows alpha.
            let a = Dual64::new(alpha, alpha_dot);
            let m = Motion {
                alpha: a,
                alpha_dot: Dual64::new(alpha_dot, alpha_ddot),
                precession: steady_precession(&d, a),
                spin: Dual64::from(0.0),
            };
            let reference = energy(&d, &m).eps;
            let unit = d.m * d.a * d.g * alpha_dot.abs();
            let bind = disk_constants(&d)
                .scalar("alpha", alpha)
                .scalar("alpha_dot", alpha_dot)
                .scalar("alpha_ddot", alpha_ddot)
                .scalar("P", reference)
                .scalar("U_rate", reference);
            let eq = b.paper.equation(73);
            for (form, side) in eq.chains[0].sides.iter().enumerate() {
                let e = eq
                    .scalar(side, &bind)
                    .map_or(f64::INFINITY, |c| (b.claim(c) - reference).abs() / unit);
                runs.add(k, None, SMALL_ALPHAS.len(), i, e);
                if e > errors[i] || e.is_nan() {
                    errors[i] = if e.is_nan() { f64::INFINITY } else { e };
                    worst_form[i] = form + 1;
                    worst_k[i] = k;
                }
            }
            if k == 0.25 && i == SMALL_ALPHAS.len() - 1 {
                let coefficient = d.m * d.a * d.g * alpha_dot;
                let printed = last_side(eq, &bind);
                // The form before the last: eq 73's own first approximation, from eq 72's U.
                let sides = &eq.chains[0].sides;
                let first = sides
                    .len()
                    .checked_sub(2)
                    .and_then(|i| eq.scalar(&sides[i], &bind).ok())
                    .unwrap_or(f64::NAN);
                headline = Some(Headline::new(
                    "$P / (m a g \\dot\\alpha)$ where $F_z = 0$ (eq 73's last form), against the exact \
                     rate of the full energy, $1/2 - k$ as $\\alpha \\to  0$",
                    printed / coefficient,
                    "printed",
                    reference / coefficient,
                    "1",
                    format!(
                        "uniform disk $(k = 1/4)$, $\\alpha = {alpha}$, $b = 0$; eq 73's own first form \
                         (eq 72's energy) gives {:.4} there",
                        first / coefficient
                    ),
                ));
            }
        }
    }
    let f = Finding::from_order(
        "every printed form of P in eq 73 against the exact $dE/dt$ where $F_z = 0$ ($b = 0$, adiabatic precession), \
         error in units of $m a g |\\dot\\alpha|$, against $\\alpha$",
        &SMALL_ALPHAS,
        &errors,
        b.paper.equation(73).entry.claimed_order.unwrap_or(2.0),
    );
    let mut f = naming_the_worst_side(f, &worst_form, headline);
    f.at = format!(
        "{}; each error is the larger of $k = 1/4$ and $k = 1/2$ at its $\\alpha$, at the smallest $\\alpha$ \
         that of $k = {}$ (2 + k in units of $m a g |\\dot\\alpha|$)",
        f.at,
        worst_k.last().copied().unwrap_or(f64::NAN)
    );
    let alternatives = runs.alternatives(&SMALL_ALPHAS, f.claimed);
    f.with_robustness(alternatives)
}

/// `f` with the printed form (side of the chain) that is worst at the smallest tilt named in
/// its `at`, and `headline`.
fn naming_the_worst_side(
    mut f: Finding,
    worst_form: &[usize],
    headline: Option<Headline>,
) -> Finding {
    f.at = format!(
        "{}; worst printed form at the smallest $\\alpha$: side {}",
        f.at,
        worst_form.last().copied().unwrap_or(0)
    );
    f.headline = headline;
    f
}
