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
//! At such a break, between the row $a$ before and the row $b$ after it, the time
//! $\Delta t = t_b - t_a$ that passed is read from the peer's own printed state: the advance of
//! its Euler angles $q_i$ is the integral of their rates,
//! $$ \Delta q_i = \int_{t_a}^{t_a + \Delta t} \dot q_i\,dt, \qquad
//!    \dot\theta = \omega_1,\ \dot\psi = \omega_3/\cos\theta,\ \dot\phi = \omega_2 - \omega_3\tan\theta $$
//! (module [`super::mapping`]), with each rate the cubic through its printed values at $a$, $b$
//! and their nearest rows of other times on either side (at $t_a$ minus a print step, at
//! $t_b$ plus one, and so on), integrated exactly by the two-point Gauss rule. The angles are
//! weighted by their mean rates $\bar{\dot q}_i$,
//! $\Delta t = \sum_i \Delta q_i\,\bar{\dot q}_i / \sum_i \bar{\dot q}_i^2$, which is solved by
//! fixed-point iteration from the trapezoid ($\bar{\dot q}_i$ the mean of the two rows' rates).
//! A neighbour beyond another break takes the time read there, so the breaks are read again in
//! turn until their readings agree. The cubic's error is $O(\Delta t^5)$ against the trapezoid's
//! $O(\Delta t^3)$ (its $\Delta t^3\dddot q/12$, which a fast nutation makes large). Elsewhere
//! rows are one print step apart, as the peer writes them.

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

/// Times every break is read again, each with its neighbours' latest times.
const SWEEPS: usize = 4;
/// Fixed-point iterations of one reading.
const ITERATIONS: usize = 8;

/// The rows with `t` the time of their state, and the breaks of the peer's clock (module
/// documentation).
pub fn on_its_clock(rows: &[PeerRow]) -> (Vec<PeerRow>, Vec<Break>) {
    let at: Vec<usize> = (1..rows.len())
        .filter(|&i| rows[i].t <= rows[i - 1].t || (rows[i].rolling && !rows[i - 1].rolling))
        .collect();
    let mut gaps: Vec<f64> = at
        .iter()
        .map(|&i| {
            let (a, b) = (&rows[i - 1], &rows[i]);
            trapezoid(a, b).unwrap_or(b.t - a.t).max(0.0)
        })
        .collect();
    for _ in 0..SWEEPS {
        for k in 0..at.len() {
            let times = times_of(rows, &at, &gaps);
            if let Some(g) = read_between(rows, &times, at[k]) {
                gaps[k] = g.max(0.0);
            }
        }
    }
    let times = times_of(rows, &at, &gaps);
    let breaks = at
        .iter()
        .map(|&i| Break {
            row: i,
            label: rows[i].t,
            offset: times[i] - rows[i].t,
            relock: rows[i].rolling && !rows[i - 1].rolling,
        })
        .collect();
    let out = rows
        .iter()
        .zip(&times)
        .map(|(r, &t)| PeerRow { t, ..r.clone() })
        .collect();
    (out, breaks)
}

/// The time of each row's state: its label, moved at each break `at[k]` so that it follows the
/// row before by `gaps[k]`.
fn times_of(rows: &[PeerRow], at: &[usize], gaps: &[f64]) -> Vec<f64> {
    let mut times: Vec<f64> = Vec::with_capacity(rows.len());
    let mut offset = 0.0;
    let mut next = at.iter().zip(gaps).peekable();
    for (i, r) in rows.iter().enumerate() {
        if let Some((_, &gap)) = next.next_if(|(&row, _)| row == i) {
            offset = times[i - 1] + gap - r.t;
        }
        times.push(r.t + offset);
    }
    times
}

/// The rates of the peer's angles $(\dot\psi, \dot\theta, \dot\phi)$ at a row.
fn rates(r: &PeerRow) -> [f64; 3] {
    let s = &r.state;
    let [w1, w2, w3] = s.omega;
    [w3 / s.theta.cos(), w1, w2 - w3 * s.theta.tan()]
}

/// The advance of the peer's angles $(\psi, \theta, \phi)$ from row `a` to row `b`.
fn advance(a: &PeerRow, b: &PeerRow) -> [f64; 3] {
    [
        b.state.psi - a.state.psi,
        b.state.theta - a.state.theta,
        b.state.phi - a.state.phi,
    ]
}

/// $\sum_i \Delta q_i\,\bar{\dot q}_i / \sum_i \bar{\dot q}_i^2$, `None` where the angles do not
/// turn or a rate is not finite.
fn weighted(dq: [f64; 3], mean: [f64; 3]) -> Option<f64> {
    let num: f64 = (0..3).map(|k| dq[k] * mean[k]).sum();
    let den: f64 = mean.iter().map(|m| m * m).sum();
    (den > 1e-12 && num.is_finite() && den.is_finite()).then(|| num / den)
}

/// The time between two rows read by the trapezoid: each angle's mean rate the mean of its
/// rates at the two rows; `None` where the angles do not turn.
pub fn trapezoid(a: &PeerRow, b: &PeerRow) -> Option<f64> {
    let (ra, rb) = (rates(a), rates(b));
    weighted(
        advance(a, b),
        std::array::from_fn(|k| 0.5 * (ra[k] + rb[k])),
    )
}

