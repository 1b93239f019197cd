//! The machinery the checks of section 11 share (eqs 72-85): the exact energy of the rolling
//! disk, the full dissipative rolling model run from steady $b = 0$ motion ([`descent`]), eq 76's
//! printed law integrated as a one-state system ([`law_runs`]), and the $t_0$ a printed relation
//! implies along a run ([`implied_t0`]). Checks call these; no check imports another check.

use crate::finding::{Finding, Headline, Method, Tolerance, Worst};
use crate::harness::disk_constants;
use crate::harness::{solve_printed, Bench};
use num_dual::DualNum;
use numerics::memo::{bits, Memo};
use paper::{Bindings, Relation};
use physics::disk::toy_sized;
use physics::disk::Disk;
use physics::model::dissipation::PowerLaw;
use physics::model::rolling::Rolling;
use physics::model::steady::steady_motion;
use physics::model::Extras;
use physics::solve::{solve, Dynamics, Event, Problem, State};
use std::f64::consts::PI;
use std::sync::Arc;

/// The exact energy of the disk rolling without slipping (eq 26's content), the model's.
pub(crate) use physics::model::rolling::energy;

/// Steady precession with the centre of mass at rest ($b = 0$, $\omega_1 = 0$), from eq 24 with
/// $\ddot\alpha = 0$: $\Omega^2 = g/(a k\sin\alpha)$, generic in alpha.
pub(crate) fn steady_precession<T: DualNum<f64> + Copy>(d: &Disk, alpha: T) -> T {
    (alpha.sin() * (d.a * d.k)).recip().sqrt() * d.g.sqrt()
}

/// The tilts at which the small-angle approximations are measured (two decades).
pub(crate) const SMALL_ALPHAS: [f64; 5] = [0.2, 0.1, 0.05, 0.025, 0.0125];

/// What the full dissipative model does from steady $b = 0$ motion at `alpha0`, over 20
/// precession periods (epsilon set so that alpha falls by about 2 % over them): the ratio
/// $\langle\dot\alpha\rangle / \langle\epsilon\Omega^\beta\rangle$ and the $C$ of eq 79,
/// $-1/\frac{d}{dt}\langle\Omega^{-(\beta+2)}\rangle$, both from least-squares slopes over the
/// samples (which average the nutation out). The start's tilt rate is set to the adiabatic
/// estimate $-\frac23\epsilon\Omega^\beta/\cos\alpha_0$ to excite little nutation. The runs
/// depend on the solver's method and rtol and the disk only, never on the paper, so they are
/// computed once per process and shared by the checks of eqs 76-79 and 84 ([`descent`]).
pub(crate) struct Descent {
    pub(crate) c: f64,
    pub(crate) epsilon: f64,
    /// The samples: time, tilt, precession rate.
    pub(crate) t: Vec<f64>,
    pub(crate) alpha: Vec<f64>,
    pub(crate) precession: Vec<f64>,
}

pub(crate) fn slope(x: &[f64], y: &[f64]) -> f64 {
    let n = x.len() as f64;
    let mx = x.iter().sum::<f64>() / n;
    let my = y.iter().sum::<f64>() / n;
    let sxy: f64 = x.iter().zip(y).map(|(a, b)| (a - mx) * (b - my)).sum();
    let sxx: f64 = x.iter().map(|a| (a - mx) * (a - mx)).sum();
    sxy / sxx
}

pub(crate) fn descent(b: &Bench, d: &Disk, beta: f64, alpha0: f64) -> Option<Arc<Descent>> {
    type Key = ([u64; 4], physics::solve::Method);
    static RUNS: Memo<Key, Option<Arc<Descent>>> = Memo::new();
    RUNS.get((bits([b.rtol, d.k, beta, alpha0]), b.method), || {
        run_descent(b, d, beta, alpha0).map(Arc::new)
    })
}

/// [`descent`] without the cache.
fn run_descent(b: &Bench, d: &Disk, beta: f64, alpha0: f64) -> Option<Descent> {
    let start = steady_motion(d, alpha0, 0.0).ok()?;
    let om0 = start.precession;
    let epsilon = 1.5e-4 * alpha0 * om0.powf(1.0 - beta);
    let law = PowerLaw { epsilon, beta };
    let sys = Rolling::<4>::new(*d, Extras::default(), Some(law));
    let alpha_dot0 = -2.0 / 3.0 * epsilon * om0.powf(beta) / alpha0.cos();
    let y0 = State::<4>::new(alpha0, alpha_dot0, om0, 0.0);
    let t_end = 20.0 * 2.0 * PI / om0;
    let sol = solve(
        Problem::new(&sys, 0.0, y0, t_end).sampled(t_end / 400.0),
        &b.settings(),
    )
    .ok()?;
    let col = |i: usize| sol.y.iter().map(|y| y[i]).collect::<Vec<f64>>();
    let x: Vec<f64> = sol.y.iter().map(|y| y[2].powf(-(beta + 2.0))).collect();
    Some(Descent {
        c: -1.0 / slope(&sol.t, &x),
        epsilon,
        alpha: col(0),
        precession: col(2),
        t: sol.t,
    })
}

