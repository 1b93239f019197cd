//! Frictionless contact: the equations of motion 60-62.
//!
//! $$\dot\omega_1 = 0 \qquad (60)$$
//! $$(k\Omega^2 + \dot\alpha^2)\sin\alpha\cos\alpha + 2k\omega_1\Omega\sin\alpha - (k + \cos^2\alpha)\ddot\alpha = \frac{g}{a}\cos\alpha \qquad (61)$$
//! $$\dot\Omega\sin\alpha + 2\dot\alpha\Omega\cos\alpha + 2\omega_1\dot\alpha = 0 \qquad (62)$$
//!
//! By eq 60 the spin $\omega_1$ is constant, so it is a parameter here, not a state; the centre of
//! mass moves only vertically (eq 59), so its horizontal position is a constant too.

use crate::disk::Disk;
use crate::model::batch_rows::{gather_columns, write_rows, SharedColumns, MAX_COLUMNS};
use crate::model::rolling::{extras_rhs, lz, lz_at_tilt, record_common};
use crate::model::{
    leading_state, rows_one_at_a_time, Extras, Layout, Model, Motion, Quantity, RowShared,
};
use crate::solve::{Batch, Dynamics, State, BATCH, LANES};
use num_dual::DualNum;

/// Eqs 61-62 solved for $(\ddot\alpha, \dot\Omega)$ at spin $\omega_1$.
pub fn accelerations<T: DualNum<f64> + Copy>(disk: &Disk, m: &Motion<T>) -> (T, T) {
    accelerations_at_tilt(disk, m, m.alpha.sin_cos())
}

/// [`accelerations`] (eqs 61-62) with $(\sin\alpha, \cos\alpha)$ given.
#[inline]
pub fn accelerations_at_tilt<T: DualNum<f64> + Copy>(
    disk: &Disk,
    m: &Motion<T>,
    (s, c): (T, T),
) -> (T, T) {
    let k = disk.k;
    let (w, ad, om) = (m.spin, m.alpha_dot, m.precession);
    let alpha_ddot = ((om * om * k + ad * ad) * s * c + w * om * s * (2.0 * k)
        - c * disk.g_over_a())
        / (c * c + k);
    let precession_dot = -(ad * om * c * 2.0 + w * ad * 2.0) / s;
    (alpha_ddot, precession_dot)
}

/// The exact Jacobian of eqs 61-62 without spin ($\omega_1 = 0$) in the state
/// $(\alpha, \dot\alpha, \Omega)$ at `y`, by dual numbers: the linearization that the stability
/// claims of the frictionless disk read.
pub fn spinless_jacobian(disk: &Disk, y: &[f64; 3]) -> nalgebra::SMatrix<f64, 3, 3> {
    numerics::linearize::jacobian(
        |y: &[num_dual::Dual64; 3]| {
            let m = Motion::from_state(y, num_dual::Dual64::from(0.0));
            let (alpha_ddot, precession_dot) = accelerations(disk, &m);
            [y[1], alpha_ddot, precession_dot]
        },
        y,
    )
}

/// The total energy without friction: the centre of mass moves vertically at
/// $a\dot\alpha\cos\alpha$ (eq 59), so
/// $E = \frac{m a^2}{2}\left[2k\omega_1^2 + (k + \cos^2\alpha)\dot\alpha^2 + k\Omega^2\sin^2\alpha + \frac{2g}{a}\sin\alpha\right]$.
pub fn energy(disk: &Disk, m: &Motion) -> f64 {
    energy_at_tilt(disk, m, m.alpha.sin_cos())
}

/// [`energy`] with $(\sin\alpha, \cos\alpha)$ given.
#[inline]
pub fn energy_at_tilt(disk: &Disk, m: &Motion, (s, c): (f64, f64)) -> f64 {
    let k = disk.k;
    0.5 * disk.m
        * disk.a
        * disk.a
        * (2.0 * k * m.spin * m.spin
            + (k + c * c) * m.alpha_dot * m.alpha_dot
            + k * m.precession * m.precession * s * s
            + 2.0 * disk.g_over_a() * s)
}

