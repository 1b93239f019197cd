//! What the toy's thickness does to the paper's steady motions and small oscillations: the
//! Euler's Disk toy (a = 37.5 mm, thickness 12.8 mm, rim fillet 2 mm as in M. Batista's data for
//! it, mass 0.4 kg) against the thin uniform disk (k = 1/4) of the same radius, both rolling
//! (mu = 10, no slip) in the sliding model.
//!
//! **Steady motion.** With $\dot\alpha = 0$ the rates $\Omega$ and $\omega_1$ of a rolling
//! axisymmetric body stay constant, so a start is steady exactly when $\ddot\alpha = 0$ there. The
//! disk spinning in place (the paper's $b = 0$, eqs 29-30) keeps its centre at rest, so
//! $\boldsymbol\omega\times\boldsymbol\rho = 0$: with $\boldsymbol\rho = p\hat{\mathbf 1} + q\hat{\mathbf 3}$
//! and $\boldsymbol\omega = \omega_1\hat{\mathbf 1} - \Omega\sin\alpha\,\hat{\mathbf 3}$,
//! $\omega_1 = -\Omega\sin\alpha\,p/q$ (0 for the thin disk). The $\Omega$ that makes such a
//! start steady at tilt $\alpha_0$ is found by bisection on the sign of $\alpha(\tau) - \alpha_0$
//! after $\tau$ = 1 ms (the error of that shooting is the integrator's, rtol 1e-12:
//! $\ddot\alpha$ and its rates vanish together at a steady start). The thin disk's own shooting
//! reproduces eq 29's $\Omega$.
//!
//! **Small oscillations.** From each steady start with $\dot\alpha$ = 1 mrad/s, the period of
//! $\alpha$ over 1 s (mean spacing of the maxima, located by linear interpolation of
//! $\dot\alpha$'s sign changes).

use physics::dispatch::sliding_model;
use physics::model::sliding::Solid;
use physics::model::steady::steady_motion;
use physics::run::sliding::integrate;
use physics::scene::Scene;

const THIN: &str = "k: 0.25";
const TOY: &str = "thickness: 0.0128, fillet: 0.002";

fn scene(
    disk: &str,
    alpha: f64,
    alpha_dot: f64,
    precession: f64,
    spin: f64,
    time: f64,
    dt: f64,
) -> Scene {
    let src = format!(
        "name: s
model: sliding
disk: {{ radius: 0.0375, mass: 0.4, {disk} }}
friction: {{ mu: 10 }}
start: {{ explicit: {{ alpha: {alpha:e}, alpha_dot: {alpha_dot:e}, precession: {precession:e}, spin: {spin:e} }} }}
stop: {{ time: {time:e} }}
sample: {dt:e}
solver: {{ rtol: 1e-12, atol: 1e-15 }}
"
    );
    Scene::parse(&src, "s.yaml").unwrap()
}

/// (t, alpha, alpha_dot) of a run.
fn tilt(s: &Scene) -> Vec<(f64, f64, f64)> {
    let m = sliding_model(s);
    let run = integrate(&m, s, s.sample).unwrap();
    assert!(run.switches.is_empty(), "the start slipped");
    run.t
        .iter()
        .zip(&run.y)
        .map(|(t, y)| {
            let mo = m.snapshot(y).motion();
            (*t, mo.alpha, mo.alpha_dot)
        })
        .collect()
}

/// $\omega_1/\Omega$ of a disk spinning in place: $-\sin\alpha\,p/q$ (0 for the thin disk).
fn spin_ratio(disk: &str, alpha0: f64) -> f64 {
    if disk == THIN {
        return 0.0;
    }
    let solid = Solid::new(0.0375, 0.4, 0.0128, 0.002);
    let (p, q) = solid.offsets(0.0375, alpha0.cos(), alpha0.sin());
    -alpha0.sin() * p / q
}

/// The precession that makes `disk` spinning in place steady at `alpha0`.
fn steady_precession(disk: &str, alpha0: f64, guess: f64) -> f64 {
    let tau = 1e-3;
    let ratio = spin_ratio(disk, alpha0);
    let drift = |om: f64| {
        let r = tilt(&scene(disk, alpha0, 0.0, om, ratio * om, tau, tau));
        r.last().unwrap().1 - alpha0
    };
    let (mut lo, mut hi) = (0.3 * guess, 3.0 * guess);
    let (f_lo, f_hi) = (drift(lo), drift(hi));
    assert!(
        f_lo * f_hi < 0.0,
        "no steady spin in [{lo}, {hi}]: {f_lo:e} {f_hi:e}"
    );
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if (drift(mid) > 0.0) == (f_lo > 0.0) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The period of the tilt's oscillation about a steady start.
fn period(disk: &str, alpha0: f64, precession: f64, spin: f64) -> f64 {
    let r = tilt(&scene(disk, alpha0, 1e-3, precession, spin, 1.0, 1e-4));
    let maxima: Vec<f64> = r
        .windows(2)
        .filter(|w| w[0].2 > 0.0 && w[1].2 <= 0.0)
        .map(|w| w[0].0 + (w[1].0 - w[0].0) * w[0].2 / (w[0].2 - w[1].2))
        .collect();
    assert!(maxima.len() >= 3, "{} maxima", maxima.len());
    (maxima[maxima.len() - 1] - maxima[0]) / (maxima.len() - 1) as f64
}

#[test]
fn thickness_changes_the_steady_motion_and_the_oscillation() {
    let thin_disk = physics::disk::toy_disk();
    println!("alpha0  Omega thin  Omega toy  change   period thin  period toy  change (rad/s, s)");
    for alpha0 in [0.3, 0.6, 1.0, 1.3] {
        let m = steady_motion(&thin_disk, alpha0, 0.0).unwrap();
        let thin = steady_precession(THIN, alpha0, m.precession);
        assert!(
            (thin - m.precession).abs() < 1e-7 * m.precession.abs(),
            "{thin} vs eq 29's {}",
            m.precession
        );
        let toy = steady_precession(TOY, alpha0, m.precession);
        let p_thin = period(THIN, alpha0, thin, 0.0);
        let p_toy = period(TOY, alpha0, toy, spin_ratio(TOY, alpha0) * toy);
        println!(
            "{alpha0:.1}  {thin:10.4}  {toy:10.4}  {:+6.1} %  {p_thin:10.5}  {p_toy:10.5}  {:+6.1} %",
            100.0 * (toy / thin - 1.0),
            100.0 * (p_toy / p_thin - 1.0)
        );
        assert!(p_thin > 0.0 && p_toy > 0.0);
        // The toy's start found steady stays at its tilt.
        let ratio = spin_ratio(TOY, alpha0);
        let held = tilt(&scene(TOY, alpha0, 0.0, toy, ratio * toy, 0.2, 1e-3))
            .iter()
            .map(|r| (r.1 - alpha0).abs())
            .fold(0.0, f64::max);
        assert!(held < 1e-6, "alpha0 {alpha0}: drifts {held:e} rad in 0.2 s");
    }
}
