//! Small oscillations about steady motion, section 7 of the paper (eqs 44-58).
//!
//! References: the exact Jacobian $J$ of the rolling model (eqs 23-25 as implemented, dual
//! numbers) at a steady motion solved from the model itself (`steady_reference::steady_ref`, Newton on
//! eq 24). Its eigenvalues are $\{0, 0, \pm i\varpi\}$ (the steady motions form a two-parameter
//! family), so the sum of its principal 2x2 minors, the second coefficient $e_2$ of its
//! characteristic polynomial, is exactly $\varpi^2$ (negative when the motion is unstable);
//! the oscillation mode's eigenvector gives the amplitude ratios. Frequencies are also measured
//! on small-amplitude integrations, and thresholds located by bisection on integrations.
//! $b/a$ enters as the ratio $\omega_{10}/\Omega_0$ (eq 28, checked by measuring the path).

use super::steady_reference::{disk, jac, rho_edge, state, steady_ref, KS};
use super::{
    add_threshold, implied_square, printed_relations, printed_threshold, solve_printed, term_scale,
    Bench, Equation,
};
use crate::disk::Disk;
use crate::finding::{Finding, Method, Tolerance, Worst};
use crate::model::rolling::Rolling;
use crate::model::{Extras, Model, Motion};
use crate::numerics::oscillation::{angular_frequency, bisect};
use crate::paper::Bindings;
use crate::solve::{solve, Ending, Event, Problem, State};
use nalgebra::{Complex, SMatrix};
use std::f64::consts::{FRAC_PI_2, PI};

/// The checks of this part of the paper.
pub const EQUATIONS: &[Equation] = &[
    Equation {
        number: 44,
        label: "e41",
        check: eq44,
    },
    Equation {
        number: 45,
        label: "e42",
        check: eq45,
    },
    Equation {
        number: 46,
        label: "e43",
        check: eq46,
    },
    Equation {
        number: 47,
        label: "e44",
        check: eq47,
    },
    Equation {
        number: 48,
        label: "e45",
        check: eq48,
    },
    Equation {
        number: 49,
        label: "e46",
        check: eq49,
    },
    Equation {
        number: 50,
        label: "e47",
        check: eq50,
    },
    Equation {
        number: 51,
        label: "e48",
        check: eq51,
    },
    Equation {
        number: 52,
        label: "e49",
        check: eq52,
    },
    Equation {
        number: 53,
        label: "e49a",
        check: eq53,
    },
    Equation {
        number: 54,
        label: "e50",
        check: eq54,
    },
    Equation {
        number: 55,
        label: "e51",
        check: eq55,
    },
    Equation {
        number: 56,
        label: "e52",
        check: eq56,
    },
    Equation {
        number: 57,
        label: "e53",
        check: eq57,
    },
    Equation {
        number: 58,
        label: "e54",
        check: eq58,
    },
];

/// $\varpi^2$ of the linearized model at state `y`: the sum of the principal 2x2 minors of the
/// Jacobian (the product of the two non-zero eigenvalues $\pm i\varpi$).
fn varpi2(d: &Disk, y: &[f64; 4]) -> f64 {
    let j = jac(d, y);
    let mut e2 = 0.0;
    for i in 0..4 {
        for l in i + 1..4 {
            e2 += j[(i, i)] * j[(l, l)] - j[(i, l)] * j[(l, i)];
        }
    }
    e2
}

