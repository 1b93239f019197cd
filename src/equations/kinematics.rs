//! Kinematics and the set-up of the dynamics, section 3 of the paper (eqs 1-22).
//!
//! The references never use the paper's triad relations. The disk's orientation is a rotation
//! matrix $R(t)$ built from lab Euler angles $z$-$x$-$z$: the heading $\psi(t)$, the nutation
//! $\theta(t)$ (the angle between the disk's normal $\mathbf n = R\hat{\mathbf e}_z$ and the
//! vertical) and the face angle $\phi(t)$, each a cubic in $t$ with random coefficients. From
//! $R$ alone the triad is CONSTRUCTED geometrically:
//! - $\hat{\mathbf 1} = -\mathbf n$ (the sense of the axis is a convention; with it, the tilt
//!   $\alpha$ is the nutation $\theta$, and $\theta \in (0, \pi)$ covers both senses),
//! - $\hat{\mathbf 3}$ = the unit vector in the disk's plane pointing most steeply down (the
//!   projection of $-\hat{\mathbf z}$ onto the plane, normalised),
//! - $\hat{\mathbf 2} = \hat{\mathbf 3}\times\hat{\mathbf 1}$, $\hat{\mathbf r} = \hat{\mathbf 2}
//!   \times\hat{\mathbf z}$.
//!
//! Time derivatives are exact, by dual numbers seeded with $dt = 1$ (nested duals where a second
//! derivative is needed). The precession $\Omega$ is MEASURED as the rate of the heading of
//! $\hat{\mathbf 2}$ (`atan2`), the spin relative to the triad $\omega_{rel}$ as the rate of the
//! angle of a mark on the face measured in the triad, the disk's angular velocity as the axial
//! vector of $\dot R R^T$ and the triad's as that of $\dot T T^T$ ($T$ = the triad as columns).
//!
//! A rolling disk is built without $\vec\omega\times\mathbf a$: its contact point $C$ moves on the
//! table as it moves along the rim, $\dot C = a R\,\dot{\mathbf u}$ with $\mathbf u = R^T\hat{\mathbf 3}$
//! the contact point in body coordinates (no slip), and $\mathbf r_{cm} = C - a\hat{\mathbf 3}$.
//! The inertia of a thin disk is summed over a quadrature of point masses (Gauss-Legendre in
//! the radius, equally spaced angles; exact for the polynomial integrands here).
//!
//! Note on the paper's figure 1: its caption says axis $\hat{\mathbf 1}$ "makes angle $\alpha$ to
//! $\hat{\mathbf z}$", but eq 4 gives $\hat{\mathbf 1}\cdot\hat{\mathbf z} = -\cos\alpha$: with
//! $\hat{\mathbf 2} = \hat{\mathbf 3}\times\hat{\mathbf 1}$ and eqs 4 and 8 it is $-\hat{\mathbf 1}$
//! that makes angle $\alpha$ with $\hat{\mathbf z}$ (axis 1 points below the horizontal for
//! $\alpha < \pi/2$). The checks adopt the equations' convention.

use super::{printed_relation, printed_relations, Bench, Equation};
use crate::finding::{Finding, Method, Tolerance, Worst};
use crate::numerics::rng::Rng;
use crate::paper::{Bindings, Value};
use nalgebra::Vector3;
use num_dual::{Dual, Dual64, DualNum};

/// The checks of this part of the paper.
pub const EQUATIONS: &[Equation] = &[
    Equation {
        number: 1,
        label: "e1",
        check: eq1,
    },
    Equation {
        number: 2,
        label: "e2",
        check: eq2,
    },
    Equation {
        number: 3,
        label: "e4",
        check: eq3,
    },
    Equation {
        number: 4,
        label: "e3",
        check: eq4,
    },
    Equation {
        number: 5,
        label: "e5",
        check: eq5,
    },
    Equation {
        number: 6,
        label: "e6",
        check: eq6,
    },
    Equation {
        number: 7,
        label: "e7",
        check: eq7,
    },
    Equation {
        number: 8,
        label: "e25b",
        check: eq8,
    },
    Equation {
        number: 9,
        label: "e250",
        check: eq9,
    },
    Equation {
        number: 10,
        label: "e8",
        check: eq10,
    },
    Equation {
        number: 11,
        label: "e9",
        check: eq11,
    },
    Equation {
        number: 12,
        label: "e10",
        check: eq12,
    },
    Equation {
        number: 13,
        label: "e11",
        check: eq13,
    },
    Equation {
        number: 14,
        label: "e10a",
        check: eq14,
    },
    Equation {
        number: 15,
        label: "e10b",
        check: eq15,
    },
    Equation {
        number: 16,
        label: "e11a",
        check: eq16,
    },
    Equation {
        number: 17,
        label: "e11b",
        check: eq17,
    },
    Equation {
        number: 18,
        label: "e12",
        check: eq18,
    },
    Equation {
        number: 19,
        label: "e13",
        check: eq19,
    },
    Equation {
        number: 20,
        label: "e14",
        check: eq20,
    },
    Equation {
        number: 21,
        label: "e15",
        check: eq21,
    },
    Equation {
        number: 22,
        label: "e17",
        check: eq22,
    },
];

// ------------------------------------------------------------------------------------------
// Small vector algebra, generic over dual numbers
// ------------------------------------------------------------------------------------------

type V<T> = [T; 3];
/// Row-major: `m[i][j]`.
type M<T> = [[T; 3]; 3];
/// Second-order time derivatives: an outer dual over an inner one.
type D2 = Dual<Dual64, f64>;

/// A scalar that dual numbers of any order can stand for.
trait S: DualNum<f64> + Copy {}
impl<T: DualNum<f64> + Copy> S for T {}

fn c<T: S>(x: f64) -> T {
    T::from(x)
}