/// The vertical contact force, the only one without friction:
/// $F_z = m g + m\,\frac{d^2}{dt^2}(a\sin\alpha)$.
pub fn normal_force(disk: &Disk, m: &Motion, alpha_ddot: f64) -> f64 {
    normal_force_at_tilt(disk, m, m.alpha.sin_cos(), alpha_ddot)
}

/// [`normal_force`] with $(\sin\alpha, \cos\alpha)$ given.
#[inline]
pub fn normal_force_at_tilt(disk: &Disk, m: &Motion, (s, c): (f64, f64), alpha_ddot: f64) -> f64 {
    disk.m * disk.g + disk.m * disk.a * (alpha_ddot * c - m.alpha_dot * m.alpha_dot * s)
}

/// The frictionless disk of eqs 60-62, states $(\alpha, \dot\alpha, \Omega)$ plus extras.
#[derive(Debug, Clone)]
pub struct Frictionless<const N: usize> {
    /// The disk.
    pub disk: Disk,
    /// The constant spin $\omega_1$ (eq 60).
    pub spin: f64,
    layout: Layout,
}

impl<const N: usize> Frictionless<N> {
    /// A frictionless model with constant spin `spin`. The path needs no state here (the centre
    /// stays at the origin), so `extras.path` adds nothing but the heading is not needed for it.
    /// Panics if `N` is not the number of states (see [`Frictionless::states`]).
    pub fn new(disk: Disk, spin: f64, extras: Extras) -> Self {
        let layout = Self::layout_for(extras);
        assert_eq!(
            layout.len, N,
            "frictionless model with {extras:?} has {} states",
            layout.len
        );
        Self { disk, spin, layout }
    }

    fn layout_for(extras: Extras) -> Layout {
        Layout::new(
            3,
            Extras {
                path: false,
                ..extras
            },
        )
    }

    /// The number of states for these extras.
    pub fn states(extras: Extras) -> usize {
        Self::layout_for(extras).len
    }
}

impl<const N: usize> Dynamics<N> for Frictionless<N> {
    fn rhs(&self, y: &State<N>, dy: &mut State<N>) {
        let m = self.motion(y);
        let (alpha_ddot, precession_dot) = accelerations(&self.disk, &m);
        dy[0] = m.alpha_dot;
        dy[1] = alpha_ddot;
        dy[2] = precession_dot;
        extras_rhs(&self.layout, &self.disk, &m, y, dy);
    }
}

impl<const N: usize> Model<N> for Frictionless<N> {
    fn layout(&self) -> &Layout {
        &self.layout
    }

    fn motion(&self, y: &State<N>) -> Motion {
        Motion::from_state(y.as_slice(), self.spin)
    }

    fn energy(&self, y: &State<N>) -> f64 {
        energy(&self.disk, &self.motion(y))
    }

    fn record(&self, y: &State<N>, q: Quantity, out: &mut Vec<f64>) -> bool {
        let m = self.motion(y);
        match q {
            Quantity::Energy => out.push(self.energy(y)),
            Quantity::Lz => out.push(lz(&self.disk, &m)),
            Quantity::NormalForce => {
                let (alpha_ddot, _) = accelerations(&self.disk, &m);
                out.push(normal_force(&self.disk, &m, alpha_ddot));
            }
            Quantity::Friction => out.extend_from_slice(&[0.0, 0.0]),
            Quantity::Path => out.extend_from_slice(&[0.0, 0.0]),
            _ => return record_common(&self.layout, &m, y, q, out),
        }
        true
    }

    fn state(&self, m: &Motion) -> State<N> {
        leading_state(&[m.alpha, m.alpha_dot, m.precession])
    }

