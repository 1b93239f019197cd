//! Steady motion, sections 4-5 of the paper (eqs 27-40).
//!
//! The references here never use the paper's steady-motion formulas (nor `model::steady`, which
//! implements eqs 28-30 and is therefore a claim): a steady motion is found by solving the
//! model's equation of motion (eq 24, `model::rolling::rates`) for $\ddot\alpha = 0$ with
//! Newton's method (exact derivatives by dual numbers), at a tilt $\alpha_0$ and a ratio
//! $\rho = \omega_{10}/\Omega_0$; the radius $b$ of the centre of mass's circle and the radius
//! $r$ of the contact point's circle are then MEASURED on an integration of the rolling model
//! that carries the heading and the centre of mass in the plane (the circle's centre is the mean
//! of the path sampled evenly over one precession period).
//!
//! The helpers here are shared with `slippage.rs` and `oscillation.rs`.

use super::{Bench, Equation};
use crate::disk::Disk;
use crate::finding::{Finding, Method, Tolerance, Worst};
use crate::model::rolling::{contact_force, rates, Rolling};
use crate::model::{Extras, Model, Motion};
use crate::numerics::linearize::jacobian;
use crate::numerics::oscillation::bisect;
use crate::solve::{solve, Problem, State};
use nalgebra::SMatrix;
use num_dual::{Dual64, DualNum};
use std::f64::consts::PI;

/// The checks of this part of the paper.
pub const EQUATIONS: &[Equation] = &[
    Equation {
        number: 27,
        label: "e21",
        check: eq27,
    },
    Equation {
        number: 28,
        label: "e22",
        check: eq28,
    },
    Equation {
        number: 29,
        label: "e23",
        check: eq29,
    },
    Equation {
        number: 30,
        label: "e23a",
        check: eq30,
    },
    Equation {
        number: 31,
        label: "e24",
        check: eq31,
    },
    Equation {
        number: 32,
        label: "e25",
        check: eq32,
    },
    Equation {
        number: 38,
        label: "e31",
        check: eq38,
    },
    Equation {
        number: 39,
        label: "e32",
        check: eq39,
    },
    Equation {
        number: 40,
        label: "e33",
        check: eq40,
    },
];

// ------------------------------------------------------------------------------------------
// Shared helpers (also used by slippage.rs and oscillation.rs)
// ------------------------------------------------------------------------------------------

/// The inertia factors swept: a thin ring-like spread from 0.1 to 0.9, with the uniform disk
/// (1/4) and the hoop (1/2).
pub(super) const KS: [f64; 4] = [0.1, 0.25, 0.5, 0.9];

/// A disk of the Euler's Disk toy's size (a = 37.5 mm) with inertia factor `k`.
pub(super) fn disk(k: f64) -> Disk {
    Disk::new(0.0375, k, 0.4, 9.81).expect("a valid disk")
}

/// The model's accelerations (eqs 23-25 as implemented in `model::rolling`, no torque) as a
/// function of the state $(\alpha, \dot\alpha, \Omega, \omega_1)$, generic over dual numbers.
pub(super) fn rhs<T: DualNum<f64> + Copy>(d: &Disk, y: &[T; 4]) -> [T; 4] {
    let m = Motion {
        alpha: y[0],
        alpha_dot: y[1],
        precession: y[2],
        spin: y[3],
    };
    let r = rates(d, &m, [T::zero(); 3]);
    [y[1], r.alpha_ddot, r.precession_dot, r.spin_dot]
}

/// The exact Jacobian of the rolling model at state `y`.
pub(super) fn jac(d: &Disk, y: &[f64; 4]) -> SMatrix<f64, 4, 4> {
    jacobian(|x: &[Dual64; 4]| rhs(d, x), y)
}

