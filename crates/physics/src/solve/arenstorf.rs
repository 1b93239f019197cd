//! Arenstorf's restricted three-body orbit (Hairer, Norsett and Wanner, *Solving ODEs I*, section
//! II.0), the test problem Hairer published with `dop853`: a periodic orbit whose steps vary over
//! four decades along one period, so that a closed orbit tests an integrator's error control and
//! its dense output where the steps change fastest. Not a disk's motion: written here so that the
//! crate's tests and the workspace's solver tests integrate the same problem.

use super::{Dynamics, State};

/// The moon's share of the mass, $\mu$.
const MU: f64 = 0.012277471;

/// The orbit's period, to the digits Hairer gives.
#[allow(clippy::excessive_precision)]
pub const PERIOD: f64 = 17.065_216_560_157_962_558_891_720_624_9;

/// The restricted three-body problem in the rotating frame: $(x, y, \dot x, \dot y)$.
pub struct Arenstorf;

/// The start of the periodic orbit: $(0.994, 0, 0, -2.00158510637908252240537862224)$.
pub fn start() -> State<4> {
    State::<4>::new(0.994, 0.0, 0.0, -2.001_585_106_379_082_5)
}

impl Dynamics<4> for Arenstorf {
    fn rhs(&self, y: &State<4>, dy: &mut State<4>) {
        let mu1 = 1.0 - MU;
        let d1 = ((y[0] + MU).powi(2) + y[1] * y[1]).powf(1.5);
        let d2 = ((y[0] - mu1).powi(2) + y[1] * y[1]).powf(1.5);
        dy[0] = y[2];
        dy[1] = y[3];
        dy[2] = y[0] + 2.0 * y[3] - mu1 * (y[0] + MU) / d1 - MU * (y[0] - mu1) / d2;
        dy[3] = y[1] - 2.0 * y[2] - mu1 * y[1] / d1 - MU * y[1] / d2;
    }
}