/// The oscillation mode's eigenvector normalised to $\epsilon = 1$: the complex amplitudes of
/// $(\Omega, \omega_1)$ for eigenvalue $\lambda = i\varpi$ (state order
/// $\alpha, \dot\alpha, \Omega, \omega_1$, so the $\dot\alpha$ entry is $\lambda$).
fn mode(j: &SMatrix<f64, 4, 4>, varpi: f64) -> (Complex<f64>, Complex<f64>) {
    let l = Complex::new(0.0, varpi);
    let c = |x: f64| Complex::new(x, 0.0);
    // (J22 - l) v2 + J23 v3 = -(J20 + J21 l); J32 v2 + (J33 - l) v3 = -(J30 + J31 l).
    let (a11, a12, a21, a22) = (
        c(j[(2, 2)]) - l,
        c(j[(2, 3)]),
        c(j[(3, 2)]),
        c(j[(3, 3)]) - l,
    );
    let r1 = -(c(j[(2, 0)]) + c(j[(2, 1)]) * l);
    let r2 = -(c(j[(3, 0)]) + c(j[(3, 1)]) * l);
    let det = a11 * a22 - a12 * a21;
    ((r1 * a22 - a12 * r2) / det, (a11 * r2 - a21 * r1) / det)
}

/// Tilts, ratios $b/a$ (the negative one half way to the model's edge) and k of the sweep.
const ALPHAS: [f64; 5] = [0.05, 0.3, 0.8, 1.2, 1.5];

fn rhos(d: &Disk, alpha0: f64) -> [f64; 4] {
    [0.5 * rho_edge(d, alpha0, 1e-12), 0.0, 0.5, 2.0]
}

fn at(k: f64, alpha0: f64, rho: f64) -> String {
    format!("k = {k}, alpha0 = {alpha0}, b/a = {rho:.4}")
}

/// Calls `f(k, disk, alpha0, rho, steady motion)` over the sweep.
fn sweep(mut f: impl FnMut(f64, &Disk, f64, f64, &Motion)) {
    for k in KS {
        let d = disk(k);
        for alpha0 in ALPHAS {
            for rho in rhos(&d, alpha0) {
                if let Some(m) = steady_ref(&d, alpha0, rho) {
                    f(k, &d, alpha0, rho, &m);
                }
            }
        }
    }
}

/// The natural size of the terms of $\varpi^2$: $\Omega_0^2 + \omega_{10}^2 + g/a$ (errors are
/// relative to it, so that a $\varpi^2$ that happens to vanish is not divided by zero).
fn scale(d: &Disk, m: &Motion) -> f64 {
    m.precession * m.precession + m.spin * m.spin + d.g_over_a()
}

/// The angular frequency of $\alpha(t)$ measured on an integration started from steady motion
/// `m` displaced by `eps` along the oscillation mode, over 4 periods at 300 samples each.
fn measured_frequency(b: &Bench, d: &Disk, m: &Motion, varpi: f64, eps: f64) -> Option<f64> {
    let j = jac(d, &state(m));
    let (dl, ga) = mode(&j, varpi);
    let model = Rolling::<4>::new(*d, Extras::default(), None);
    let mut start = *m;
    start.alpha += eps;
    start.precession += eps * dl.re;
    start.spin += eps * ga.re;
    let period = 2.0 * PI / varpi;
    let sol = solve(
        Problem::new(&model, 0.0, model.state(&start), 4.0 * period).sampled(period / 300.0),
        &b.settings(),
    )
    .ok()?;
    let alpha: Vec<f64> = sol.y.iter().map(|y| y[0]).collect();
    angular_frequency(&sol.t, &alpha)
}

/// The paper's constants and a steady motion bound to its symbols.
fn steady_bindings(d: &Disk, m: &Motion) -> Bindings<f64> {
    Bindings::new()
        .scalar("a", d.a)
        .scalar("k", d.k)
        .scalar("g", d.g)
        .scalar("alpha_0", m.alpha)
        .scalar("Omega_0", m.precession)
        .scalar("omega_10", m.spin)
        .scalar("epsilon", EPSILON)
}

/// The amplitude bound to $\epsilon$ in the linearization checks (eqs 47-50): the relations
/// are linear in it, and any value but 1 shows a dropped factor.
const EPSILON: f64 = 1e-3;

/// The $\varpi^2$ the printed eq `n` gives at a steady motion (its first relation, solved for
/// $\varpi^2$; extra bindings in `bind`), read through [`Bench::claim`].
fn printed_varpi2(b: &Bench, n: u32, bind: &Bindings<f64>) -> f64 {
    let eq = b.paper.equation(n);
    eq.relations().first().map_or(f64::NAN, |rel| {
        b.claim(implied_square(eq, rel, "varpi", bind))
    })
}

