//! Checks of eqs 59-71: the disk on a frictionless table (sections 8 and 9 of the paper).
//!
//! The reference for the equations of motion (60-62) and for every linearization (64, 66-71) is
//! an independent Lagrangian of the frictionless disk, built here from geometry alone:
//! generalized coordinates $(\alpha, \psi, \phi)$ (tilt, heading of the horizontal diameter,
//! rotation of the disk about its axis), the triad constructed from them, its angular velocity
//! from $\vec\omega_{123} = \frac12\sum_i \hat{\mathbf e}_i\times\dot{\hat{\mathbf e}}_i$, the
//! centre of mass at the height of the disk's lowest rim point above the table, moving only
//! vertically, and
//! $$L = \tfrac12 m\dot h^2 + \tfrac12 k m a^2\left(|\vec\omega|^2 + (\vec\omega\cdot\hat{\mathbf 1})^2\right) - m g h.$$
//! Its Euler-Lagrange equations are evaluated numerically: the mass matrix
//! $\partial^2L/\partial\dot q\partial\dot q$, the mixed matrix $\partial^2L/\partial\dot q\partial q$
//! and the forces $\partial L/\partial q$ by hyper-dual numbers, exact to round-off, and the
//! paper's variables $\dot\alpha$, $\Omega = \vec\omega_{123}\cdot\hat{\mathbf z}$,
//! $\omega_1 = \vec\omega\cdot\hat{\mathbf 1}$ and their rates by dual numbers. Nothing of the
//! paper's eqs 60-62 enters it. The reference is generic over dual numbers, so its Jacobians (for
//! the linearizations) are exact too.

use crate::equations::{row, Row};
use crate::finding::{Finding, Method, Tolerance, Verdict, Worst};
use crate::harness::disk_constants;
use crate::harness::{add_threshold, printed_relations, printed_threshold, term_scale, Bench};
use nalgebra::{Complex, Matrix3, SMatrix, Vector3};
use num_dual::{Dual, Dual64, DualNum, HyperDual};
use numerics::linearize::{eigenvalues, jacobian};
use numerics::oscillation::{angular_frequency, bisect};
use numerics::rng::Rng;
use paper::Bindings;
use physics::disk::Disk;
use physics::model::frictionless::Frictionless;
use physics::model::{Extras, Model, Motion};
use physics::solve::{solve, Dynamics, Ending, Event, Problem, State};
use std::f64::consts::{FRAC_PI_2, PI};

mod motion;
mod oscillation;
mod sleeping;
#[cfg(test)]
mod tests;

use motion::{eq59, eq60, eq61, eq62, eq63};
use oscillation::{eq66, eq67, eq68, eq69, eq70, eq71};
use sleeping::{eq64, eq65};

/// The checks of this part of the paper.
pub const EQUATIONS: &[Row] = &[
    row(59, eq59),
    row(60, eq60),
    row(61, eq61),
    row(62, eq62),
    row(63, eq63),
    row(64, eq64),
    row(65, eq65),
    row(66, eq66),
    row(67, eq67),
    row(68, eq68),
    row(69, eq69),
    row(70, eq70),
    row(71, eq71),
];

/// The inertia factors swept: thin shells to hoops, with the uniform disk (1/4) and hoop (1/2).
const KS: [f64; 4] = [0.1, 0.25, 0.5, 0.9];

// ------------------------------------------------------------------ the Lagrangian reference

/// Vectors of the reference, over dual numbers of any order (nalgebra's arithmetic, cross and
/// dot need only a ring, which nested duals are).
type V3<S> = Vector3<S>;

/// The triad of the disk at tilt `alpha` and heading `psi`, built from its verbal definition:
/// $\hat{\mathbf 2} = (\cos\psi, \sin\psi, 0)$ the horizontal diameter, $\hat{\mathbf 1}$ the
/// symmetry axis at angle $\alpha$ to the vertical, $\hat{\mathbf 3}$ in the disk's plane pointing
/// down (to the lowest rim point). Returns the vectors and their derivatives with respect to
/// alpha (a rotation by psi about z is differentiated as $\hat{\mathbf z}\times$).
fn triad<S: DualNum<f64> + Copy>(alpha: S, psi: S) -> ([V3<S>; 3], [V3<S>; 3]) {
    let (sp, cp) = psi.sin_cos();
    let (sa, ca) = alpha.sin_cos();
    let e1 = V3::new(-(sa * sp), sa * cp, -ca);
    let e2 = V3::new(cp, sp, S::zero());
    let e3 = V3::new(ca * sp, -(ca * cp), -sa);
    let d1 = V3::new(-(ca * sp), ca * cp, sa);
    let d3 = V3::new(-(sa * sp), sa * cp, -ca);
    ([e1, e2, e3], [d1, V3::zeros(), d3])
}

/// Angular velocities of the triad and of the disk, and the triad, at coordinates `q` and rates
/// `qd` (q = alpha, psi, phi).
struct Kinematics<S> {
    e: [V3<S>; 3],
    e1_dot: V3<S>,
    w_triad: V3<S>,
    w_disk: V3<S>,
}

