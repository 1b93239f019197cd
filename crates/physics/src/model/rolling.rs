//! Rolling without slipping: the equations of motion 23-25.
//!
//! $$ (2k + 1)\dot\omega_1 + \dot\alpha\Omega\sin\alpha = 0 \qquad (23)$$
//! $$ k\Omega^2\sin\alpha\cos\alpha + (2k+1)\omega_1\Omega\sin\alpha - (k+1)\ddot\alpha = \frac{g}{a}\cos\alpha \qquad (24)$$
//! $$ \dot\Omega\sin\alpha + 2\dot\alpha\Omega\cos\alpha + 2\omega_1\dot\alpha = 0 \qquad (25)$$
//!
//! With an optional torque $\mathbf N$ about the centre of mass (the dissipation of eq 75), the
//! $\hat{\mathbf 1}, \hat{\mathbf 2}, \hat{\mathbf 3}$ components of eq 22 gain $N_1/ma^2$,
//! $N_2/ma^2$ and $N_3/ma^2$ on their right-hand sides (eq 24 written as $(k+1)\ddot\alpha - \dots$,
//! eq 25 multiplied by $-k$).

use crate::disk::Disk;
use crate::model::batch_rows::{gather_columns, write_rows, SharedColumns, MAX_COLUMNS};
use crate::model::dissipation::{Placement, PowerLaw};
use crate::model::mechanism::Mechanism;
use crate::model::{
    leading_state, rows_one_at_a_time, Extras, Layout, Model, Motion, Quantity, RowShared,
};
use crate::solve::{Batch, Dynamics, State, BATCH, LANES};
use num_dual::DualNum;
use numerics::trig::{sin_cos, sin_cos_each, sin_each};

/// Time derivatives of the paper's variables.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rates<T = f64> {
    /// $\ddot\alpha$.
    pub alpha_ddot: T,
    /// $\dot\Omega$.
    pub precession_dot: T,
    /// $\dot\omega_1$.
    pub spin_dot: T,
}

/// Eqs 23-25 (no torque) as a first-order system in the state
/// $(\alpha, \dot\alpha, \Omega, \omega_1)$, generic over dual numbers (the linearizations and
/// Newton's method on steady motions read it).
pub fn field<T: DualNum<f64> + Copy>(disk: &Disk, y: &[T; 4]) -> [T; 4] {
    let m = Motion::from_state(y, y[3]);
    let r = rates(disk, &m, [T::zero(); 3]);
    [y[1], r.alpha_ddot, r.precession_dot, r.spin_dot]
}

/// The exact Jacobian of [`field`] at state `y`, by dual numbers: the linearization of eqs
/// 23-25 that the stability checks and studies read (eq 54's independent reference).
pub fn jacobian(disk: &Disk, y: &[f64; 4]) -> nalgebra::SMatrix<f64, 4, 4> {
    numerics::linearize::jacobian(|x: &[num_dual::Dual64; 4]| field(disk, x), y)
}

/// Eqs 23-25 solved for the accelerations, with an optional torque $\mathbf N / m a^2$ in the
/// triad. $\dot\Omega$ is singular at $\alpha = 0$ (the disk flat on the table).
pub fn rates<T: DualNum<f64> + Copy>(
    disk: &Disk,
    m: &Motion<T>,
    torque_per_ma2: [T; 3],
) -> Rates<T> {
    rates_at_tilt(disk, m, m.alpha.sin_cos(), torque_per_ma2)
}