/// Eq 50, $\varpi^2(k+1) = \Omega_0^2(k(1 + 2\cos^2\alpha_0) + \sin^2\alpha_0) +
/// (6k+1)\omega_{10}\Omega_0\cos\alpha_0 + 2(2k+1)\omega_{10}^2 - \frac{g}{a}\sin\alpha_0$, as
/// printed, solved for $\varpi^2$.
fn eq50_claim(b: &Bench, d: &Disk, m: &Motion) -> f64 {
    printed_varpi2(b, 50, &steady_bindings(d, m))
}

/// Eq 50: the squared frequency of small oscillations about a general steady motion.
///
/// Linearization and integration: compared with $\varpi^2 = e_2(J)$ of the model's exact
/// Jacobian over k in {0.1, 0.25, 0.5, 0.9}, tilts 0.05-1.5 and b/a in {negative, 0, 0.5, 2}
/// (relative to $\Omega_0^2 + \omega_{10}^2 + g/a$, round-off rule); and, at the stable points
/// of k = 1/4 (tilts below 1.5, b/a below 1), with the frequency of $\alpha(t)$ measured on integrations of
/// amplitudes $\epsilon = 10^{-5}\alpha_0$ and $2\epsilon$ along the mode, extrapolated to zero
/// amplitude (Richardson in $\epsilon^2$; relative, solver rule).
fn eq50(b: &Bench) -> Finding {
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
        "varpi^2 against e2 of the model's Jacobian, relative to Omega_0^2 + omega_10^2 + g/a",
        lin,
        Tolerance::roundoff(),
        false,
    );
    let bfind = Finding::from_worst(
        Method::Integration,
        "varpi against the frequency of alpha measured on small-amplitude integrations",
        int,
        Tolerance::solver(b.rtol),
        false,
    );
    worse(a, bfind)
}

/// The worse of two findings (a failure first, then the larger error relative to tolerance).
fn worse(a: Finding, b: Finding) -> Finding {
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
fn eq47(b: &Bench) -> Finding {
    ratio_check(b, 47)
}

/// Eq 48, $\gamma = -\epsilon\dfrac{\Omega_0\sin\alpha_0}{2k+1}$.
///
/// Linearization: the $\omega_1$ entry of the oscillation mode's eigenvector, as for eq 47.
fn eq48(b: &Bench) -> Finding {
    ratio_check(b, 48)
}

fn ratio_check(b: &Bench, which: u32) -> Finding {
    let mut w = Worst::default();
    sweep(|k, d, alpha0, rho, m| {
        let v2 = varpi2(d, &state(m));
        if v2 <= 0.0 {
            return;
        }
        let j = jac(d, &state(m));
        let (dl, ga) = mode(&j, v2.sqrt());
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
            "delta/epsilon against the mode's eigenvector of the model's Jacobian"
        } else {
            "gamma/epsilon against the mode's eigenvector of the model's Jacobian"
        },
        w,
        Tolerance::roundoff(),
        false,
    )
}

/// Eq 49, the first-order part of eq 24:
/// $\epsilon\varpi^2(k+1) = -(2k+1)(\epsilon\omega_{10}\Omega_0\cos\alpha_0 + \gamma\Omega_0\sin\alpha_0
/// + \delta\omega_{10}\sin\alpha_0) + \epsilon k\Omega_0^2(1 - 2\cos^2\alpha_0)
/// - 2\delta k\Omega_0\sin\alpha_0\cos\alpha_0 - \epsilon\frac{g}{a}\sin\alpha_0$.
///
/// Linearization: with $\epsilon = 1$ and $\delta$, $\gamma$ from the model's eigenvector (not
/// from eqs 47-48), the right-hand side divided by $k+1$ is compared with $\varpi^2 = e_2(J)$.
fn eq49(b: &Bench) -> Finding {
    let mut w = Worst::default();
    sweep(|k, d, alpha0, rho, m| {
        let v2 = varpi2(d, &state(m));
        if v2 <= 0.0 {
            return;
        }
        let j = jac(d, &state(m));
        let (dl, ga) = mode(&j, v2.sqrt());
        let bind = steady_bindings(d, m)
            .scalar("delta", EPSILON * dl.re)
            .scalar("gamma", EPSILON * ga.re);
        let claimed = printed_varpi2(b, 49, &bind);
        w.add(claimed, v2, scale(d, m), || at(k, alpha0, rho));
    });
    Finding::from_worst(
        Method::Linearization,
        "varpi^2 from the alpha row with the eigenvector's delta, gamma, against e2 of the Jacobian",
        w,
        Tolerance::roundoff(),
        false,
    )
}

/// Eq 51, $\varpi^2(k+1) = 2(2k+1)\omega_{10}^2 - \frac{g}{a}$ for a wheel rolling straight
/// ($\alpha_0 = \pi/2$, $\Omega_0 = 0$).
///
/// Linearization: $e_2$ of the model's Jacobian at the upright rolling state, for
/// $\omega_{10}^2$ from 0.1 to 10 times $g/a$.
fn eq51(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for k in KS {
        let d = disk(k);
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
                format!("k = {k}, omega_10^2 = {f} g/a")
            });
        }
    }
    Finding::from_worst(
        Method::Linearization,
        "varpi^2 of the straight wheel against e2 of the Jacobian, relative to omega_10^2 + g/a",
        w,
        Tolerance::roundoff(),
        false,
    )
}

