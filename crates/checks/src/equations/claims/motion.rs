//! Claims of secs. 3-6: the moment of inertia, the centre of motion, steady motions and the
//! friction they need.

use super::judge::{printed, stated, worse};
use super::{
    bisect, mid, mu_required, rolling, solve, steady_motion, unit_disk, Bench, Contact, DualNum,
    Extras, Finding, Headline, LabFrame, Method, Model, Motion, Problem, Quantity, Rolling, State,
    Tolerance, Worst, FRAC_PI_2, FRAC_PI_3, PI, WIDTH,
};
use crate::finding::Verdict;
use crate::robustness::Alternative;

// ------------------------------------------------------------------------------ sec. 3

/// `k-rim-disk`: $k = I_{11}/2ma^2 = 1/2$ for a ring, by summing $r^2\,dm$ over its mass points
/// (exact for a ring); the diametral moment by the same sum gives $I_{22}/ma^2$ equal to it.
pub(super) fn k_rim_disk(b: &Bench) -> Finding {
    let (n, m, a) = (24, 1.0, 1.0);
    let (mut i11, mut i22) = (0.0, 0.0);
    for i in 0..n {
        let th = 2.0 * PI * i as f64 / n as f64;
        let (x, y) = (a * th.cos(), a * th.sin());
        i11 += m / n as f64 * (x * x + y * y);
        i22 += m / n as f64 * y * y;
    }
    let mut w = Worst::default();
    w.add(
        b.claim(printed(b, "k-rim-disk")),
        i11 / (2.0 * m * a * a),
        0.5,
        || "$I_{11}/(2 m a^{2})$ of a ring of 24 point masses".into(),
    );
    w.add(
        b.claim(printed(b, "k-rim-disk")),
        i22 / (m * a * a),
        0.5,
        || "$I_{22}/(m a^{2})$, diametral moment of the same ring".into(),
    );
    Finding::from_worst(
        Method::Derivation,
        "k of a ring from its moments of inertia",
        w,
        Tolerance::roundoff(),
    )
}

/// `k-uniform-disk`: $k = 1/4$ from $\int r^2\,dm$ over a uniform disk (3-point Gauss-Legendre in
/// $r$, exact for the cubic integrand; equally spaced angles, exact for $\sin^2$).
pub(super) fn k_uniform_disk(b: &Bench) -> Finding {
    let (m, a, na) = (1.0, 1.0, 24);
    let sigma = m / (PI * a * a);
    let nodes = [
        (-(0.6f64).sqrt(), 5.0 / 9.0),
        (0.0, 8.0 / 9.0),
        ((0.6f64).sqrt(), 5.0 / 9.0),
    ];
    let (mut mass, mut i11, mut i22) = (0.0, 0.0, 0.0);
    for (x, wgt) in nodes {
        let r = 0.5 * a * (1.0 + x);
        let dr = 0.5 * a * wgt;
        for i in 0..na {
            let th = 2.0 * PI * i as f64 / na as f64;
            let dm = sigma * r * dr * 2.0 * PI / na as f64;
            mass += dm;
            i11 += dm * r * r;
            i22 += dm * (r * th.sin()).powi(2);
        }
    }
    let mut w = Worst::default();
    w.add(
        b.claim(printed(b, "k-uniform-disk")),
        i11 / (2.0 * mass * a * a),
        0.25,
        || "$I_{11}/(2 m a^{2})$ by quadrature".into(),
    );
    w.add(
        b.claim(printed(b, "k-uniform-disk")),
        i22 / (mass * a * a),
        0.25,
        || "$I_{22}/(m a^{2})$ by quadrature".into(),
    );
    Finding::from_worst(
        Method::Derivation,
        "k of a uniform disk from its moments of inertia",
        w,
        Tolerance::roundoff(),
    )
}

