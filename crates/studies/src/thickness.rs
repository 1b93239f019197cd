//! What the Euler's Disk toy's thickness does to the paper's numbers: the toy (a = 37.5 mm,
//! thickness 12.8 mm, rim fillet 2 mm as in M. Batista's data for it, mass 0.4 kg) beside the
//! thin uniform disk ($k = 1/4$) of the same radius and mass, both rolling (μ = 10) in the
//! sliding model, which carries the thickness (its moments, the contact on the rounded rim).
//!
//! **Steady motion** (eqs 29-30 at $b = 0$). With $\dot\alpha = 0$ the rates of a rolling
//! axisymmetric body stay constant, so a start is steady exactly when $\ddot\alpha = 0$ there.
//! The disk spinning in place keeps its centre at rest, $\boldsymbol\omega\times\boldsymbol\rho = 0$:
//! with $\boldsymbol\rho = p\hat{\mathbf 1} + q\hat{\mathbf 3}$ and
//! $\boldsymbol\omega = \omega_1\hat{\mathbf 1} - \Omega\sin\alpha\,\hat{\mathbf 3}$,
//! $\omega_1 = -\Omega\sin\alpha\,p/q$ (0 for the thin disk). The $\Omega$ that makes such a start
//! steady at $\alpha_0$ is found by bisection on the sign of $\alpha(\tau) - \alpha_0$ after
//! $\tau$ = 1 ms (rtol 1e-12).
//!
//! **Small oscillations.** From each steady start with $\dot\alpha$ = 1 mrad/s, the period of
//! $\alpha$ over 1 s (mean spacing of its maxima).
//!
//! **Spin-down** (eqs 76-79). Eq 75's power $P = -\epsilon m a g \Omega^\beta$ ($\beta = 2$,
//! $\epsilon = 1.2\times10^{-6}$ s (its unit is s^(β−1)), the built-in spin-down's) as a torque against
//! $\boldsymbol\omega$, from the steady $b = 0$ motion at 0.15 rad down to $10^{-4}$ rad. Eq 79's
//! law $\Omega^{-(\beta+2)} = (t_0 - t)/C$ is fitted by least squares on the samples with
//! $\alpha$ between [`FIT_TILTS`]; its exponent by eq 85, the slope of $\ln\dot\Omega$ against
//! $\ln\Omega$ there ($\beta + 3$).
//!
//! **Contact lost** (eqs 80-81). The normal force is $F_z = m(g + \ddot h)$ with $h(\alpha)$ the
//! centre's height: $a\sin\alpha$ for the thin disk, $(a - f)\sin\alpha + (c - f)\cos\alpha + f$
//! on the rounded rim ($c$ the half thickness). With the tilt law fitted on the same samples,
//! $\alpha = A(t_0 - t)^{2/(\beta+2)}$, the contact is lost where
//! $g + h'(\alpha)\ddot\alpha + h''(\alpha)\dot\alpha^2 = 0$, found by bisection in $t_0 - t$.
//! For the thin disk this is eq 80's $\Omega_{\max}$ through eq 31 (the paper drops the
//! $\dot\alpha^2$ term); the simulated run's least $F_z/mg$ says whether the run got there.

use crate::sliding::swing::Swing;
use crate::StudyError;
use physics::dispatch::sliding_model;
use physics::model::sliding::{Mode, Solid};
use physics::model::steady::steady_motion;
use physics::model::steady_solid::RollingSolid;
use physics::run::sliding::integrate;
use physics::scene::Scene;
use serde::{Deserialize, Serialize};

/// The toy's radius (m), thickness (m), fillet (m) and mass (kg).
pub const TOY: (f64, f64, f64, f64) = (0.0375, 0.0128, 0.002, 0.4);
/// Tilts of the steady motions compared (rad).
pub const STEADY_TILTS: [f64; 4] = [0.3, 0.6, 1.0, 1.3];
/// The spin-down's eq 75: $(\epsilon, \beta)$.
pub const DRAG: (f64, f64) = (1.2e-6, 2.0);
/// The spin-down's start tilt (rad).
pub const SPIN_DOWN_START: f64 = 0.15;
/// The tilts between which eq 79 is fitted (rad).
pub const FIT_TILTS: (f64, f64) = (0.002, 0.05);

/// Which disk.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, schemars::JsonSchema)]
pub enum Shape {
    /// The thin uniform disk, $k = 1/4$.
    Thin,
    /// The toy, thick with a rounded rim.
    Toy,
}

impl Shape {
    fn disk_keys(self) -> String {
        match self {
            Shape::Thin => "k: 0.25".into(),
            Shape::Toy => format!("thickness: {:e}, fillet: {:e}", TOY.1, TOY.2),
        }
    }

