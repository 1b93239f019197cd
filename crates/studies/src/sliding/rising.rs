//! Sec. 10, "rising": a disk launched spinning about a nearly vertical diameter rises toward the
//! vertical before it falls, the paper argues, only when its contact point slides (the friction
//! of the slip gives the torque $\mathbf N_s = -aF_s\hat{\mathbf 1}$ that turns $\mathbf L$ up).
//!
//! **The launch** (the section's premise): tilt $\alpha_0 = 85°$, the disk turning about the
//! vertical through its centre at $\Omega = 1.5\sqrt{g/ak}$, above eq 65's sleeping threshold
//! $\sqrt{g/ak}$, its centre at rest. Turning about that axis, the material point at the contact
//! slides at $\Omega a\cos\alpha_0$ (0.16 m/s for the toy disk). The same launch is run
//! - without friction ($\mu = 0$),
//! - with Coulomb friction over a range of $\mu$ (the sliding model decides when the slip
//!   stops), and
//! - rolling from the start: the rolling state with the same $\alpha_0$, $\Omega$ and
//!   $\omega_1 = 0$ (centre at rest, contact point at rest), on a table whose friction it
//!   never exhausts (no switch is allowed).
//!
//! **What "rising" is here.** The tilt nutates in every case, and a launch off the steady motion
//! may well first swing toward the vertical without friction: that swing comes back. Rising is
//! a lasting gain: the lowest tilt over the second half of a 3 s run, minus $\alpha_0$. A
//! conservative motion (no slip, or no friction) returns to its launch tilt, a turning point of
//! its nutation, so its rise is zero to the sampling; a disk that has risen stays above it.

use nalgebra::Vector3;
use physics::disk::Disk;
use physics::model::lab_frame::Snapshot;
use physics::model::sliding::contact_events::contact_events;
use physics::model::sliding::{Friction, Sliding};
use physics::model::Motion;
use physics::solve::{Event, Settings, SettingsError, State};
use serde::Serialize;

/// The launch tilt $\alpha_0$ (rad): 5 degrees from the vertical.
pub const LAUNCH_TILT: f64 = 85.0 * std::f64::consts::PI / 180.0;
/// The launch rate in units of eq 65's threshold $\sqrt{g/ak}$.
pub const LAUNCH_OVER_THRESHOLD: f64 = 1.5;
/// How long each launch is run (s).
pub const DURATION: f64 = 3.0;
/// The Coulomb coefficients tried.
pub const MUS: [f64; 4] = [0.05, 0.1, 0.3, 1.0];
/// Sampling of the tilt (s).
const SAMPLE: f64 = 1e-3;

/// One launch.
#[derive(Debug, Clone, PartialEq, Serialize, schemars::JsonSchema)]
pub struct RisingCase {
    /// "no friction", "Coulomb friction" or "rolling".
    pub contact: &'static str,
    /// Coulomb's coefficient ($0$ without friction; the table's for rolling).
    pub mu: f64,
    /// Lowest tilt over the second half of the run, minus the launch tilt (deg); positive: risen.
    pub rise_deg: f64,
    /// Highest tilt over the run (deg).
    pub highest_deg: f64,
    /// Time the contact point spent sliding (s).
    pub slip_time: f64,
    /// Stick, slip and contact switches in the run.
    pub switches: usize,
}

/// The study: every launch (module documentation).
#[derive(Debug, Clone, PartialEq, Serialize, schemars::JsonSchema)]
pub struct Rising {
    /// Launch tilt (deg).
    pub launch_tilt_deg: f64,
    /// Launch rate $\Omega$ (rad/s).
    pub launch_rate: f64,
    /// Eq 65's threshold $\sqrt{g/ak}$ as used (rad/s).
    pub threshold: f64,
    /// Contact point's slide at launch, $\Omega a\cos\alpha_0$ (m/s).
    pub launch_slip: f64,
    /// The launches: no friction, then each $\mu$ of [`MUS`], then rolling.
    pub cases: Vec<RisingCase>,
}

impl Rising {
    /// Largest rise among the launches whose contact point slid (deg).
    pub fn largest_rise_with_slip(&self) -> f64 {
        self.cases
            .iter()
            .filter(|c| c.slip_time > 0.0 && c.mu > 0.0)
            .map(|c| c.rise_deg)
            .fold(f64::NEG_INFINITY, f64::max)
    }

