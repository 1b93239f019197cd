//! Does an equation FOLLOW from its printed premises? Each check here takes the premises'
//! LaTeX, as printed, for the reference, and the equation's own LaTeX for the claim: it asks
//! about the paper's algebra, not about the physics. The physics is asked by the equation's own
//! check (its [`super::Equation::check`]). Together they let [`crate::cause`] tell a root cause
//! (the premises hold, or the step from them is wrong) from an inherited error (a correct step
//! from a wrong premise).
//!
//! Only the equations that fail and have a failing premise need this (an equation that fails
//! while all its premises hold cannot follow from them): the chain of section 11.

use super::spin_down_reference::{
    derivation_from_eq76, law_bindings, printed_c, toy_laws, SMALL_ALPHAS,
};
use crate::equations::Derivation;
use crate::finding::{Finding, Method, Tolerance, Worst};
use crate::harness::{last_side, printed_relations, solve_printed, worst_order, Bench};
use num_dual::Dual64;
use paper::{Bindings, Relation};
use physics::disk::toy_sized;
use physics::model::dissipation::PowerLaw;
use std::f64::consts::FRAC_PI_2;

/// The derivation checks.
pub const DERIVATIONS: &[Derivation] = &[
    Derivation {
        number: 73,
        check: eq73_from_eq72,
    },
    Derivation {
        number: 76,
        check: eq76_from_eqs73_75,
    },
    Derivation {
        number: 77,
        check: eq77_from_eq76,
    },
    Derivation {
        number: 78,
        check: eq78_from_eq77,
    },
    Derivation {
        number: 79,
        check: eq79_from_eqs78_31,
    },
    Derivation {
        number: 83,
        check: eq83_from_eq82,
    },
    Derivation {
        number: 84,
        check: eq84_from_eq79,
    },
];

/// Eq 83 from eq 82 AS PRINTED (the physics is [`super::air_film::eq83`]):
/// $\Omega = \sqrt{g/ak}\,((m/2\pi\eta a)/(t_0 - t))^{1/6}$ from eq 82's tilt as printed,
/// $\alpha = ((2\pi\eta a/m)(t_0 - t))^{1/3}$, and the small-angle precession
/// $\Omega^2 = g/ak\alpha$ that the paper uses, evaluated at times before $t_0$ from 10 s to
/// 1 ms (air, $\eta = 1.8\times10^{-5}$ Pa s; k = 1/4, 1/2).
pub fn eq83_from_eq82(b: &Bench) -> Finding {
    let eta = 1.8e-5;
    let mut worst = Worst::default();
    for &k in &[0.25, 0.5] {
        let d = toy_sized(k);
        for i in 0..20 {
            let tau = 10f64.powf(1.0 - 4.0 * f64::from(i) / 19.0);
            let bind = law_bindings(
                &d,
                &PowerLaw {
                    epsilon: 0.0,
                    beta: 4.0,
                },
            )
            .scalar("eta", eta)
            // The squeeze film's number, for forms that carry it (the corrected ones): eq 83
            // follows from eq 82 for any value, so a fixed one serves.
            .scalar("film_number", 0.1068)
            .scalar("t_0", 7.27)
            .scalar("t", 7.27 - tau);
            // Eq 82 as printed gives alpha; the small-angle precession gives Omega.
            let eq82 = b.paper.equation(82);
            let alpha = last_side(eq82, &bind);
            let reference = (d.g / (d.a * k * alpha)).sqrt();
            printed_relations(
                b,
                83,
                &bind.scalar("Omega", reference),
                reference,
                &mut worst,
                &|| format!("$k = {k}$, $t_0 - t = {tau:.3e}$ s"),
            );
        }
    }
    Finding::from_worst(
        Method::Derivation,
        "$\\Omega$ of eq 83 against eq 82's $\\alpha$ put into $\\Omega^{2} = g/(a k \\alpha)$",
        worst,
        Tolerance::roundoff(),
    )
}

