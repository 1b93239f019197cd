//! The registry of checks: one per numbered equation of the paper (1-85) and one per prose claim
//! (`paper/claims.yaml`), each comparing the paper's CLAIM with a REFERENCE that does not depend
//! on it.
//!
//! Every check reads the claimed side through [`Bench::claim`], so that the mutation test can
//! perturb it (by a relative 1e-3) and see the check fail: a check that cannot fail is no check.

pub mod claims;
pub mod friction;
pub mod frictionless;
pub mod kinematics;
pub mod motion;
pub mod oscillation;
pub mod slippage;
pub mod steady;

use crate::finding::Finding;
use crate::solve::{Method, Settings};

/// What a check runs with.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bench {
    /// Relative perturbation applied to every claimed value (0 in normal runs, 1e-3 in the
    /// mutation test).
    pub perturbation: f64,
    /// The solver's relative tolerance for integrations.
    pub rtol: f64,
}

impl Default for Bench {
    fn default() -> Self {
        Self {
            perturbation: 0.0,
            rtol: 1e-12,
        }
    }
}

impl Bench {
    /// The same bench with the claimed side perturbed by relative `p`.
    pub fn perturbed(p: f64) -> Self {
        Self {
            perturbation: p,
            ..Self::default()
        }
    }

    /// A claimed value, as the check must see it: multiplied by (1 + perturbation). For an
    /// inequality, pass its bound.
    pub fn claim(&self, x: f64) -> f64 {
        x * (1.0 + self.perturbation)
    }

    /// The same bench with integrations at least as accurate as rtol `finest`, for a check that
    /// cannot resolve its claim otherwise (a residual's order of convergence, a growth test
    /// under bisection), whatever accuracy preset the user chose.
    pub fn resolving(&self, finest: f64) -> Self {
        Self {
            rtol: self.rtol.min(finest),
            ..*self
        }
    }

    /// Solver settings for the integrations of a check (DOP853 at this bench's rtol).
    pub fn settings(&self) -> Settings {
        Settings {
            method: Method::Dop853,
            rtol: self.rtol,
            atol: self.rtol * 1e-2,
            ..Settings::default()
        }
    }
}

/// One numbered equation and its check.
#[derive(Debug, Clone, Copy)]
pub struct Equation {
    /// The printed number (1-85).
    pub number: u32,
    /// The LaTeX label in the paper's source.
    pub label: &'static str,
    /// The check.
    pub check: fn(&Bench) -> Finding,
}

/// One prose claim (an entry of `paper/claims.yaml`) and its check.
#[derive(Debug, Clone, Copy)]
pub struct Claim {
    /// The claim's id in `paper/claims.yaml`.
    pub id: &'static str,
    /// The check.
    pub check: fn(&Bench) -> Finding,
}

/// Equations that have no check, and why: each is a defect of the paper's checkability, not a
/// gap to hide. The coverage test requires every other number to have a check.
pub const UNCHECKABLE_EQUATIONS: &[(u32, &str)] = &[(
    82,
    "Moffatt's air-film law: only its exponent 1/3 follows from the paper (eq 78 at beta = 4); its \
     prefactor 2 pi eta a / m comes from Moffatt's viscous dissipation, which the paper cites but \
     does not give, so no reference independent of the claim can be built from the paper",
)];

/// Prose claims (ids of paper/claims.yaml) that have no check, and why.
pub const UNCHECKABLE_CLAIMS: &[(&str, &str)] = &[
    (
        "transition-observed-range",
        "an observation on the authors' video frames",
    ),
    (
        "drag-exponent-moffatt-revised",
        "reports another paper's revised model, not given here",
    ),
    (
        "last-analysable-cycle",
        "an observation on the authors' unpublished scope record",
    ),
    (
        "t0-range",
        "an observation on the authors' unpublished scope record",
    ),
    (
        "beta-two-fits-data",
        "a judgement on the authors' unpublished data",
    ),
    (
        "nutation-disappears-below-0p1",
        "the equations give no threshold at 0.1 rad: the beat ratio there is about 0.1, not small",
    ),
    (
        "contact-speed-exceeds-sound",
        "names no number; its content (Omega unbounded) is checked by finite-time-singularity",
    ),
    (
        "summary-nutation-10-15-deg",
        "a range at whole-degree precision that no 1e-3 change of the claim can move across: \
         the coincidence tilt is 9.65 deg (linearization) or 11.46 deg (eq 58)",
    ),
];

/// Every registered equation check, by number.
pub fn equations() -> Vec<Equation> {
    let mut all: Vec<Equation> = [
        kinematics::EQUATIONS,
        motion::EQUATIONS,
        steady::EQUATIONS,
        slippage::EQUATIONS,
        oscillation::EQUATIONS,
        frictionless::EQUATIONS,
        friction::EQUATIONS,
    ]
    .concat();
    all.sort_by_key(|e| e.number);
    all
}

/// Every registered claim check.
pub fn claims() -> Vec<Claim> {
    claims::CLAIMS.to_vec()
}

/// The worst of several order fits: the first failing, else the largest order error.
pub(crate) fn worst_order(findings: Vec<(String, Finding)>) -> Finding {
    let mut best: Option<Finding> = None;
    for (label, mut f) in findings {
        f.at = format!("{label}: {}", f.at);
        best = Some(match best {
            None => f,
            Some(b) => {
                let bad = |x: &Finding| matches!(x.verdict, crate::finding::Verdict::Fails);
                if (bad(&f) && !bad(&b)) || (bad(&f) == bad(&b) && f.error > b.error) {
                    f
                } else {
                    b
                }
            }
        });
    }
    best.expect("at least one fit")
}
