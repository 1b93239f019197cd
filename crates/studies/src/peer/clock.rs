//! The peer's rows on the clock of the motion they record.
//!
//! The peer writes a row at each print time $t_k = k\,\Delta t$ with the state its DOP853 dense
//! output gives there (`model2/solout.f90`), except where it restarts its integration
//! (`model2/integ.f90`):
//! - **at its start** it assumes sliding; a relock it finds at its first print step is not
//!   carried out (its first output call leaves before switching), and it restarts sliding from
//!   the start with a seed slip $\max(10^4\,{\rm atol}, 5\varepsilon)$, printing the start again
//!   at $t = 0$. Where that seed is below its relock threshold it relocks once more, this time
//!   with its clock set back by up to a print step while it keeps the state: a row at $t = 0$
//!   then carries the state one print step on, and every later row is labelled that much early;
//! - **on a switch to rolling**, found at a print time $t_s$ whose slip speed is below its
//!   threshold, it sets its clock back to the relock $t^* \le t_s$ it places at the least value
//!   of the parabola through its last three printed slip speeds, but keeps the state its DOP853
//!   returned at the end of the step that holds $t_s$ (it copies the located state only on a
//!   switch to sliding), so its rolling rows carry a state from later than their label.
//!
//! Both are breaks of its clock at a row where its label repeats or its mode turns to rolling.
//! At such a break the time that passed between the row before and the row after is read from
//! the peer's own printed state: the advance of its Euler angles over their mean rate,
//! $\Delta t = \sum_i \Delta q_i\,\bar{\dot q}_i / \sum_i \bar{\dot q}_i^2$ with
//! $\dot\theta = \omega_1$, $\dot\psi = \omega_3/\cos\theta$, $\dot\phi = \omega_2 - \omega_3\tan\theta$
//! (module [`super::mapping`]); the trapezoid's error is $O(\Delta t^3)$. Elsewhere rows are one
//! print step apart, as the peer writes them.

use super::result::PeerRow;

/// A break of the peer's clock: where its label no longer tells the time of its state.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Break {
    /// The row (0 = the first after the header).
    pub row: usize,
    /// Its label, the peer's clock (s).
    pub label: f64,
    /// The time of its state minus its label, from here on (s).
    pub offset: f64,
    /// True at a switch to rolling, false at a repeated label.
    pub relock: bool,
}

/// The rows with `t` the time of their state, and the breaks of the peer's clock (module
/// documentation).
pub fn on_its_clock(rows: &[PeerRow]) -> (Vec<PeerRow>, Vec<Break>) {
    let mut out: Vec<PeerRow> = Vec::with_capacity(rows.len());
    let mut breaks = Vec::new();
    let mut offset = 0.0;
    for (i, r) in rows.iter().enumerate() {
        let mut row = r.clone();
        if let Some(before) = i.checked_sub(1).map(|k| &rows[k]) {
            let repeated = r.t <= before.t;
            let relock = r.rolling && !before.rolling;
            if repeated || relock {
                let gap = advance(before, r).unwrap_or(r.t - before.t);
                let was = out[i - 1].t;
                let new_offset = was + gap.max(0.0) - r.t;
                breaks.push(Break {
                    row: i,
                    label: r.t,
                    offset: new_offset,
                    relock,
                });
                offset = new_offset;
            }
        }
        row.t = r.t + offset;
        out.push(row);
    }
    (out, breaks)
}

/// The time between two rows read from the advance of the Euler angles over their mean rate,
/// `None` where the angles do not move.
fn advance(a: &PeerRow, b: &PeerRow) -> Option<f64> {
    let rates = |r: &PeerRow| {
        let s = &r.state;
        let [w1, w2, w3] = s.omega;
        [w3 / s.theta.cos(), w1, w2 - w3 * s.theta.tan()]
    };
    let (ra, rb) = (rates(a), rates(b));
    let dq = [
        b.state.psi - a.state.psi,
        b.state.theta - a.state.theta,
        b.state.phi - a.state.phi,
    ];
    let (mut num, mut den) = (0.0, 0.0);
    for k in 0..3 {
        let rate = 0.5 * (ra[k] + rb[k]);
        num += dq[k] * rate;
        den += rate * rate;
    }
    (den > 1e-12 && num.is_finite()).then(|| num / den)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::peer::mapping::PeerState;

    /// A row of a disk precessing at 10 rad/s, spinning at 20 rad/s, at the time `t` of its
    /// state and labelled `label`.
    fn row(label: f64, t: f64, rolling: bool) -> PeerRow {
        PeerRow {
            t: label,
            state: PeerState {
                psi: 10.0 * t,
                theta: 0.5,
                phi: 20.0 * t,
                omega: [
                    0.0,
                    20.0 + 10.0 * 0.5f64.tan() * 0.5f64.cos(),
                    10.0 * 0.5f64.cos(),
                ],
                centre: [0.0; 3],
                velocity: [0.0; 3],
            },
            rolling,
            slip_speed: 0.0,
            normal: 1.0,
            tangential: 0.0,
        }
    }

    #[test]
    fn a_row_one_step_on_at_a_repeated_label_moves_every_later_row() {
        let rows = vec![
            row(0.0, 0.0, false),
            row(0.0, 0.0, false),
            row(0.0, 1e-3, true),
            row(1e-3, 2e-3, true),
        ];
        let (timed, breaks) = on_its_clock(&rows);
        let t: Vec<f64> = timed.iter().map(|r| r.t).collect();
        for (got, want) in t.iter().zip([0.0, 0.0, 1e-3, 2e-3]) {
            assert!((got - want).abs() < 1e-12, "{t:?}");
        }
        assert_eq!(breaks.len(), 2);
        // The start printed again is no break of the clock's reading.
        assert_eq!(breaks[0].offset, 0.0);
    }

    #[test]
    fn a_relock_whose_state_is_later_than_its_label_is_read_back() {
        let rows = vec![
            row(0.010, 0.010, false),
            row(0.011, 0.011, false),
            row(0.012, 0.012 + 3e-4, true),
            row(0.013, 0.013 + 3e-4, true),
        ];
        let (timed, breaks) = on_its_clock(&rows);
        assert!((timed[3].t - 0.0133).abs() < 1e-12, "{}", timed[3].t);
        assert!(breaks[0].relock && (breaks[0].offset - 3e-4).abs() < 1e-12);
        // Rows without a break keep their labels.
        assert_eq!(on_its_clock(&rows[..2]).0, rows[..2].to_vec());
    }
}