/// Eq 73 from eq 72 AS PRINTED under the condition the paper attaches to its last form,
/// $F_z \approx 0$, with the vertical force the same section gives, $F_z \approx m g + m a\ddot\alpha$:
/// so $\ddot\alpha = -g/a$. The rate of eq 72's last form,
/// $\frac{d}{dt}\left(\frac12 m a^2\dot\alpha^2 + \frac32 m a g\alpha\right)$, is taken exactly by a dual
/// number through the parsed LaTeX (tilt $\alpha + \dot\alpha\,\varepsilon$, tilt rate
/// $\dot\alpha + \ddot\alpha\,\varepsilon$) and every printed form of eq 73 is compared with it, in
/// units of $m a g|\dot\alpha|$. The middle form follows exactly; the last, $\frac52 m a g\dot\alpha$,
/// does not: eq 72 gives $\frac12 m a g\dot\alpha$ there.
pub fn eq73_from_eq72(b: &Bench) -> Finding {
    let eq72 = b.paper.equation(72);
    let mut worst = Worst::default();
    for &k in &[0.25, 0.5] {
        let d = toy_sized(k);
        for &alpha in &SMALL_ALPHAS {
            let alpha_dot = -0.1 * (d.g * alpha / d.a).sqrt();
            let alpha_ddot = -d.g_over_a();
            let constant = Dual64::from_re;
            let bind = Bindings::<Dual64>::new()
                .scalar("m", constant(d.m))
                .scalar("a", constant(d.a))
                .scalar("g", constant(d.g))
                .scalar("k", constant(k))
                .scalar("alpha", Dual64::new(alpha, alpha_dot))
                .scalar("alpha_dot", Dual64::new(alpha_dot, alpha_ddot));
            let derived = eq72.chains[0]
                .sides
                .last()
                .and_then(|e| eq72.scalar(e, &bind).ok())
                .map_or(f64::NAN, |u| u.eps);
            let unit = d.m * d.a * d.g * alpha_dot.abs();
            let at = Bindings::new()
                .scalar("m", d.m)
                .scalar("a", d.a)
                .scalar("g", d.g)
                .scalar("k", k)
                .scalar("alpha_dot", alpha_dot)
                .scalar("alpha_ddot", alpha_ddot)
                .scalar("P", derived)
                .scalar("U_rate", derived);
            printed_relations(b, 73, &at, unit, &mut worst, &|| {
                format!(
                    "$k = {k}$, $\\alpha = {alpha}$, $\\dot\\alpha = {alpha_dot:.4}$ rad/s, $\\ddot\\alpha = -g/a$; \
                     eq 72's last form gives $dU/dt = {:.4} m a g \\dot\\alpha$",
                    derived / (d.m * d.a * d.g * alpha_dot)
                )
            });
        }
    }
    Finding::from_worst(
        Method::Derivation,
        "every printed form of eq 73 against the rate of eq 72's last form where $F_z = m g + m a \\ddot\\alpha = 0$ \
         (error in units of $m a g |\\dot\\alpha|$)",
        worst,
        Tolerance::roundoff())
}

