//! Sec. 6's radial slippage: a steady roll whose $|b|$ needs more friction than the table gives
//! (eq 42, $\mu < |b|/(ak\sin\alpha_0)$) slips, and the slip reduces $|b|$; the centre's path
//! becomes an inward spiral toward $b = 0$, the paper argues.
//!
//! The study starts the sliding model in a steady roll $(\alpha_0, b_0)$ and runs it for
//! [`DURATION`] seconds. It reports the radius of the centre's path over the last second (a
//! least-squares circle through the sampled centres: in steady motion that radius is $|b|$),
//! the tilt at the end, how long the contact slid, and eq 42's largest $|b|$ at the start.
//! Without dissipation nothing drives $\alpha$ down here, so only the first part of the
//! argument is tested: whether slipping reduces $|b|$.

use nalgebra::{Matrix3, Vector3};
use physics::disk::Disk;
use physics::model::lab_frame::Snapshot;
use physics::model::sliding::{Friction, Sliding};
use physics::model::steady::steady_motion;
use physics::solve::{Ending, Event, Settings, SettingsError};
use serde::Serialize;

/// How long each start is run (s).
pub const DURATION: f64 = 3.0;
/// The steady starts $(\alpha_0\ {\rm rad}, b_0\ {\rm m})$ of the toy disk, each slipping at the
/// coefficients of [`MUS`] except where eq 42 allows it to roll.
pub const STARTS: [(f64, f64); 4] = [(0.4, 0.02), (0.4, 0.005), (0.2, 0.004), (1.0, -0.003)];
/// The Coulomb coefficients tried.
pub const MUS: [f64; 3] = [0.1, 0.3, 0.6];
const SAMPLE: f64 = 1e-3;

/// One start on one table.
#[derive(Debug, Clone, PartialEq, Serialize, schemars::JsonSchema)]
pub struct Spiral {
    /// Steady start tilt (rad).
    pub alpha0: f64,
    /// Steady start $b$ (m).
    pub b0: f64,
    /// Coulomb's coefficient.
    pub mu: f64,
    /// Eq 42's largest $|b|$ that rolls at $\alpha_0$: $\mu ak\sin\alpha_0$ (m).
    pub b_eq42: f64,
    /// Radius of the centre's path over the last second (m); `None` if the run ended early.
    pub radius_end: Option<f64>,
    /// Tilt at the end (rad).
    pub alpha_end: f64,
    /// Time the contact slid (s).
    pub slip_time: f64,
    /// How the run ended.
    pub ending: String,
}

fn no_stops<'a>() -> Vec<Event<'a, 14>> {
    Vec::new()
}

/// The radius of the least-squares circle through `points` (Kåsa's algebraic fit:
/// $x^2 + y^2 + Dx + Ey + F = 0$ solved as a linear least-squares problem); `None` for fewer
/// than three points or points on a line.
pub fn circle_radius(points: &[(f64, f64)]) -> Option<f64> {
    if points.len() < 3 {
        return None;
    }
    let mut normal = Matrix3::<f64>::zeros();
    let mut rhs = Vector3::<f64>::zeros();
    for &(x, y) in points {
        let row = Vector3::new(x, y, 1.0);
        normal += row * row.transpose();
        rhs -= row * (x * x + y * y);
    }
    let s = normal.lu().solve(&rhs)?;
    let r2 = 0.25 * (s[0] * s[0] + s[1] * s[1]) - s[2];
    (r2 > 0.0 && r2.is_finite()).then(|| r2.sqrt())
}

/// Runs the steady start `(alpha0, b0)` of disk `d` on a table with coefficient `mu`.
pub fn spiral(
    d: &Disk,
    alpha0: f64,
    b0: f64,
    mu: f64,
    settings: &Settings,
) -> Result<Option<Spiral>, SettingsError> {
    let Ok(start) = steady_motion(d, alpha0, b0) else {
        return Ok(None);
    };
    let model = Sliding::new(
        *d,
        Friction {
            mu,
            restitution: 0.0,
        },
    );
    let run = model.run(
        &model.start_state(&start),
        DURATION,
        settings,
        Some(SAMPLE),
        &no_stops,
    )?;
    let finished = run.ending == Ending::TimeReached;
    let last: Vec<(f64, f64)> = run
        .t
        .iter()
        .zip(&run.y)
        .filter(|(t, _)| **t >= DURATION - 1.0)
        .map(|(_, y)| {
            let c = Snapshot::of(d.a, y).centre;
            (c.x, c.y)
        })
        .collect();
    let slip_time = run.slip_time();
    let alpha_end = run
        .y
        .last()
        .map_or(f64::NAN, |y| Snapshot::of(d.a, y).motion().alpha);
    Ok(Some(Spiral {
        alpha0,
        b0,
        mu,
        b_eq42: mu * d.a * d.k * alpha0.sin(),
        radius_end: if finished { circle_radius(&last) } else { None },
        alpha_end,
        slip_time,
        ending: run.ending.to_string(),
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_circle_fit_finds_a_known_radius() {
        let pts: Vec<(f64, f64)> = (0..50)
            .map(|i| {
                let t = i as f64 * 0.1;
                (1.0 + 0.3 * t.cos(), -2.0 + 0.3 * t.sin())
            })
            .collect();
        assert!((circle_radius(&pts).unwrap() - 0.3).abs() < 1e-12);
        assert!(circle_radius(&[(0.0, 0.0), (1.0, 1.0), (2.0, 2.0)]).is_none());
    }

    #[test]
    fn slipping_reduces_a_positive_b() {
        let d = physics::disk::toy_disk();
        let settings = Settings::dop853(1e-10, 1e-12);
        for (alpha0, b0) in [(0.4, 0.02), (0.2, 0.004)] {
            for mu in [0.1, 0.3] {
                let s = spiral(&d, alpha0, b0, mu, &settings).unwrap().unwrap();
                eprintln!("{s:?}");
                assert!(b0 > s.b_eq42, "the start must slip: {s:?}");
                assert!(s.slip_time > 0.0, "{s:?}");
                let r = s.radius_end.unwrap();
                assert!(r < 0.5 * b0, "b not reduced: {s:?}");
            }
        }
    }
}
