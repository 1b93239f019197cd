//! Where the peer's fixed floors will shape its run of a scene, found on this tool's run of it
//! (`rolling-disk peer export` prints them as warnings). From its source (`model2/solout.f90`,
//! `model2/integ.f90`, `model2/disk_data.f90`):
//! - **energy**: it stops where its excess energy, kinetic plus $mg\max(0, z_c - c)$ above
//!   lying flat ($c$ the half thickness), falls to [`ENERGY_STOP`];
//! - **seed slip**: it starts every run sliding and restarts a slip with a seed
//!   $\max(10^4\,{\rm atol}, 5\varepsilon)$ against the friction, $\varepsilon =$ [`REGULARIZATION`];
//! - **relock threshold**: it relocks only when the slip speed is below
//!   $\max(10^3\,{\rm atol}, 10^{-4})$ m/s at a print step; its regularized friction
//!   $\mu_kF_z\,v/\sqrt{v^2+\varepsilon^2}$ holds a friction $F_t$ only while slipping at
//!   $v = \varepsilon r/\sqrt{1-r^2}$, $r = F_t/\mu_kF_z$, so where rolling needs $v$ above the
//!   threshold it creeps instead of rolling;
//! - **margin**: it leaves rolling only when the friction needed exceeds $\mu_sF_z$ by
//!   $\max(10^3\,{\rm atol}, 5\times10^{-3})\max(F_z/m, 1)$ (per unit mass) and relocks only
//!   below $\mu_sF_z$ less that margin.

use super::PeerError;
use physics::dispatch::sliding_model;
use physics::model::sliding::{Flow, Mode};
use physics::run::sliding::integrate;
use physics::scene::Scene;

/// The peer's energy stop (J).
pub const ENERGY_STOP: f64 = 3e-4;
/// The peer's slip regularization speed in its source (m/s).
pub const REGULARIZATION: f64 = 1e-3;

/// The warnings for `scene` (module documentation), in the order of the list there.
pub fn floors(scene: &Scene) -> Result<Vec<String>, PeerError> {
    let m = sliding_model(scene);
    let atol = scene.settings.atol;
    let (mu_s, mu_k) = (m.friction.mu, m.mu_kinetic());
    let half = scene.toy.solid.map_or(0.0, |s| 0.5 * s.thickness);
    let weight = m.disk.m * m.disk.g;
    let run = integrate(&m, scene, scene.sample).map_err(PeerError::Settings)?;
    let mut out = Vec::new();
    let excess = |y| {
        let z = m.snapshot(y).centre.z;
        m.energy(y) - weight * z + weight * (z - half).max(0.0)
    };
    if let Some(k) = run.y.iter().position(|y| excess(y) <= ENERGY_STOP) {
        out.push(format!(
            "the peer stops where its energy above lying flat falls to {ENERGY_STOP:e} J: this \
             scene's does at t = {:.4} s (it has {:.3e} J at the start), so the peer's record \
             ends there",
            run.t[k],
            run.y.first().map_or(0.0, excess)
        ));
    }
    let seed = (1e4 * atol).max(5.0 * REGULARIZATION);
    let lock = (1e3 * atol).max(1e-4);
    if scene.slip.forward == 0.0 && scene.slip.sideways == 0.0 {
        out.push(format!(
            "the scene starts without slip; the peer starts every run sliding and restarts it \
             with a seed slip of {seed:e} m/s (max(1e4 atol, 5 x its regularization {REGULARIZATION:e} m/s)): \
             its first rows slide with that seed until it relocks below {lock:e} m/s"
        ));
    }
    let margin = (1e3 * atol).max(5e-3);
    // (from, to, largest creep speed) and (from, to) of the stick stretches warned about.
    let mut creep: Option<(f64, f64, f64)> = None;
    let mut held: Option<(f64, f64)> = None;
    for ((t, y), mode) in run.t.iter().zip(&run.y).zip(&run.mode) {
        if !matches!(mode, Mode::Stick) {
            continue;
        }
        let f = Flow {
            model: &m,
            mode: *mode,
        }
        .force(y);
        if f.z <= 0.0 {
            continue;
        }
        let r = (f.xy().norm() / (mu_k * f.z)).min(1.0);
        let v = REGULARIZATION * r / (1.0 - r * r).max(1e-300).sqrt();
        if v > lock {
            let c = creep.get_or_insert((*t, *t, v));
            c.1 = *t;
            c.2 = c.2.max(v);
        }
        let per_mass = f.z / m.disk.m;
        let needed = f.xy().norm() / f.z;
        if needed > mu_s - margin * per_mass.max(1.0) / per_mass {
            let h = held.get_or_insert((*t, *t));
            h.1 = *t;
        }
    }
    if let Some((a, b, v)) = creep {
        out.push(format!(
            "where this tool rolls between t = {a:.4} and {b:.4} s the peer's regularized friction \
             ({REGULARIZATION:e} m/s) holds the friction rolling needs only while slipping at up to \
             {v:.3e} m/s, above its relock threshold {lock:e} m/s: it creeps there instead of \
             rolling (scripts/peer_run.sh with PEER_SLIP_REGULARIZATION=1e-7 runs it sharp)"
        ));
    }
    if let Some((a, b)) = held {
        out.push(format!(
            "where this tool rolls between t = {a:.4} and {b:.4} s the friction needed comes \
             within the peer's margin ({margin:e} x max(Fz/m, 1) m/s^2) of static friction: the \
             peer does not relock there, and leaves rolling only past that margin"
        ));
    }
    Ok(out)
}
