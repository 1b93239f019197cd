//! The peer's stored runs (`tests/reference/peer/<scene>/`), built into the tool so that the
//! report compares them without a source tree: each scene, the peer's `result.txt` with its
//! slip regularization speed $\varepsilon = 10^{-3}$ m/s as in its source, and, where stored,
//! the same scene run with $\varepsilon = 10^{-7}$ m/s (`eps-1e-7/`). Their provenance (the
//! peer's commit, compiler and response file) is in each folder's `provenance.txt`.

use super::compare::{compare, Largest, PeerComparison};
use super::result::parse;
use super::PeerError;
use physics::scene::Scene;
use serde::Serialize;

/// One stored peer run.
#[derive(Debug, Clone, Copy)]
pub struct StoredRun {
    /// Its folder under `tests/reference/peer/`.
    pub name: &'static str,
    /// The scene in words.
    pub words: &'static str,
    /// What explains a difference larger than the peer's printed digits, if one remains.
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

/// The ten stored runs, thin first.
pub const STORED: [StoredRun; 10] = [
    stored!(
        "thin-fall",
        "nearly thin disk (0.2 mm) falling without spin from near upright, frictionless",
        "nothing: both stop near the table (this tool at the scene's 0.1 rad)"
    ),
    stored!(
        "thin-sliding",
        "nearly thin disk sliding fast on a slippery table for the whole run",
        "the peer's slip regularization (its friction is short of mu F_z by eps^2/2v^2)"
    ),
    stored!(
        "thin-slide",
        "nearly thin disk spinning in place, launched slipping; friction ends the slip",
        "the peer's slip regularization: where the slip ends it creeps (1e-4 to 5e-3 m/s) and \
         never relocks; with eps = 1e-7 the rest is its start, sliding with a 5 mm/s seed",
        sharp
    ),
    stored!(
        "thick-fall",
        "the toy (12.8 mm, fillet 2 mm) falling without spin from near upright, frictionless",
        "nothing: both stop near the table (this tool at the scene's 0.1 rad)"
    ),
    stored!(
        "thick-sliding",
        "the toy sliding fast on a slippery table for the whole run",
        "the peer's slip regularization (its friction is short of mu F_z by eps^2/2v^2)",
        sharp
    ),
    stored!(
        "thick-sliding-resisted",
        "the toy sliding fast against rolling and boring resistance (arms 0.01 a and 0.05 a)",
        "the peer's slip regularization",
        sharp
    ),
    stored!(
        "thick-slip-stick",
        "the toy with static 0.3 and kinetic 0.2 friction launched slipping sideways",
        "the peer's slip regularization: it creeps where this tool sticks; with eps = 1e-7 \
         the rest is its seeded start and its relock found only at print steps",
        sharp
    ),
    stored!(
        "thick-roll",
        "the toy rolling on a circle from the thin disk's steady motion, high friction",
        "the peer's start (every run starts sliding, here with a 5 mm/s seed slip) and its \
         creep with eps = 1e-3 m/s",
        sharp
    ),
    stored!(
        "thick-spin-down",
        "the toy spinning in place at 34 deg under rolling and boring resistance (arms 0.001 a \
         and 0.01 a), 2 s",
        "the peer's seeded start and its creep with eps = 1e-3 m/s",
        sharp
    ),
    stored!(
        "thick-near-vertical",
        "the toy launched 3 deg from upright with a fast spin and a slip (outside the peer's \
         0.02 rad smoothing band)",
        "the peer's slip regularization before its relock",
        sharp
    ),
];

/// The largest differences of one peer run from this tool's.
#[derive(Debug, Clone, PartialEq, Serialize, schemars::JsonSchema)]
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
#[derive(Debug, Clone, PartialEq, Serialize, schemars::JsonSchema)]
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
}

/// Every stored run compared with this tool's run of its scene.
pub fn compare_stored() -> Result<Vec<StoredComparison>, PeerError> {
    STORED
        .iter()
        .map(|s| {
            let file = format!("tests/reference/peer/{}/scene.yaml", s.name);
            let scene = Scene::parse(s.scene, &file)
                .map_err(|e| PeerError::Scene(file.clone(), e.to_string()))?;
            let against = |text: &str, what: &str| -> Result<Differences, PeerError> {
                let name = format!("tests/reference/peer/{}/{what}", s.name);
                Ok(Differences::of(compare(&scene, &parse(text, &name)?)?))
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
            })
        })
        .collect()
}