/// The time from row `b - 1` to row `b` read with each rate the cubic through its values at the
/// two rows and their nearest rows of other times (module documentation); `times` gives every
/// other row's time, and the rows from `b` on move with the reading. The trapezoid where there
/// is no other row; `None` where the angles do not turn.
pub fn read_between(rows: &[PeerRow], times: &[f64], b: usize) -> Option<f64> {
    let a = b.checked_sub(1)?;
    let mut gap = trapezoid(&rows[a], &rows[b])?;
    // Rows closer in time than this are one time to the cubic.
    let apart = print_step(rows) / 100.0;
    if gap <= apart {
        return Some(gap);
    }
    let dq = advance(&rows[a], &rows[b]);
    for _ in 0..ITERATIONS {
        let shift = times[a] + gap - times[b];
        let time = |j: usize| if j >= b { times[j] + shift } else { times[j] };
        let mut nodes = vec![a, b];
        for j in [a.checked_sub(1), Some(b + 1), a.checked_sub(2), Some(b + 2)]
            .into_iter()
            .flatten()
        {
            if nodes.len() < 4
                && j < rows.len()
                && nodes.iter().all(|&n| (time(n) - time(j)).abs() > apart)
            {
                nodes.push(j);
            }
        }
        let at: Vec<f64> = nodes.iter().map(|&j| time(j)).collect();
        let values: Vec<[f64; 3]> = nodes.iter().map(|&j| rates(&rows[j])).collect();
        // The two-point Gauss rule, exact for a cubic.
        let (mid, half) = (times[a] + 0.5 * gap, 0.5 * gap / 3f64.sqrt());
        let (w1, w2) = (lagrange(&at, mid - half), lagrange(&at, mid + half));
        let mean = std::array::from_fn(|k| {
            (0..nodes.len())
                .map(|n| 0.5 * (w1[n] + w2[n]) * values[n][k])
                .sum()
        });
        let next = weighted(dq, mean)?;
        let done = (next - gap).abs() <= 1e-16;
        gap = next;
        if done {
            break;
        }
    }
    Some(gap)
}

/// The Lagrange basis of the nodes `at`, evaluated at `t`.
fn lagrange(at: &[f64], t: f64) -> Vec<f64> {
    (0..at.len())
        .map(|i| {
            (0..at.len())
                .filter(|&j| j != i)
                .map(|j| (t - at[j]) / (at[i] - at[j]))
                .product()
        })
        .collect()
}

/// The peer's print step: the least step between its labels (1 ms where none advances).
fn print_step(rows: &[PeerRow]) -> f64 {
    let least = rows
        .windows(2)
        .map(|w| w[1].t - w[0].t)
        .filter(|d| *d > 0.0)
        .fold(f64::INFINITY, f64::min);
    if least.is_finite() {
        least
    } else {
        1e-3
    }
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

    /// A row of a disk nutating at $\nu = 100$ rad/s about a precession at 10 rad/s and a spin
    /// at 20 rad/s: $\theta = 0.5 + 0.01\sin\nu t$, $\psi = 10t + 0.05\sin\nu t$,
    /// $\phi = 20t + 0.05\cos\nu t$, at the time `t` of its state and labelled `label`.
    fn nutating(label: f64, t: f64, rolling: bool) -> PeerRow {
        let nu = 100.0;
        let (s, c) = (nu * t).sin_cos();
        let (theta, theta_dot) = (0.5 + 0.01 * s, 0.01 * nu * c);
        let psi_dot = 10.0 + 0.05 * nu * c;
        let phi_dot = 20.0 - 0.05 * nu * s;
        let w3 = psi_dot * theta.cos();
        let mut r = row(label, t, rolling);
        r.state.psi = 10.0 * t + 0.05 * s;
        r.state.theta = theta;
        r.state.phi = 20.0 * t + 0.05 * c;
        r.state.omega = [theta_dot, phi_dot + w3 * theta.tan(), w3];
        r
    }

    /// On a fast nutation the trapezoid misreads a print step by its $\Delta t^3\dddot q/12$,
    /// the cubic through the neighbouring rows' rates reads it to its $O(\Delta t^5)$.
    #[test]
    fn the_cubic_reads_a_fast_nutation_where_the_trapezoid_does_not() {
        let h = 1e-3;
        // The start, printed again, then the state 1.3 print steps on labelled at 0 (a
        // restart), then a relock whose state is 2e-4 s later than its label.
        let (late, relock) = (1.3 * h, 2e-4);
        let mut rows = vec![nutating(0.0, 0.0, false), nutating(0.0, 0.0, false)];
        for k in 0..4 {
            rows.push(nutating(k as f64 * h, late + k as f64 * h, false));
        }
        for k in 4..10 {
            rows.push(nutating(k as f64 * h, late + relock + k as f64 * h, true));
        }
        let (timed, breaks) = on_its_clock(&rows);
        let offsets: Vec<f64> = breaks.iter().map(|b| b.offset).collect();
        assert_eq!(breaks.len(), 3, "{breaks:?}");
        assert!((offsets[1] - late).abs() < 1e-9, "{offsets:?}");
        assert!((offsets[2] - late - relock).abs() < 1e-9, "{offsets:?}");
        // Every row at the time of its state.
        let truth = [0.0, 0.0]
            .into_iter()
            .chain((0..4).map(|k| late + k as f64 * h))
            .chain((4..10).map(|k| late + relock + k as f64 * h));
        for (r, want) in timed.iter().zip(truth) {
            assert!((r.t - want).abs() < 1e-9, "{} {want}", r.t);
        }
        // The trapezoid at the same breaks is off by more than a hundred times as much.
        let trapezoid_off = (trapezoid(&rows[1], &rows[2]).unwrap() - late).abs();
        assert!(trapezoid_off > 1e-7, "{trapezoid_off:e}");
    }
}