/// Integrations last $N$ natural times $\sqrt{a/g}$. The upright disk is kicked with a small
/// $\dot\alpha_0$ (which excites only the oscillation: $\Omega$ and $\omega_1$ follow $\alpha$ by
/// the first-order eqs 23 and 25 and so start on the mode); it is stable when $\dot\alpha$
/// turns back, which it does within $T$ iff $\varpi > \pi/2T$ (unstable: $\dot\alpha \propto
/// \cosh\sigma t$ never turns back). Near both thresholds $(k+1)\varpi^2 = (g/a)(x/x_* - 1)$ for
/// the squared rate $x$ with threshold $x_*$ (eq 50 at $\alpha_0 = \pi/2$, whose linearization is
/// verified in eqs 50-51), so the located threshold in $x$ is high by at most
/// $(k+1)(\pi/2)^2/N^2$ relatively; half that for $\sqrt{x}$.
const N_NATURAL: f64 = 2000.0;

fn finite_time_tolerance(k: f64, width: f64, squared: bool) -> Tolerance {
    let bias = (k + 1.0) * FRAC_PI_2 * FRAC_PI_2 / (N_NATURAL * N_NATURAL);
    let bias = if squared { bias } else { 0.5 * bias };
    Tolerance {
        value: bias + 2.0 * width,
        rule: format!(
            "threshold from integrations of {N_NATURAL} sqrt(a/g): finite-time bias \
             (k+1) (pi/2)^2 / N^2{} plus twice the bracket ({width:e})",
            if squared { "" } else { " / 2" }
        ),
    }
}

/// Does the upright disk with $(\Omega, \omega_1)$, kicked with
/// $\dot\alpha_0 = 10^{-8}\sqrt{g/a}$, turn back (its $\dot\alpha$ changes sign) within $N$
/// natural times, before it falls $10^{-3}$ rad off upright (a disk that falls may turn back
/// later into another motion: that is not stability)?
fn turns_back(b: &Bench, d: &Disk, precession: f64, spin: f64) -> bool {
    let model = Rolling::<4>::new(*d, Extras::default(), None);
    let m = Motion {
        alpha: FRAC_PI_2,
        alpha_dot: 1e-8 * d.g_over_a().sqrt(),
        precession,
        spin,
    };
    let t = N_NATURAL / d.g_over_a().sqrt();
    let sol = solve(
        Problem::new(&model, 0.0, model.state(&m), t)
            .stop_when(Event::new("alpha_dot turns back", |y: &State<4>| y[1]))
            .stop_when(Event::new("falls 1e-3 rad off upright", |y: &State<4>| {
                1e-3 - (y[0] - FRAC_PI_2).abs()
            })),
        &b.settings(),
    )
    .expect("valid settings");
    matches!(sol.ending, Ending::Event { index: 0, .. })
}

