//! The integrals of the rolling motion (sec. 3): besides the energy and the centre of motion,
//! Chaplygin's two.

use super::judge::{printed, single};
use super::{
    bisect, mid, solve, steady_motion, unit_disk, Bench, Dynamics, Extras, Finding, Method, Model,
    Problem, Rolling, State, Tolerance,
};

// ------------------------------------------------------------------------------ integrals

/// Cubic Hermite interpolation on $[0, 1]$ from end values and end derivatives (already
/// multiplied by the interval's length).
pub(super) fn hermite(p0: f64, p1: f64, d0: f64, d1: f64, s: f64) -> f64 {
    let (s2, s3) = (s * s, s * s * s);
    (2.0 * s3 - 3.0 * s2 + 1.0) * p0
        + (s3 - 2.0 * s2 + s) * d0
        + (-2.0 * s3 + 3.0 * s2) * p1
        + (s3 - s2) * d1
}

/// `rolling-extra-integrals`: along a strongly nutating rolling motion (eqs 23-25, $k = 1/4$,
/// $\alpha_0 = 0.5$, $b = 0.1a$, $\alpha$ pushed by 0.4 rad: it swings between 0.90 and 1.22
/// rad) the precession rate $\Omega$ and
/// the spin $\omega_1$ take, at every return of $\alpha$ to one value (either direction), the
/// same values to the integration's accuracy, although each swings widely in between. On the
/// reduced state $(\alpha, \dot\alpha, \Omega, \omega_1)$ the energy alone would leave a 3-D
/// surface to wander on; the motion stays on a closed curve, so two more integrals exist (they
/// are Chaplygin's, 1897, linear in $\Omega$ and $\omega_1$ with coefficients that depend on
/// $\alpha$). The paper's "only (known) constants are $E$ and $(x_A, y_A)$" counts none: FAILS.
/// Crossings are located by cubic Hermite interpolation between samples (the derivatives from
/// the model's own rates), whose error at this sampling is far below the spreads measured.
pub(super) fn rolling_extra_integrals(b: &Bench) -> Finding {
    let disk = unit_disk(0.25);
    let model = Rolling::<4>::new(disk, Extras::default(), None);
    let Ok(mut m0) = steady_motion(&disk, 0.5, 0.1) else {
        panic!("the steady motion at $\\alpha_0 = 0.5$, $b = 0.1 a$ exists (eq 30)")
    };
    m0.alpha += 0.4;
    let dt = 2e-3;
    let b = b.resolving(1e-11);
    let sol = solve(
        Problem::new(&model, 0.0, model.state(&m0), 60.0).sampled(dt),
        &b.settings(),
    )
    .expect("valid settings");
    let rates: Vec<State<4>> = sol
        .y
        .iter()
        .map(|y| {
            let mut dy = State::<4>::zeros();
            model.rhs(y, &mut dy);
            dy
        })
        .collect();
    // The middle of the tilt's swing, crossed twice in every nutation.
    let (lo, hi) = sol
        .y
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), y| {
            (lo.min(y[0]), hi.max(y[0]))
        });
    let level = 0.5 * (lo + hi);
    // Values of (Omega, omega_1) at each crossing of alpha = level.
    let mut at_level: Vec<[f64; 2]> = Vec::new();
    for i in 0..sol.y.len() - 1 {
        let (ya, yb) = (&sol.y[i], &sol.y[i + 1]);
        let h = sol.t[i + 1] - sol.t[i];
        if (ya[0] - level) * (yb[0] - level) > 0.0 || h <= 0.0 {
            continue;
        }
        let alpha = |s: f64| hermite(ya[0], yb[0], h * ya[1], h * yb[1], s) - level;
        let rising = ya[0] < level;
        let s = mid(bisect(0.0, 1.0, 1e-14, |s| (alpha(s) >= 0.0) == rising));
        let at = |j: usize| hermite(ya[j], yb[j], h * rates[i][j], h * rates[i + 1][j], s);
        at_level.push([at(2), at(3)]);
    }
    let spread = |values: &mut dyn Iterator<Item = f64>| {
        let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
            (lo.min(x), hi.max(x))
        });
        hi - lo
    };
    let ratios: [f64; 2] = std::array::from_fn(|j| {
        spread(&mut at_level.iter().map(|v| v[j])) / spread(&mut sol.y.iter().map(|y| y[j + 2]))
    });
    let found = ratios.iter().filter(|r| (0.0..1e-6).contains(*r)).count() as f64;
    let verdict_at = format!(
        "$k = 1/4$, from the steady motion $\\alpha_0 = 0.5$, $b = 0.1 a$ with $\\alpha$ raised by 0.4: \
         {} returns to $\\alpha = {level:.4}$ (swing {lo:.4} to {hi:.4}) over $60 \\sqrt{{a/g}}$; spread \
         there / swing along the motion: $\\Omega {:.1e}$, $\\omega_1 {:.1e}$ (below 1e-6 counts as an \
         integral)",
        at_level.len(),
        ratios[0],
        ratios[1]
    );
    let mut f = single(
        Method::Integration,
        "integrals of the rolling motion besides $E$ and $(x_A, y_A)$ (count)",
        b.claim(printed(&b, "rolling-extra-integrals")),
        found,
        Tolerance::roundoff(),
        verdict_at,
    );
    if at_level.len() < 10 {
        f.verdict = crate::finding::Verdict::Fails;
        f.at = format!("{}; TOO FEW RETURNS TO JUDGE", f.at);
    }
    f
}
