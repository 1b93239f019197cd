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

use super::steady_reference::{rho_edge, state, steady_ref, KS};
use crate::equations::{row, Row};
use crate::finding::{Finding, Method, Tolerance, Worst};
use crate::harness::disk_constants;
use crate::harness::{
    add_threshold, implied_square, printed_relations, printed_threshold, term_scale, Bench,
};
use nalgebra::{Complex, SMatrix};
use numerics::oscillation::{angular_frequency, bisect};
use paper::Bindings;
use physics::disk::toy_sized;
use physics::disk::Disk;
use physics::model::rolling::{self, Rolling};
use physics::model::{Extras, Model, Motion};
use physics::solve::{solve, Ending, Event, Problem, State};
use std::f64::consts::{FRAC_PI_2, PI};

/// The checks of this part of the paper.
pub const EQUATIONS: &[Row] = &[
    row(44, eq44),
    row(45, eq45),
    row(46, eq46),
    row(47, eq47),
    row(48, eq48),
    row(49, eq49),
    row(50, eq50),
    row(51, eq51),
    row(52, eq52),
    row(53, eq53),
    row(54, eq54),
    row(55, eq55),
    row(56, eq56),
    row(57, eq57),
    row(58, eq58),
];

mod ansatz;
mod frequency;
mod ratios;
mod stability;
#[cfg(test)]
mod tests;

use ansatz::{eq44, eq45, eq46};
use frequency::{eq47, eq48, eq49, eq50, eq51};
use ratios::{eq54, eq55, eq56, eq57, eq58};
use stability::{eq52, eq53};

/// $\varpi^2$ of the linearized model at state `y`: the sum of the principal 2x2 minors of the
/// Jacobian (the product of the two non-zero eigenvalues $\pm i\varpi$).
fn varpi2(d: &Disk, y: &[f64; 4]) -> f64 {
    let j = rolling::jacobian(d, y);
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
    format!("$k = {k}$, $\\alpha_0 = {alpha0}$, $b/a = {rho:.4}$")
}

/// Calls `f(k, disk, alpha0, rho, steady motion)` over the sweep.
fn sweep(mut f: impl FnMut(f64, &Disk, f64, f64, &Motion)) {
    for k in KS {
        let d = toy_sized(k);
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
    let j = rolling::jacobian(d, &state(m));
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
    disk_constants(d)
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