/// A steady motion found from the model alone: at tilt `alpha0` with $\omega_{10} = \rho\,\Omega_0$,
/// Newton's method on $\ddot\alpha(\Omega) = 0$ (eq 24 of the model), exact derivative by a dual
/// number. $\Omega_0$ has the sign of $\rho$ (or is positive for $\rho = 0$) so that
/// $\omega_{10} \ge 0$. `None` when no real root exists (the model's $\ddot\alpha$ does not
/// change sign along $\Omega$).
pub(super) fn steady_ref(d: &Disk, alpha0: f64, rho: f64) -> Option<Motion> {
    let sign = if rho < 0.0 { -1.0 } else { 1.0 };
    let f = |om: Dual64| {
        let y = [Dual64::from(alpha0), Dual64::from(0.0), om, om * rho];
        rhs(d, &y)[1]
    };
    let mut om = sign * d.g_over_a().sqrt();
    // Walk outwards until alpha_ddot > 0 (the convex branch to the right of the root).
    let mut tries = 0;
    while f(Dual64::from(om)).re <= 0.0 {
        om *= 2.0;
        tries += 1;
        if tries > 60 {
            return None;
        }
    }
    for _ in 0..200 {
        let v = f(Dual64::new(om, 1.0));
        let step = v.re / v.eps;
        om -= step;
        if step.abs() <= 4.0 * f64::EPSILON * om.abs() {
            break;
        }
    }
    // A final clean-up step.
    let v = f(Dual64::new(om, 1.0));
    om -= v.re / v.eps;
    om.is_finite().then_some(Motion {
        alpha: alpha0,
        alpha_dot: 0.0,
        precession: om,
        spin: rho * om,
    })
}

/// The model's state vector of a motion.
pub(super) fn state(m: &Motion) -> [f64; 4] {
    [m.alpha, m.alpha_dot, m.precession, m.spin]
}

/// The steady state's geometry measured on an integration: $(b, r)$, the signed horizontal
/// distance from the axis of the circular motion to the centre of mass, along $\hat{\mathbf r}$,
/// and the same for the contact point. The axis is the mean of the centre of mass's path sampled
/// at 64 even times over one precession period (exact for a uniform circle); $\hat{\mathbf r}$ is
/// $\hat{\mathbf 2}\times\hat{\mathbf z}$ with $\hat{\mathbf 2}$ along the heading; the contact
/// point lies at $a\cos\alpha_0$ beyond the centre of mass along $\hat{\mathbf r}$ (the disk's
/// geometry: the radius to the contact point is in the disk's vertical plane, at angle
/// $\alpha_0$ to the table).
pub(super) fn measure_b_r(bench: &Bench, d: &Disk, m: &Motion) -> (f64, f64) {
    let extras = Extras {
        heading: true,
        path: true,
        face: false,
    };
    let model = Rolling::<7>::new(*d, extras, None);
    let n = 64;
    let period = 2.0 * PI / m.precession.abs();
    let sol = solve(
        Problem::new(&model, 0.0, model.state(m), period).sampled(period / n as f64),
        &bench.settings(),
    )
    .expect("valid settings");
    let (mut cx, mut cy) = (0.0, 0.0);
    for y in sol.y.iter().take(n) {
        cx += y[5] / n as f64;
        cy += y[6] / n as f64;
    }
    let y0 = &sol.y[0];
    let psi = y0[4];
    let (rx, ry) = (psi.sin(), -psi.cos());
    let b = (y0[5] - cx) * rx + (y0[6] - cy) * ry;
    (b, b + d.a * m.alpha.cos())
}

/// The largest deviations of $\alpha$, $\Omega$ and $\omega_1$ from their start values along an
/// integration of `periods` precession periods, relative to $\alpha_0$, $|\Omega_0|$ and
/// $|\Omega_0|$ (the spin's natural scale, as $\omega_{10}$ may vanish).
pub(super) fn steady_drift(bench: &Bench, d: &Disk, m: &Motion, periods: f64) -> f64 {
    let model = Rolling::<4>::new(*d, Extras::default(), None);
    let t_end = periods * 2.0 * PI / m.precession.abs();
    let sol = solve(
        Problem::new(&model, 0.0, model.state(m), t_end).sampled(t_end / 200.0),
        &bench.settings(),
    )
    .expect("valid settings");
    if !sol.ending.is_complete() {
        return f64::INFINITY;
    }
    let om = m.precession.abs();
    sol.y
        .iter()
        .map(|y: &State<4>| {
            ((y[0] - m.alpha).abs() / m.alpha)
                .max((y[2] - m.precession).abs() / om)
                .max((y[3] - m.spin).abs() / om)
        })
        .fold(0.0, f64::max)
}

/// Tilts swept for steady motion.
const ALPHAS: [f64; 4] = [0.1, 0.5, 1.0, 1.4];

/// Ratios $\rho = \omega_{10}/\Omega_0$ swept, as fractions of the most negative one allowed by
/// the model (found numerically): -0.5 of it, 0, and the positive values 0.2 and 1.5.
fn rhos(d: &Disk, alpha0: f64) -> [f64; 4] {
    let edge = rho_edge(d, alpha0, 1e-12);
    [0.5 * edge, 0.0, 0.2, 1.5]
}