/// The laws of eq 75 at $\epsilon = 10^{-3}$ with each of `betas`, on the toy-sized uniform disk
/// ($k = 1/4$) and on one with $k = 1/2$: the points of the single-step derivations.
pub(crate) fn toy_laws(betas: &[f64]) -> Vec<(Disk, PowerLaw)> {
    [toy_sized(0.25), toy_sized(0.5)]
        .into_iter()
        .flat_map(|d| {
            betas.iter().map(move |&beta| {
                (
                    d,
                    PowerLaw {
                        epsilon: 1e-3,
                        beta,
                    },
                )
            })
        })
        .collect()
}

/// The dissipation exponents and disks of the spin-down checks.
pub(crate) const BETAS: [f64; 3] = [1.0, 2.0, 4.0];

/// Bindings of the quantities of sec. 11 for a disk and a dissipation law.
pub(crate) fn law_bindings(d: &Disk, law: &PowerLaw) -> Bindings<f64> {
    disk_constants(d)
        .scalar("dissipation", law.epsilon)
        .scalar("beta", law.beta)
}

/// The one-state law of eq 76 AS PRINTED (its last form, a function of $\alpha$ alone) integrated
/// from $\alpha_0 = 0.2$ until $\alpha$ falls below $\alpha_0/10$ (closer to the finite-time
/// singularity the solver's error relative to $\alpha$ grows past its tolerance rule), sampled.
/// These runs are the premise of eqs 77-79: each must follow from the eq 76 of the paper under
/// check, whatever its coefficient.
pub(crate) struct LawRun {
    pub(crate) law: PowerLaw,
    pub(crate) t: Vec<f64>,
    pub(crate) alpha: Vec<f64>,
}

pub(crate) const LAW_ALPHA0: f64 = 0.2;

/// Eq 76's last printed form as a one-state system.
pub(crate) struct PrintedLaw<'a> {
    pub(crate) eq: &'a paper::Equation,
    pub(crate) bind: std::cell::RefCell<Bindings<f64>>,
}

impl PrintedLaw<'_> {
    pub(crate) fn rate(&self, alpha: f64) -> f64 {
        let mut bind = self.bind.borrow_mut();
        bind.set("alpha", paper::Value::Scalar(alpha));
        let last = self.eq.chains[0].sides.last();
        last.and_then(|e| self.eq.scalar(e, &bind).ok())
            .unwrap_or(f64::NAN)
    }
}

impl Dynamics<1> for PrintedLaw<'_> {
    fn rhs(&self, y: &State<1>, dy: &mut State<1>) {
        dy[0] = self.rate(y[0]);
    }
}

pub(crate) fn law_runs(b: &Bench) -> Vec<(Disk, LawRun)> {
    let mut out = Vec::new();
    let eq76 = b.paper.equation(76);
    for &k in &[0.25, 0.5] {
        let d = toy_sized(k);
        for &beta in &[1.0, 2.0, 2.5, 4.0] {
            let unit = PrintedLaw {
                eq: eq76,
                bind: law_bindings(&d, &PowerLaw { epsilon: 1.0, beta }).into(),
            };
            // epsilon so that alpha0 / |alpha_dot(alpha0)| is one second.
            let epsilon = LAW_ALPHA0 / unit.rate(LAW_ALPHA0).abs();
            if !epsilon.is_finite() {
                continue;
            }
            let law = PowerLaw { epsilon, beta };
            let model = PrintedLaw {
                eq: eq76,
                bind: law_bindings(&d, &law).into(),
            };
            let Ok(sol) = solve(
                Problem::new(&model, 0.0, State::<1>::new(LAW_ALPHA0), 10.0)
                    .sampled(0.01)
                    .stop_when(Event::new("$\\alpha$ small", |y: &State<1>| {
                        y[0] - LAW_ALPHA0 / 10.0
                    })),
                &b.settings(),
            ) else {
                continue;
            };
            out.push((
                d,
                LawRun {
                    law,
                    alpha: sol.y.iter().map(|y| y[0]).collect(),
                    t: sol.t,
                },
            ));
        }
    }
    out
}

