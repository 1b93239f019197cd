//! The changes between rolling and sliding of the two runs, paired by direction and time.
//!
//! The peer prints no switch time; its rows bound it (module [`super::clock`] for their times):
//! it detects a slip's end at a print step and locates the relock on a quadratic through its
//! last three print points, within the print step before the last row it prints sliding; it
//! detects a slip's start at a print step it does not print, locates it within the print step
//! before, and prints that step's row sliding. So a relock lies in
//! $[T_{\rm last\,sliding} - \Delta t, T_{\rm last\,sliding}]$ and a slip's start in
//! $[T_{\rm first\,sliding} - \Delta t, T_{\rm first\,sliding}]$. A switch of this tool pairs
//! with a peer switch of the same direction, the nearest to its interval within
//! [`WINDOW`] print steps, one to one; those left over are listed as unpaired.

use serde::Serialize;

/// How far, in print steps, a switch of this tool may lie from the peer's interval to pair.
pub const WINDOW: f64 = 5.0;

/// A change of mode: `to_rolling` true for a relock, false for a slip's start.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PeerSwitch {
    /// The direction.
    pub to_rolling: bool,
    /// The interval of the peer's located switch (s).
    pub within: (f64, f64),
}

/// A peer switch and this tool's of the same direction.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Paired {
    /// The peer's.
    pub peer: PeerSwitch,
    /// This tool's time (s).
    pub tool: f64,
}

impl Paired {
    /// How far this tool's switch lies outside the peer's interval (s), 0 inside it.
    pub fn outside(&self) -> f64 {
        let (lo, hi) = self.peer.within;
        (lo - self.tool).max(self.tool - hi).max(0.0)
    }
}

/// The pairing of two runs' switches.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct Pairing {
    /// Paired, in the peer's order.
    pub paired: Vec<Paired>,
    /// The peer's switches without a partner.
    pub peer_only: Vec<PeerSwitch>,
    /// This tool's switches without a partner: (relock, time).
    pub tool_only: Vec<(bool, f64)>,
}

impl Pairing {
    /// The largest [`Paired::outside`], `None` when nothing paired.
    pub fn largest_outside(&self) -> Option<f64> {
        self.paired.iter().map(Paired::outside).reduce(f64::max)
    }
}

/// Pairs `peer` with `tool` ((relock, time) each), `dt` the print step.
pub fn pair(peer: &[PeerSwitch], tool: &[(bool, f64)], dt: f64) -> Pairing {
    let mut used = vec![false; tool.len()];
    let mut out = Pairing::default();
    for p in peer {
        let (lo, hi) = p.within;
        let best = tool
            .iter()
            .enumerate()
            .filter(|(k, (dir, _))| !used[*k] && *dir == p.to_rolling)
            .map(|(k, (_, t))| (k, (lo - t).max(t - hi).max(0.0)))
            .filter(|(_, d)| *d <= WINDOW * dt)
            .min_by(|a, b| a.1.total_cmp(&b.1));
        match best {
            Some((k, _)) => {
                used[k] = true;
                out.paired.push(Paired {
                    peer: *p,
                    tool: tool[k].1,
                });
            }
            None => out.peer_only.push(*p),
        }
    }
    out.tool_only = tool
        .iter()
        .zip(&used)
        .filter(|(_, u)| !**u)
        .map(|(s, _)| *s)
        .collect();
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn switches_pair_by_direction_and_nearest_time() {
        let sw = |to_rolling, t: f64| PeerSwitch {
            to_rolling,
            within: (t - 1e-3, t),
        };
        // The peer's first relock has no partner here; this tool's slip start pairs with the
        // peer's, not with the relock before it in order.
        let peer = [sw(true, 0.010), sw(false, 0.050), sw(true, 0.100)];
        let tool = [(false, 0.0495), (true, 0.1003), (true, 0.3)];
        let p = pair(&peer, &tool, 1e-3);
        assert_eq!(p.paired.len(), 2);
        assert_eq!(p.peer_only, vec![peer[0]]);
        assert_eq!(p.tool_only, vec![(true, 0.3)]);
        assert_eq!(p.paired[0].outside(), 0.0);
        assert!((p.paired[1].outside() - 3e-4).abs() < 1e-12);
        assert_eq!(pair(&[], &tool, 1e-3).largest_outside(), None);
    }
}