/// The most negative $\rho = \omega_{10}/\Omega_0$ with a steady motion at `alpha0`, by bisection
/// on whether the model's $\ddot\alpha(\Omega)$ at $\omega_1 = \rho\Omega$ can vanish: it is
/// $A\Omega^2 - C$ with $C > 0$ (the weight) for $\alpha_0 < \pi/2$, so a root exists iff the
/// growth $A = \ddot\alpha(1) - \ddot\alpha(0) > 0$.
pub(super) fn rho_edge(d: &Disk, alpha0: f64, width: f64) -> f64 {
    let exists = |rho: f64| {
        let f = |om: f64| rhs(d, &[alpha0, 0.0, om, rho * om])[1];
        f(1.0) - f(0.0) > 0.0
    };
    let (lo, hi) = bisect(-2.0, 2.0, width, exists);
    0.5 * (lo + hi)
}

fn at(k: f64, alpha0: f64, rho: f64) -> String {
    format!("k = {k}, alpha0 = {alpha0}, b/a = {rho:.4}")
}

// ------------------------------------------------------------------------------------------
// Section 4
// ------------------------------------------------------------------------------------------

/// Eq 27, the steady balance
/// $k\Omega_0^2\sin\alpha_0\cos\alpha_0 + (2k+1)\omega_{10}\Omega_0\sin\alpha_0 = \frac{g}{a}\cos\alpha_0$.
///
/// Integration: at each tilt and ratio $\omega_{10}/\Omega_0$, the $\Omega_0$ that eq 27 gives
/// is the start of an integration of the rolling model over two precession periods; the claim
/// holds if $\alpha$, $\Omega$ and $\omega_1$ stay constant to the solver's accuracy (a wrong
/// $\Omega_0$ makes the disk nutate with an amplitude proportional to the error).
fn eq27(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for k in KS {
        let d = disk(k);
        for alpha0 in [0.1, 0.5, 1.0] {
            for rho in rhos(&d, alpha0) {
                let (s, c) = alpha0.sin_cos();
                // Eq 27 with omega_10 = rho Omega_0: a quadratic in Omega_0.
                let om2 = d.g_over_a() * c / (k * s * c + (2.0 * k + 1.0) * rho * s);
                let sign = if rho < 0.0 { -1.0 } else { 1.0 };
                let om = sign * b.claim(om2.sqrt());
                let m = Motion {
                    alpha: alpha0,
                    alpha_dot: 0.0,
                    precession: om,
                    spin: rho * om,
                };
                let drift = steady_drift(b, &d, &m, 2.0);
                w.add(drift, 0.0, 1.0, || {
                    format!(
                        "{}; largest relative drift of (alpha, Omega, omega_1) over 2 precession periods",
                        at(k, alpha0, rho)
                    )
                });
            }
        }
    }
    Finding::from_worst(
        Method::Integration,
        "drift of alpha, Omega, omega_1 started at eq 27's steady state",
        w,
        Tolerance::solver(b.rtol),
        false,
    )
}

/// Eq 28, $\omega_{10} = \frac{b}{a}\Omega_0 = \Omega_0\left(\frac{r}{a} - \cos\alpha_0\right)$.
///
/// Integration: steady motions solved from the model (Newton on eq 24); $b$ and $r$ measured on
/// the integrated path of the centre of mass; both forms of the claim are compared with the
/// state's $\omega_{10}$ (relative to $|\Omega_0|$, since $\omega_{10}$ vanishes at $b = 0$).
fn eq28(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for k in KS {
        let d = disk(k);
        for alpha0 in ALPHAS {
            for rho in rhos(&d, alpha0) {
                let Some(m) = steady_ref(&d, alpha0, rho) else {
                    continue;
                };
                let (bb, r) = measure_b_r(b, &d, &m);
                let om = m.precession;
                let claims = [
                    b.claim(bb / d.a * om),
                    b.claim(om * (r / d.a - alpha0.cos())),
                ];
                for (i, cl) in claims.into_iter().enumerate() {
                    w.add(cl, m.spin, om.abs(), || {
                        format!(
                            "{} ({} form); b and r measured on the path",
                            at(k, alpha0, rho),
                            ["b", "r"][i]
                        )
                    });
                }
            }
        }
    }
    Finding::from_worst(
        Method::Integration,
        "omega_10 from eq 28 (b, r measured) against the model's steady spin, relative to |Omega_0|",
        w,
        Tolerance::solver(b.rtol),
        false,
    )
}