fn kinematics<S: DualNum<f64> + Copy>(q: V3<S>, qd: V3<S>) -> Kinematics<S> {
    let (e, d_alpha) = triad(q[0], q[1]);
    let z = V3::z();
    let dots: [V3<S>; 3] = std::array::from_fn(|i| d_alpha[i] * qd[0] + z.cross(&e[i]) * qd[1]);
    // The axial vector of the frame's rotation: (1/2) sum_i e_i x de_i/dt.
    let w = (0..3).fold(V3::zeros(), |w, i| w + e[i].cross(&dots[i]) * S::from(0.5));
    Kinematics {
        e,
        e1_dot: dots[0],
        w_triad: w,
        w_disk: w + e[0] * qd[2],
    }
}

/// The Lagrangian divided by $m a^2$.
fn lagrangian<S: DualNum<f64> + Copy>(d: &Disk, q: V3<S>, qd: V3<S>) -> S {
    let kin = kinematics(q, qd);
    let nz = kin.e[0][2];
    let nz_dot = kin.e1_dot[2];
    // Lowest rim point: the disk's plane spans u, v with u_z^2 + v_z^2 = 1 - n_z^2, so the
    // centre is a sqrt(1 - n_z^2) above it.
    let h = (S::one() - nz * nz).sqrt(); // h / a
    let h_dot = -(nz * nz_dot) / h;
    let w = kin.w_disk;
    let w1 = w.dot(&kin.e[0]);
    h_dot * h_dot * 0.5 + (w.dot(&w) + w1 * w1) * (0.5 * d.k) - h * d.g_over_a()
}

/// The paper's variables $(\dot\alpha, \Omega, \omega_1)$ at coordinates `q` and rates `qd`.
fn paper_rates<S: DualNum<f64> + Copy>(q: V3<S>, qd: V3<S>) -> V3<S> {
    let kin = kinematics(q, qd);
    V3::new(qd[0], kin.w_triad[2], kin.w_disk.dot(&kin.e[0]))
}

/// The solution of the 3x3 system `m x = r` by Cramer's rule. Written here because nalgebra's
/// LU and inverse need a `ComplexField`, which nested dual numbers are not.
fn solve3<S: DualNum<f64> + Copy>(m: &Matrix3<S>, r: V3<S>) -> V3<S> {
    let det3 = |c0: V3<S>, c1: V3<S>, c2: V3<S>| c0.dot(&c1.cross(&c2));
    let col = |j: usize| -> V3<S> { m.column(j).into_owned() };
    let d = det3(col(0), col(1), col(2));
    V3::new(
        det3(r, col(1), col(2)) / d,
        det3(col(0), r, col(2)) / d,
        det3(col(0), col(1), r) / d,
    )
}

/// The Euler-Lagrange equations solved for $\ddot q$.
fn euler_lagrange<T: DualNum<f64> + Copy>(d: &Disk, q: V3<T>, qd: V3<T>) -> V3<T> {
    type H<T> = HyperDual<T, f64>;
    let lift = |x: V3<T>| x.map(H::<T>::from_re);
    let mut mass = Matrix3::<T>::zeros();
    let mut mixed = Matrix3::<T>::zeros();
    let mut force = V3::<T>::zeros();
    for i in 0..3 {
        for j in 0..3 {
            if j >= i {
                let (qh, mut qdh) = (lift(q), lift(qd));
                qdh[i].eps1 = T::one();
                qdh[j].eps2 = T::one();
                mass[(i, j)] = lagrangian(d, qh, qdh).eps1eps2;
                mass[(j, i)] = mass[(i, j)];
            }
            let (mut qh, mut qdh) = (lift(q), lift(qd));
            qdh[i].eps1 = T::one();
            qh[j].eps2 = T::one();
            let l = lagrangian(d, qh, qdh);
            mixed[(i, j)] = l.eps1eps2;
            force[j] = l.eps2;
        }
    }
    solve3(&mass, force - mixed * qd)
}

/// The coordinate rates $\dot q$ at coordinates `q` that give the paper's variables of `m`: the
/// paper's rates are linear in $\dot q$, the columns of the map its images of unit rates.
fn coordinate_rates<T: DualNum<f64> + Copy>(q: V3<T>, m: &Motion<T>) -> V3<T> {
    let cols: [V3<T>; 3] = std::array::from_fn(|j| {
        let mut u = V3::zeros();
        u[j] = T::one();
        paper_rates(q, u)
    });
    solve3(
        &Matrix3::from_columns(&cols),
        V3::new(m.alpha_dot, m.precession, m.spin),
    )
}