/// Eq 52, $\omega_{10}^2 > \dfrac{g}{2(2k+1)a}$: a wheel rolling straight is stable only above it.
///
/// Threshold: located by bisection on the outcome of integrations (does the wheel, kicked off
/// upright, turn back within 2000 natural times?), and by bisection on the sign
/// of the linearized $\varpi^2 = e_2(J)$; both compared with the claimed bound on
/// $\omega_{10}^2$.
fn eq52(b: &Bench) -> Finding {
    threshold_check(b, 52)
}

/// Eq 53, $|\Omega_0| > \sqrt{\dfrac{g}{a(k+1)}}$: a disk spinning about a vertical diameter is
/// stable only above it.
///
/// Threshold: as for eq 52, on $|\Omega_0|$ with $\omega_{10} = 0$.
fn eq53(b: &Bench) -> Finding {
    threshold_check(b, 53)
}

/// Eqs 52 and 53: the threshold on $\omega_{10}$ (eq 52, printed on its square) or on
/// $|\Omega_0|$ (eq 53) where the upright disk becomes stable, located by bisection on the
/// linearized $\varpi^2$ and on integrations; compared with the edge the printed inequality gives
/// (solved for $\omega_{10}$ or $\Omega_0$), and its direction with the linearization's verdict
/// 0.1 % either side.
fn threshold_check(b: &Bench, which: u32) -> Finding {
    let width = 1e-10;
    let width_int = 1e-6;
    let mut out: Option<Finding> = None;
    for k in KS {
        let d = disk(k);
        let ga = d.g_over_a();
        // x is omega_10 (eq 52) or |Omega_0| (eq 53): the state (Omega, omega_1) at x.
        let y_of = |x: f64| if which == 52 { (0.0, x) } else { (x, 0.0) };
        let (lo, hi) = (0.3 * ga.sqrt(), 3.0 * ga.sqrt());
        let stable = |x: f64| {
            let (om, w) = y_of(x);
            varpi2(&d, &[FRAC_PI_2, 0.0, om, w]) > 0.0
        };
        let lin = {
            let (l, h) = bisect(lo, hi, width, stable);
            0.5 * (l + h)
        };
        let int = {
            let (l, h) = bisect(lo, hi, width_int, |x| {
                let (om, w) = y_of(x);
                turns_back(b, &d, om, w)
            });
            0.5 * (l + h)
        };
        let quantity = if which == 52 { "omega_10" } else { "Omega_0" };
        let bind = Bindings::new()
            .scalar("g", d.g)
            .scalar("a", d.a)
            .scalar("k", k);
        let probes = [lin * (1.0 - 1e-3), lin * (1.0 + 1e-3)];
        let printed = printed_threshold(b, which, quantity, &bind, (lo, hi), probes);
        let allowed = probes.map(stable);
        let mut wl = Worst::default();
        add_threshold(b, &mut wl, &printed, lin, allowed, &|| {
            format!("k = {k}, linearization")
        });
        let mut wi = Worst::default();
        wi.add(b.claim(printed.edge), int, int, || {
            format!("{}: k = {k}, integrations", printed.relation)
        });
        let what = if which == 52 {
            "omega_10 threshold"
        } else {
            "|Omega_0| threshold"
        };
        let fl = Finding::from_worst(
            Method::Linearization,
            format!("{what}: the printed edge and direction against the sign change of the linearized varpi^2"),
            wl,
            Tolerance::bisection(width),
            false,
        );
        let fi = Finding::from_worst(
            Method::Threshold,
            format!("{what}: the printed edge against bisection on integrations (does a kick turn back?)"),
            wi,
            finite_time_tolerance(k, width_int, false),
            false,
        );
        let f = worse(fi, fl);
        out = Some(match out {
            None => f,
            Some(o) => worse(o, f),
        });
    }
    out.unwrap_or_else(|| {
        Finding::from_worst(
            Method::Threshold,
            "no disk was swept",
            Worst::default(),
            Tolerance::bisection(width),
            false,
        )
    })
}