/// `center-of-motion-constant`: the centre $A = \mathbf r_{cm} - (a\omega_1/\Omega)\hat{\mathbf r}$
/// of the contact point's circle, followed along integrations of eqs 23-25 with heading and
/// centre of mass. It is fixed on a steady motion, but on a nutating one it MOVES: $dA/dt =
/// -\dot r\,\hat{\mathbf r}$ with $r = a(\omega_1 + \Omega\cos\alpha)/\Omega$ oscillating. The
/// paper's claim (a constant of every rolling motion) FAILS; the excursion grows linearly with
/// the perturbation of the steady motion (shown in `at`).
pub(super) fn center_of_motion_constant(b: &Bench) -> Finding {
    let mut w = Worst::default();
    let mut notes = Vec::new();
    // The largest drift for each push of the tilt, over both disks.
    let mut by_push = [(1e-2, 0.0f64), (1e-3, 0.0f64)];
    for &(k, alpha0, beta) in &[(0.25, 0.5, 0.3), (0.5, 0.5, -0.1)] {
        let disk = unit_disk(k);
        let model = Rolling::<7>::new(
            disk,
            Extras {
                heading: true,
                path: true,
                face: false,
            },
            None,
        );
        let steady = steady_motion(&disk, alpha0, beta).expect("a steady motion");
        let period = 2.0 * PI / steady.precession.abs();
        for &delta in &[0.0, 1e-3, 1e-2] {
            let mut m0 = steady;
            m0.alpha += delta;
            let y0 = model.state(&m0);
            let sol = solve(
                Problem::new(&model, 0.0, y0, 6.0 * period).sampled(period / 40.0),
                &b.settings(),
            )
            .expect("valid settings");
            let centre = |y: &State<7>| {
                let (psi, x, yy) = (y[4], y[5], y[6]);
                let r_over = y[3] / y[2]; // a omega_1 / Omega with a = 1
                (x - r_over * psi.sin(), yy + r_over * psi.cos())
            };
            let a0 = centre(&sol.y[0]);
            let mut excursion: f64 = 0.0;
            // The drift |A(t) - A(0)| / a from the claimed A(0) (moved by the mutation sweep):
            // a distance, independent of where the origin is.
            let start = (b.claim(a0.0), b.claim(a0.1));
            for (t, y) in sol.t.iter().zip(&sol.y) {
                let a = centre(y);
                excursion = excursion.max((a.0 - a0.0).hypot(a.1 - a0.1));
                let drift = (a.0 - start.0).hypot(a.1 - start.1) / disk.a;
                w.add_error(0.0, drift, drift, "a", || {
                    format!("$|A - A(0)|$ at $t = {t:.3}$, $k = {k}$, $\\alpha_0 = {alpha0}$, $b = {beta} a$, $\\alpha$ perturbed by {delta}")
                });
            }
            notes.push(format!(
                "$k = {k}$, $\\delta = {delta}$: $|A - A(0)|_{{\\max}} = {excursion:.3e} a$"
            ));
            for (push, most) in by_push.iter_mut() {
                if *push == delta {
                    *most = most.max(excursion / disk.a);
                }
            }
        }
    }
    let mut f = Finding::from_worst(
        Method::Integration,
        "drift $|A - A(0)|$ of the centre of motion along rolling motions, in units of a (claimed: 0, a constant)",
        w,
        Tolerance::solver(b.rtol),
    );
    f.at = format!("{}; {}", f.at, notes.join("; "));
    let h = Headline::new(
        "the drift $|A - A(0)|$ of the centre of motion at the worst time (the paper: 0, a constant)",
        f.claimed,
        "implied",
        f.reference,
        "a",
        f.at.clone(),
    );
    // The paper says "rolling motion" without saying how far from steady: each push of the
    // tilt is a reading of its own, judged by the same tolerance.
    let tolerance = f.tolerance.value;
    let alternatives = by_push
        .iter()
        .map(|&(push, most)| {
            Alternative::new(
                "how far the motion is from steady",
                format!("the tilt pushed {push} rad off steady motion ($k = 1/4$ and 1/2)"),
                most,
                if most > tolerance {
                    Verdict::Fails
                } else {
                    Verdict::Holds
                },
            )
        })
        .collect();
    f.with_headline(h).with_robustness(alternatives)
}

// ------------------------------------------------------------------------------ sec. 4