/// [`rates`] with $(\sin\alpha, \cos\alpha)$ given, for a caller that already has them.
#[inline]
pub fn rates_at_tilt<T: DualNum<f64> + Copy>(
    disk: &Disk,
    m: &Motion<T>,
    (s, c): (T, T),
    torque_per_ma2: [T; 3],
) -> Rates<T> {
    let k = disk.k;
    let [n1, n2, n3] = torque_per_ma2;
    let (w, ad, om) = (m.spin, m.alpha_dot, m.precession);
    Rates {
        spin_dot: (n1 - ad * om * s) * (1.0 / (2.0 * k + 1.0)),
        alpha_ddot: (om * om * s * c * k + w * om * s * (2.0 * k + 1.0) - c * disk.g_over_a() + n2)
            * (1.0 / (k + 1.0)),
        precession_dot: -(ad * om * c * 2.0 + w * ad * 2.0 + n3 * (1.0 / k)) / s,
    }
}

/// Eq 26: the total energy of a disk rolling without slipping,
/// $E = \frac{m a^2}{2}\left[(2k+1)\omega_1^2 + (k+1)\dot\alpha^2 + k\Omega^2\sin^2\alpha + \frac{2g}{a}\sin\alpha\right]$,
/// generic so that its rate along a motion is exact by a dual number (the checks of sec. 11
/// differentiate it).
pub fn energy<T: DualNum<f64> + Copy>(disk: &Disk, m: &Motion<T>) -> T {
    energy_at_tilt(disk, m, m.alpha.sin())
}

/// [`energy`] (eq 26) with $\sin\alpha$ given.
#[inline]
pub fn energy_at_tilt<T: DualNum<f64> + Copy>(disk: &Disk, m: &Motion<T>, s: T) -> T {
    let k = disk.k;
    let kinetic = m.spin * m.spin * (2.0 * k + 1.0)
        + m.alpha_dot * m.alpha_dot * (k + 1.0)
        + m.precession * m.precession * s * s * k;
    (kinetic + s * (2.0 * disk.g_over_a())) * (0.5 * disk.m * disk.a * disk.a)
}

/// Eq 63's $L_z = k m a^2(\Omega\sin^2\alpha - 2\omega_1\cos\alpha)$, the vertical component of
/// the angular momentum about the centre of mass (eq 19 dotted with $\hat{\mathbf z}$ of eq 4).
pub fn lz(disk: &Disk, m: &Motion) -> f64 {
    lz_at_tilt(disk, m, m.alpha.sin_cos())
}

/// [`lz`] (eq 63) with $(\sin\alpha, \cos\alpha)$ given.
#[inline]
pub fn lz_at_tilt(disk: &Disk, m: &Motion, (s, c): (f64, f64)) -> f64 {
    disk.i22() * (m.precession * s * s - 2.0 * m.spin * c)
}

/// The contact force from eq 20, $\mathbf F = m\ddot{\mathbf r}_{cm} + mg\hat{\mathbf z}$, with
/// $\ddot{\mathbf r}_{cm}$ the derivative of eq 13's velocity $-a\dot\alpha\hat{\mathbf 1} +
/// a\omega_1\hat{\mathbf 2}$ through eqs 5-6. Returned as (vertical $F_z$, along $\hat{\mathbf r}$,
/// along $\hat{\mathbf 2}$) in newtons.
pub fn contact_force(disk: &Disk, m: &Motion, r: &Rates) -> [f64; 3] {
    contact_force_at_tilt(disk, m, m.alpha.sin_cos(), r)
}

/// [`contact_force`] (eq 20) with $(\sin\alpha, \cos\alpha)$ given.
#[inline]
pub fn contact_force_at_tilt(disk: &Disk, m: &Motion, (s, c): (f64, f64), r: &Rates) -> [f64; 3] {
    let a = disk.a;
    let (w, ad, om) = (m.spin, m.alpha_dot, m.precession);
    // Acceleration of the centre of mass in the triad.
    let acc1 = -a * r.alpha_ddot + a * w * om * s;
    let acc2 = a * ad * om * s + a * r.spin_dot;
    let acc3 = a * ad * ad - a * w * om * c;
    // F = m acc + m g z, with z = -cos(alpha) 1 - sin(alpha) 3 and r = -sin(alpha) 1 + cos(alpha) 3.
    let f1 = disk.m * acc1 - disk.m * disk.g * c;
    let f2 = disk.m * acc2;
    let f3 = disk.m * acc3 - disk.m * disk.g * s;
    let fz = -c * f1 - s * f3;
    let fr = -s * f1 + c * f3;
    [fz, fr, f2]
}

