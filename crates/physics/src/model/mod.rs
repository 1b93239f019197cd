//! Equations of motion, one file per set, each a [`Dynamics`] that carries only the states its
//! scene needs.
//!
//! The core rolling state is the paper's $(\alpha, \dot\alpha, \Omega, \omega_1)$; the heading of
//! the triad, the centre of mass in the plane and the face angle are added only when a scene
//! records them (see [`Layout`]).

pub mod adiabatic;
pub mod air_film;
mod batch_rows;
pub mod dissipation;
pub mod film_bound;
pub mod frictionless;
pub mod lab_frame;
pub mod layout;
pub mod mechanism;
#[cfg(test)]
mod record_row;
pub mod rolling;
pub mod sliding;
pub mod steady;
pub mod steady_solid;

pub use layout::{Extras, Layout};

use crate::solve::{Batch, Dynamics, State, BATCH};
use serde::{Deserialize, Serialize};

/// The paper's four variables of motion at one instant. The scalar is `f64`, or a dual number
/// when a check differentiates the equations of motion exactly.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Motion<T = f64> {
    /// $\alpha$: angle of the symmetry axis $\hat{\mathbf 1}$ to the vertical, equal to the angle
    /// of the disk's plane to the table (rad).
    pub alpha: T,
    /// $\dot\alpha$ (rad/s).
    pub alpha_dot: T,
    /// $\Omega$: rate at which the triad turns about the vertical, the precession (rad/s).
    pub precession: T,
    /// $\omega_1$: the component of the disk's angular velocity along its symmetry axis (rad/s).
    pub spin: T,
}

impl<T: Copy> Motion<T> {
    /// The paper's variables from a state that starts $(\alpha, \dot\alpha, \Omega)$, with the
    /// spin $\omega_1$ given (a state entry, or a constant of the model).
    pub fn from_state(y: &[T], spin: T) -> Self {
        Motion {
            alpha: y[0],
            alpha_dot: y[1],
            precession: y[2],
            spin,
        }
    }
}

/// A state whose first entries are `values` and whose optional entries (the extras) start at
/// zero.
pub fn leading_state<const N: usize>(values: &[f64]) -> State<N> {
    let mut y = State::<N>::zeros();
    y.as_mut_slice()[..values.len()].copy_from_slice(values);
    y
}

/// Something a scene can record, one column of a trajectory.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Quantity {
    /// $\alpha$ (rad).
    Alpha,
    /// $\dot\alpha$ (rad/s).
    AlphaDot,
    /// $\Omega$ (rad/s).
    Precession,
    /// $\omega_1$ (rad/s).
    Spin,
    /// Heading of the triad: the angle of $\hat{\mathbf 2}$ from the lab's x axis, $\int\Omega\,dt$ (rad).
    Heading,
    /// The centre of mass in the plane: x and y (m).
    Path,
    /// Angle of a mark on the face relative to the triad, $\int(\omega_1 + \Omega\cos\alpha)\,dt$ (rad).
    Face,
    /// Total energy (J): eq 26 when rolling; its frictionless counterpart otherwise.
    Energy,
    /// Vertical angular momentum about the centre of mass, eq 63 (kg m^2/s).
    Lz,
    /// Vertical contact force $F_z$ (N).
    NormalForce,
    /// Horizontal contact (friction) force along $\hat{\mathbf r}$ and $\hat{\mathbf 2}$ (N).
    Friction,
    /// Speed of the material point at the contact along the table, $|\mathbf v_{c,h}|$ (m/s):
    /// zero while rolling (lab-frame and sliding models).
    SlipSpeed,
    /// Speed of the centre of mass, $|\mathbf v|$ (m/s) (lab-frame and sliding models).
    CmSpeed,
    /// Height of the rim's lowest point above the table (m): zero in contact, positive in flight
    /// (lab-frame and sliding models).
    ContactGap,
    /// Energy taken out by the contact so far (J): the work of sliding friction plus the losses
    /// of impacts (sliding model; zero in the lab-frame models, whose contact does no work).
    Dissipated,
    /// The lowest rim point on the table, $(x, y)$ (m): the contact's path.
    ContactPath,
}

impl Quantity {
    /// Every quantity, in column order.
    pub const ALL: [Quantity; 16] = [
        Quantity::Alpha,
        Quantity::AlphaDot,
        Quantity::Precession,
        Quantity::Spin,
        Quantity::Heading,
        Quantity::Path,
        Quantity::Face,
        Quantity::Energy,
        Quantity::Lz,
        Quantity::NormalForce,
        Quantity::Friction,
        Quantity::SlipSpeed,
        Quantity::CmSpeed,
        Quantity::ContactGap,
        Quantity::Dissipated,
        Quantity::ContactPath,
    ];