/// Eq 54, $\dfrac{\varpi^2}{\Omega_0^2}(k+1) = 3k\cos^2\alpha_0 + \sin^2\alpha_0 + \dfrac{b}{a}
/// \left((6k+1)\cos\alpha_0 - (2k+1)\dfrac{\sin^2\alpha_0}{\cos\alpha_0}\right) + 2\dfrac{b^2}{a^2}(2k+1)$.
///
/// Linearization: compared with $e_2(J)(k+1)/\Omega_0^2$ over the sweep of eq 50 (tilts up to
/// 1.5 rad, where the $b$ term's $\sin^2/\cos$ is 14 times its size at 1 rad), relative to the
/// size of the terms $3k\cos^2\alpha_0 + \sin^2\alpha_0 + |b/a|(\dots) + 2(b/a)^2(2k+1)$
/// (each evaluated in absolute value), plus $g/(a\Omega_0^2)$.
fn eq54(b: &Bench) -> Finding {
    let mut w = Worst::default();
    sweep(|k, d, alpha0, rho, m| {
        let om2 = m.precession * m.precession;
        let reference = varpi2(d, &state(m)) * (k + 1.0) / om2;
        let bind = steady_bindings(d, m).scalar("b", rho * d.a);
        let claimed = printed_varpi2(b, 54, &bind) * (k + 1.0) / om2;
        // Relative to the size of the printed terms (each in absolute value).
        let eq = b.paper.equation(54);
        let terms = eq
            .relations()
            .first()
            .map_or(0.0, |rel| term_scale(eq, rel.rhs, &bind));
        let sc = terms + d.g_over_a() / om2 + (m.spin * m.spin) / om2;
        w.add(claimed, reference, sc, || at(k, alpha0, rho));
    });
    Finding::from_worst(
        Method::Linearization,
        "varpi^2 (k+1) / Omega_0^2 against the model's Jacobian",
        w,
        Tolerance::roundoff(),
        false,
    )
}

/// The reference ratio $\varpi/\Omega_0$ at a steady motion of the model.
fn ratio_ref(d: &Disk, alpha0: f64, rho: f64) -> f64 {
    let m = steady_ref(d, alpha0, rho).expect("a steady motion");
    varpi2(d, &state(&m)).sqrt() / m.precession.abs()
}

/// The ratio $\varpi/\Omega_0$ that the printed eq `n` gives (its first relation solved for
/// $\varpi$), read through [`Bench::claim`].
fn printed_ratio(b: &Bench, n: u32, k: f64, alpha0: f64) -> f64 {
    let eq = b.paper.equation(n);
    // Any Omega_0 other than 1 will do (a ratio); 1 would hide a dropped factor.
    let omega0 = 3.7;
    let bind = Bindings::new()
        .scalar("k", k)
        .scalar("alpha_0", alpha0)
        .scalar("Omega_0", omega0);
    eq.relations()
        .first()
        .and_then(|rel| solve_printed(eq, rel, "varpi", &bind, 0.0, 100.0 * omega0))
        .map_or(f64::NAN, |x| b.claim(x / omega0))
}