/// Derivatives of the optional states: heading ($\dot\psi = \Omega$), centre of mass (eq 13's
/// velocity resolved in the lab with $\hat{\mathbf 2} = (\cos\psi, \sin\psi, 0)$), face angle
/// ($\dot\phi = \omega_{rel} = \omega_1 + \Omega\cos\alpha$, eq 11).
pub(crate) fn extras_rhs<const N: usize>(
    layout: &Layout,
    disk: &Disk,
    m: &Motion,
    y: &State<N>,
    dy: &mut State<N>,
) {
    if let Some(h) = layout.heading {
        dy[h] = m.precession;
    }
    if let Some(p) = layout.path {
        let psi = y[layout.heading.expect("the path needs the heading")];
        let (sp, cp) = psi.sin_cos();
        let v_r = disk.a * m.alpha_dot * m.alpha.sin(); // along r = (sin psi, -cos psi)
        let v_2 = disk.a * m.spin; // along 2 = (cos psi, sin psi)
        dy[p] = v_r * sp + v_2 * cp;
        dy[p + 1] = -v_r * cp + v_2 * sp;
    }
    if let Some(f) = layout.face {
        dy[f] = m.spin + m.precession * m.alpha.cos();
    }
}

/// The rolling disk of eqs 23-25 with `N` states, optionally dissipating by eq 75.
#[derive(Debug, Clone)]
pub struct Rolling<const N: usize> {
    /// The disk.
    pub disk: Disk,
    /// The dissipation, if any.
    pub dissipation: Option<PowerLaw>,
    /// Mechanisms of dissipation from their physics, added to eq 75's law
    /// ([`crate::model::mechanism`]).
    pub mechanisms: Vec<Mechanism>,
    /// Where eq 75's torque acts (against $\vec\omega$ unless set).
    pub placement: Placement,
    layout: Layout,
}

impl<const N: usize> Rolling<N> {
    /// A rolling model with these extras. Panics if `N` is not the number of states they need
    /// (a programming error: [`Layout::new`]`(4, extras).len` is the right `N`).
    pub fn new(disk: Disk, extras: Extras, dissipation: Option<PowerLaw>) -> Self {
        let layout = Layout::new(4, extras);
        assert_eq!(
            layout.len, N,
            "rolling model with {extras:?} has {} states",
            layout.len
        );
        Self {
            disk,
            dissipation,
            mechanisms: Vec::new(),
            placement: Placement::default(),
            layout,
        }
    }

    /// The same model with eq 75's torque along `placement`'s axis.
    pub fn with_placement(mut self, placement: Placement) -> Self {
        self.placement = placement;
        self
    }

    /// The same model with these mechanisms of dissipation as well.
    pub fn with_mechanisms(mut self, mechanisms: &[Mechanism]) -> Self {
        self.mechanisms = mechanisms.to_vec();
        self
    }

    fn torque(&self, m: &Motion) -> [f64; 3] {
        let mut n = self.dissipation.map_or([0.0; 3], |d| {
            d.placed_torque_per_ma2(&self.disk, m, self.placement)
        });
        for mech in &self.mechanisms {
            let t = mech.torque_per_ma2(&self.disk, m);
            for (n, t) in n.iter_mut().zip(t) {
                *n += t;
            }
        }
        n
    }

    /// The accelerations in state `y`.
    pub fn rates(&self, y: &State<N>) -> Rates {
        let m = self.motion(y);
        rates(&self.disk, &m, self.torque(&m))
    }
}

