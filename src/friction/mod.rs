//! The paper's claims that need friction, checked with the sliding model
//! ([`crate::model::sliding`]): one study per file, each a pure function returning numbers.
//!
//! - [`slip_onset`]: the friction that steady motion with $b > 0$ needs (eq 42) against the
//!   onset of slip found by integration;
//! - [`negative_b`]: whether steady motion with $b < 0$ survives a realistic $\mu$ (eq 43).
//! - [`contact_loss`]: whether a spin-down with eq 75's drag and Coulomb friction loses contact (the premise of eqs 80-81) or slips first;
//! - [`spiral`]: whether slipping reduces $|b|$ (the inward spiral of sec. 6);
//! - [`rising`]: whether a disk spun about a nearly vertical diameter rises only when it slides (sec. 10).

pub mod contact_loss;
pub mod negative_b;
pub mod rising;
pub mod slip_onset;
pub mod spiral;

use crate::disk::Disk;
use crate::model::sliding::{scene::contact_events, Friction, Sliding};
use crate::model::steady::steady_motion;
use crate::solve::{Event, Method, Settings};

/// How long a steady start is run to see whether it slips (s).
pub const WATCH: f64 = 0.02;

fn no_stops<'a>() -> Vec<Event<'a, 14>> {
    Vec::new()
}

/// True when the steady rolling motion $(\alpha_0, b)$ of disk `d` on a table with Coulomb
/// coefficient `mu` starts to slip (or leaves the table) within [`WATCH`] seconds; `None` when
/// no such steady motion exists or the run fails.
pub fn slips(d: &Disk, alpha0: f64, b: f64, mu: f64) -> Option<bool> {
    let m = steady_motion(d, alpha0, b).ok()?;
    let model = Sliding::new(
        *d,
        Friction {
            mu,
            restitution: 0.0,
        },
    );
    let settings = Settings {
        method: Method::Dop853,
        rtol: 1e-10,
        atol: 1e-12,
        ..Settings::default()
    };
    let y0 = model.start_state(&m);
    let run = model.run(&y0, WATCH, &settings, None, &no_stops).ok()?;
    let started_rolling = run.mode.first().map(|m| m.name()) == Some("stick");
    Some(!started_rolling || !contact_events(&run).is_empty())
}

/// The boundary between `lo` (predicate false) and `hi` (true) by bisection to `width`.
pub(crate) fn bisect(
    mut lo: f64,
    mut hi: f64,
    width: f64,
    pred: impl Fn(f64) -> Option<bool>,
) -> Option<f64> {
    while (hi - lo).abs() > width {
        let mid = 0.5 * (lo + hi);
        if pred(mid)? {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Some(0.5 * (lo + hi))
}
