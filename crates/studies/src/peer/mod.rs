//! An independent program as a reference: Milan Batista's Euler disk simulation (Fortran 90
//! with Hairer's DOP853), a rigid disk of finite thickness with a rounded rim on one contact
//! point, rolling and sliding modes switched at its print steps, Coulomb static and kinetic
//! friction and rolling and boring resistance. It is never part of this tool: it is built and
//! run by `scripts/peer_run.sh`, and its outputs come in as data (`tests/reference/peer/`).
//!
//! - [`response::response`] writes its response file for a scene (`rolling-disk peer export`);
//! - [`result::parse`] reads its `result.txt`;
//! - [`compare::compare`] runs the scene here and measures the differences
//!   (`rolling-disk peer compare`);
//! - [`stored::compare_stored`] compares the stored runs, built into the tool;
//! - [`mapping`] is the one place where its Euler angles and rates meet this tool's state.
//!
//! **Its modelling choices** that a comparison meets (read from its source):
//! - it regularizes the kinetic friction's direction, $\mathbf F_t = -\mu_k F_z\mathbf v_s/\sqrt{v_s^2 + \varepsilon^2}$
//!   with $\varepsilon = 10^{-3}$ m/s, so a slip ends only asymptotically; it relocks when the
//!   slip speed falls below $10^{-4}$ m/s at a print step, if sticking then needs less than
//!   $\mu_s F_z$ minus a margin;
//! - it leaves rolling when the friction needed exceeds $\mu_s F_z$ by a margin of
//!   $5\times10^{-3}\max(F_z/m, 1)$ (m/s², i.e. $\mu_s$ raised by about 0.005), and starts the slip
//!   with a seed velocity of $5\varepsilon = 5$ mm/s against the friction;
//! - it starts every run sliding; a relock it finds at its first print step is not carried out
//!   and the run restarts sliding from the start with the seed
//!   ($\max(10^4\,{\rm atol}, 5\varepsilon)$), printing the start again; where the seed is below
//!   its relock threshold it relocks with its clock set back, and on every switch to rolling it
//!   keeps the state of the end of its integration step on the clock of the located relock:
//!   [`clock::on_its_clock`] reads the time of each row's state back from its angles;
//! - its resistance moments take the sign of the rotation they oppose and it has no phase in
//!   which that rotation stays stopped: where the rotation passes through zero and the moment
//!   could hold it, it stalls, where this tool holds it (Coulomb stick of the moment,
//!   `physics::model::sliding` `stall.rs`);
//! - it locates switches on a quadratic through three print points, so a switch time is known
//!   to a fraction of the print step;
//! - within $|\theta| < 0.02$ rad of upright it smooths the contact point's axial offset (a cubic
//!   blend between the faces);
//! - it stops when the kinetic plus potential energy above lying flat falls below $3\times10^{-4}$ J,
//!   within $2\times10^{-4}$ rad of flat, or where the normal force vanishes (it has no flight).

pub mod along;
pub mod builtin;
pub mod clock;
pub mod compare;
pub mod floors;
pub mod mapping;
pub mod pairing;
mod printed;
pub mod relock;
pub mod response;
pub mod result;
pub mod stored;

use physics::scene::Scene;
use std::path::Path;

/// Why a peer file could not be written or read.
#[derive(Debug, thiserror::Error)]
pub enum PeerError {
    /// The scene cannot be run by the peer.
    #[error("{0}: {1}")]
    Scene(String, String),
    /// A result file is not the peer's.
    #[error("{0}:{1}: {2}")]
    Result(String, usize, String),
    /// A file could not be read.
    #[error("{0}: {1}")]
    Read(String, String),
    /// This tool's run was refused.
    #[error("{0}")]
    Settings(physics::solve::SettingsError),
}

/// Reads the peer's `result.txt` at `path` and compares it with `scene` run here.
pub fn compare_file(scene: &Scene, path: &Path) -> Result<compare::PeerComparison, PeerError> {
    let name = path.display().to_string();
    let text = files::input::read_text(path, 1 << 30)
        .map_err(|e| PeerError::Read(name.clone(), e.reason()))?;
    let rows = result::parse(&text, &name)?;
    compare::compare(scene, &rows)
}