/// `no-steady-motion-beyond-vertical`: equilibria of eqs 23-25 ($\dot\alpha = 0$, $\ddot\alpha =
/// 0$) with the contact circle's radius $r > 0$, i.e. $\omega_1 = \Omega(r/a - \cos\alpha)$,
/// searched for directly on the model's $\ddot\alpha(\Omega)$ (a root exists iff it changes sign
/// between $\Omega = 0$ and large $\Omega$, being linear in $\Omega^2$). None exists on a grid of
/// $(\alpha_0, r/a, k)$ with $\pi/2 < \alpha_0 < \pi$, and the edge of existence, located by
/// bisection in $\alpha_0$, is $\pi/2$ (the claimed boundary).
pub(super) fn no_steady_motion_beyond_vertical(b: &Bench) -> Finding {
    let exists = |k: f64, alpha: f64, r: f64| {
        let disk = unit_disk(k);
        let add = |om: f64| {
            let m = Motion {
                alpha,
                alpha_dot: 0.0,
                precession: om,
                spin: om * (r - alpha.cos()),
            };
            rolling::rates(&disk, &m, [0.0; 3]).alpha_ddot
        };
        add(0.0).signum() != add(1e4).signum()
    };
    let mut w = Worst::default();
    let mut found = 0;
    for &k in &[0.1, 0.25, 0.5, 1.0] {
        for &r in &[0.01, 0.3, 1.0, 5.0] {
            for i in 1..30 {
                let alpha = FRAC_PI_2 + (PI - FRAC_PI_2) * i as f64 / 30.0;
                if exists(k, alpha, r) {
                    found += 1;
                }
            }
            let edge = mid(bisect(FRAC_PI_2 - 0.005, PI - 0.01, WIDTH, |al| {
                !exists(k, al, r)
            }));
            w.add(b.claim(FRAC_PI_2), edge, FRAC_PI_2, || {
                format!("edge of existence at $k = {k}$, $r = {r} a$")
            });
        }
    }
    if found > 0 {
        w.add(f64::NAN, 0.0, 1.0, || {
            format!("{found} steady motions found with $\\pi/2 < \\alpha_0 < \\pi$")
        });
    }
    let mut f = Finding::from_worst(
        Method::Derivation,
        "largest tilt with a steady motion $(r > 0)$, from the equilibria of eqs 23-25 (rad)",
        w,
        Tolerance::bisection(WIDTH),
    )
    .in_unit("rad");
    f.at = format!(
        "{}; no equilibrium on 464 grid points in ($\\pi/2$, $\\pi$)",
        f.at
    );
    f
}

// ------------------------------------------------------------------------------ sec. 5

/// The face figure's rate and the precession rate measured on the lab-frame model (Newton-Euler,
/// rolling contact; none of the paper's equations) over five precession periods of the steady
/// $b = 0$ motion at tilt `alpha0` ($k = 1/4$): the heading of $\hat{\mathbf 2}$ turns at
/// $\Omega_0$ about $\hat{\mathbf z}$, the body turns relative to the triad at $\dot\phi$ about
/// $\hat{\mathbf 1} \approx -\hat{\mathbf z}$, so a mark on the face turns in the lab at
/// $\dot\psi - \dot\phi$. Both rates from the unwrapped angles' end points.
fn face_rate_in_the_lab(b: &Bench, alpha0: f64) -> (f64, f64) {
    let disk = unit_disk(0.25);
    let model = LabFrame::new(disk, Contact::Rolling);
    let m = steady_motion(&disk, alpha0, 0.0).expect("a steady $b = 0$ motion at a small tilt");
    let span = 5.0 * 2.0 * PI / m.precession;
    let sol = solve(
        Problem::new(&model, 0.0, model.state(&m), span).sampled(span / 400.0),
        &b.settings(),
    )
    .expect("valid settings");
    let unwrapped = |q: Quantity| {
        let mut total = 0.0;
        let mut last: Option<f64> = None;
        for y in &sol.y {
            let mut out = Vec::new();
            model.record(y, q, &mut out);
            if let Some(prev) = last {
                total += (out[0] - prev + PI).rem_euclid(2.0 * PI) - PI;
            }
            last = Some(out[0]);
        }
        total / sol.t[sol.t.len() - 1]
    };
    let (heading, face) = (unwrapped(Quantity::Heading), unwrapped(Quantity::Face));
    (heading - face, heading)
}