/// Eq 55, $\dfrac{\varpi}{\Omega_0} = \sqrt{\dfrac{3k\cos^2\alpha_0 + \sin^2\alpha_0}{k+1}}$ for
/// $b \ll a$.
///
/// Asymptotic: the relative error against the model's $\sqrt{e_2(J)}/|\Omega_0|$ at
/// $b/a = 10^{-2}\dots10^{-6}$ (both signs) falls as $(b/a)^1$ (the dropped term of eq 54 is
/// linear in $b/a$); k = 1/4, 1/2, 0.9 and tilts 0.3 and 1.3 (away from the tilt where the linear
/// term's coefficient vanishes).
fn eq55(b: &Bench) -> Finding {
    let small: Vec<f64> = (2..=6).map(|i| 10f64.powi(-i)).collect();
    let mut fits = Vec::new();
    for k in [0.25, 0.5, 0.9] {
        let d = disk(k);
        for alpha0 in [0.3f64, 1.3] {
            for sign in [1.0, -1.0] {
                let claimed = printed_ratio(b, 55, k, alpha0);
                let errs: Vec<f64> = small
                    .iter()
                    .map(|&x| {
                        let r = ratio_ref(&d, alpha0, sign * x);
                        ((claimed - r) / r).abs()
                    })
                    .collect();
                fits.push((
                    format!("k = {k}, alpha0 = {alpha0}, sign of b {sign}"),
                    Finding::from_order(
                        "varpi/Omega_0 for b << a",
                        &small,
                        &errs,
                        b.paper.equation(55).entry.claimed_order.unwrap_or(1.0),
                    ),
                ));
            }
        }
    }
    super::worst_order(fits)
}

/// Eq 56, $\dfrac{\varpi}{\Omega_0} \approx \sqrt{\dfrac{3k}{k+1}}$ at small tilt ($b = 0$).
///
/// Asymptotic: relative error against the model's linearization at $b = 0$ for
/// $\alpha_0 = 0.2 \cdot 4^{-i}$; claimed order 2 ($\cos^2\alpha_0 = 1 - \alpha_0^2 + \dots$).
fn eq56(b: &Bench) -> Finding {
    let small: Vec<f64> = (0..5).map(|i| 0.2 * 4f64.powi(-i)).collect();
    let mut fits = Vec::new();
    for k in KS {
        let d = disk(k);
        let errs: Vec<f64> = small
            .iter()
            .map(|&al| {
                let r = ratio_ref(&d, al, 0.0);
                ((printed_ratio(b, 56, k, al) - r) / r).abs()
            })
            .collect();
        fits.push((
            format!("k = {k}"),
            Finding::from_order("varpi/Omega_0 at small tilt, b = 0", &small, &errs, 2.0),
        ));
    }
    super::worst_order(fits)
}

/// Shared by eqs 57-58: $\varpi/\Omega_0$ at $b = \alpha_0 a$ against the printed eq `n`, over
/// $\alpha_0 = 0.1\cdot4^{-i}$, $i = 0\dots7$ (down to $6\times10^{-6}$, where a 0.1 % error in the
/// printed first-order coefficient outgrows the second-order remainder); claimed order 2 (eq 54 at $b = \alpha_0 a$ is
/// $3k + (6k+1)\alpha_0 + (k+3)\alpha_0^2 + O(\alpha_0^3)$).
fn small_tilt_b(b: &Bench, n: u32, ks: &[f64]) -> Finding {
    let small: Vec<f64> = (0..8).map(|i| 0.1 * 4f64.powi(-i)).collect();
    let mut fits = Vec::new();
    for &k in ks {
        let d = disk(k);
        let errs: Vec<f64> = small
            .iter()
            .map(|&al| {
                let r = ratio_ref(&d, al, al);
                ((printed_ratio(b, n, k, al) - r) / r).abs()
            })
            .collect();
        fits.push((
            format!("k = {k}"),
            Finding::from_order(
                "varpi/Omega_0 at small tilt with b = alpha_0 a",
                &small,
                &errs,
                2.0,
            ),
        ));
    }
    super::worst_order(fits)
}

/// Eq 57, $\varpi \approx \Omega_0\sqrt{\dfrac{3k + (6k+1)\alpha_0}{k+1}}$ with $b = \alpha_0 a$.
///
/// Asymptotic: against the model's linearization at the steady motion with $b = \alpha_0 a$,
/// k in {0.1, 0.25, 0.5, 0.9}.
fn eq57(b: &Bench) -> Finding {
    small_tilt_b(b, 57, &KS)
}