    /// CSV column headers (with units) that this quantity produces.
    pub fn columns(self) -> &'static [&'static str] {
        match self {
            Quantity::Alpha => &["alpha_rad"],
            Quantity::AlphaDot => &["alpha_dot_rad_per_s"],
            Quantity::Precession => &["precession_rad_per_s"],
            Quantity::Spin => &["spin_rad_per_s"],
            Quantity::Heading => &["heading_rad"],
            Quantity::Path => &["x_m", "y_m"],
            Quantity::Face => &["face_rad"],
            Quantity::Energy => &["energy_J"],
            Quantity::Lz => &["lz_kg_m2_per_s"],
            Quantity::NormalForce => &["normal_force_N"],
            Quantity::Friction => &["friction_r_N", "friction_2_N"],
            Quantity::SlipSpeed => &["slip_speed_m_per_s"],
            Quantity::CmSpeed => &["cm_speed_m_per_s"],
            Quantity::ContactGap => &["contact_gap_m"],
            Quantity::Dissipated => &["dissipated_J"],
            Quantity::ContactPath => &["contact_x_m", "contact_y_m"],
        }
    }

    /// The name used in scene files.
    pub fn name(self) -> &'static str {
        match self {
            Quantity::Alpha => "alpha",
            Quantity::AlphaDot => "alpha_dot",
            Quantity::Precession => "precession",
            Quantity::Spin => "spin",
            Quantity::Heading => "heading",
            Quantity::Path => "path",
            Quantity::Face => "face",
            Quantity::Energy => "energy",
            Quantity::Lz => "lz",
            Quantity::NormalForce => "normal_force",
            Quantity::Friction => "friction",
            Quantity::SlipSpeed => "slip_speed",
            Quantity::CmSpeed => "cm_speed",
            Quantity::ContactGap => "contact_gap",
            Quantity::Dissipated => "dissipated",
            Quantity::ContactPath => "contact_path",
        }
    }
}

/// A model of the disk: a [`Dynamics`] whose states can be read back as the paper's variables
/// and as recordable quantities.
pub trait Model<const N: usize>: Dynamics<N> {
    /// Where each optional state sits.
    fn layout(&self) -> &Layout;
    /// The paper's variables in state `y`.
    fn motion(&self, y: &State<N>) -> Motion;
    /// The total energy in state `y` (J).
    fn energy(&self, y: &State<N>) -> f64;
    /// Appends the columns of quantity `q` in state `y` to `out`; false when this model cannot
    /// provide it.
    fn record(&self, y: &State<N>, q: Quantity, out: &mut Vec<f64>) -> bool;
    /// The start state of this model for the paper's variables (extras start at zero).
    fn state(&self, m: &Motion) -> State<N>;

    /// Appends the columns of `quantities` in state `y` to `out`, each as [`Model::record`]
    /// writes it, and returns the energy and, when `normal_force` is asked, the normal force
    /// (`None` for a model without one). What the columns share is computed once for the row:
    /// the energy, the normal force (one evaluation of the accelerations), and in a model that
    /// overrides this, the tilt's sine and cosine or the geometry.
    fn record_row(
        &self,
        y: &State<N>,
        quantities: &[Quantity],
        normal_force: bool,
        out: &mut Vec<f64>,
    ) -> RowShared {
        let mut force = None;
        if normal_force {
            let at = out.len();
            if self.record(y, Quantity::NormalForce, out) {
                force = out.get(at).copied();
            }
            out.truncate(at);
        }
        let energy = self.energy(y);
        for &q in quantities {
            match (q, force) {
                (Quantity::Energy, _) => out.push(energy),
                (Quantity::NormalForce, Some(f)) => out.push(f),
                _ => {
                    let ok = self.record(y, q, out);
                    debug_assert!(ok, "validated scenes only record what their model provides");
                }
            }
        }
        RowShared {
            energy,
            normal_force: force,
        }
    }

    /// Appends one row per sample of `batch` to `out`, row after row: the sample's time, then
    /// the columns of `quantities` as [`Model::record_row`] writes them for its state; writes
    /// each row's energy to `energy` and, when `normal_force` is given, each row's normal force
    /// $F_z$ to it (`NaN` for a model without one), as [`Model::record_row`] returns them (the
    /// entries past the batch's samples are left unspecified). A model that overrides this
    /// computes a column over all the rows at once, to the same bits.
    fn record_rows(
        &self,
        batch: &Batch<N>,
        quantities: &[Quantity],
        out: &mut Vec<f64>,
        energy: &mut [f64; BATCH],
        normal_force: Option<&mut [f64; BATCH]>,
    ) {
        rows_one_at_a_time(self, batch, quantities, out, energy, normal_force);
    }

    /// The normal force $F_z$ (N) in state `y` from the state's time derivative `dy` (the
    /// right-hand side there, which an integrator has at each step's end), and the largest
    /// amount by which it may differ from the $F_z$ of [`Model::record_row`] (round-off: the
    /// two take the tilt's sine from different functions); `None` for a model that computes its
    /// force otherwise or has none.
    fn normal_force_from_rates(&self, _y: &State<N>, _dy: &State<N>) -> Option<(f64, f64)> {
        None
    }
}

/// [`Model::record_rows`] made row by row through [`Model::record_row`]: the trait's default,
/// and what a model that overrides it falls back to for the rows it cannot make together.
pub(crate) fn rows_one_at_a_time<M: Model<N> + ?Sized, const N: usize>(
    model: &M,
    batch: &Batch<N>,
    quantities: &[Quantity],
    out: &mut Vec<f64>,
    energy: &mut [f64; BATCH],
    mut normal_force: Option<&mut [f64; BATCH]>,
) {
    let asked = normal_force.is_some();
    for (j, &t) in batch.times().iter().enumerate() {
        out.push(t);
        let shared = model.record_row(&batch.state(j), quantities, asked, out);
        energy[j] = shared.energy;
        if let Some(f) = normal_force.as_deref_mut() {
            f[j] = shared.normal_force.unwrap_or(f64::NAN);
        }
    }
}

/// What [`Model::record_row`] computes for a row beside its columns.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RowShared {
    /// The total energy (J).
    pub energy: f64,
    /// The normal force $F_z$ (N), when asked and the model has one.
    pub normal_force: Option<f64>,
}