    /// $\omega_1/\Omega$ of the rolling disk whose centre goes round a circle of radius `b` at
    /// the tilt `alpha0` ([`RollingSolid::spin_ratio`]).
    pub fn spin_ratio(self, alpha0: f64, b: f64) -> f64 {
        self.rolling().spin_ratio(alpha0, b)
    }

    /// The disk's [`RollingSolid`]: its mass, moments and rim, for eqs 29-30's closed form.
    pub fn rolling(self) -> RollingSolid {
        let solid = match self {
            Shape::Thin => None,
            Shape::Toy => Some(Solid::new(TOY.0, TOY.3, TOY.1, TOY.2)),
        };
        RollingSolid::of(&physics::disk::toy_disk(), solid)
    }

    /// The centre's height $h(\alpha)$ and its first two derivatives (module documentation).
    fn height(self, alpha: f64) -> (f64, f64, f64) {
        let (s, c) = alpha.sin_cos();
        let (a, f, half) = match self {
            Shape::Thin => (TOY.0, 0.0, 0.0),
            Shape::Toy => (TOY.0, TOY.2, 0.5 * TOY.1),
        };
        let (r, z) = (a - f, half - f);
        (r * s + z * c + f, r * c - z * s, -r * s - z * c)
    }
}

/// A rolling scene of `shape` from an explicit start; `extra` adds keys (a dissipation).
#[allow(clippy::too_many_arguments)]
pub fn scene(
    shape: Shape,
    alpha: f64,
    alpha_dot: f64,
    precession: f64,
    spin: f64,
    time: f64,
    dt: f64,
    extra: &str,
) -> Result<Scene, StudyError> {
    let src = format!(
        "name: toy-thickness
model: sliding
disk: {{ radius: {:e}, mass: {:e}, {} }}
friction: {{ mu: 10 }}
{extra}start: {{ explicit: {{ alpha: {alpha:e}, alpha_dot: {alpha_dot:e}, precession: {precession:e}, spin: {spin:e} }} }}
stop: {{ time: {time:e}, alpha_below: 1e-4 }}
sample: {dt:e}
solver: {{ rtol: 1e-12, atol: 1e-15 }}
",
        TOY.0,
        TOY.3,
        shape.disk_keys()
    );
    Ok(Scene::parse(&src, "toy-thickness.yaml")?)
}

/// $(t, \alpha, \dot\alpha, \Omega, F_z/mg)$ at each sample of a run that must roll throughout.
pub fn samples(s: &Scene) -> Result<Vec<[f64; 5]>, StudyError> {
    let m = sliding_model(s);
    let run = integrate(&m, s, s.sample)?;
    if !run.switches.is_empty() {
        return Err(format!("{}: the rolling start slipped or flew", s.name).into());
    }
    let weight = s.disk.m * s.disk.g;
    Ok(run
        .t
        .iter()
        .zip(&run.y)
        .map(|(t, y)| {
            let snap = m.snapshot(y);
            let mo = snap.motion();
            let fz = m.contact_force(&Mode::Stick, &snap).force.z / weight;
            [*t, mo.alpha, mo.alpha_dot, mo.precession, fz]
        })
        .collect())
}

/// The precession that makes `shape` rolling with its centre on a circle of radius `b` steady
/// at `alpha0`, searched in `[0.3, 5] guess`.
pub fn steady_precession(shape: Shape, alpha0: f64, b: f64, guess: f64) -> Result<f64, StudyError> {
    let tau = 1e-3;
    let ratio = shape.spin_ratio(alpha0, b);
    let drift = |om: f64| -> Result<f64, StudyError> {
        let r = samples(&scene(shape, alpha0, 0.0, om, ratio * om, tau, tau, "")?)?;
        Ok(r.last().map_or(0.0, |x| x[1]) - alpha0)
    };
    let (mut lo, mut hi) = (0.3 * guess, 5.0 * guess);
    let f_lo = drift(lo)?;
    if f_lo * drift(hi)? >= 0.0 {
        return Err(format!("no steady spin at alpha0 = {alpha0} in [{lo}, {hi}] rad/s").into());
    }
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if (drift(mid)? > 0.0) == (f_lo > 0.0) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(0.5 * (lo + hi))
}