/// Eqs 77-79 share this: along each run of eq 76's printed law, the $t_0$ that makes the printed
/// relation `relation` of eq `n` hold at each sample (a root, [`super::solve_printed`]); the
/// relation follows from eq 76 exactly when that $t_0$ is the same at every sample. The error is
/// the largest spread of the implied $t_0$ relative to the first, the tolerance the solver's.
/// `omega` binds $\Omega$ where the relation names it (eq 79: $\Omega^2 = g/ak\alpha$, the
/// premise eq 76 itself uses).
pub(crate) fn implied_t0(b: &Bench, n: u32, relation: usize, worst: &mut Worst) {
    let eq = b.paper.equation(n);
    let Some(rel) = eq.relations().get(relation).copied() else {
        worst.add(f64::NAN, 0.0, 1.0, || {
            format!("eq {n} has no relation {}", relation + 1)
        });
        return;
    };
    implied_t0_of(b, n, &rel, worst);
}

/// [`implied_t0`] for any relation between two printed sides of eq `n` (eq 79's $\Omega$ against
/// its last side, which no printed relation states alone).
pub(crate) fn implied_t0_of(b: &Bench, n: u32, rel: &Relation<'_>, worst: &mut Worst) {
    let eq = b.paper.equation(n);
    for (d, run) in law_runs(b) {
        let beta = run.law.beta;
        let c = printed_c(b, &d, &run.law);
        let mut first = None;
        for (t, a) in run.t.iter().zip(&run.alpha) {
            // C as eq 79 defines it, for the relations written with it (eq 84).
            let bind = law_bindings(&d, &run.law)
                .scalar("alpha", *a)
                .scalar("t", *t)
                .scalar("C", c)
                .scalar("Omega", (d.g / (d.a * d.k * a)).sqrt());
            let t0 = solve_printed(eq, rel, "t_0", &bind, *t + 1e-12, *t + 1e3).unwrap_or(f64::NAN);
            let reference = *first.get_or_insert(t0);
            worst.add(b.claim(t0), reference, reference.abs(), || {
                format!(
                    "eq {n} {}: implied $t_0$ at $t = {t:.4}$ s against {reference:.9} s at the start, $k = {}$, $\\beta = {beta}$, $\\alpha = {a:.4}$",
                    rel.name(),
                    d.k
                )
            });
        }
    }
}

pub(crate) fn derivation_from_eq76(b: &Bench, n: u32, relation: usize, what: &str) -> Finding {
    let mut worst = Worst::default();
    implied_t0(b, n, relation, &mut worst);
    Finding::from_worst(
        Method::Derivation,
        format!("{what}: the $t_0$ it implies along eq 76's printed law integrated numerically, which must not drift"),
        worst,
        Tolerance::solver(b.rtol))
}

/// The $C$ that eq 79's second relation defines for a disk and a law (solved for from the
/// printed text), NaN if it cannot be.
pub(crate) fn printed_c(b: &Bench, d: &Disk, law: &PowerLaw) -> f64 {
    let eq = b.paper.equation(79);
    let bind = law_bindings(d, law).scalar("t_0", 1.7).scalar("t", 0.7);
    let guess = d.g / (law.epsilon * d.a * d.k);
    eq.relations()
        .get(1)
        .and_then(|rel| solve_printed(eq, rel, "C", &bind, 0.0, 1e3 * guess))
        .unwrap_or(f64::NAN)
}

/// The initial tilts of the model runs that judge the small-angle laws 77-79 and 84.
pub(crate) const MODEL_ALPHAS: [f64; 3] = [0.1, 0.05, 0.025];

/// Every how many samples of a model run a $t_0$ is solved for (40 per run: the slope of the
/// implied $t_0$ over 20 precession periods needs no more, and each is a bisection).
const EVERY: usize = 10;