impl<const N: usize> Dynamics<N> for Rolling<N> {
    fn rhs(&self, y: &State<N>, dy: &mut State<N>) {
        let m = self.motion(y);
        let r = rates_at_tilt(
            &self.disk,
            &m,
            numerics::libm::sin_cos(m.alpha),
            self.torque(&m),
        );
        dy[0] = m.alpha_dot;
        dy[1] = r.alpha_ddot;
        dy[2] = r.precession_dot;
        dy[3] = r.spin_dot;
        extras_rhs(&self.layout, &self.disk, &m, y, dy);
    }
}

impl<const N: usize> Model<N> for Rolling<N> {
    fn layout(&self) -> &Layout {
        &self.layout
    }

    fn motion(&self, y: &State<N>) -> Motion {
        Motion::from_state(y.as_slice(), y[3])
    }

    /// Eq 26 with the tilt's sine of [`numerics::trig`], the one every recorded row uses.
    fn energy(&self, y: &State<N>) -> f64 {
        let m = self.motion(y);
        energy_at_tilt(&self.disk, &m, sin_cos(m.alpha).0)
    }

    fn record(&self, y: &State<N>, q: Quantity, out: &mut Vec<f64>) -> bool {
        let m = self.motion(y);
        let sc = sin_cos(m.alpha);
        match q {
            Quantity::Energy => out.push(self.energy(y)),
            Quantity::Lz => out.push(lz_at_tilt(&self.disk, &m, sc)),
            Quantity::NormalForce | Quantity::Friction => {
                let r = rates_at_tilt(&self.disk, &m, sc, self.torque(&m));
                let f = contact_force_at_tilt(&self.disk, &m, sc, &r);
                if q == Quantity::NormalForce {
                    out.push(f[0]);
                } else {
                    out.extend_from_slice(&f[1..]);
                }
            }
            _ => return record_common(&self.layout, &m, y, q, out),
        }
        true
    }

    fn state(&self, m: &Motion) -> State<N> {
        leading_state(&[m.alpha, m.alpha_dot, m.precession, m.spin])
    }

    /// Eq 20's $F_z$ with $\ddot\alpha$, $\dot\Omega$ and $\dot\omega_1$ read from `dy` (the
    /// right-hand side, torque included) instead of solved from eqs 23-25 again. The
    /// right-hand side took the C library's sine and cosine and the row takes
    /// [`sin_cos`]'s, within 2 ulp of them, so the two differ by a few ulp of the largest term
    /// ($m g$ or $m a$ times an acceleration); the bound returned is $10^{-12}$ of their sum.
    fn normal_force_from_rates(&self, y: &State<N>, dy: &State<N>) -> Option<(f64, f64)> {
        let m = self.motion(y);
        let r = Rates {
            alpha_ddot: dy[1],
            precession_dot: dy[2],
            spin_dot: dy[3],
        };
        let fz = contact_force_at_tilt(&self.disk, &m, sin_cos(m.alpha), &r)[0];
        let d = &self.disk;
        let accelerations = d.a
            * (r.alpha_ddot.abs()
                + (m.spin * m.precession).abs()
                + m.alpha_dot * m.alpha_dot
                + (m.alpha_dot * m.precession).abs()
                + r.spin_dot.abs());
        Some((fz, 1e-12 * d.m * (d.g + accelerations)))
    }