    /// The row with the tilt's sine and cosine taken once, and the accelerations only when
    /// the normal force is asked.
    fn record_row(
        &self,
        y: &State<N>,
        quantities: &[Quantity],
        normal_force: bool,
        out: &mut Vec<f64>,
    ) -> RowShared {
        let m = self.motion(y);
        let sc = m.alpha.sin_cos();
        let energy = energy_at_tilt(&self.disk, &m, sc);
        let needs_force = normal_force || quantities.contains(&Quantity::NormalForce);
        let force = needs_force.then(|| {
            let (alpha_ddot, _) = accelerations_at_tilt(&self.disk, &m, sc);
            normal_force_at_tilt(&self.disk, &m, sc, alpha_ddot)
        });
        for &q in quantities {
            match (q, force) {
                (Quantity::Alpha, _) => out.push(m.alpha),
                (Quantity::AlphaDot, _) => out.push(m.alpha_dot),
                (Quantity::Precession, _) => out.push(m.precession),
                (Quantity::Spin, _) => out.push(m.spin),
                (Quantity::Energy, _) => out.push(energy),
                (Quantity::Lz, _) => out.push(lz_at_tilt(&self.disk, &m, sc)),
                (Quantity::NormalForce, Some(f)) => out.push(f),
                (Quantity::Friction | Quantity::Path, _) => out.extend_from_slice(&[0.0, 0.0]),
                _ => {
                    let ok = record_common(&self.layout, &m, y, q, out);
                    debug_assert!(ok, "validated scenes only record what their model provides");
                }
            }
        }
        RowShared {
            energy,
            normal_force: force.filter(|_| normal_force),
        }
    }

    /// The rows column by column over the batch: the tilt's sine and cosine of each row (the C
    /// library's, as [`Model::record_row`] takes them), then the energy, $L_z$ and the normal
    /// force over the rows with the same operations as a row alone, then every row written
    /// from its columns.
    fn record_rows(
        &self,
        batch: &Batch<N>,
        quantities: &[Quantity],
        out: &mut Vec<f64>,
        energy: &mut [f64; BATCH],
        normal_force: Option<&mut [f64; BATCH]>,
    ) {
        let n = batch.len();
        let width = 1 + quantities.iter().map(|q| q.columns().len()).sum::<usize>();
        // Fewer rows than a register holds go one by one: the same bits, for less work.
        if width > MAX_COLUMNS || n < LANES {
            rows_one_at_a_time(self, batch, quantities, out, energy, normal_force);
            return;
        }
        let y = |i: usize| batch.component_rows(i);
        let at = |j: usize| Motion {
            alpha: y(0)[j],
            alpha_dot: y(1)[j],
            precession: y(2)[j],
            spin: self.spin,
        };
        let mut sc = [(0.0, 0.0); BATCH];
        for (sc, &alpha) in sc.iter_mut().zip(&y(0)[..n]) {
            *sc = alpha.sin_cos();
        }
        for (j, e) in energy[..n].iter_mut().enumerate() {
            *e = energy_at_tilt(&self.disk, &at(j), sc[j]);
        }
        let mut lz = [0.0; BATCH];
        if quantities.contains(&Quantity::Lz) {
            for (j, l) in lz[..n].iter_mut().enumerate() {
                *l = lz_at_tilt(&self.disk, &at(j), sc[j]);
            }
        }
        let mut force = [0.0; BATCH];
        if normal_force.is_some() || quantities.contains(&Quantity::NormalForce) {
            for (j, f) in force[..n].iter_mut().enumerate() {
                let (alpha_ddot, _) = accelerations_at_tilt(&self.disk, &at(j), sc[j]);
                *f = normal_force_at_tilt(&self.disk, &at(j), sc[j], alpha_ddot);
            }
        }
        if let Some(f) = normal_force {
            f[..n].copy_from_slice(&force[..n]);
        }
        let (spin, zero) = ([self.spin; BATCH], [0.0; BATCH]);
        let shared = SharedColumns {
            batch,
            layout: &self.layout,
            energy,
            lz: &lz,
            normal_force: &force,
        };
        let (columns, c) = gather_columns(batch.time_rows(), quantities, |q| {
            shared.of(q).unwrap_or(match q {
                Quantity::Spin => (Some(&spin), None),
                Quantity::Friction | Quantity::Path => (Some(&zero), Some(&zero)),
                _ => (None, None),
            })
        });
        write_rows(&columns[..c], n, out);
    }
}
