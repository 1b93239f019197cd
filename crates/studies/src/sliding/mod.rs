//! The paper's claims that need friction, checked with the sliding model
//! ([`physics::model::sliding`]): one study per file, each a pure function returning numbers.
//!
//! - [`slip_onset`]: the friction that steady motion with $b > 0$ needs (eq 42) against the
//!   onset of slip found by integration;
//! - [`negative_b`]: whether steady motion with $b < 0$ survives a realistic $\mu$ (eq 43);
//! - [`spiral`]: whether slipping reduces $|b|$ (the inward spiral of sec. 6);
//! - [`rising`]: whether a disk spun about a nearly vertical diameter rises only when it slides
//!   (sec. 10);
//! - [`contact_loss`]: whether a spin-down with eq 75's drag and Coulomb friction loses contact
//!   (the premise of eqs 80-81) or slips first;
//! - [`fall`]: where a disk in unstable steady motion ($b > 0$, large tilt) falls to, rolling
//!   and on Coulomb tables ("falls to about 60 degrees", sec. 7 and the summary);
//! - [`mechanisms`](experiment::mechanisms): dissipation mechanisms from their physics, side by side: the exponent each
//!   gives a spin-down through the experiment's fits, and where each would dominate.
//!
//! [`studies`] runs them all for the report, each over a range of $\mu$.

pub mod contact_loss;
pub mod fall;
pub mod negative_b;
pub mod rising;
pub mod slip_onset;
pub mod spiral;
pub mod swing;

use experiment::mechanisms;
pub use physics::disk::toy_disk;

use experiment::law::Law;
use physics::disk::Disk;
use physics::model::sliding::contact_events::contact_events;
use physics::model::sliding::{Friction, Mode, Sliding};
use physics::model::steady::steady_motion;
use physics::solve::SettingsError;
use physics::solve::{Ending, Event, Settings};
use serde::Serialize;

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
    let settings = Settings::dop853(1e-10, 1e-12);
    let y0 = model.start_state(&m);
    if model.enter_contact(&y0).0 != Mode::Stick {
        return Some(true);
    }
    // Rolling at the start: any guard of the stick mode (the friction limit, the contact lost)
    // ends the run at once (no switch allowed), and that is the answer.
    let mut model = model;
    model.max_switches = 0;
    let run = model.run(&y0, WATCH, &settings, None, &no_stops).ok()?;
    Some(!contact_events(&run).is_empty() || matches!(run.ending, Ending::Halted { .. }))
}

/// The friction studies of the report, for the toy disk (a = 37.5 mm, k = 1/4, m = 0.4 kg).
#[derive(Debug, Clone, PartialEq, Serialize, schemars::JsonSchema)]
pub struct Studies {
    /// Eq 42 against integration, at each tilt of [`ONSET_TILTS`] and each $\mu$ of [`ONSET_MUS`].
    pub slip_onset: Vec<slip_onset::SlipOnset>,
    /// Eq 43 with realistic tables, at each tilt of [`ONSET_TILTS`] and each $\mu$ of
    /// [`NEGATIVE_B_MUS`].
    pub negative_b: Vec<negative_b::NegativeB>,
    /// Radial slippage (sec. 6), every start of [`spiral::STARTS`] on every table of
    /// [`spiral::MUS`].
    pub spiral: Vec<spiral::Spiral>,
    /// Rising near the vertical (sec. 10).
    pub rising: rising::Rising,
    /// The spin-down on Coulomb tables, to the first slip (eqs 80-81's premise).
    pub contact_loss: Vec<contact_loss::SpinDownContact>,
    /// Dissipation mechanisms side by side, held against the record's law.
    pub mechanisms: mechanisms::Mechanisms,
    /// The fall from unstable steady motion at large tilt (sec. 7, summary).
    pub fall: fall::Fall,
}

/// Tilts of the slip-onset and negative-b studies (rad).
pub const ONSET_TILTS: [f64; 2] = [0.3, 1.0];
/// Coulomb coefficients of the slip-onset study.
pub const ONSET_MUS: [f64; 3] = [0.1, 0.3, 0.6];
/// Coulomb coefficients of the negative-b study.
pub const NEGATIVE_B_MUS: [f64; 2] = [0.3, 1.0];

/// Runs every friction study (a few seconds of computing), the studies in parallel; `record`
/// is the law of sec. 11's record (the paper's fit) the mechanisms are held against.
pub fn studies(settings: &Settings, record: &Law) -> Result<Studies, SettingsError> {
    let d = toy_disk();
    let onset = || -> Vec<slip_onset::SlipOnset> {
        ONSET_TILTS
            .iter()
            .flat_map(|&a| ONSET_MUS.iter().map(move |&mu| (a, mu)))
            .filter_map(|(a, mu)| slip_onset::slip_onset(&d, a, mu))
            .collect()
    };
    let negative = || -> Vec<negative_b::NegativeB> {
        ONSET_TILTS
            .iter()
            .flat_map(|&a| NEGATIVE_B_MUS.iter().map(move |&mu| (a, mu)))
            .filter_map(|(a, mu)| negative_b::negative_b(&d, a, mu))
            .collect()
    };
    let spirals = || -> Result<Vec<spiral::Spiral>, SettingsError> {
        let mut out = Vec::new();
        for (a, b) in spiral::STARTS {
            for mu in spiral::MUS {
                out.extend(spiral::spiral(&d, a, b, mu, settings)?);
            }
        }
        Ok(out)
    };
    let (((slip_onset, negative_b), mechanisms), (spiral, (rising, (contact_loss, fall)))) =
        rayon::join(
            || {
                rayon::join(
                    || rayon::join(onset, negative),
                    || mechanisms::mechanisms(&d, record, settings),
                )
            },
            || {
                rayon::join(spirals, || {
                    let rising = rising::rising(&d, (d.g / (d.a * d.k)).sqrt(), settings);
                    let losses: Result<Vec<_>, SettingsError> = contact_loss::MUS
                        .iter()
                        .map(|&mu| contact_loss::spin_down_contact(&d, mu, settings, false))
                        .collect();
                    (rising, (losses, fall::fall(&d, settings)))
                })
            },
        );
    Ok(Studies {
        slip_onset,
        negative_b,
        spiral: spiral?,
        rising: rising?,
        contact_loss: contact_loss?,
        mechanisms: mechanisms?,
        fall: fall?,
    })
}
