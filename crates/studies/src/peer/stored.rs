//! The peer's stored runs (`tests/reference/peer/<scene>/`), built into the tool so that the
//! report compares them without a source tree: each scene, the peer's `result.txt` with its
//! slip regularization speed $\varepsilon = 10^{-3}$ m/s as in its source, and, where stored,
//! the same scene run with $\varepsilon = 10^{-7}$ m/s (`eps-1e-7/`). Their provenance (the
//! peer's commit, compiler and response file) is in each folder's `provenance.txt`.

use super::clock::on_its_clock;
use super::compare::{compare, Largest, PeerComparison};
use super::relock::{split, RelockSplit};
use super::result::parse;
use super::PeerError;
use physics::scene::Scene;
use serde::{Deserialize, Serialize};

/// One stored peer run.
#[derive(Debug, Clone, Copy)]
pub struct StoredRun {
    /// Its folder under `tests/reference/peer/`.
    pub name: &'static str,
    /// The scene in words.
    pub words: &'static str,
    /// What explains a difference larger than the peer's printed digits, in a phrase of
    /// [`EXPLANATIONS`] (first with the peer's source's regularization, then with
    /// $\varepsilon = 10^{-7}$ m/s), or "–".
    pub explained_by: &'static str,
    /// `scene.yaml`.
    pub scene: &'static str,
    /// `result.txt`, the peer's slip regularization at $10^{-3}$ m/s.
    pub result: &'static str,
    /// `eps-1e-7/result.txt`, the same scene with $\varepsilon = 10^{-7}$ m/s, if stored.
    pub sharp: Option<&'static str>,
}

macro_rules! stored {
    ($name:literal, $words:literal, $why:literal, sharp) => {
        StoredRun {
            sharp: Some(include_str!(concat!(
                "../../../../tests/reference/peer/",
                $name,
                "/eps-1e-7/result.txt"
            ))),
            ..stored!($name, $words, $why)
        }
    };
    ($name:literal, $words:literal, $why:literal) => {
        StoredRun {
            name: $name,
            words: $words,
            explained_by: $why,
            scene: include_str!(concat!(
                "../../../../tests/reference/peer/",
                $name,
                "/scene.yaml"
            )),
            result: include_str!(concat!(
                "../../../../tests/reference/peer/",
                $name,
                "/result.txt"
            )),
            sharp: None,
        }
    };
}

/// The phrases that explain a difference, and what each means.
pub const EXPLANATIONS: [(&str, &str); 4] = [
    (
        "regularization",
        "the peer's slip regularization: its kinetic friction falls short of μ F_z by about \
         ε²/2v² while the contact slides at v",
    ),
    (
        "creep",
        "where the slip ends, the regularized peer creeps (slip 1e-4 to 5e-3 m/s) and never \
         relocks, while this tool rolls",
    ),
    (
        "relock at a print step",
        "the peer relocks only at a print step, up to 1 ms after this tool: split there, the \
         runs agree before this tool's slip ends and after the peer's relock (this tool \
         restarted from the peer's printed state), far closer than over the whole run",
    ),
    (
        "its start",
        "the print step the peer slides at its start before it relocks (its later rows read \
         on the clock of its run)",
    ),
];

/// The eleven stored runs, thin first.
pub const STORED: [StoredRun; 11] = [
    stored!(
        "thin-fall",
        "a nearly thin disk (0.2 mm) falling without spin from near upright, frictionless",
        "–"
    ),
    stored!(
        "thin-sliding",
        "a nearly thin disk sliding fast on a slippery table for the whole run",
        "regularization"
    ),
    stored!(
        "thin-slide",
        "a nearly thin disk spinning in place, launched slipping; friction ends the slip",
        "creep; then relock at a print step",
        sharp
    ),
    stored!(
        "thick-fall",
        "the toy (12.8 mm, fillet 2 mm) falling without spin from near upright, frictionless",
        "–"
    ),
    stored!(
        "thick-sliding",
        "the toy sliding fast on a slippery table for the whole run",
        "regularization",
        sharp
    ),
    stored!(
        "thick-sliding-resisted",
        "the toy sliding fast against rolling and boring resistance (arms 0.01 a and 0.05 a)",
        "regularization",
        sharp
    ),
    stored!(
        "thick-slip-stick",
        "the toy with static 0.3 and kinetic 0.2 friction launched slipping sideways",
        "creep; then relock at a print step",
        sharp
    ),
    stored!(
        "thick-roll",
        "the toy rolling on a circle from the thin disk's steady motion, high friction",
        "creep; then its start",
        sharp
    ),
    stored!(
        "thick-spin-down",
        "the toy spinning in place at 34° under rolling and boring resistance (arms 0.001 a \
         and 0.01 a), 2 s",
        "creep; then its start",
        sharp
    ),
    stored!(
        "thick-long-spin-down",
        "the toy spinning in place from 29° under rolling and boring resistance (arms 0.001 a \
         and 0.01 a), 6 s, losing a quarter of its energy",
        "creep; then its start",
        sharp
    ),
    stored!(
        "thick-near-vertical",
        "the toy launched 3° from upright with a fast spin and a slip",
        "regularization",
        sharp
    ),
];