/// The period of the tilt's oscillation about the steady start (`alpha0`, `precession`).
pub fn period(shape: Shape, alpha0: f64, precession: f64) -> Result<f64, StudyError> {
    let spin = shape.spin_ratio(alpha0, 0.0) * precession;
    let r = samples(&scene(
        shape, alpha0, 1e-3, precession, spin, 1.0, 1e-4, "",
    )?)?;
    let maxima: Vec<f64> = r
        .windows(2)
        .filter(|w| w[0][2] > 0.0 && w[1][2] <= 0.0)
        .map(|w| w[0][0] + (w[1][0] - w[0][0]) * w[0][2] / (w[0][2] - w[1][2]))
        .collect();
    match maxima.as_slice() {
        [first, .., last] if maxima.len() >= 3 => Ok((last - first) / (maxima.len() - 1) as f64),
        _ => Err(format!("alpha0 = {alpha0}: fewer than 3 maxima of the tilt in 1 s").into()),
    }
}

/// One tilt's steady motion and small oscillation, thin and toy.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
pub struct SteadyPair {
    /// $\alpha_0$ (rad).
    pub alpha0: f64,
    /// Eq 29's $\Omega_0$ at $b = 0$ (rad/s).
    pub eq29: f64,
    /// The thin disk's steady $\Omega_0$, shot (rad/s).
    pub thin: f64,
    /// The toy's steady $\Omega_0$, shot (rad/s).
    pub toy: f64,
    /// The toy's spin $\omega_1$ in that motion (rad/s; 0 for the thin disk).
    pub toy_spin: f64,
    /// The thin disk's period of small oscillations (s).
    pub thin_period: f64,
    /// The toy's (s).
    pub toy_period: f64,
}

/// One disk's spin-down under eq 75.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
pub struct SpinDownLaw {
    /// Which disk.
    pub shape: Shape,
    /// Eq 79's $C$ fitted (s$^{-1}$ rad$^{\beta+2}$ s$^{-\beta-2}$, i.e. rad⁴/s³ at $\beta = 2$).
    pub c: f64,
    /// The fitted $t_0$ (s).
    pub t0: f64,
    /// The slope of $\ln\dot\Omega$ against $\ln\Omega$ (eq 85: $\beta + 3$).
    pub exponent: f64,
    /// $A$ of $\alpha = A(t_0 - t)^{2/(\beta+2)}$ fitted (rad s$^{-2/(\beta+2)}$).
    pub tilt_coefficient: f64,
    /// The tilt where the fitted law would lose contact (rad).
    pub loss_tilt: f64,
    /// $t_0 - t$ there (s).
    pub loss_before_t0: f64,
    /// The least $F_z/mg$ of the run, and the tilt there (rad).
    pub least_normal: (f64, f64),
    /// Where the run ended: the time (s) and the tilt (rad).
    pub end: (f64, f64),
}

/// One fall from unstable steady motion (sec. 7), thin and toy.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
pub struct FallPair {
    /// The steady tilt (deg).
    pub alpha0_deg: f64,
    /// $b/a$: the middle of the thin disk's unstable band (`sliding::fall::band`).
    pub b_over_a: f64,
    /// The steady $\Omega_0$ of the thin disk (eq 29) and of the toy (eq 29 for the solid,
    /// [`RollingSolid::steady`]), rad/s; `None` where the toy has no steady motion at that $b$
    /// (eq 30 for the solid).
    pub precession: (f64, Option<f64>),
    /// The first dip of each (deg), thin and toy: the first minimum of the tilt; `None`: it did
    /// not fall [`FALL_LEFT`]° within [`FALL_TIME`] s. One extreme of the motion.
    pub fell_to_deg: (Option<f64>, Option<f64>),
    /// What each tilt does over the run, thin and toy: least, greatest, mean, and whether it
    /// settles into a lower steady rolling (`sliding::swing`); `None` where the toy has no
    /// steady motion at that $b$.
    pub swing: (Swing, Option<Swing>),
}

/// How long each fall runs (s), as the fall study.
pub const FALL_TIME: f64 = 3.0;
/// How far below $\alpha_0$ the tilt must go to have fallen (deg), as the fall study.
pub const FALL_LEFT: f64 = crate::sliding::swing::FALLEN;

/// The fall of `shape` from its steady motion at (`alpha0`, `b`, `precession`) with the tilt
/// lowered by 1 mrad, rolling: its first dip (deg), the first minimum of $\alpha$ (to the 1 ms
/// sampling) once it is [`FALL_LEFT`]° below $\alpha_0$, as `sliding::fall` defines it, and
/// what the tilt does over the whole run.
pub fn fall_to(
    shape: Shape,
    alpha0: f64,
    b: f64,
    precession: f64,
) -> Result<(Option<f64>, Swing), StudyError> {
    let spin = shape.spin_ratio(alpha0, b) * precession;
    let r = samples(&scene(
        shape,
        alpha0 - 1e-3,
        0.0,
        precession,
        spin,
        FALL_TIME,
        1e-3,
        "",
    )?)?;
    let column = |i: usize| r.iter().map(|x| x[i]).collect::<Vec<f64>>();
    let swing = Swing::of(&column(0), &column(1), &column(2), alpha0);
    let Some(left) = r
        .iter()
        .position(|x| x[1] < alpha0 - FALL_LEFT.to_radians())
    else {
        return Ok((None, swing));
    };
    let dip = r[left..]
        .windows(2)
        .find(|w| w[0][2] < 0.0 && w[1][2] >= 0.0)
        .map(|w| w[0][1].min(w[1][1]).to_degrees());
    Ok((dip, swing))
}