/// Eq 76's first relation from eq 73's last form and eq 75, both AS PRINTED: the power of eq 75,
/// $P = -\epsilon m a g\Omega^\beta$, put into $P \approx \frac52 m a g\dot\alpha$ and solved for
/// $\dot\alpha$ (a root of the printed relation between eq 73's first and last sides, with
/// $\ddot\alpha = 0$: eq 76 is a first-order law for the tilt, the adiabatic regime, so a form
/// of eq 73 that keeps $\ddot\alpha$ is read there), against the
/// $\dot\alpha$ eq 76 prints, at tilts and rates over the sweep of the section (k = 1/4, 1/2;
/// beta = 1, 2, 4; $\Omega$ from 10 to 1000 rad/s). Its second relation (the small-angle form of
/// eq 31) is derived from the first with eq 31 as printed ([`eq76_second_from_eq31`]).
pub fn eq76_from_eqs73_75(b: &Bench) -> Finding {
    let (eq73, eq75, eq76) = (
        b.paper.equation(73),
        b.paper.equation(75),
        b.paper.equation(76),
    );
    let mut worst = Worst::default();
    let sides = &eq73.chains[0].sides;
    let (Some(first), Some(last), Some(rel)) = (
        sides.first(),
        sides.last(),
        eq73.chains[0].rels.last().copied(),
    ) else {
        return no_form(73);
    };
    let power_to_rate = Relation {
        chain: 0,
        index: sides.len() - 2,
        rel,
        lhs: first,
        rhs: last,
    };
    for &k in &[0.25, 0.5] {
        let d = toy_sized(k);
        for &beta in &[1.0, 2.0, 4.0] {
            for omega in [10.0f64, 100.0, 1000.0] {
                let law = PowerLaw {
                    epsilon: 1e-3 * omega.powf(1.0 - beta),
                    beta,
                };
                let bind = law_bindings(&d, &law)
                    .scalar("Omega", omega)
                    .scalar("alpha_ddot", 0.0);
                let power = last_side(eq75, &bind);
                let scale = (power / (d.m * d.a * d.g)).abs();
                let derived = solve_printed(
                    eq73,
                    &power_to_rate,
                    "alpha_dot",
                    &bind.clone().scalar("P", power),
                    -1e3 * scale,
                    1e3 * scale,
                )
                .unwrap_or(f64::NAN);
                let printed = eq76
                    .relations()
                    .first()
                    .and_then(|r| eq76.scalar(r.rhs, &bind).ok())
                    .unwrap_or(f64::NAN);
                worst.add(b.claim(printed), derived, derived.abs(), || {
                    format!(
                        "$k = {k}$, $\\beta = {beta}$, $\\Omega = {omega}$ rad/s: eqs 73 and 75 give $\\dot\\alpha = {derived:.6e}$ rad/s"
                    )
                });
            }
        }
    }
    let first = Finding::from_worst(
        Method::Derivation,
        "eq 76's first relation against $\\dot\\alpha$ solved from eq 73's last form with the power of eq 75",
        worst,
        Tolerance::roundoff());
    worst_order(vec![
        ("first relation".into(), first),
        ("second relation".into(), eq76_second_from_eq31(b)),
    ])
}

/// Eq 76's second relation from its first with $\Omega_0$ solved from eq 31 AS PRINTED
/// ($\Omega_0^2 = g/ak\sin\alpha_0$) at each tilt: a small-angle form, whose relative error must
/// fall at the order eq 76 claims (k = 1/4, 1/2; beta = 1, 2, 4).
fn eq76_second_from_eq31(b: &Bench) -> Finding {
    let eq76 = b.paper.equation(76);
    let rels = eq76.relations();
    let mut errors = vec![0.0f64; SMALL_ALPHAS.len()];
    for (d, law) in toy_laws(&[1.0, 2.0, 4.0]) {
        for (i, &alpha) in SMALL_ALPHAS.iter().enumerate() {
            let bind = law_bindings(&d, &law);
            let omega = omega_from_eq31(b, &d, alpha, &bind);
            let at = bind.scalar("alpha", alpha).scalar("Omega", omega);
            let e = match (rels.first(), rels.get(1)) {
                (Some(r1), Some(r2)) => {
                    match (eq76.scalar(r1.rhs, &at), eq76.scalar(r2.rhs, &at)) {
                        (Ok(l), Ok(r)) => ((b.claim(r) - l) / l).abs(),
                        _ => f64::INFINITY,
                    }
                }
                _ => f64::INFINITY,
            };
            errors[i] = errors[i].max(if e.is_nan() { f64::INFINITY } else { e });
        }
    }
    Finding::from_order(
        "eq 76's second relation against its first with $\\Omega_0$ solved from eq 31 as printed, relative error against $\\alpha$",
        &SMALL_ALPHAS,
        &errors,
        eq76.entry.claimed_order.unwrap_or(2.0),
    )
}

fn no_form(n: u32) -> Finding {
    let mut worst = Worst::default();
    worst.add(f64::NAN, 0.0, 1.0, || {
        format!("eq {n} has no printed relation")
    });
    Finding::from_worst(
        Method::Derivation,
        format!("eq {n} as printed"),
        worst,
        Tolerance::roundoff(),
    )
}