/// The largest differences of one peer run from this tool's.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
pub struct Differences {
    /// Print times compared.
    pub rows: usize,
    /// The last time compared (s).
    pub until: f64,
    /// Largest $|\Delta\alpha|$ (rad).
    pub tilt: f64,
    /// Largest difference of the spin about the symmetry axis (rad/s).
    pub spin: f64,
    /// Largest difference of the heading of $\hat{\mathbf 2}$ (rad).
    pub heading: f64,
    /// Largest distance between the centres on the table (m).
    pub centre: f64,
    /// Largest difference of the paired rolling/sliding switch times (s).
    pub switch_time: f64,
    /// Switches (peer, this tool) before `until`.
    pub switch_counts: (usize, usize),
    /// Where the peer's record ends (s).
    pub peer_end: f64,
    /// Where this tool's run ends (s).
    pub tool_end: f64,
    /// $(t, |\Delta\alpha|)$ at each compared print time (s, rad), for the figures.
    #[serde(skip)]
    #[schemars(skip)]
    pub tilt_gap: Vec<(f64, f64)>,
    /// $(t, \alpha_{\rm tool}, \alpha_{\rm peer})$ at each compared print time, for the figures.
    #[serde(skip)]
    #[schemars(skip)]
    pub tilts: Vec<[f64; 3]>,
}

impl Differences {
    fn of(c: PeerComparison) -> Self {
        let v = |l: Largest| l.value;
        Self {
            rows: c.rows,
            until: c.until,
            tilt: v(c.tilt),
            spin: v(c.spin),
            heading: v(c.heading),
            centre: v(c.centre),
            switch_time: c.switch_time(),
            switch_counts: c.switch_counts,
            peer_end: c.peer_end,
            tool_end: c.tool_end.0,
            tilt_gap: c
                .tilts
                .iter()
                .map(|r| (r[0], (r[1] - r[2]).abs()))
                .collect(),
            tilts: c.tilts,
        }
    }

    /// True when every difference is within the peer's printed digits: $5\times10^{-8}$ with
    /// room for the rounding of both ends of a difference and of the rates' larger values
    /// (tilt, heading and centre $10^{-7}$, spin $10^{-6}$), the switches paired one to one.
    pub fn at_printed_digits(&self) -> bool {
        self.tilt < 1e-7
            && self.heading < 1e-7
            && self.centre < 1.5e-7
            && self.spin < 1e-6
            && self.switch_counts.0 == self.switch_counts.1
    }
}

/// One stored run compared with this tool.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
pub struct StoredComparison {
    /// Its folder's name.
    pub name: String,
    /// The scene in words.
    pub words: String,
    /// Thick (true) or nearly thin.
    pub thick: bool,
    /// Against the peer with $\varepsilon = 10^{-3}$ m/s.
    pub regularized: Differences,
    /// Against the peer with $\varepsilon = 10^{-7}$ m/s, if stored.
    pub sharp: Option<Differences>,
    /// What explains what remains above the printed digits.
    pub explained_by: String,
    /// True when the peer restarted its clock after a relock at its first print step
    /// ([`super::clock::on_its_clock`]), in the run with $\varepsilon = 10^{-7}$ m/s if stored.
    pub restarted: bool,
    /// The peer's least $|\theta|$, the tilt from upright (rad): its near-vertical smoothing
    /// acts below 0.02 rad.
    pub closest_to_upright: f64,
    /// The run with $\varepsilon = 10^{-7}$ m/s split at the peer's first relock
    /// ([`super::relock::split`]); `None` without that run or without a relock.
    pub relock: Option<RelockSplit>,
}

/// Every stored run compared with this tool's run of its scene.
pub fn compare_stored() -> Result<Vec<StoredComparison>, PeerError> {
    use rayon::prelude::*;
    STORED
        .par_iter()
        .map(|s| {
            let file = format!("tests/reference/peer/{}/scene.yaml", s.name);
            let scene = Scene::parse(s.scene, &file)
                .map_err(|e| PeerError::Scene(file.clone(), e.to_string()))?;
            let rows = |text: &str, what: &str| {
                parse(text, &format!("tests/reference/peer/{}/{what}", s.name))
            };
            let against = |text: &str, what: &str| -> Result<Differences, PeerError> {
                Ok(Differences::of(compare(&scene, &rows(text, what)?)?))
            };
            Ok(StoredComparison {
                name: s.name.into(),
                words: s.words.into(),
                thick: scene.toy.solid.is_some_and(|d| d.thickness > 1e-3),
                regularized: against(s.result, "result.txt")?,
                sharp: s
                    .sharp
                    .map(|t| against(t, "eps-1e-7/result.txt"))
                    .transpose()?,
                explained_by: s.explained_by.into(),
                restarted: {
                    let (text, what) = s
                        .sharp
                        .map_or((s.result, "result.txt"), |t| (t, "eps-1e-7/result.txt"));
                    let r = rows(text, what)?;
                    on_its_clock(&r)
                        .1
                        .iter()
                        .any(|b| !b.relock && b.offset != 0.0)
                },
                relock: match s.sharp {
                    Some(t) => split(&scene, &rows(t, "eps-1e-7/result.txt")?)?,
                    None => None,
                },
                closest_to_upright: rows(s.result, "result.txt")?
                    .iter()
                    .map(|r| r.state.theta.abs())
                    .fold(f64::INFINITY, f64::min),
            })
        })
        .collect()
}
