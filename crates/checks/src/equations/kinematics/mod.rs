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

use crate::equations::{row, Row};
use crate::finding::{Finding, Method, Stated, Tolerance, Worst};
use crate::harness::{printed_relation, printed_relations, Bench};
use nalgebra::{Matrix3, Vector3};
use num_dual::{Dual, Dual64, DualNum};
use numerics::rng::Rng;
use paper::{Bindings, Value};

mod axes;
mod mass;
mod rolling;
#[cfg(test)]
mod tests;

use axes::{eq8, identity_check};
use mass::{eq18, eq19, eq20, eq21, eq22};
use rolling::{eq12, eq13, eq14, eq15, eq16, eq17, v_cm_rolling, A};

/// The checks of this part of the paper.
#[rustfmt::skip]
pub const EQUATIONS: &[Row] = &[
    row(1, identity_check::<1>),
    row(2, identity_check::<2>),
    row(3, identity_check::<3>),
    row(4, identity_check::<4>),
    row(5, identity_check::<5>),
    row(6, identity_check::<6>),
    row(7, identity_check::<7>),
    row(8, eq8),
    row(9, identity_check::<9>),
    row(10, identity_check::<10>),
    row(11, identity_check::<11>),
    row(12, eq12),
    row(13, eq13),
    row(14, eq14),
    row(15, eq15),
    row(16, eq16),
    row(17, eq17),
    row(18, eq18),
    row(19, eq19),
    row(20, eq20),
    row(21, eq21),
    row(22, eq22),
];

// ------------------------------------------------------------------------------------------
// Small vector algebra, generic over dual numbers
// ------------------------------------------------------------------------------------------

/// Vectors and matrices of the construction, over dual numbers of any order (nalgebra's
/// arithmetic, cross and dot need only a ring, which nested duals are).
type V<T> = Vector3<T>;
type M<T> = Matrix3<T>;
/// Second-order time derivatives: an outer dual over an inner one.
type D2 = Dual<Dual64, f64>;

/// A scalar that dual numbers of any order can stand for.
trait S: DualNum<f64> + Copy {}
impl<T: DualNum<f64> + Copy> S for T {}

/// The axial vector of the antisymmetric part of $\dot A A^T$: the angular velocity of a frame
/// whose columns are $A$, from the values `a` and rates `a_dot` of its entries.
fn axial<T: S>(a: &M<T>, a_dot: &M<T>) -> V<T> {
    let w = a_dot * a.transpose();
    V::new(
        (w[(2, 1)] - w[(1, 2)]) * 0.5,
        (w[(0, 2)] - w[(2, 0)]) * 0.5,
        (w[(1, 0)] - w[(0, 1)]) * 0.5,
    )
}

fn re<T: S>(v: &V<Dual<T, f64>>) -> V<T> {
    v.map(|x| x.re)
}

fn eps<T: S>(v: &V<Dual<T, f64>>) -> V<T> {
    v.map(|x| x.eps)
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
    M::new(
        cp * cf - sp * ct * sf,
        -cp * sf - sp * ct * cf,
        sp * st,
        sp * cf + cp * ct * sf,
        -sp * sf + cp * ct * cf,
        -cp * st,
        st * sf,
        st * cf,
        ct,
    )
}

/// The triad constructed from the orientation: $(\hat{\mathbf 1}, \hat{\mathbf 2},
/// \hat{\mathbf 3}, \hat{\mathbf r})$.
fn triad<T: S>(rot: &M<T>) -> [V<T>; 4] {
    let one = -rot.column(2).into_owned();
    let z = V::<T>::z();
    let down_in_plane = one * z.dot(&one) - z;
    let three = down_in_plane * down_in_plane.dot(&down_in_plane).sqrt().recip();
    let two = three.cross(&one);
    let r_hat = two.cross(&z);
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
    let mark = rot.column(0).into_owned();
    let face = mark.dot(&three).atan2(mark.dot(&two));
    let rot_re: M<T> = rot.map(|x| x.re);
    let rot_dot: M<T> = rot.map(|x| x.eps);
    let columns = M::from_columns(&axes[..3]);
    let (frame, frame_dot): (M<T>, M<T>) = (columns.map(|x| x.re), columns.map(|x| x.eps));
    let u = rot.tr_mul(&three);
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
        contact_rate: rot_re * eps(&u),
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
    k.precession.abs() + k.alpha_dot.abs() + k.omega.norm()
}

fn at(k: &Kin<f64>, what: &str) -> String {
    format!(
        "{what} at $\\alpha = {:.4}$, $\\dot\\alpha = {:.4}$, $\\Omega = {:.4}$, $\\omega_1 = {:.4}$ (rad, rad/s)",
        k.alpha,
        k.alpha_dot,
        k.precession,
        k.omega.dot(&k.axes[0])
    )
}

const POINTS: usize = 200;
/// Rates of the random motions (rad/s): a spinning coin's.
const RATE: f64 = 20.0;
const ONE: usize = 0;
const TWO: usize = 1;
const THREE: usize = 2;
const R_HAT: usize = 3;

fn identity(compared: &str, w: Worst, stated: Stated) -> Finding {
    Finding::judged(Method::Identity, compared, w, Tolerance::roundoff(), stated)
}

// ------------------------------------------------------------------------------------------
// Eqs 1-11: the triad and the angular velocities
// ------------------------------------------------------------------------------------------

/// The offset of the rim's lowest point from the centre, found in BODY coordinates (the rim
/// point $aR(\cos\vartheta, \sin\vartheta, 0)$ whose height is least): the reference for
/// $\mathbf a$.
fn lowest_rim_point(k: &Kin<f64>) -> V<f64> {
    let angle = (-k.rot[(2, 1)]).atan2(-k.rot[(2, 0)]);
    k.rot * V::new(angle.cos(), angle.sin(), 0.0) * A
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
        .scalar("omega_1", k.omega.dot(&k.axes[ONE]))
        .scalar("a", A)
        .vector("e1", k.axes[ONE])
        .vector("e2", k.axes[TWO])
        .vector("e3", k.axes[THREE])
        .vector("r_hat", k.axes[R_HAT])
        .vector("z_hat", Vector3::z())
        .vector("e1_rate", k.rates[ONE])
        .vector("e2_rate", k.rates[TWO])
        .vector("e3_rate", k.rates[THREE])
        .vector("r_hat_rate", k.rates[R_HAT])
        .vector("omega_vec", k.omega)
        .vector("omega_123", k.omega_123)
        .vector("a_vec", lowest_rim_point(k))
        .vector("v_cm", v_cm)
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