/// Eq 77 from eq 76's printed law, integrated numerically: the $t_0$ it implies must not drift.
pub fn eq77_from_eq76(b: &Bench) -> Finding {
    derivation_from_eq76(b, 77, 0, "eq 77")
}

/// Eq 78 from eq 77 AS PRINTED: the tilt that makes eq 77 hold (a root in $(0, \pi/2)$) against
/// the tilt eq 78 prints, at times before $t_0$ over ten decades (k = 1/4, 1/2; beta = 1, 2,
/// 2.5, 4; epsilon = 1e-3).
pub fn eq78_from_eq77(b: &Bench) -> Finding {
    let eq77 = b.paper.equation(77);
    let mut worst = Worst::default();
    for (d, law, tau, bind) in chain_points() {
        let from77 = eq77
            .relations()
            .first()
            .and_then(|r| solve_printed(eq77, r, "alpha", &bind, 1e-9, FRAC_PI_2));
        let Some(alpha) = from77 else {
            continue;
        };
        printed_relations(
            b,
            78,
            &bind.scalar("alpha", alpha),
            alpha,
            &mut worst,
            &|| {
                format!(
                    "$k = {}$, $\\beta = {}$, $t_0 - t = {tau:e}$ s: eq 77 gives $\\alpha = {alpha:.6e}$",
                    d.k, law.beta
                )
            },
        );
    }
    Finding::from_worst(
        Method::Derivation,
        "eq 78's tilt against the tilt that solves eq 77, at times before $t_0$ over ten decades",
        worst,
        Tolerance::roundoff(),
    )
}

/// Eq 79 from eq 78 and eq 31, both AS PRINTED: the tilt of eq 78 at a time before $t_0$, put
/// into eq 31 ($\Omega_0^2 = g/ak\sin\alpha_0$, solved for $\Omega_0$), against the $\Omega$ of eq
/// 79's first relation and of its last side (with the $C$ its second relation defines). Eq 79
/// uses $\sin\alpha \approx \alpha$, so its relative error must fall at the order eq 76 claims as
/// the tilt shrinks (times chosen so that eq 78 gives the tilts 0.2 ... 0.0125).
pub fn eq79_from_eqs78_31(b: &Bench) -> Finding {
    let (eq78, eq79) = (b.paper.equation(78), b.paper.equation(79));
    let mut errors = vec![0.0f64; SMALL_ALPHAS.len()];
    for (d, law) in toy_laws(&[1.0, 2.0, 2.5, 4.0]) {
        let c = printed_c(b, &d, &law);
        for (i, &alpha) in SMALL_ALPHAS.iter().enumerate() {
            let base = law_bindings(&d, &law).scalar("t", 0.0).scalar("C", c);
            // The time before t_0 at which eq 78 gives this tilt.
            let t0 = eq78
                .relations()
                .first()
                .and_then(|r| {
                    solve_printed(
                        eq78,
                        r,
                        "t_0",
                        &base.clone().scalar("alpha", alpha),
                        1e-12,
                        1e12,
                    )
                })
                .unwrap_or(f64::NAN);
            let bind = base.scalar("t_0", t0);
            let tilt = last_side(eq78, &bind);
            let omega = omega_from_eq31(b, &d, tilt, &bind);
            let first = eq79
                .relations()
                .first()
                .and_then(|r| eq79.scalar(r.rhs, &bind).ok())
                .unwrap_or(f64::NAN);
            let last = last_side(eq79, &bind);
            let e = [first, last]
                .iter()
                .map(|v| ((b.claim(*v) - omega) / omega).abs())
                .fold(
                    0.0,
                    |m: f64, e| if e.is_nan() { f64::INFINITY } else { m.max(e) },
                );
            errors[i] = errors[i].max(e);
        }
    }
    Finding::from_order(
        "eq 79's $\\Omega$ (first relation and last side) against eq 31's $\\Omega$ at eq 78's tilt, relative error against $\\alpha$",
        &SMALL_ALPHAS,
        &errors,
        eq79.entry.claimed_order.unwrap_or(2.0),
    )
}