/// The reference accelerations $(\ddot\alpha, \dot\Omega, \dot\omega_1)$ of the frictionless
/// disk from the Lagrangian, at the paper's variables `m` (heading and face angle are cyclic;
/// they are set to arbitrary values).
fn reference_rates<T: DualNum<f64> + Copy>(d: &Disk, m: &Motion<T>) -> V3<T> {
    let q = V3::new(m.alpha, T::from(0.7), T::from(-1.3));
    let qd = coordinate_rates(q, m);
    let qdd = euler_lagrange(d, q, qd);
    // d/dt of the paper's variables along (qd, qdd).
    let qdual = V3::from_fn(|i, _| Dual::<T, f64>::new(q[i], qd[i]));
    let qddual = V3::from_fn(|i, _| Dual::<T, f64>::new(qd[i], qdd[i]));
    paper_rates(qdual, qddual).map(|x| x.eps)
}

/// The Lagrangian reference as a model $(\alpha, \dot\alpha, \Omega, \omega_1)$.
struct Reference {
    disk: Disk,
}

impl Dynamics<4> for Reference {
    fn rhs(&self, y: &State<4>, dy: &mut State<4>) {
        let m = Motion::from_state(y.as_slice(), y[3]);
        let r = reference_rates(&self.disk, &m);
        dy[0] = y[1];
        dy[1] = r[0];
        dy[2] = r[1];
        dy[3] = r[2];
    }
}

/// Jacobian of the reference (states alpha, alpha_dot, Omega at spin `spin`) at `y`.
fn reference_jacobian(d: &Disk, y: [f64; 3], spin: f64) -> SMatrix<f64, 3, 3> {
    jacobian(
        |y: &[Dual64; 3]| {
            let m = Motion::from_state(y, Dual64::from(spin));
            let r = reference_rates(d, &m);
            [y[1], r[0], r[1]]
        },
        &y,
    )
}

/// Steady motion without spin at tilt `alpha0`, derived from the reference: with omega_1 = 0
/// and no tilt rate, alpha_ddot is a quadratic in Omega without linear term (kinetic energy
/// quadratic in the rates, mirror symmetry Omega -> -Omega), so two evaluations give the Omega_0^2
/// at which it vanishes.
fn steady_precession(d: &Disk, alpha0: f64) -> f64 {
    let add = |om: f64| {
        reference_rates(
            d,
            &Motion {
                alpha: alpha0,
                alpha_dot: 0.0,
                precession: om,
                spin: 0.0,
            },
        )[0]
    };
    let (a0, a1) = (add(0.0), add(1.0));
    (-a0 / (a1 - a0)).sqrt()
}

/// Linear small oscillations about steady spinless motion at `alpha0`, from the reference:
/// Omega_0, the Jacobian, the angular frequency varpi and the complex eigenvector ratio
/// delta/epsilon (component Omega over component alpha of the eigenvector of i varpi).
struct Linear {
    omega0: f64,
    jac: SMatrix<f64, 3, 3>,
    varpi: f64,
    ratio: Complex<f64>,
}

fn linear(d: &Disk, alpha0: f64) -> Linear {
    let omega0 = steady_precession(d, alpha0);
    let jac = reference_jacobian(d, [alpha0, 0.0, omega0], 0.0);
    let ev = eigenvalues(&jac);
    let varpi = ev.iter().map(|c| c.im).fold(f64::NEG_INFINITY, f64::max);
    let l = Complex::new(0.0, varpi);
    let j = |r: usize, c: usize| Complex::new(jac[(r, c)], 0.0);
    // Rows 0 and 2 of (J - lambda I) v = 0 with v_alpha = 1.
    let (a11, a12, b1) = (j(0, 1), j(0, 2), l - j(0, 0));
    let (a21, a22, b2) = (j(2, 1), j(2, 2) - l, -j(2, 0));
    let det = a11 * a22 - a12 * a21;
    let ratio = (a11 * b2 - a21 * b1) / det;
    Linear {
        omega0,
        jac,
        varpi,
        ratio,
    }
}

// ------------------------------------------------------------------ checks

/// The paper's variables of the frictionless disk at state `m`, with the rates
/// `[alpha_ddot, Omega_dot, omega_1_dot]`, bound to the quantities of paper/symbols.yaml.
fn state_bindings(d: &Disk, m: &Motion, rates: V3<f64>) -> Bindings<f64> {
    disk_constants(d)
        .scalar("alpha", m.alpha)
        .scalar("alpha_dot", m.alpha_dot)
        .scalar("alpha_ddot", rates[0])
        .scalar("Omega", m.precession)
        .scalar("Omega_dot", rates[1])
        .scalar("omega_1", m.spin)
        .scalar("omega_1_dot", rates[2])
}

/// The largest sum of the magnitudes of the terms of a printed relation of `eq` at `bind`: the
/// round-off scale of its residual (its terms may cancel).
fn relation_scale(eq: &paper::Equation, bind: &Bindings<f64>) -> f64 {
    eq.relations()
        .iter()
        .map(|r| term_scale(eq, r.lhs, bind) + term_scale(eq, r.rhs, bind))
        .fold(0.0, f64::max)
}