fn dot<T: S>(a: &V<T>, b: &V<T>) -> T {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross<T: S>(a: &V<T>, b: &V<T>) -> V<T> {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn add<T: S>(a: &V<T>, b: &V<T>) -> V<T> {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn sub<T: S>(a: &V<T>, b: &V<T>) -> V<T> {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn scale<T: S>(s: T, v: &V<T>) -> V<T> {
    [v[0] * s, v[1] * s, v[2] * s]
}

fn norm<T: S>(v: &V<T>) -> T {
    dot(v, v).sqrt()
}

fn mat_vec<T: S>(m: &M<T>, v: &V<T>) -> V<T> {
    std::array::from_fn(|i| m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2])
}

fn mat_t_vec<T: S>(m: &M<T>, v: &V<T>) -> V<T> {
    std::array::from_fn(|j| m[0][j] * v[0] + m[1][j] * v[1] + m[2][j] * v[2])
}

fn column<T: S>(m: &M<T>, j: usize) -> V<T> {
    [m[0][j], m[1][j], m[2][j]]
}

fn up<T: S>() -> V<T> {
    [c(0.0), c(0.0), c(1.0)]
}

/// The axial vector of the antisymmetric part of $\dot A A^T$: the angular velocity of a frame
/// whose columns are $A$, from the values `a` and rates `a_dot` of its entries.
fn axial<T: S>(a: &M<T>, a_dot: &M<T>) -> V<T> {
    let w =
        |i: usize, k: usize| -> T { (0..3).fold(c::<T>(0.0), |s, j| s + a_dot[i][j] * a[k][j]) };
    [
        (w(2, 1) - w(1, 2)) * 0.5,
        (w(0, 2) - w(2, 0)) * 0.5,
        (w(1, 0) - w(0, 1)) * 0.5,
    ]
}

fn re<T: S>(v: &V<Dual<T, f64>>) -> V<T> {
    std::array::from_fn(|i| v[i].re)
}

fn eps<T: S>(v: &V<Dual<T, f64>>) -> V<T> {
    std::array::from_fn(|i| v[i].eps)
}

fn norm_f(v: &V<f64>) -> f64 {
    norm(v)
}

// ------------------------------------------------------------------------------------------
// The disk's motion and its geometry
// ------------------------------------------------------------------------------------------

/// A cubic in time.
#[derive(Debug, Clone, Copy)]
struct Cubic([f64; 4]);

impl Cubic {
    /// Value `x0`, rate `v` and random second and third coefficients of size `curl * v`.
    fn random(rng: &mut Rng, x0: f64, v: f64, curl: f64) -> Self {
        Self([
            x0,
            v,
            rng.uniform(-curl, curl) * v.abs().max(1.0),
            rng.uniform(-curl, curl) * v.abs().max(1.0),
        ])
    }

    fn linear(x0: f64, v: f64) -> Self {
        Self([x0, v, 0.0, 0.0])
    }

    fn at<T: S>(&self, t: T) -> T {
        let [c0, c1, c2, c3] = self.0;
        ((t * c3 + c2) * t + c1) * t + c0
    }
}

/// Lab Euler angles $z$-$x$-$z$ as functions of time.
#[derive(Debug, Clone, Copy)]
struct History {
    heading: Cubic,
    nutation: Cubic,
    face: Cubic,
}

impl History {
    /// A random smooth motion: nutation in `(0.25, pi - 0.25)` at `t = 0` (the triad needs
    /// $\sin\alpha \ne 0$; it is sampled within 4 ms of `t = 0`, where it stays above 0.15),
    /// rates of size `rate`.
    fn random(rng: &mut Rng, rate: f64) -> Self {
        let mut angle = |lo: f64, hi: f64| {
            let x0 = rng.uniform(lo, hi);
            let v = rng.uniform(-rate, rate);
            Cubic::random(rng, x0, v, 0.5)
        };
        Self {
            heading: angle(-3.0, 3.0),
            nutation: angle(0.25, 2.89),
            face: angle(-3.0, 3.0),
        }
    }
}

/// $R = R_z(\psi) R_x(\theta) R_z(\phi)$.
fn euler<T: S>(psi: T, theta: T, phi: T) -> M<T> {
    let (sp, cp) = psi.sin_cos();
    let (st, ct) = theta.sin_cos();
    let (sf, cf) = phi.sin_cos();
    [
        [cp * cf - sp * ct * sf, -cp * sf - sp * ct * cf, sp * st],
        [sp * cf + cp * ct * sf, -sp * sf + cp * ct * cf, -cp * st],
        [st * sf, st * cf, ct],
    ]
}

/// The triad constructed from the orientation: $(\hat{\mathbf 1}, \hat{\mathbf 2},
/// \hat{\mathbf 3}, \hat{\mathbf r})$.
fn triad<T: S>(rot: &M<T>) -> [V<T>; 4] {
    let one = scale(c(-1.0), &column(rot, 2));
    let z = up::<T>();
    let down_in_plane = add(&scale(c(-1.0), &z), &scale(dot(&z, &one), &one));
    let three = scale(norm(&down_in_plane).recip(), &down_in_plane);
    let two = cross(&three, &one);
    let r_hat = cross(&two, &z);
    [one, two, three, r_hat]
}

/// The kinematics at one instant, each quantity of scalar `T` (`f64`, or `Dual64` to carry one
/// more time derivative).
#[derive(Debug, Clone, Copy)]
struct Kin<T> {
    /// $\alpha$ and $\dot\alpha$ (the nutation and its rate).
    alpha: T,
    alpha_dot: T,
    /// $\Omega$: rate of the heading of $\hat{\mathbf 2}$.
    precession: T,
    /// Rate of the angle of a mark on the face, measured in the triad from $\hat{\mathbf 2}$
    /// towards $\hat{\mathbf 3}$ (positive about $\hat{\mathbf 1}$).
    omega_rel: T,
    rot: M<T>,
    rot_dot: M<T>,
    /// $\hat{\mathbf 1}, \hat{\mathbf 2}, \hat{\mathbf 3}, \hat{\mathbf r}$ and their rates.
    axes: [V<T>; 4],
    rates: [V<T>; 4],
    /// The disk's angular velocity (axial vector of $\dot R R^T$).
    omega: V<T>,
    /// The triad's angular velocity (axial vector of $\dot T T^T$).
    omega_123: V<T>,
    /// $\dot C / a = R\,\dot{\mathbf u}$: the velocity of the contact point of a disk rolling
    /// without slipping, per unit radius.
    contact_rate: V<T>,
}

fn kin<T: S>(h: &History, t: Dual<T, f64>) -> Kin<T> {
    let (psi, theta, phi) = (h.heading.at(t), h.nutation.at(t), h.face.at(t));
    let rot = euler(psi, theta, phi);
    let axes = triad(&rot);
    let [_, two, three, _] = axes;
    let heading = two[1].atan2(two[0]);
    let mark = column(&rot, 0);
    let face = dot(&mark, &three).atan2(dot(&mark, &two));
    let rot_re: M<T> = std::array::from_fn(|i| std::array::from_fn(|j| rot[i][j].re));
    let rot_dot: M<T> = std::array::from_fn(|i| std::array::from_fn(|j| rot[i][j].eps));
    let frame: M<T> = std::array::from_fn(|i| std::array::from_fn(|j| axes[j][i].re));
    let frame_dot: M<T> = std::array::from_fn(|i| std::array::from_fn(|j| axes[j][i].eps));
    let u = mat_t_vec(&rot, &three);
    Kin {
        alpha: theta.re,
        alpha_dot: theta.eps,
        precession: heading.eps,
        omega_rel: face.eps,
        rot: rot_re,
        rot_dot,
        axes: std::array::from_fn(|i| re(&axes[i])),
        rates: std::array::from_fn(|i| eps(&axes[i])),
        omega: axial(&rot_re, &rot_dot),
        omega_123: axial(&frame, &frame_dot),
        contact_rate: mat_vec(&rot_re, &eps(&u)),
    }
}

/// The kinematics with first derivatives.
fn kin1(h: &History, t: f64) -> Kin<f64> {
    kin(h, Dual64::new(t, 1.0))
}

/// The kinematics with second derivatives (every field carries its own rate in `.eps`).
fn kin2(h: &History, t: f64) -> Kin<Dual64> {
    kin(h, D2::new(Dual64::new(t, 1.0), Dual64::new(1.0, 0.0)))
}

/// Random points of random motions: `n` pairs (history, time).
fn sample(seed: u64, n: usize, rate: f64) -> Vec<(History, f64)> {
    let mut rng = Rng::new(seed);
    (0..n)
        .map(|_| {
            let h = History::random(&mut rng, rate);
            (h, rng.uniform(-0.004, 0.004))
        })
        .collect()
}

/// A characteristic angular rate at a point (for relative errors of rates and velocities).
fn rate_scale(k: &Kin<f64>) -> f64 {
    k.precession.abs() + k.alpha_dot.abs() + norm_f(&k.omega)
}

fn at(k: &Kin<f64>, what: &str) -> String {
    format!(
        "{what} at alpha = {:.4}, alpha_dot = {:.4}, Omega = {:.4}, omega_1 = {:.4} (rad, rad/s)",
        k.alpha,
        k.alpha_dot,
        k.precession,
        dot(&k.omega, &k.axes[0])
    )
}

const POINTS: usize = 200;
/// Rates of the random motions (rad/s): a spinning coin's.
const RATE: f64 = 20.0;
const ONE: usize = 0;
const TWO: usize = 1;
const THREE: usize = 2;
const R_HAT: usize = 3;

fn identity(compared: &str, w: Worst, definition: bool) -> Finding {
    Finding::from_worst(
        Method::Identity,
        compared,
        w,
        Tolerance::roundoff(),
        definition,
    )
}

// ------------------------------------------------------------------------------------------
// Eqs 1-11: the triad and the angular velocities
// ------------------------------------------------------------------------------------------

/// The offset of the rim's lowest point from the centre, found in BODY coordinates (the rim
/// point $aR(\cos\vartheta, \sin\vartheta, 0)$ whose height is least): the reference for
/// $\mathbf a$.
fn lowest_rim_point(k: &Kin<f64>) -> V<f64> {
    let angle = (-k.rot[2][1]).atan2(-k.rot[2][0]);
    scale(A, &mat_vec(&k.rot, &[angle.cos(), angle.sin(), 0.0]))
}

fn v3(v: &V<f64>) -> Vector3<f64> {
    Vector3::new(v[0], v[1], v[2])
}

/// Every kinematic quantity of the paper's sec. 3, MEASURED on the constructed motion (see the
/// module's documentation), bound to the quantities of paper/symbols.yaml. The disk is rolled
/// along its rim, so the contact point is at rest and $\mathbf v_{cm}$ comes from the rim's
/// geometry, never from $\vec\omega\times\mathbf a$.
fn kin_bindings(k: &Kin<f64>) -> Bindings<f64> {
    let v_cm = v_cm_rolling(k);
    Bindings::new()
        .scalar("alpha", k.alpha)
        .scalar("alpha_dot", k.alpha_dot)
        .scalar("Omega", k.precession)
        .scalar("omega_rel", k.omega_rel)
        .scalar("omega_1", dot(&k.omega, &k.axes[ONE]))
        .scalar("a", A)
        .vector("e1", v3(&k.axes[ONE]))
        .vector("e2", v3(&k.axes[TWO]))
        .vector("e3", v3(&k.axes[THREE]))
        .vector("r_hat", v3(&k.axes[R_HAT]))
        .vector("z_hat", Vector3::z())
        .vector("e1_rate", v3(&k.rates[ONE]))
        .vector("e2_rate", v3(&k.rates[TWO]))
        .vector("e3_rate", v3(&k.rates[THREE]))
        .vector("r_hat_rate", v3(&k.rates[R_HAT]))
        .vector("omega_vec", v3(&k.omega))
        .vector("omega_123", v3(&k.omega_123))
        .vector("a_vec", v3(&lowest_rim_point(k)))
        .vector("v_cm", v3(&v_cm))
        .vector("v_contact", Vector3::zeros())
}

/// Eqs 1-13 share this: every printed relation of eq `n` at random points of random motions,
/// differences relative to `scale(k)`.
fn printed_kinematics(
    b: &Bench,
    n: u32,
    seed: u64,
    scale: impl Fn(&Kin<f64>) -> f64,
    what: &str,
) -> Worst {
    let mut w = Worst::default();
    for (h, t) in sample(seed, POINTS, RATE) {
        let k = kin1(&h, t);
        printed_relations(b, n, &kin_bindings(&k), scale(&k), &mut w, &|| at(&k, what));
    }
    w
}

/// Eq 1, $\mathbf a = a\hat{\mathbf 3}$ (definition): the offset of the contact point from the
/// centre. Reference: the lowest point of the rim, found in body coordinates, against $a$ times
/// the constructed $\hat{\mathbf 3}$.
fn eq1(b: &Bench) -> Finding {
    let w = printed_kinematics(b, 1, 1, |_| A, "a");
    identity(
        "the printed a against the offset of the rim's lowest point (body coordinates)",
        w,
        true,
    )
}

/// Eq 2, $\vec\omega = \vec\omega_{123} + \omega_{rel}\hat{\mathbf 1}$ (definition). Reference:
/// the disk's angular velocity from $\dot R R^T$, the triad's from $\dot T T^T$, and the measured
/// rate of a face mark relative to the triad.
fn eq2(b: &Bench) -> Finding {
    let w = printed_kinematics(b, 2, 2, rate_scale, "omega");
    identity(
        "the printed composition of omega against the axial vector of dR/dt R^T",
        w,
        true,
    )
}

/// Eq 3, $\vec\omega_{123} = \Omega\hat{\mathbf z} + \dot\alpha\hat{\mathbf 2} =
/// -\Omega\cos\alpha\hat{\mathbf 1} + \dot\alpha\hat{\mathbf 2} - \Omega\sin\alpha\hat{\mathbf 3}$.
/// Reference: the triad's angular velocity from $\dot T T^T$; each printed equality in turn.
fn eq3(b: &Bench) -> Finding {
    let w = printed_kinematics(b, 3, 3, rate_scale, "omega_123");
    identity(
        "both printed equalities for omega_123 against the axial vector of dT/dt T^T",
        w,
        false,
    )
}

/// Eq 4, $\hat{\mathbf z} = -\cos\alpha\hat{\mathbf 1} - \sin\alpha\hat{\mathbf 3}$. Reference:
/// the lab's vertical; $\alpha$ is the disk plane's tilt (the nutation angle).
fn eq4(b: &Bench) -> Finding {
    let w = printed_kinematics(b, 4, 4, |_| 1.0, "z");
    identity("the printed z against the lab's vertical", w, false)
}

/// Eq 5, $d\hat{\mathbf 1}/dt = \vec\omega_{123}\times\hat{\mathbf 1} = -\Omega\sin\alpha
/// \hat{\mathbf 2} - \dot\alpha\hat{\mathbf 3}$. Reference: the exact derivative of the
/// constructed axis and the measured $\vec\omega_{123}$.
fn eq5(b: &Bench) -> Finding {
    let w = printed_kinematics(b, 5, 5, rate_scale, "the axis' rate");
    identity(
        "d1/dt, both printed equalities, against the exact derivative",
        w,
        false,
    )
}

/// Eq 6, $d\hat{\mathbf 2}/dt = \vec\omega_{123}\times\hat{\mathbf 2} = \Omega\sin\alpha
/// \hat{\mathbf 1} - \Omega\cos\alpha\hat{\mathbf 3} = -\Omega\hat{\mathbf r}$ (the printed stray
/// comma dropped). Reference: the exact derivative of the constructed axis.
fn eq6(b: &Bench) -> Finding {
    let w = printed_kinematics(b, 6, 6, rate_scale, "the axis' rate");
    identity(
        "d2/dt, all three printed equalities, against the exact derivative",
        w,
        false,
    )
}

/// Eq 7, $d\hat{\mathbf 3}/dt = \vec\omega_{123}\times\hat{\mathbf 3} = \dot\alpha\hat{\mathbf 1}
/// + \Omega\cos\alpha\hat{\mathbf 2}$. Reference: the exact derivative of the constructed axis.
fn eq7(b: &Bench) -> Finding {
    let w = printed_kinematics(b, 7, 7, rate_scale, "the axis' rate");
    identity(
        "d3/dt, both printed equalities, against the exact derivative",
        w,
        false,
    )
}

/// Eq 8, $\hat{\mathbf r} = \hat{\mathbf 2}\times\hat{\mathbf z} = -\sin\alpha\hat{\mathbf 1} +
/// \cos\alpha\hat{\mathbf 3}$ (definition). Reference: where the disk leans with axis 1 below the
/// horizontal ($\cos\alpha > 0.1$), $\hat{\mathbf r}$ is bound to the horizontal direction of
/// $\hat{\mathbf 3}$ (figure 1's $\hat{\mathbf r}$ points from the centre's vertical towards the
/// contact point); elsewhere to the constructed $\hat{\mathbf 2}\times\hat{\mathbf z}$.
fn eq8(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for (h, t) in sample(8, POINTS, RATE) {
        let k = kin1(&h, t);
        let mut bind = kin_bindings(&k);
        let t3 = k.axes[THREE];
        let horizontal = [t3[0], t3[1], 0.0];
        if k.alpha.cos() > 0.1 {
            let dir = scale(1.0 / norm_f(&horizontal), &horizontal);
            bind.set("r_hat", Value::Vector(v3(&dir)));
        }
        printed_relations(b, 8, &bind, 1.0, &mut w, &|| at(&k, "r-hat"));
    }
    identity(
        "the printed r-hat against 3's horizontal direction and 2 x z",
        w,
        true,
    )
}

/// Eq 9, $d\hat{\mathbf r}/dt = \Omega\hat{\mathbf 2}$. Reference: the exact derivative of the
/// constructed $\hat{\mathbf r}$.
fn eq9(b: &Bench) -> Finding {
    let w = printed_kinematics(b, 9, 9, rate_scale, "r-hat's rate");
    identity(
        "the printed rate of r-hat against its exact derivative",
        w,
        false,
    )
}

/// Eq 10, $\vec\omega = \omega_1\hat{\mathbf 1} + \dot\alpha\hat{\mathbf 2} -
/// \Omega\sin\alpha\hat{\mathbf 3}$, with $\omega_1 = \vec\omega\cdot\hat{\mathbf 1}$. Reference:
/// the axial vector of $\dot R R^T$ (the 2 and 3 components are the content).
fn eq10(b: &Bench) -> Finding {
    let w = printed_kinematics(b, 10, 10, rate_scale, "omega");
    identity(
        "the printed triad form of omega against dR/dt R^T",
        w,
        false,
    )
}

/// Eq 11, $\omega_1 = \omega_{rel} - \Omega\cos\alpha$ (definition). Reference: $\vec\omega\cdot
/// \hat{\mathbf 1}$ from $\dot R R^T$, the measured rate of a face mark relative to the triad and
/// the measured precession.
fn eq11(b: &Bench) -> Finding {
    let w = printed_kinematics(b, 11, 11, rate_scale, "omega_1");
    identity(
        "the printed omega_1 against omega . 1 from dR/dt R^T",
        w,
        true,
    )
}

// ------------------------------------------------------------------------------------------
// Eqs 12-17: rolling without slipping
// ------------------------------------------------------------------------------------------

/// Disk radius of the toy (m); rolling checks use it so that velocities have their real size.
const A: f64 = 0.0375;

/// The centre of mass's velocity of a disk rolling without slipping: $\dot C - a\dot{\hat{\mathbf
/// 3}}$, the contact point advancing on the table as it advances along the rim.
fn v_cm_rolling(k: &Kin<f64>) -> V<f64> {
    sub(&scale(A, &k.contact_rate), &scale(A, &k.rates[THREE]))
}

/// Eq 12, $\mathbf v_{contact} = \mathbf v_{cm} + \vec\omega\times\mathbf a = 0$. Reference: a disk
/// rolling without slipping built from the rim's geometry (no cross product): its contact point
/// is at rest and its $\mathbf v_{cm}$ measured.
fn eq12(b: &Bench) -> Finding {
    let w = printed_kinematics(b, 12, 12, |k| A * rate_scale(k), "v_contact");
    identity(
        "the printed contact velocity against a disk rolled along its rim",
        w,
        false,
    )
}

/// Eq 13, $\mathbf v_{cm} = d\mathbf r_{cm}/dt = a\hat{\mathbf 3}\times\vec\omega =
/// -a\dot\alpha\hat{\mathbf 1} + a\omega_1\hat{\mathbf 2}$. Reference: the velocity of the centre
/// of a disk rolled along its rim; every printed equality.
fn eq13(b: &Bench) -> Finding {
    let w = printed_kinematics(b, 13, 13, |k| A * rate_scale(k), "v_cm");
    identity(
        "the printed forms of v_cm against a disk rolled along its rim",
        w,
        false,
    )
}

/// The centre of curvature of the contact point's path, from its velocity and acceleration
/// (relative to the contact point): $(\hat{\mathbf z}\times\dot C)\,|\dot C|^2/((\dot C\times
/// \ddot C)\cdot\hat{\mathbf z})$.
fn curvature_centre(v: &V<f64>, acc: &V<f64>) -> V<f64> {
    let turn = cross(v, acc)[2];
    scale(dot(v, v) / turn, &cross(&up(), v))
}

/// Eq 14, $\mathbf r_{cm} = x_A\hat{\mathbf x} + y_A\hat{\mathbf y} + r\hat{\mathbf r} -
/// a\hat{\mathbf 3}$ (definition). Reference: a disk rolled along its rim; $(x_A, y_A)$ is the
/// centre of curvature of the contact point's path (measured from its exact velocity and
/// acceleration) and $r = (C - A)\cdot\hat{\mathbf r}$ (signed: in a general motion the contact
/// path may curve away from the lean, and then $r < 0$, although the paper writes $r \ge 0$; the
/// count is in `at`). The content: the contact point moves along $\hat{\mathbf 2}$, so its circle's
/// centre lies on $\hat{\mathbf r}$'s line through it.
fn eq14(b: &Bench) -> Finding {
    let mut w = Worst::default();
    let mut negative = 0;
    let points = sample(14, POINTS, RATE);
    for (h, t) in &points {
        let k2 = kin2(h, *t);
        let v: V<f64> = std::array::from_fn(|i| A * k2.contact_rate[i].re);
        let acc: V<f64> = std::array::from_fn(|i| A * k2.contact_rate[i].eps);
        let k = kin1(h, *t);
        let contact = [0.0; 3];
        let centre = add(&contact, &curvature_centre(&v, &acc));
        let r = dot(&sub(&contact, &centre), &k.axes[R_HAT]);
        if r < 0.0 {
            negative += 1;
        }
        let r_cm = sub(&contact, &scale(A, &k.axes[THREE]));
        let bind = kin_bindings(&k)
            .vector("r_cm", v3(&r_cm))
            .scalar("x_A", centre[0])
            .scalar("y_A", centre[1])
            .scalar("r", r)
            .vector("x_hat", Vector3::x())
            .vector("y_hat", Vector3::y());
        printed_relations(b, 14, &bind, A + r.abs(), &mut w, &|| {
            at(&k, &format!("r_cm (r = {r:.4e} m)"))
        });
    }
    w.at = format!("{}; r < 0 at {negative} of {} points", w.at, points.len());
    identity(
        "x_A x + y_A y + r r-hat - a 3 against a rolled disk's centre, A the contact path's centre of curvature",
        w,
        true,
    )
}

/// Eq 15, $d\mathbf r_{cm}/dt = \dot x_A\hat{\mathbf x} + \dot y_A\hat{\mathbf y} + \dot r\hat{\mathbf
/// r} - a\dot\alpha\hat{\mathbf 1} + (r - a\cos\alpha)\Omega\hat{\mathbf 2}$: the derivative of
/// eq 14 for any smooth $x_A(t), y_A(t), r(t)$ (random cubics here). Reference: eq 14's vector
/// differentiated exactly (the triad's rates by dual numbers).
fn eq15(b: &Bench) -> Finding {
    let mut w = Worst::default();
    let mut rng = Rng::new(15);
    for (h, t) in sample(15, POINTS, RATE) {
        let k = kin1(&h, t);
        let v_scale = A * RATE;
        let mut cubic = |x0: f64| {
            let v = rng.uniform(-v_scale, v_scale);
            Cubic::random(&mut rng, x0, v, 0.5)
        };
        let (xa, ya) = (cubic(0.1), cubic(-0.2));
        let r0 = rng.uniform(-0.1, 0.1);
        let rr = {
            let v = rng.uniform(-v_scale, v_scale);
            Cubic::random(&mut rng, r0, v, 0.5)
        };
        let d = |p: &Cubic| {
            let x = p.at(Dual64::new(t, 1.0));
            (x.re, x.eps)
        };
        let ((_, xa_dot), (_, ya_dot), (r, r_dot)) = (d(&xa), d(&ya), d(&rr));
        let reference = add(
            &add(&[xa_dot, ya_dot, 0.0], &scale(r_dot, &k.axes[R_HAT])),
            &sub(&scale(r, &k.rates[R_HAT]), &scale(A, &k.rates[THREE])),
        );
        let sc = norm_f(&reference) + (A + r.abs()) * rate_scale(&k);
        let bind = kin_bindings(&k)
            .vector("v_cm", v3(&reference))
            .scalar("x_A_dot", xa_dot)
            .scalar("y_A_dot", ya_dot)
            .scalar("r", r)
            .scalar("r_dot", r_dot)
            .vector("x_hat", Vector3::x())
            .vector("y_hat", Vector3::y());
        printed_relations(b, 15, &bind, sc, &mut w, &|| at(&k, "dr_cm/dt"));
    }
    identity(
        "the printed derivative against eq 14 differentiated exactly",
        w,
        false,
    )
}

/// A steady rolling motion: constant tilt, precession and relative spin; measured: the
/// contact point's circle (centre A, signed radius r along r-hat), the centre of mass's signed
/// horizontal distance b from the circle's axis, omega_1 and Omega.
struct Steady {
    alpha: f64,
    precession: f64,
    spin: f64,
    r: f64,
    b: f64,
}

fn steady(alpha: f64, precession: f64, omega_rel: f64) -> Steady {
    // omega_rel about 1 = -n is -phi_dot.
    let h = History {
        heading: Cubic::linear(0.4, precession),
        nutation: Cubic::linear(alpha, 0.0),
        face: Cubic::linear(-0.7, -omega_rel),
    };
    let k2 = kin2(&h, 0.3);
    let k = kin1(&h, 0.3);
    let v: V<f64> = std::array::from_fn(|i| A * k2.contact_rate[i].re);
    let acc: V<f64> = std::array::from_fn(|i| A * k2.contact_rate[i].eps);
    let contact = [0.0; 3];
    let centre = add(&contact, &curvature_centre(&v, &acc));
    let r_cm = sub(&contact, &scale(A, &k.axes[THREE]));
    Steady {
        alpha,
        precession: k.precession,
        spin: dot(&k.omega, &k.axes[ONE]),
        r: dot(&sub(&contact, &centre), &k.axes[R_HAT]),
        b: dot(&sub(&r_cm, &centre), &k.axes[R_HAT]),
    }
}

/// The steady motions swept: tilts from 0.1 to 2.8 rad (past the vertical too), both senses of
/// precession, and relative spins chosen so that $b/a \in \{-0.3, 0, 0.5, 2\}$ (through eq 11;
/// only to place the points, the b used is measured). Half of these have $\omega_1 < 0$, against
/// the paper's sign convention for axis 1: the relations are kinematic and hold either way.
fn steady_sweep() -> Vec<Steady> {
    let mut out = Vec::new();
    for alpha in [0.1, 0.4, 0.8, 1.2, 1.5, 2.0, 2.8] {
        for precession in [7.0, -4.0] {
            for beta in [-0.3, 0.0, 0.5, 2.0] {
                out.push(steady(
                    alpha,
                    precession,
                    precession * (f64::cos(alpha) + beta),
                ));
            }
        }
    }
    out
}

fn steady_at(s: &Steady) -> String {
    format!(
        "alpha = {:.3}, Omega = {:+.3}, b = {:+.4e} m, r = {:.4e} m",
        s.alpha, s.precession, s.b, s.r
    )
}

/// Eq 16, $\omega_1 = b\Omega/a$ in steady motion. Reference: a steady motion rolled along the
/// rim (constant tilt, precession and relative spin); $b$ measured as the centre of mass's signed
/// horizontal distance from the axis of the contact point's circle (its centre of curvature),
/// $\omega_1 = \vec\omega\cdot\hat{\mathbf 1}$ from $\dot R R^T$.
fn eq16(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for s in steady_sweep() {
        let bind = Bindings::new()
            .scalar("omega_1", s.spin)
            .scalar("b", s.b)
            .scalar("a", A)
            .scalar("Omega", s.precession);
        printed_relations(
            b,
            16,
            &bind,
            s.precession.abs() + s.spin.abs(),
            &mut w,
            &|| steady_at(&s),
        );
    }
    identity(
        "b Omega / a against omega . 1 on steady rolling, b measured on the circle",
        w,
        false,
    )
}

/// Eq 17, $b = r - a\cos\alpha$ (definition). Reference: on steady rolling motions, $b$ and $r$
/// measured on the circles (see eq 16).
fn eq17(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for s in steady_sweep() {
        let bind = Bindings::new()
            .scalar("b", s.b)
            .scalar("r", s.r)
            .scalar("a", A)
            .scalar("alpha", s.alpha);
        printed_relations(b, 17, &bind, A + s.b.abs(), &mut w, &|| steady_at(&s));
    }
    identity(
        "r - a cos(alpha) against the measured b on steady rolling",
        w,
        true,
    )
}

// ------------------------------------------------------------------------------------------
// Eqs 18-22: inertia and the dynamics
// ------------------------------------------------------------------------------------------

/// A thin body as point masses in its body frame (plane z = 0, symmetry axis z), with the
/// inertia factor the paper states (uniform 1/4, ring 1/2) or derived here by hand
/// (annulus: $I_{22} = m(a^2 + c^2)/4$; a ring of radius $\rho$: $k = \rho^2 / 2a^2$).
struct Body {
    name: &'static str,
    k: f64,
    points: Vec<(V<f64>, f64)>,
}

const MASS: f64 = 0.4;
const G: f64 = 9.81;

/// Point masses of a thin annulus between radii `inner` and `outer` (3-point Gauss-Legendre in
/// the radius with weight r, exact to degree 5; 12 equal angles, exact for the quadratic
/// moments), or a ring when they are equal. Total mass `MASS`.
fn plate(inner: f64, outer: f64) -> Vec<(V<f64>, f64)> {
    let gl = [
        (-(0.6f64).sqrt(), 5.0 / 9.0),
        (0.0, 8.0 / 9.0),
        ((0.6f64).sqrt(), 5.0 / 9.0),
    ];
    let radial: Vec<(f64, f64)> = if inner == outer {
        vec![(outer, 1.0)]
    } else {
        gl.iter()
            .map(|&(x, wt)| {
                let r = 0.5 * (outer + inner) + 0.5 * (outer - inner) * x;
                (r, wt * r)
            })
            .collect()
    };
    let n = 12;
    let total: f64 = radial.iter().map(|p| p.1).sum::<f64>() * n as f64;
    let mut out = Vec::new();
    for &(r, wt) in &radial {
        for j in 0..n {
            let th = 0.3 + 2.0 * std::f64::consts::PI * j as f64 / n as f64;
            out.push(([r * th.cos(), r * th.sin(), 0.0], MASS * wt / total));
        }
    }
    out
}

fn bodies() -> Vec<Body> {
    vec![
        Body {
            name: "uniform disk (k = 1/4)",
            k: 0.25,
            points: plate(0.0, A),
        },
        Body {
            name: "ring (k = 1/2)",
            k: 0.5,
            points: plate(A, A),
        },
        Body {
            name: "annulus c = a/2 (k = 5/16)",
            k: 5.0 / 16.0,
            points: plate(0.5 * A, A),
        },
        Body {
            name: "ring at radius a sqrt(0.2) (k = 0.1)",
            k: 0.1,
            points: plate(A * 0.2f64.sqrt(), A * 0.2f64.sqrt()),
        },
    ]
}

/// The inertia tensor about the centre in body axes, summed over the point masses.
fn inertia(points: &[(V<f64>, f64)]) -> M<f64> {
    let mut i = [[0.0; 3]; 3];
    for (p, m) in points {
        let r2 = dot(p, p);
        for a in 0..3 {
            for b in 0..3 {
                i[a][b] += m * (if a == b { r2 } else { 0.0 } - p[a] * p[b]);
            }
        }
    }
    i
}

/// Eq 18, $I_{11} = 2kma^2$, $I_{22} = kma^2 = I_{33}$ (definition). Reference: the inertia
/// tensor summed over point masses of a uniform disk, a ring, an annulus and a smaller ring;
/// $k$ as the paper states it (1/4, 1/2) or derived by hand; off-diagonal entries must vanish.
fn eq18(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for body in bodies() {
        let i = inertia(&body.points);
        let unit = body.k * MASS * A * A;
        // Body axes: symmetry axis z is 1-hat; x and y are diameters.
        let bind = Bindings::new()
            .scalar("I_11", i[2][2])
            .scalar("I_22", i[0][0])
            .scalar("I_33", i[1][1])
            .scalar("k", body.k)
            .scalar("m", MASS)
            .scalar("a", A);
        printed_relations(b, 18, &bind, unit, &mut w, &|| {
            format!("the principal moments of the {}", body.name)
        });
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            w.add(0.0, i[p][q], unit, || {
                format!("off-diagonal I[{p}][{q}] of the {}", body.name)
            });
        }
    }
    identity(
        "the principal moments against quadratures of thin disks and rings",
        w,
        true,
    )
}

/// The inertia tensor in the lab, $R I_{body} R^T$.
fn lab_tensor(rot: &M<f64>, i_body: &M<f64>) -> nalgebra::Matrix3<f64> {
    let r = nalgebra::Matrix3::from_fn(|i, j| rot[i][j]);
    let ib = nalgebra::Matrix3::from_fn(|i, j| i_body[i][j]);
    r * ib * r.transpose()
}

/// The angular momentum about the centre in the lab, $R I_{body} R^T\vec\omega$.
fn l_lab<T: S>(rot: &M<T>, i_body: &M<f64>, omega: &V<T>) -> V<T> {
    let body = mat_t_vec(rot, omega);
    let lb: V<T> =
        std::array::from_fn(|p| (0..3).fold(c::<T>(0.0), |s, q| s + body[q] * i_body[p][q]));
    mat_vec(rot, &lb)
}

/// Eq 19, $\mathbf L_{cm} = \mathbf I\cdot\vec\omega = kma^2(2\omega_1\hat{\mathbf 1} +
/// \dot\alpha\hat{\mathbf 2} - \Omega\sin\alpha\hat{\mathbf 3})$. Reference: $R I_{body} R^T
/// \vec\omega$ in the lab, $I_{body}$ summed over point masses, projected on the triad.
fn eq19(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for (n, body) in bodies().iter().enumerate() {
        let i_body = inertia(&body.points);
        for (h, t) in sample(190 + n as u64, 50, RATE) {
            let k = kin1(&h, t);
            let l = l_lab(&k.rot, &i_body, &k.omega);
            let unit = body.k * MASS * A * A;
            let i_lab = lab_tensor(&k.rot, &i_body);
            let bind = kin_bindings(&k)
                .vector("L_cm", v3(&l))
                .value("I_tensor", Value::Tensor(i_lab))
                .scalar("k", body.k)
                .scalar("m", MASS);
            printed_relations(b, 19, &bind, unit * rate_scale(&k), &mut w, &|| {
                at(&k, &format!("L_cm for the {}", body.name))
            });
        }
    }
    identity(
        "the triad components of L_cm against R I_body R^T omega (I_body by quadrature)",
        w,
        false,
    )
}

/// A random rigid motion of a body of point masses: its centre moving on a random cubic path.
/// Returns, at the sampled instant, the kinematics (with second derivatives), the centre's
/// acceleration and the point masses' lab offsets and accelerations.
struct Particles {
    k: Kin<Dual64>,
    acc_cm: V<f64>,
    offsets: Vec<(V<f64>, V<f64>, f64)>,
}

fn particles(h: &History, t: f64, rng: &mut Rng, body: &Body) -> Particles {
    let k = kin2(h, t);
    let acc_scale = G;
    let path: Vec<Cubic> = (0..3)
        .map(|_| {
            Cubic([
                0.0,
                rng.uniform(-1.0, 1.0),
                rng.uniform(-acc_scale, acc_scale),
                rng.uniform(-acc_scale, acc_scale),
            ])
        })
        .collect();
    let td = D2::new(Dual64::new(t, 1.0), Dual64::new(1.0, 0.0));
    let acc_cm: V<f64> = std::array::from_fn(|i| path[i].at(td).eps.eps);
    let rot: M<f64> = std::array::from_fn(|i| std::array::from_fn(|j| k.rot[i][j].re));
    let rot_dd: M<f64> = std::array::from_fn(|i| std::array::from_fn(|j| k.rot_dot[i][j].eps));
    let offsets = body
        .points
        .iter()
        .map(|(p, m)| (mat_vec(&rot, p), add(&acc_cm, &mat_vec(&rot_dd, p)), *m))
        .collect();
    Particles { k, acc_cm, offsets }
}

/// Eq 20, $m\,d^2\mathbf r_{cm}/dt^2 = \mathbf F - mg\hat{\mathbf z}$. Reference: a body of point
/// masses in a random rigid motion, each obeying Newton's law under gravity, internal forces
/// (which cancel in pairs) and its share of the external force; the external non-gravitational
/// force is then $\mathbf F = \sum_i m_i(\ddot{\mathbf x}_i + g\hat{\mathbf z})$. Claimed:
/// $m\ddot{\mathbf r}_{cm}$ of the body's centre against $\mathbf F - mg\hat{\mathbf z}$.
fn eq20(b: &Bench) -> Finding {
    let mut w = Worst::default();
    let mut rng = Rng::new(20);
    for body in bodies() {
        for (h, t) in sample(200, 25, RATE) {
            let p = particles(&h, t, &mut rng, &body);
            let force: V<f64> = p.offsets.iter().fold([0.0; 3], |s, (_, acc, m)| {
                add(&s, &scale(*m, &add(acc, &scale(G, &up()))))
            });
            let sc = MASS * (G + norm_f(&p.acc_cm));
            let bind = Bindings::new()
                .scalar("m", MASS)
                .scalar("g", G)
                .vector("a_cm", v3(&p.acc_cm))
                .vector("F", v3(&force))
                .vector("z_hat", Vector3::z());
            printed_relations(b, 20, &bind, sc, &mut w, &|| {
                format!("m d2r_cm/dt2 for the {}", body.name)
            });
        }
    }
    identity(
        "m d2r_cm/dt2 against F - m g z summed over the point masses of a rigid body",
        w,
        false,
    )
}

/// Eq 21, $d\mathbf L_{cm}/dt = \mathbf N_{cm} = \mathbf a\times\mathbf F$. Reference: the same
/// point-mass body; the torque about the centre of the external forces is $\sum_i m_i\boldsymbol
/// \rho_i\times\ddot{\mathbf x}_i$ (internal central forces give none; gravity's,
/// $-\sum_i m_i\boldsymbol\rho_i\times g\hat{\mathbf z}$, vanishes about the centre of mass and is
/// kept in the sum). Claimed: the rate of $\mathbf L_{cm} = R I_{body}R^T\vec\omega$, exact by
/// dual numbers. When that torque comes from one force at the contact point, it is
/// $\mathbf a\times\mathbf F$ with $\mathbf a$ the contact point's offset (eq 1): a random motion
/// needs a general force system, so only the first equality is compared here; the second is the
/// torque of a force applied at $\mathbf a$, and eq 22 checks its use (tests/mutation.rs lists
/// the mutants of that relation as not compared here).
fn eq21(b: &Bench) -> Finding {
    let mut w = Worst::default();
    let mut rng = Rng::new(21);
    for body in bodies() {
        let i_body = inertia(&body.points);
        for (h, t) in sample(210, 25, RATE) {
            let p = particles(&h, t, &mut rng, &body);
            let torque = p.offsets.iter().fold([0.0; 3], |s, (rho, acc, m)| {
                add(&s, &scale(*m, &cross(rho, &add(acc, &scale(G, &up())))))
            });
            let gravity = p.offsets.iter().fold([0.0; 3], |s, (rho, _, m)| {
                add(&s, &scale(-*m * G, &cross(rho, &up())))
            });
            let reference = add(&torque, &gravity);
            let l = l_lab(&p.k.rot, &i_body, &p.k.omega);
            let l_dot: V<f64> = std::array::from_fn(|i| l[i].eps);
            let omega: V<f64> = std::array::from_fn(|i| p.k.omega[i].re);
            let omega_dot: V<f64> = std::array::from_fn(|i| p.k.omega[i].eps);
            let rates = norm_f(&omega);
            let sc =
                body.k * MASS * A * A * (rates * rates + norm_f(&omega_dot)) + norm_f(&reference);
            let bind = Bindings::new()
                .vector("L_cm_rate", v3(&l_dot))
                .vector("N_cm", v3(&reference));
            printed_relation(b, 21, 0, &bind, sc, &mut w, &|| {
                format!("dL_cm/dt for the {}", body.name)
            });
        }
    }
    identity(
        "dL_cm/dt of R I R^T omega against the torque summed over point masses",
        w,
        false,
    )
}

/// Eq 22, $\frac{1}{ma}\frac{d\mathbf L_{cm}}{dt} + \frac{d^2\mathbf r_{cm}}{dt^2}\times
/// \hat{\mathbf 3} = g\hat{\mathbf 3}\times\hat{\mathbf z}$: eqs 20 and 21 with the force
/// eliminated. For ANY motion of a rolling disk (built along its rim, second derivatives by
/// nested duals, $\mathbf L_{cm} = R I_{body}R^T\vec\omega$), eq 20 defines the contact force
/// $\mathbf F = m(\ddot{\mathbf r}_{cm} + g\hat{\mathbf z})$ and the residual of eq 21 is
/// $\boldsymbol\rho = \dot{\mathbf L}_{cm} - a\hat{\mathbf 3}\times\mathbf F$; eq 22's residual
/// (its left side minus its right) must equal $\boldsymbol\rho/ma$, so that eq 22 holds exactly
/// when eq 21 does. Claimed: eq 22's left side.
fn eq22(b: &Bench) -> Finding {
    let mut w = Worst::default();
    for body in bodies() {
        let i_body = inertia(&body.points);
        for (h, t) in sample(220, 50, RATE) {
            let k = kin2(&h, t);
            let three: V<f64> = std::array::from_fn(|i| k.axes[THREE][i].re);
            let acc: V<f64> =
                std::array::from_fn(|i| A * k.contact_rate[i].eps - A * k.rates[THREE][i].eps);
            let l = l_lab(&k.rot, &i_body, &k.omega);
            let l_dot: V<f64> = std::array::from_fn(|i| l[i].eps);
            let force = scale(MASS, &add(&acc, &scale(G, &up())));
            let residual21 = sub(&l_dot, &cross(&scale(A, &three), &force));
            let bind = Bindings::new()
                .scalar("m", MASS)
                .scalar("a", A)
                .scalar("g", G)
                .vector("L_cm_rate", v3(&l_dot))
                .vector("a_cm", v3(&acc))
                .vector("e3", v3(&three))
                .vector("z_hat", Vector3::z());
            let eq = b.paper.equation(22);
            let rel = eq.relations()[0];
            let side = |e| {
                eq.eval(e, &bind)
                    .and_then(|v| v.vector())
                    .map_or([f64::NAN; 3], |v| [v.x, v.y, v.z])
            };
            let (lhs, rhs) = (side(rel.lhs), side(rel.rhs));
            let sc = G + norm_f(&lhs);
            for i in 0..3 {
                w.add(
                    b.claim(lhs[i]) - rhs[i],
                    residual21[i] / (MASS * A),
                    sc,
                    || {
                        format!(
                            "component {} of eq 22's residual for the {}, alpha = {:.3}",
                            ["x", "y", "z"][i],
                            body.name,
                            k.alpha.re
                        )
                    },
                );
            }
        }
    }
    Finding::from_worst(
        Method::Derivation,
        "eq 22's residual against eq 21's residual / (m a), F from eq 20, on rolling motions",
        w,
        Tolerance::roundoff(),
        false,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::finding::Verdict;

    fn verdicts(number: u32) -> (Finding, Finding) {
        let e = EQUATIONS.iter().find(|e| e.number == number).unwrap();
        (
            (e.check)(&Bench::default()),
            (e.check)(&Bench::perturbed(1e-3)),
        )
    }

    fn expect(number: u32, verdict: Verdict) {
        let (ok, bad) = verdicts(number);
        eprintln!(
            "eq {number}: {} error {:.2e} at {}; perturbed: {} error {:.2e}",
            ok.verdict, ok.error, ok.at, bad.verdict, bad.error
        );
        assert_eq!(ok.verdict, verdict, "eq {number}: {ok:?}");
        // Equations read from the LaTeX are mutated in their text by tests/mutation.rs (a
        // relative change of a side that is zero, as in eq 12, would change nothing).
        if !crate::equations::FROM_LATEX.contains(&number) {
            assert_eq!(
                bad.verdict,
                Verdict::Fails,
                "eq {number} perturbed: {bad:?}"
            );
        }
    }

    #[test]
    fn definitions_are_consistent_and_perturbations_fail() {
        for n in [1, 2, 8, 11, 14, 17, 18] {
            expect(n, Verdict::Definition);
        }
    }

    #[test]
    fn identities_hold_and_perturbations_fail() {
        for n in [3, 4, 5, 6, 7, 9, 10, 12, 13, 15, 16, 19, 20, 21, 22] {
            expect(n, Verdict::Holds);
        }
    }

    #[test]
    fn the_registry_lists_equations_1_to_22() {
        let numbers: Vec<u32> = EQUATIONS.iter().map(|e| e.number).collect();
        assert_eq!(numbers, (1..=22).collect::<Vec<_>>());
    }

    #[test]
    fn the_constructed_triad_is_right_handed_and_alpha_is_the_tilt() {
        for (h, t) in sample(99, 50, RATE) {
            let k = kin1(&h, t);
            let [one, two, three, r] = k.axes;
            let e = norm_f(&sub(&cross(&one, &two), &three));
            assert!(e < 1e-14, "{e}");
            assert!(two[2].abs() < 1e-14 && r[2].abs() < 1e-14);
            // 3 dips below the horizontal by the plane's tilt.
            assert!((three[2] + k.alpha.sin()).abs() < 1e-14);
        }
    }

    #[test]
    fn steady_sweep_covers_positive_zero_and_negative_b() {
        let s = steady_sweep();
        assert!(s.iter().any(|s| s.b > 1e-3 * A));
        assert!(s.iter().any(|s| s.b < -1e-3 * A));
        assert!(s.iter().any(|s| s.b.abs() < 1e-12));
        // Kinematically r = b + a cos(alpha) takes either sign; r < 0 (b < -a cos(alpha)) is
        // excluded only dynamically, by eq 30's bound, for alpha < pi/2.
        assert!(s.iter().any(|s| s.r < 0.0) && s.iter().any(|s| s.r > 0.0));
    }

    #[test]
    fn checks_are_fast() {
        let start = std::time::Instant::now();
        for e in EQUATIONS {
            (e.check)(&Bench::default());
        }
        let elapsed = start.elapsed().as_secs_f64();
        eprintln!("22 checks in {elapsed:.3} s");
        if !cfg!(debug_assertions) {
            assert!(elapsed < 0.5);
        }
    }
}