/// The falls at each tilt of `sliding::fall::TILTS_DEG` from the middle of the thin disk's
/// unstable band.
fn falls() -> Result<Vec<FallPair>, StudyError> {
    let d = physics::disk::toy_disk();
    let mut out = Vec::new();
    for deg in crate::sliding::fall::TILTS_DEG {
        let alpha0 = deg.to_radians();
        let Some(band) = crate::sliding::fall::band(&d, alpha0) else {
            continue;
        };
        let b = band.start * d.a;
        let thin = steady_motion(&d, alpha0, b)?.precession;
        let toy = Shape::Toy
            .rolling()
            .steady(alpha0, b)
            .ok()
            .map(|m| m.precession);
        let (thin_dip, thin_swing) = fall_to(Shape::Thin, alpha0, b, thin)?;
        let (toy_dip, toy_swing) = match toy {
            Some(om) => {
                let (dip, swing) = fall_to(Shape::Toy, alpha0, b, om)?;
                (dip, Some(swing))
            }
            None => (None, None),
        };
        out.push(FallPair {
            alpha0_deg: deg,
            b_over_a: band.start,
            precession: (thin, toy),
            fell_to_deg: (thin_dip, toy_dip),
            swing: (thin_swing, toy_swing),
        });
    }
    Ok(out)
}

/// The toy against the thin disk.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
pub struct Thickness {
    /// At each of [`STEADY_TILTS`].
    pub steady: Vec<SteadyPair>,
    /// Thin, then toy.
    pub spin_down: Vec<SpinDownLaw>,
    /// The falls from unstable steady motion.
    pub falls: Vec<FallPair>,
    /// Eq 79's printed $C = 5g/(\epsilon(\beta+2)ak)$ for the thin disk.
    pub eq79_c: f64,
    /// Eq 80's $\Omega_{\max}$ from the thin disk's fitted $C$, and the tilt there by eq 31
    /// ($g / (a k \Omega^2)$, rad).
    pub eq80_thin: (f64, f64),
}

/// Least-squares line through `xy`: (slope, intercept).
fn line(xy: &[(f64, f64)]) -> (f64, f64) {
    let n = xy.len() as f64;
    let (mx, my) = xy
        .iter()
        .fold((0.0, 0.0), |(a, b), (x, y)| (a + x / n, b + y / n));
    let (sxy, sxx) = xy.iter().fold((0.0, 0.0), |(a, b), (x, y)| {
        (a + (x - mx) * (y - my), b + (x - mx) * (x - mx))
    });
    let slope = sxy / sxx;
    (slope, my - slope * mx)
}