/// `face-figure-rate-vanishes`: the face figure's rate measured on the lab-frame model
/// ([`face_rate_in_the_lab`]) against the paper's $\Omega_0(1 - \cos\alpha_0)$ with the
/// precession rate measured there too, and its fitted exponent as $\alpha_0 \to 0$ (3/2, since
/// $\Omega_0 \propto \alpha_0^{-1/2}$); the total angular velocity $|\vec\omega|$ of the
/// steady motions of eqs 28-29 vanishes as $\alpha_0^{1/2}$.
pub(super) fn face_figure_rate_vanishes(b: &Bench) -> Finding {
    let disk = unit_disk(0.25);
    let alphas = [3e-1, 1e-1, 3e-2, 1e-2, 3e-3];
    let mut w = Worst::default();
    let (mut face, mut total) = (Vec::new(), Vec::new());
    for &al in &alphas {
        let (face_rate, precession) = face_rate_in_the_lab(b, al);
        w.add(
            b.claim(precession * (1.0 - al.cos())),
            face_rate,
            face_rate.abs(),
            || {
                format!(
                    "face rate at $\\alpha_0 = {al}$: {face_rate:.6e} measured in the lab frame"
                )
            },
        );
        let m = steady_motion(&disk, al, 0.0).expect("a steady $b = 0$ motion at a small tilt");
        let omega =
            (m.spin * m.spin + m.alpha_dot * m.alpha_dot + (m.precession * al.sin()).powi(2))
                .sqrt();
        face.push(face_rate);
        total.push(omega);
    }
    let values = Finding::from_worst(
        Method::Integration,
        "face figure's rate in the lab-frame model against the paper's $\\Omega_0 (1 - \\cos \\alpha_0)$",
        w,
        Tolerance::solver(b.rtol),
    );
    let face_order = Finding::from_order(
        "face figure's rate $\\Omega_0 (1 - \\cos \\alpha_0)$ vanishing as $\\alpha_0 \\to  0$",
        &alphas,
        &face,
        1.5,
    );
    let total_order = Finding::from_order(
        "total angular velocity $|\\omega|$ vanishing as $\\alpha_0 \\to  0$",
        &alphas,
        &total,
        0.5,
    );
    let mut f = worse(worse(face_order, total_order), values);
    f.at = format!("{}; $k = 1/4$, $b = 0$", f.at);
    f
}

// ------------------------------------------------------------------------------ sec. 6

/// `slip-when-b-large`: the exact friction coefficient required by a steady motion, $|F_h|/F_z$
/// from the model's contact force (eq 20), at $|b| = a k\sin\alpha_0$ (both signs, $k = 1/4,
/// 1/2$): the paper's threshold is where it equals 1. Exactly it is $1/(1 \pm (2k+1)\tan\alpha_0)$,
/// so it tends to 1 at first order in $\alpha_0$: the claim holds at small tilt (the section's
/// setting). At larger tilt the requirement is lower (0.40 at 45 degrees, $k = 1/4$).
pub(super) fn slip_when_b_large(b: &Bench) -> Finding {
    let alphas = [1e-1, 1e-2, 1e-3, 1e-4, 1e-5];
    let mut errors = Vec::new();
    for &al in &alphas {
        let mut e: f64 = 0.0;
        for &k in &[0.25, 0.5] {
            for sign in [1.0, -1.0] {
                let beta = sign * k * al.sin();
                e = e.max((mu_required(k, al, beta) - b.claim(1.0)).abs());
            }
        }
        errors.push(e);
    }
    let mut f = Finding::from_order(
        "required friction coefficient at $|b| = a k \\sin(\\alpha_0)$ against 1 (eq 42's threshold)",
        &alphas,
        &errors,
        1.0,
    );
    f.at = format!(
        "{}; at 45 deg, $k = 1/4$ the exact requirement is {:.3}",
        f.at,
        mu_required(0.25, PI / 4.0, 0.25 * (PI / 4.0).sin())
    );
    f
}

/// `negative-b-friction-angle`: the tilt above which eq 43 can be met with $\mu = 1$ at $k = 1/4$,
/// by bisection on eq 43: $\tan^{-1}(2/3) = 0.588$ rad (33.7 deg), not the claimed $\pi/3$. The
/// stated $\pi/3$ needs $\mu = \cot(\pi/3)/1.5 = 0.385$. (The exact requirement at the edge of
/// eq 30, where eq 43 sets $|b|$, diverges: eq 43 is eq 42's small-angle form used at $|b|$
/// where it does not apply.) FAILS.
pub(super) fn negative_b_friction_angle(b: &Bench) -> Finding {
    let (k, mu) = (0.25, 1.0);
    // Eq 43's printed right side (NaN if an edit makes it unreadable: the finding then fails).
    let eq43 = |al: f64| {
        let bind = paper::Bindings::new().scalar("k", k).scalar("alpha_0", al);
        b.paper.right_side(43, &bind).unwrap_or(f64::NAN)
    };
    let edge = if eq43(0.01) > mu && eq43(1.5) <= mu {
        mid(bisect(0.01, 1.5, WIDTH, |al| eq43(al) <= mu))
    } else {
        f64::NAN
    };
    stated(
        b,
        "negative-b-friction-angle",
        Method::Derivation,
        "lowest tilt meeting eq 43 with $\\mu = 1$, $k = 1/4$ (rad)",
        edge,
        format!(
            "edge {:.4} rad = {:.2} deg; the claimed $\\pi/3$ implies $\\mu = {:.3}$",
            edge,
            edge.to_degrees(),
            eq43(FRAC_PI_3)
        ),
    )
}