/// Eq 29, $\Omega_0^2 = \dfrac{g\cot\alpha_0}{k a\cos\alpha_0 + (2k+1)b}
/// = \dfrac{g\cot\alpha_0}{(2k+1)r - (k+1)a\cos\alpha_0}$.
///
/// Integration and derivation: the steady motion is solved from the model (Newton on eq 24 at a
/// ratio $\omega_{10}/\Omega_0$), $b$ and $r$ are measured on its integrated path, and both
/// forms of eq 29 at the measured $b$, $r$ are compared with the solved $\Omega_0^2$. Tilts
/// 0.1-1.4, $b$ negative (half way to eq 30's edge found numerically), zero and positive.
fn eq29(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for k in KS {
        let d = disk(k);
        for alpha0 in ALPHAS {
            for rho in rhos(&d, alpha0) {
                let Some(m) = steady_ref(&d, alpha0, rho) else {
                    continue;
                };
                let (bb, r) = measure_b_r(b, &d, &m);
                let (a, g, c) = (d.a, d.g, alpha0.cos());
                let cot = 1.0 / alpha0.tan();
                let claims = [
                    b.claim(g * cot / (k * a * c + (2.0 * k + 1.0) * bb)),
                    b.claim(g * cot / ((2.0 * k + 1.0) * r - (k + 1.0) * a * c)),
                ];
                let om2 = m.precession * m.precession;
                for (i, cl) in claims.into_iter().enumerate() {
                    w.add(cl, om2, om2, || {
                        format!("{} ({} form)", at(k, alpha0, rho), ["b", "r"][i])
                    });
                }
            }
        }
    }
    Finding::from_worst(
        Method::Integration,
        "Omega_0^2 of eq 29 at the measured b (and r) against the model's steady Omega_0^2",
        w,
        Tolerance::solver(b.rtol),
        false,
    )
}

/// Eq 30, $b > -\dfrac{a k\cos\alpha_0}{2k+1}$.
///
/// Threshold: the most negative ratio $\rho = \omega_{10}/\Omega_0$ at which the model's eq 24
/// still has a real steady $\Omega_0$ is located by bisection (the coefficient of $\Omega^2$ in
/// $\ddot\alpha$ changes sign there and $\Omega_0^2$ diverges); $b = \rho a$ by the kinematics
/// verified in eq 28's check. Compared with the claimed bound.
fn eq30(b: &Bench) -> Finding {
    let width = 1e-10;
    let mut w = Worst::default();
    for k in KS {
        let d = disk(k);
        for alpha0 in [0.1, 0.5, 1.0, 1.4, 1.55] {
            let edge = rho_edge(&d, alpha0, width) * d.a;
            let claimed = b.claim(-d.a * k * alpha0.cos() / (2.0 * k + 1.0));
            w.add(claimed, edge, edge.abs(), || {
                format!("k = {k}, alpha0 = {alpha0}")
            });
        }
    }
    Finding::from_worst(
        Method::Threshold,
        "lower bound on b for a steady motion: claimed against the model's edge found by bisection",
        w,
        Tolerance::bisection(width),
        false,
    )
}

/// Eq 31, $\Omega_0^2 = \dfrac{g}{a k\sin\alpha_0}$ for $b = 0$.
///
/// Integration: the centre of mass at rest means $\dot\alpha = 0$ and $\omega_1 = 0$ (eq 13's
/// velocity vanishes); the rolling model is started with eq 31's $\Omega_0$ and integrated
/// over two precession periods; $\alpha$, $\Omega$, $\omega_1$ must stay constant to the solver's
/// accuracy. Tilts 0.05-1.5.
fn eq31(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for k in KS {
        let d = disk(k);
        for alpha0 in [0.05, 0.3, 0.8, 1.2, 1.5] {
            let om = b.claim((d.g / (d.a * k * alpha0.sin())).sqrt());
            let m = Motion {
                alpha: alpha0,
                alpha_dot: 0.0,
                precession: om,
                spin: 0.0,
            };
            let drift = steady_drift(b, &d, &m, 2.0);
            w.add(drift, 0.0, 1.0, || {
                format!("k = {k}, alpha0 = {alpha0}; relative drift over 2 precession periods")
            });
        }
    }
    Finding::from_worst(
        Method::Integration,
        "drift of alpha, Omega, omega_1 started at eq 31's steady state (b = 0)",
        w,
        Tolerance::solver(b.rtol),
        false,
    )
}