    /// The row with the tilt's sine and cosine taken once, and the accelerations (for the
    /// contact force) only when the normal force or the friction is asked.
    fn record_row(
        &self,
        y: &State<N>,
        quantities: &[Quantity],
        normal_force: bool,
        out: &mut Vec<f64>,
    ) -> RowShared {
        let m = self.motion(y);
        let sc = sin_cos(m.alpha);
        let energy = energy_at_tilt(&self.disk, &m, sc.0);
        let needs_force = normal_force
            || quantities
                .iter()
                .any(|q| matches!(q, Quantity::NormalForce | Quantity::Friction));
        let force = needs_force.then(|| {
            let r = rates_at_tilt(&self.disk, &m, sc, self.torque(&m));
            contact_force_at_tilt(&self.disk, &m, sc, &r)
        });
        for &q in quantities {
            match (q, force) {
                (Quantity::Alpha, _) => out.push(m.alpha),
                (Quantity::AlphaDot, _) => out.push(m.alpha_dot),
                (Quantity::Precession, _) => out.push(m.precession),
                (Quantity::Spin, _) => out.push(m.spin),
                (Quantity::Energy, _) => out.push(energy),
                (Quantity::Lz, _) => out.push(lz_at_tilt(&self.disk, &m, sc)),
                (Quantity::NormalForce, Some(f)) => out.push(f[0]),
                (Quantity::Friction, Some(f)) => out.extend_from_slice(&f[1..]),
                _ => {
                    let ok = record_common(&self.layout, &m, y, q, out);
                    debug_assert!(ok, "validated scenes only record what their model provides");
                }
            }
        }
        RowShared {
            energy,
            normal_force: force.filter(|_| normal_force).map(|f| f[0]),
        }
    }

    /// The rows column by column over the batch: the tilt's sines (and cosines, where a column
    /// needs them) over the batch ([`sin_each`], [`sin_cos_each`], the bits of [`sin_cos`]),
    /// then each column over every row, in the AVX2 build where the processor has it (the same
    /// operations, so the same bits).
    fn record_rows(
        &self,
        batch: &Batch<N>,
        quantities: &[Quantity],
        out: &mut Vec<f64>,
        energy: &mut [f64; BATCH],
        normal_force: Option<&mut [f64; BATCH]>,
    ) {
        // Fewer rows than a register holds go one by one: the same bits, for less work than
        // the batch's loops.
        if batch.len() < LANES {
            rows_one_at_a_time(self, batch, quantities, out, energy, normal_force);
            return;
        }
        #[cfg(target_arch = "x86_64")]
        if numerics::wider::avx2() {
            // SAFETY: the processor has AVX2, checked just above.
            unsafe { self.rows_avx2(batch, quantities, out, energy, normal_force) };
            return;
        }
        self.rows(batch, quantities, out, energy, normal_force);
    }
}