/// The spin-down of `shape` (module documentation).
pub fn spin_down(shape: Shape) -> Result<SpinDownLaw, StudyError> {
    let (epsilon, beta) = DRAG;
    let alpha0 = SPIN_DOWN_START;
    let guess = steady_motion(&physics::disk::toy_disk(), alpha0, 0.0)?.precession;
    let om = match shape {
        Shape::Thin => guess,
        Shape::Toy => steady_precession(shape, alpha0, 0.0, guess)?,
    };
    let drag = format!("dissipation: {{ epsilon: {epsilon:e}, beta: {beta:e} }}\n");
    let s = scene(
        shape,
        alpha0,
        0.0,
        om,
        shape.spin_ratio(alpha0, 0.0) * om,
        120.0,
        1e-3,
        &drag,
    )?;
    let r = samples(&s)?;
    let fit: Vec<&[f64; 5]> = r
        .iter()
        .filter(|x| (FIT_TILTS.0..=FIT_TILTS.1).contains(&x[1]))
        .collect();
    if fit.len() < 100 {
        return Err(format!("the spin-down has {} samples to fit", fit.len()).into());
    }
    let q = beta + 2.0;
    let (slope, icpt) = line(
        &fit.iter()
            .map(|x| (x[0], x[3].powf(-q)))
            .collect::<Vec<_>>(),
    );
    let (c, t0) = (-1.0 / slope, -icpt / slope);
    // Eq 85: the slope of ln(dOmega/dt) against ln(Omega), dOmega/dt by central differences
    // over 2 W samples.
    const W: usize = 25;
    let rates: Vec<(f64, f64)> = (W..r.len().saturating_sub(W))
        .filter(|&i| (FIT_TILTS.0..=FIT_TILTS.1).contains(&r[i][1]))
        .map(|i| {
            let d = (r[i + W][3] - r[i - W][3]) / (r[i + W][0] - r[i - W][0]);
            (r[i][3].ln(), d.ln())
        })
        .collect();
    let (exponent, _) = line(&rates);
    let (ks, _) = line(
        &fit.iter()
            .map(|x| (x[0], x[1].powf(q / 2.0)))
            .collect::<Vec<_>>(),
    );
    let a_coef = (-ks).powf(2.0 / q);
    let (loss_before_t0, loss_tilt) = contact_loss(shape, a_coef, 2.0 / q, s.disk.g, t0)?;
    let least = r.iter().fold((f64::INFINITY, 0.0), |m, x| {
        if x[4] < m.0 {
            (x[4], x[1])
        } else {
            m
        }
    });
    let last = r.last().map_or([0.0; 5], |x| *x);
    Ok(SpinDownLaw {
        shape,
        c,
        t0,
        exponent,
        tilt_coefficient: a_coef,
        loss_tilt,
        loss_before_t0,
        least_normal: least,
        end: (last[0], last[1]),
    })
}

/// Where $\alpha = A u^p$ ($u = t_0 - t$) loses contact: $(u, \alpha)$.
fn contact_loss(
    shape: Shape,
    a: f64,
    p: f64,
    g: f64,
    longest: f64,
) -> Result<(f64, f64), StudyError> {
    let excess = |u: f64| {
        let alpha = a * u.powf(p);
        let rate = -a * p * u.powf(p - 1.0);
        let accel = a * p * (p - 1.0) * u.powf(p - 2.0);
        let (_, h1, h2) = shape.height(alpha);
        g + h1 * accel + h2 * rate * rate
    };
    let (mut lo, mut hi) = (1e-14, longest);
    if excess(lo) >= 0.0 || excess(hi) <= 0.0 {
        return Err("the fitted tilt law never loses contact".into());
    }
    for _ in 0..200 {
        let mid = (lo * hi).sqrt();
        if excess(mid) < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let u = (lo * hi).sqrt();
    Ok((u, a * u.powf(p)))
}

/// The study: steady motions and oscillations at [`STEADY_TILTS`], and both spin-downs.
pub fn compute() -> Result<Thickness, StudyError> {
    use rayon::prelude::*;
    let thin_disk = physics::disk::toy_disk();
    let pair = |alpha0: f64| -> Result<SteadyPair, StudyError> {
        let eq29 = steady_motion(&thin_disk, alpha0, 0.0)?.precession;
        let thin = steady_precession(Shape::Thin, alpha0, 0.0, eq29)?;
        let toy = steady_precession(Shape::Toy, alpha0, 0.0, eq29)?;
        Ok(SteadyPair {
            alpha0,
            eq29,
            thin,
            toy,
            toy_spin: Shape::Toy.spin_ratio(alpha0, 0.0) * toy,
            thin_period: period(Shape::Thin, alpha0, thin)?,
            toy_period: period(Shape::Toy, alpha0, toy)?,
        })
    };
    // Every run is independent and deterministic: side by side, in order.
    let ((steady, falls), (thin, toy)) = rayon::join(
        || {
            rayon::join(
                || {
                    STEADY_TILTS
                        .par_iter()
                        .map(|a| pair(*a))
                        .collect::<Result<Vec<_>, StudyError>>()
                },
                falls,
            )
        },
        || rayon::join(|| spin_down(Shape::Thin), || spin_down(Shape::Toy)),
    );
    let steady = steady?;
    let spin_down = vec![thin?, toy?];
    let (epsilon, beta) = DRAG;
    let (a, k, g) = (thin_disk.a, thin_disk.k, thin_disk.g);
    let eq79_c = 5.0 * g / (epsilon * (beta + 2.0) * a * k);
    let omega_max = (k * (beta + 2.0).powi(2) / (2.0 * beta)).powf(1.0 / (2.0 * (beta + 1.0)))
        * spin_down[0].c.powf(1.0 / (beta + 1.0));
    Ok(Thickness {
        steady,
        spin_down,
        falls: falls?,
        eq79_c,
        eq80_thin: (omega_max, g / (a * k * omega_max * omega_max)),
    })
}
