//! Whether the phase's fit miscounted a turn: the turns it counts against the pitch track's.
//!
//! The phase fit ([`phase_fit`](crate::sound_analysis::phase_fit)) follows the heading block by block, each block's
//! offset known only modulo a turn; a slip of one turn between blocks leaves a heading that fits
//! its blocks as well but runs one turn more or fewer over the record. The pitch track counts the
//! turns independently, as the integral of its fitted rate: between the first block's start
//! $t_a$ and the last block's end $t_b$,
//! $$N = \frac{\Phi(t_b) - \Phi(t_a)}{2\pi}$$
//! for eq 79's heading $\Phi$ with either fit's parameters (a law whose $t_0$ falls before $t_b$
//! counts its turns to its $t_0$), and the track's count has the standard
//! uncertainty $\sigma_N = \sqrt{g^{\mathsf T} \Sigma\, g}$, $g = \partial N/\partial(\beta, t_0,
//! \ln C)$ and $\Sigma$ the track fit's covariance.
//!
//! **Why the turns and not $\beta$ and $t_0$.** Where eq 79 does not hold exactly over the record
//! (a spin-down whose law drifts, [`law_stability`](crate::fit::law_stability)), the two fits weigh the
//! record differently (the track evenly, the phase most near $t_0$), and their $\beta$ and $t_0$
//! differ by many of the track's sigmas though every turn is counted. Both fits follow the same
//! rate on average, so their counts agree to a fraction of a turn all the same; a slip moves
//! the count by a whole turn. A count is called miscounted when it differs from the track's by
//! more than half a turn and by more than [`SIGMAS`] of the track's count.

use crate::fit::eq84_85::phase;
use nalgebra::{SMatrix, SVector};
use serde::Serialize;
use std::f64::consts::TAU;

/// How many of the track's $\sigma_N$ the counts must differ by, besides half a turn, to call a
/// turn miscounted.
pub const SIGMAS: f64 = 3.0;

/// The turns counted between two times by the phase's fit and by the pitch track's.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TurnCount {
    /// From $t_a$ to $t_b$ (s).
    pub from: f64,
    /// (s)
    pub to: f64,
    /// Turns by the phase's fit.
    pub phase: f64,
    /// Turns by the track's fit.
    pub track: f64,
    /// The track's count's standard uncertainty.
    pub sigma: f64,
}

impl TurnCount {
    /// The counts of the laws `phase` and `track` = $(\beta, t_0, \ln C)$ from `from` to `to`,
    /// with `cov` the track's covariance.
    pub fn of(
        phase_law: &SVector<f64, 3>,
        track_law: &SVector<f64, 3>,
        cov: &SMatrix<f64, 3, 3>,
        (from, to): (f64, f64),
    ) -> Self {
        let count = |p: &SVector<f64, 3>| {
            let (a, ga) = heading(p, from);
            let (b, gb) = heading(p, to);
            ((b - a) / TAU, (gb - ga) / TAU)
        };
        let (phase_turns, _) = count(phase_law);
        let (track_turns, g) = count(track_law);
        Self {
            from,
            to,
            phase: phase_turns,
            track: track_turns,
            sigma: (g.transpose() * cov * g)[0].max(0.0).sqrt(),
        }
    }

    /// Whether the phase's count differs from the track's by more than half a turn and by more
    /// than [`SIGMAS`] of the track's uncertainty.
    pub fn miscounted(&self) -> bool {
        let d = (self.phase - self.track).abs();
        !(d <= 0.5 || d <= SIGMAS * self.sigma)
    }
}

/// Eq 79's heading at `t` and its gradient in $(\beta, t_0, \ln C)$: past the law's $t_0$ the
/// disk turns no more, and the heading stays at its value there, 0.
fn heading(p: &SVector<f64, 3>, t: f64) -> (f64, SVector<f64, 3>) {
    if t < p[1] {
        let (phi, _, g) = phase(p, t);
        (phi, g)
    } else {
        (0.0, SVector::zeros())
    }
}

impl std::fmt::Display for TurnCount {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "from {:.3} s to {:.3} s the phase's fit counts {:.2} turns, the pitch track's \
             {:.2} +- {:.2}",
            self.from, self.to, self.phase, self.track, self.sigma
        )
    }
}