impl<const N: usize> Rolling<N> {
    /// [`Model::record_rows`] compiled for AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn rows_avx2(
        &self,
        batch: &Batch<N>,
        quantities: &[Quantity],
        out: &mut Vec<f64>,
        energy: &mut [f64; BATCH],
        normal_force: Option<&mut [f64; BATCH]>,
    ) {
        self.rows(batch, quantities, out, energy, normal_force);
    }

    /// [`Model::record_rows`]'s loops, in the build this is inlined into: the sines (and
    /// cosines), energies (and $L_z$) four rows at a time over the batch's [`Batch::lanes`],
    /// the contact force row by row where it is recorded or asked, then every row written from
    /// its columns.
    #[inline(always)]
    fn rows(
        &self,
        batch: &Batch<N>,
        quantities: &[Quantity],
        out: &mut Vec<f64>,
        energy: &mut [f64; BATCH],
        normal_force: Option<&mut [f64; BATCH]>,
    ) {
        let (n, m) = (batch.len(), batch.lanes());
        let width = 1 + quantities.iter().map(|q| q.columns().len()).sum::<usize>();
        if width > MAX_COLUMNS {
            rows_one_at_a_time(self, batch, quantities, out, energy, normal_force);
            return;
        }
        let records_force = quantities
            .iter()
            .any(|q| matches!(q, Quantity::NormalForce | Quantity::Friction));
        let needs_force = records_force || normal_force.is_some();
        let needs_cos = needs_force || quantities.contains(&Quantity::Lz);
        let tilt = &batch.component_rows(0)[..m];
        let mut sin = [0.0; BATCH];
        let cos_rows;
        let cos: &[f64; BATCH] = if needs_cos {
            let mut c = [0.0; BATCH];
            sin_cos_each(tilt, &mut sin, &mut c);
            cos_rows = c;
            &cos_rows
        } else {
            sin_each(tilt, &mut sin);
            &[0.0; BATCH]
        };
        let y = |i: usize| batch.component_rows(i);
        let at = |j: usize| Motion {
            alpha: y(0)[j],
            alpha_dot: y(1)[j],
            precession: y(2)[j],
            spin: y(3)[j],
        };
        // Four rows at a time with no remainder: the rows past the samples are computed too.
        for (k, e) in energy[..m].chunks_exact_mut(LANES).enumerate() {
            for (l, e) in e.iter_mut().enumerate() {
                let j = k * LANES + l;
                *e = energy_at_tilt(&self.disk, &at(j), sin[j]);
            }
        }
        // The columns not asked for are left as zeros, and not written.
        let lz_rows;
        let lz: &[f64; BATCH] = if quantities.contains(&Quantity::Lz) {
            let mut lz = [0.0; BATCH];
            for (k, l) in lz[..m].chunks_exact_mut(LANES).enumerate() {
                for (i, l) in l.iter_mut().enumerate() {
                    let j = k * LANES + i;
                    *l = lz_at_tilt(&self.disk, &at(j), (sin[j], cos[j]));
                }
            }
            lz_rows = lz;
            &lz_rows
        } else {
            &[0.0; BATCH]
        };
        let force_rows;
        let force: &[[f64; BATCH]; 3] = if needs_force {
            let mut force = [[0.0; BATCH]; 3];
            for j in 0..n {
                let (motion, sc) = (at(j), (sin[j], cos[j]));
                let r = rates_at_tilt(&self.disk, &motion, sc, self.torque(&motion));
                let f = contact_force_at_tilt(&self.disk, &motion, sc, &r);
                (force[0][j], force[1][j], force[2][j]) = (f[0], f[1], f[2]);
            }
            force_rows = force;
            &force_rows
        } else {
            &[[0.0; BATCH]; 3]
        };
        if let Some(f) = normal_force {
            f[..n].copy_from_slice(&force[0][..n]);
        }
        let shared = SharedColumns {
            batch,
            layout: &self.layout,
            energy,
            lz,
            normal_force: &force[0],
        };
        let state = |i: Option<usize>| i.map(y);
        let (columns, c) = gather_columns(batch.time_rows(), quantities, |q| {
            shared.of(q).unwrap_or(match q {
                Quantity::Spin => (Some(y(3)), None),
                Quantity::Friction => (Some(&force[1]), Some(&force[2])),
                Quantity::Path => (
                    state(self.layout.path),
                    state(self.layout.path.map(|p| p + 1)),
                ),
                _ => (None, None),
            })
        });
        write_rows(&columns[..c], n, out);
    }
}

/// The quantities every model reads the same way: the paper's variables and the extra states.
#[inline]
pub(crate) fn record_common<const N: usize>(
    layout: &Layout,
    m: &Motion,
    y: &State<N>,
    q: Quantity,
    out: &mut Vec<f64>,
) -> bool {
    let state_at = |i: Option<usize>| i.map(|i| y[i]);
    let v = match q {
        Quantity::Alpha => Some(m.alpha),
        Quantity::AlphaDot => Some(m.alpha_dot),
        Quantity::Precession => Some(m.precession),
        Quantity::Spin => Some(m.spin),
        Quantity::Heading => state_at(layout.heading),
        Quantity::Face => state_at(layout.face),
        Quantity::Path => {
            let Some(p) = layout.path else { return false };
            out.push(y[p]);
            out.push(y[p + 1]);
            return true;
        }
        _ => None,
    };
    match v {
        Some(v) => {
            out.push(v);
            true
        }
        None => false,
    }
}