/// Eq 58, $\varpi \approx \Omega_0\sqrt{\dfrac{3 + 10\alpha_0}{5}}$ (eq 57 at k = 1/4).
///
/// Asymptotic: as eq 57, for the uniform disk only.
fn eq58(b: &Bench) -> Finding {
    small_tilt_b(b, 58, &[0.25])
}

/// The ansatz of eqs 44-46 checked on integrations: started from a stable steady motion
/// displaced by $\epsilon$ along the model's oscillation mode, the variable `which`
/// (0 = $\alpha$, 2 = $\Omega$, 3 = $\omega_1$) is compared over two periods with
/// steady value + amplitude $\cos\varpi t$ (amplitude and $\varpi$ from the model's
/// linearization). Its residual relative to the amplitude must shrink as $\epsilon^1$ (the
/// ansatz is the first-order solution); the fitted order's distance to 1 is compared with
/// [`Tolerance::order`], for $\epsilon/\alpha_0 = 10^{-3}\dots10^{-6}$.
fn ansatz(b: &Bench, which: usize) -> Finding {
    // Resolving this claim needs tight integrations whatever the preset (see Bench::resolving).
    let b = &b.resolving(1e-12);
    let mut w = Worst::default();
    let eps_rel: Vec<f64> = (3..=6).map(|i| 10f64.powi(-i)).collect();
    for k in [0.25, 0.5] {
        let d = disk(k);
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
            let (dl, ga) = mode(&jac(&d, &y), varpi);
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
            let order = crate::numerics::fit::log_log_slope(&eps_rel, &errs);
            let shrinking = errs[errs.len() - 1] < errs[0];
            let order = if shrinking { order } else { f64::NAN };
            w.add(order, 1.0, 1.0, || {
                format!(
                    "k = {k}, alpha0 = {alpha0}, b/a = {rho}: residual / amplitude {:.2e} at epsilon/alpha0 = 1e-6",
                    errs[errs.len() - 1]
                )
            });
        }
    }
    Finding::from_worst(
        Method::Integration,
        "fitted order of the ansatz's residual (relative to its amplitude) in epsilon, against 1",
        w,
        Tolerance::order(),
        true,
    )
}

/// Eq 44, $\alpha = \alpha_0 + \epsilon\cos\varpi t$ (the ansatz; a definition).
///
/// Consistency: a small-amplitude integration along the model's mode follows it to first order
/// in $\epsilon$ (see `ansatz`).
fn eq44(b: &Bench) -> Finding {
    ansatz(b, 0)
}

/// Eq 45, $\Omega = \Omega_0 + \delta\cos\varpi t$ (the ansatz; a definition): in phase with
/// $\alpha$, checked as eq 44.
fn eq45(b: &Bench) -> Finding {
    ansatz(b, 2)
}

/// Eq 46, $\omega_1 = \omega_{10} + \gamma\cos\varpi t$ (the ansatz; a definition): in phase with
/// $\alpha$, checked as eq 44.
fn eq46(b: &Bench) -> Finding {
    ansatz(b, 3)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::finding::Verdict;

    #[test]
    fn every_check_passes_and_fails_when_perturbed() {
        for e in EQUATIONS {
            let t0 = std::time::Instant::now();
            let ok = (e.check)(&Bench::default());
            let dt = t0.elapsed();
            let bad = (e.check)(&Bench::perturbed(1e-3));
            eprintln!(
                "eq {}: {} err {:.3e} tol {:.1e} claimed {:.6e} ref {:.6e} at {} [{dt:?}]; perturbed {} err {:.3e}",
                e.number, ok.verdict, ok.error, ok.tolerance.value, ok.claimed, ok.reference, ok.at, bad.verdict, bad.error
            );
            assert!(ok.verdict.passes(), "eq {}: {ok:?}", e.number);
            assert_eq!(bad.verdict, Verdict::Fails, "eq {} perturbed", e.number);
        }
    }
}