/// Eqs 77-79 and 84 against the full dissipative rolling model (the physics, where
/// [`derivation_from_eq76`] asks only whether they follow from eq 76 as printed).
///
/// Along a run of the model from steady $b = 0$ motion at $\alpha_0$, solve the printed relation
/// `relation` of eq `n` for the $t_0$ it implies at each sample (tilt, precession rate and time of
/// the model bound, $C$ as eq 79 defines it). If the relation has the form
/// $F(\alpha, \Omega) = K_{printed}(t_0 - t)$ while the model obeys $F = K_{true}(T - t)$, the
/// implied $t_0 = t + (K_{true}/K_{printed})(T - t)$ drifts at the rate
/// $s = 1 - K_{true}/K_{printed}$: the printed relation puts the time remaining at
/// $X = 1 - s$ times the true one. $X - 1$ is the error of a small-angle law and must fall at the
/// order eq 76 claims as $\alpha_0$ shrinks (k = 1/4, 1/2; beta = 1, 2, 4;
/// $\alpha_0$ = 0.1, 0.05, 0.025).
pub(crate) fn time_remaining_on_model(b: &Bench, n: u32, relation: usize, what: &str) -> Finding {
    let eq = b.paper.equation(n);
    let rel = eq.relations().get(relation).copied();
    let mut runs = crate::equations::disk_runs::DiskRuns::default();
    let mut seen = String::new();
    let mut headline = None;
    for &k in &[0.25, 0.5] {
        let d = toy_sized(k);
        for &beta in &BETAS {
            for (i, &alpha0) in MODEL_ALPHAS.iter().enumerate() {
                let factor = rel.zip(descent(b, &d, beta, alpha0)).map(|(rel, r)| {
                    let law = PowerLaw {
                        epsilon: r.epsilon,
                        beta,
                    };
                    let c = printed_c(b, &d, &law);
                    let (mut ts, mut t0s) = (Vec::new(), Vec::new());
                    for j in (0..r.t.len()).step_by(EVERY) {
                        let t = r.t[j];
                        let bind = law_bindings(&d, &law)
                            .scalar("alpha", r.alpha[j])
                            .scalar("Omega", r.precession[j])
                            .scalar("t", t)
                            .scalar("C", c);
                        let t0 = solve_printed(eq, &rel, "t_0", &bind, t + 1e-12, t + 1e12)
                            .unwrap_or(f64::NAN);
                        ts.push(t);
                        t0s.push(b.claim(t0 - t) + t);
                    }
                    1.0 - slope(&ts, &t0s)
                });
                let x = factor.unwrap_or(f64::NAN);
                if i == MODEL_ALPHAS.len() - 1 && k == 0.25 && beta == 2.0 {
                    headline = Some(Headline::new(
                        format!("time remaining to $t_0$ that {what} implies, over the true time remaining"),
                        x,
                        "implied",
                        1.0,
                        "1",
                        format!("uniform disk $(k = 1/4)$, $\\beta = 2$, $\\alpha_0 = {alpha0}$"),
                    ));
                }
                if i == MODEL_ALPHAS.len() - 1 {
                    seen = format!(
                        "the printed relation puts the time remaining at {x:.4} times the model's at $k = {k}$, $\\beta = {beta}$, $\\alpha_0 = {alpha0}$"
                    );
                }
                runs.add(k, Some(beta), MODEL_ALPHAS.len(), i, (x - 1.0).abs());
            }
        }
    }
    let claimed_order = b.paper.equation(76).entry.claimed_order.unwrap_or(2.0);
    let mut f = Finding::from_order(
        format!(
            "{what}: the time remaining to $t_0$ that it implies along the full dissipative rolling model, \
             as a multiple of the true one (relative error against $\\alpha_0$)"
        ),
        &MODEL_ALPHAS,
        &runs.all(MODEL_ALPHAS.len()),
        claimed_order,
    );
    f.at = format!("{}; {seen}", f.at);
    f.headline = headline;
    f.with_robustness(runs.alternatives(&MODEL_ALPHAS, claimed_order))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The closed form [`steady_precession`] (eq 24 with $\ddot\alpha = 0$, $\omega_1 = 0$) is
    /// the steady motion the model itself has: Newton's method on the rolling model's
    /// $\ddot\alpha$ (`steady_reference::steady_ref`) finds the same $\Omega_0$ to round-off,
    /// from near the vertical down to the tilts of sec. 11.
    #[test]
    fn the_steady_precession_is_the_models_steady_motion() {
        for k in [0.1, 0.25, 0.5, 0.9] {
            let d = toy_sized(k);
            for alpha in [1.5, 1.0, 0.3, 0.05, 1e-3, 1e-5] {
                let model = super::super::steady_reference::steady_ref(&d, alpha, 0.0)
                    .expect("a steady motion at b = 0")
                    .precession;
                let closed = steady_precession(&d, alpha);
                assert!(
                    (closed / model - 1.0).abs() < 1e-12,
                    "k = {k}, alpha = {alpha}: {closed} against the model's {model}"
                );
            }
        }
    }
}
