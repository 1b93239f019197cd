//! The frequency study: small oscillations about steady motion measured on integrations, for
//! comparison with eq 54 ($b = a/2$), eq 55 ($b = 0$, rolling) and eq 71 ($b = 0$, no friction).
//! Each measurement starts from the steady motion of eqs 28-29 with $\alpha$ raised by
//! [`NUDGE`] of itself and takes $\varpi$ from the mean spacing of $\alpha$'s upward crossings
//! over eight predicted periods.

use crate::error::StudyError;
use numerics::oscillation::angular_frequency;
use physics::disk::Disk;
use physics::model::frictionless::Frictionless;
use physics::model::rolling::Rolling;
use physics::model::steady::steady_motion;
use physics::model::{Extras, Model, Motion};
use physics::solve::{solve, Dynamics, Problem, Settings, State};

/// The measured frequencies (computed by [`compute`]): $(\alpha_0$ in
/// degrees$, \varpi/\Omega_0)$ for each family, for a disk of ratio `k`.
#[derive(Debug, Clone, PartialEq)]
pub struct Measured {
    /// $k = I_1/ma^2$ of the disk.
    pub k: f64,
    /// Rolling model, b = 0 (compare eq 55).
    pub rolled0: Vec<(f64, f64)>,
    /// Rolling model, b = a/2 (compare eq 54).
    pub rolled_half: Vec<(f64, f64)>,
    /// Frictionless model, b = 0 (compare eq 71).
    pub slid0: Vec<(f64, f64)>,
}

/// The relative size of the nudge to alpha that starts the oscillation.
pub const NUDGE: f64 = 1e-6;

/// $\varpi/|\Omega_0|$ of the model linearized at the steady motion `start` (central differences
/// of its right side; $\varpi^2 = -\mathrm{tr}(J^2)/2$, the other eigenvalues being zero), to
/// size the integration window without reading the paper; `None` where $\varpi^2 \le 0$ (an
/// unstable steady motion has no frequency to measure).
fn linearized_ratio<M: Model<N> + Dynamics<N>, const N: usize>(
    model: &M,
    start: &Motion,
) -> Option<f64> {
    let y0 = model.state(start);
    let mut jac = nalgebra::SMatrix::<f64, N, N>::zeros();
    for j in 0..N {
        let h = 1e-6 * y0[j].abs().max(1.0);
        let (mut up, mut down) = (y0, y0);
        up[j] += h;
        down[j] -= h;
        let (mut f_up, mut f_down) = (State::<N>::zeros(), State::<N>::zeros());
        model.rhs(&up, &mut f_up);
        model.rhs(&down, &mut f_down);
        jac.set_column(j, &((f_up - f_down) / (2.0 * h)));
    }
    let w2 = -(jac * jac).trace() / 2.0;
    (w2 > 0.0).then(|| w2.sqrt() / start.precession.abs())
}

/// $\varpi/\Omega_0$ measured on an integration of `model` from `start` nudged, over 8 periods
/// of the `predicted` ratio sampled 100 times per period; `None` when the run does not finish
/// or shows no oscillation.
fn measure<M: Model<N> + Dynamics<N>, const N: usize>(
    model: &M,
    start: &Motion,
    predicted: f64,
) -> Result<Option<f64>, StudyError> {
    let omega0 = start.precession.abs();
    let period = std::f64::consts::TAU / (predicted * omega0);
    let mut m = *start;
    m.alpha += NUDGE * start.alpha;
    let y0 = model.state(&m);
    let settings = Settings {
        rtol: 1e-11,
        atol: 1e-13,
        ..Settings::default()
    };
    let sol = solve(
        Problem::new(model, 0.0, y0, 8.0 * period).sampled(period / 100.0),
        &settings,
    )?;
    if !sol.ending.is_complete() {
        return Ok(None);
    }
    let alpha: Vec<f64> = sol.y.iter().map(|y| model.motion(y).alpha).collect();
    Ok(angular_frequency(&sol.t, &alpha).map(|w| w / omega0))
}

/// Measures the toy's uniform disk (a = 37.5 mm, k = 1/4) at tilts 5, 10, ..., 85 degrees,
/// the tilts on rayon's threads (each measurement is independent; the order of the result is
/// the tilts' whatever the threads do).
pub fn compute() -> Result<Measured, StudyError> {
    use rayon::prelude::*;
    let disk = Disk::uniform(0.0375);
    let k = disk.k;
    let rolling = Rolling::<4>::new(disk, Extras::default(), None);
    let frictionless = Frictionless::<3>::new(disk, 0.0, Extras::default());
    let per_tilt = |i: u32| -> Result<[Option<(f64, f64)>; 3], StudyError> {
        let deg = 5.0 * i as f64;
        let a = deg.to_radians();
        let m0 = steady_motion(&disk, a, 0.0)?;
        let rolled0 = match linearized_ratio(&rolling, &m0) {
            Some(p) => measure(&rolling, &m0, p)?.map(|r| (deg, r)),
            None => None,
        };
        let slid0 = match linearized_ratio(&frictionless, &m0) {
            Some(p) => measure(&frictionless, &m0, p)?.map(|r| (deg, r)),
            None => None,
        };
        let mh = steady_motion(&disk, a, 0.5 * disk.a)?;
        let rolled_half = match linearized_ratio(&rolling, &mh) {
            Some(p) => measure(&rolling, &mh, p)?.map(|r| (deg, r)),
            None => None,
        };
        Ok([rolled0, rolled_half, slid0])
    };
    let measured: Vec<[Option<(f64, f64)>; 3]> = (1..=17_u32)
        .into_par_iter()
        .map(per_tilt)
        .collect::<Result<_, _>>()?;
    Ok(Measured {
        k,
        rolled0: measured.iter().filter_map(|m| m[0]).collect(),
        rolled_half: measured.iter().filter_map(|m| m[1]).collect(),
        slid0: measured.iter().filter_map(|m| m[2]).collect(),
    })
}