/// Eq 84 from eq 79 AS PRINTED: $1/\Omega$ from eq 79's last side (with the $C$ its second
/// relation defines) against eq 84's right side, at times before $t_0$ over ten decades.
pub fn eq84_from_eq79(b: &Bench) -> Finding {
    let eq79 = b.paper.equation(79);
    let mut worst = Worst::default();
    for (d, law, tau, bind) in chain_points() {
        let bind = bind.scalar("C", printed_c(b, &d, &law));
        let omega = last_side(eq79, &bind);
        printed_relations(
            b,
            84,
            &bind.scalar("Omega", omega),
            1.0 / omega,
            &mut worst,
            &|| {
                format!(
                    "$k = {}$, $\\beta = {}$, $t_0 - t = {tau:e}$ s",
                    d.k, law.beta
                )
            },
        );
    }
    Finding::from_worst(
        Method::Derivation,
        "eq 84's $1/\\Omega$ against the reciprocal of eq 79's last side, at times before $t_0$ over ten decades",
        worst,
        Tolerance::roundoff())
}

/// $\Omega_0$ solved from eq 31 AS PRINTED ($\Omega_0^2 = g/ak\sin\alpha_0$) at the tilt
/// `alpha` for disk `d`, the other symbols bound by `bind` (NaN if it has no root).
fn omega_from_eq31(b: &Bench, d: &physics::disk::Disk, alpha: f64, bind: &Bindings<f64>) -> f64 {
    let eq31 = b.paper.equation(31);
    let guess = (d.g / (d.a * d.k * alpha)).sqrt();
    eq31.relations()
        .first()
        .and_then(|r| {
            let at = bind.clone().scalar("alpha_0", alpha);
            solve_printed(eq31, r, "Omega_0", &at, 0.0, 1e3 * guess)
        })
        .unwrap_or(f64::NAN)
}

/// The points of the single-step derivations along the chain 77-84: (disk, law, time before
/// $t_0$, bindings with $t = 0.3$ s and $t_0$ that much later; $t \neq 0$ so that a printed $t$
/// is seen).
fn chain_points() -> Vec<(physics::disk::Disk, PowerLaw, f64, Bindings<f64>)> {
    let mut out = Vec::new();
    for (d, law) in toy_laws(&[1.0, 2.0, 2.5, 4.0]) {
        for i in 0..9 {
            let tau = 10f64.powi(i - 6);
            let bind = law_bindings(&d, &law)
                .scalar("t", 0.3)
                .scalar("t_0", 0.3 + tau);
            out.push((d, law, tau, bind));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::finding::Verdict;

    fn run(n: u32) -> (Finding, Finding) {
        let d = DERIVATIONS.iter().find(|d| d.number == n).map(|d| d.check);
        let check = d.unwrap_or(|_| panic!("no derivation"));
        let ok = check(&Bench::default());
        let bad = check(&Bench::perturbed(1e-3));
        eprintln!(
            "eq {n}: {} error {:.3e} at {}\n  perturbed: {} error {:.3e}",
            ok.verdict, ok.error, ok.at, bad.verdict, bad.error
        );
        (ok, bad)
    }

    #[test]
    fn eq73_last_form_does_not_follow_from_eq72_at_zero_normal_force() {
        let (f, _) = run(73);
        assert_eq!(f.verdict, Verdict::Fails);
        // 5/2 printed against 1/2 derived, in units of m a g |alpha_dot|.
        assert!((f.error - 2.0).abs() < 1e-9, "{}", f.error);
        assert!(f.at.contains("relation 3"), "{}", f.at);
    }

    #[test]
    fn the_rest_of_the_chain_follows_from_its_printed_premises() {
        for n in [76, 77, 78, 79, 84] {
            let (ok, bad) = run(n);
            assert!(ok.verdict.passes(), "eq {n}: {}", ok.at);
            assert_eq!(bad.verdict, Verdict::Fails, "eq {n} perturbed");
        }
    }
}