    /// Largest rise without slip: rolling, or without friction (deg).
    pub fn largest_rise_without_slip(&self) -> f64 {
        self.cases
            .iter()
            .filter(|c| c.slip_time == 0.0 || c.mu == 0.0)
            .map(|c| c.rise_deg)
            .fold(f64::NEG_INFINITY, f64::max)
    }
}

fn no_stops<'a>() -> Vec<Event<'a, 14>> {
    Vec::new()
}

/// Runs every launch of the study for disk `d`, with eq 65's threshold taken as `threshold`
/// (rad/s; the paper's $\sqrt{g/ak}$, passed in so that a check can use the printed form).
pub fn rising(d: &Disk, threshold: f64, settings: &Settings) -> Result<Rising, SettingsError> {
    let omega = LAUNCH_OVER_THRESHOLD * threshold;
    let launch = Motion {
        alpha: LAUNCH_TILT,
        alpha_dot: 0.0,
        precession: omega,
        spin: 0.0,
    };
    let mut cases = Vec::new();
    let spun = |mu: f64, contact: &'static str| -> Result<RisingCase, SettingsError> {
        let model = Sliding::new(
            *d,
            Friction {
                mu,
                restitution: 0.0,
            },
        );
        let y0 = about_the_vertical(&model, &launch, omega);
        run_case(&model, &y0, contact, settings)
    };
    cases.push(spun(0.0, "no friction")?);
    for mu in MUS {
        cases.push(spun(mu, "Coulomb friction")?);
    }
    // Rolling: a table that never lets it slide here (the peak friction it needs is far
    // below 1; a slip would show as switches and is reported).
    let table = Sliding::new(
        *d,
        Friction {
            mu: 1.0,
            restitution: 0.0,
        },
    );
    let y0 = table.start_state(&launch);
    cases.push(run_case(&table, &y0, "rolling", settings)?);
    Ok(Rising {
        launch_tilt_deg: LAUNCH_TILT.to_degrees(),
        launch_rate: omega,
        threshold,
        launch_slip: omega * d.a * LAUNCH_TILT.cos(),
        cases,
    })
}

/// The launch state: tilt and heading of `m`, centre at rest at its height, angular velocity
/// $\Omega\hat{\mathbf z}$ (a turn about the vertical through the centre).
fn about_the_vertical(model: &Sliding, m: &Motion, omega: f64) -> State<14> {
    let mut y = model.start_state(m);
    for i in 10..13 {
        y[i] = 0.0;
    }
    let r = Snapshot::of(model.disk.a, &y).rotation;
    let body = r.inverse() * Vector3::new(0.0, 0.0, omega);
    for i in 0..3 {
        y[4 + i] = body[i];
    }
    y
}

fn run_case(
    model: &Sliding,
    y0: &State<14>,
    contact: &'static str,
    settings: &Settings,
) -> Result<RisingCase, SettingsError> {
    let run = model.run(y0, DURATION, settings, Some(SAMPLE), &no_stops)?;
    let tilt = |y: &State<14>| {
        let s = Snapshot::of(model.disk.a, y);
        s.sin_alpha.atan2(s.cos_alpha)
    };
    let lowest_late = run
        .t
        .iter()
        .zip(&run.y)
        .filter(|(t, _)| **t >= 0.5 * DURATION)
        .map(|(_, y)| tilt(y))
        .fold(f64::INFINITY, f64::min);
    let highest = run.y.iter().map(tilt).fold(f64::NEG_INFINITY, f64::max);
    let slip_time = run.slip_time();
    Ok(RisingCase {
        contact,
        mu: model.friction.mu,
        rise_deg: (lowest_late - LAUNCH_TILT).to_degrees(),
        highest_deg: highest.to_degrees(),
        slip_time,
        switches: contact_events(&run).len(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sliding_contact_raises_the_disk_and_no_slip_or_no_friction_does_not() {
        let d = physics::disk::toy_disk();
        let settings = Settings::dop853(1e-10, 1e-12);
        let r = rising(&d, (d.g / (d.a * d.k)).sqrt(), &settings).unwrap();
        for c in &r.cases {
            eprintln!("{c:?}");
        }
        // The conservative launches come back to their launch tilt (a turning point).
        assert!(r.largest_rise_without_slip().abs() < 0.01, "{r:?}");
        assert!(r.largest_rise_with_slip() > 1.0, "{r:?}");
        let rolling = r.cases.last().unwrap();
        assert_eq!((rolling.contact, rolling.switches), ("rolling", 0));
        assert!(r.cases[0].rise_deg < -10.0, "without friction it falls");
    }
}