/// The rate of the face angle (the disk's spin relative to the triad) measured on an
/// integration of `m` over one precession period: the face state's advance divided by the time.
/// The model advances the face angle at $\omega_1 + \Omega\cos\alpha$ (eq 11, checked with the
/// kinematics).
fn measured_rel_spin(bench: &Bench, d: &Disk, m: &Motion) -> f64 {
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
fn rel_spin_check(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for k in KS {
        let d = disk(k);
        for alpha0 in ALPHAS {
            let Some(m) = steady_ref(&d, alpha0, 0.0) else {
                continue;
            };
            let measured = measured_rel_spin(b, &d, &m);
            let claimed = b.claim(m.precession * alpha0.cos());
            w.add(claimed, measured, m.precession.abs(), || {
                format!("k = {k}, alpha0 = {alpha0}, b = 0")
            });
        }
    }
    Finding::from_worst(
        Method::Integration,
        "omega_rel = Omega_0 cos(alpha_0) against the face angle's measured rate at b = 0, relative to |Omega_0|",
        w,
        Tolerance::solver(b.rtol),
        false,
    )
}

/// Eq 32, $\omega_{rel} = \Omega_0\cos\alpha_0$ for $b = 0$.
///
/// Integration: the model's $b = 0$ steady motion (Newton on eq 24 at $\omega_{10} = 0$) is
/// integrated with the face angle over one precession period; its rate is the relative spin.
fn eq32(b: &Bench) -> Finding {
    rel_spin_check(b)
}

/// Eq 39, $\omega_{rel} = \Omega_0\cos\alpha_0$ (section 5's rederivation of eq 32).
///
/// Integration, as for eq 32.
fn eq39(b: &Bench) -> Finding {
    rel_spin_check(b)
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
fn eq38(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for k in KS {
        let d = disk(k);
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
                format!("k = {k}, alpha0 = {alpha0}: F along axis 2 / mg")
            });
            let claimed = b.claim(-m.precession * s);
            w.add(claimed, omega_ref, omega_ref.abs(), || {
                format!("k = {k}, alpha0 = {alpha0}, b = 0")
            });
        }
    }
    Finding::from_worst(
        Method::Derivation,
        "rate about axis 3 at b = 0: claimed against the rate the model's contact torque sustains",
        w,
        Tolerance::roundoff(),
        false,
    )
}

/// Eq 40, $\Omega_0^2 = \dfrac{g}{a k\sin\alpha_0}$ (section 5's rederivation of eq 31).
///
/// Derivation: compared with the $\Omega_0^2$ of the model's steady motion at $\omega_{10} = 0$
/// (Newton on eq 24), tilts 0.05-1.5.
fn eq40(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for k in KS {
        let d = disk(k);
        for alpha0 in [0.05, 0.3, 0.8, 1.2, 1.5] {
            let Some(m) = steady_ref(&d, alpha0, 0.0) else {
                continue;
            };
            let om2 = m.precession * m.precession;
            let claimed = b.claim(d.g / (d.a * k * alpha0.sin()));
            w.add(claimed, om2, om2, || format!("k = {k}, alpha0 = {alpha0}"));
        }
    }
    Finding::from_worst(
        Method::Derivation,
        "Omega_0^2 at b = 0 against the model's steady state solved by Newton",
        w,
        Tolerance::roundoff(),
        false,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::finding::Verdict;

    fn run(number: u32) -> (Finding, Finding) {
        let e = EQUATIONS.iter().find(|e| e.number == number).unwrap();
        (
            (e.check)(&Bench::default()),
            (e.check)(&Bench::perturbed(1e-3)),
        )
    }

    #[test]
    fn every_check_holds_and_fails_when_perturbed() {
        for e in EQUATIONS {
            let (ok, bad) = run(e.number);
            eprintln!(
                "eq {}: {} err {:.3e} tol {:.1e} at {}; perturbed {} err {:.3e}",
                e.number, ok.verdict, ok.error, ok.tolerance.value, ok.at, bad.verdict, bad.error
            );
            assert_eq!(ok.verdict, Verdict::Holds, "eq {}: {ok:?}", e.number);
            assert_eq!(bad.verdict, Verdict::Fails, "eq {} perturbed", e.number);
        }
    }
}
