//! The registry of checks: one per numbered equation of the paper (1-85) and one per prose claim
//! (`paper/claims.yaml`), each comparing the paper's CLAIM with a REFERENCE that does not depend
//! on it. The checks share the [`harness`](crate::harness); the registry only lists them.
//!
//! The list of equations is the paper's: [`equations`] takes every entry of
//! `paper/equations.yaml` (its printed number and LaTeX label) and joins it with the one row of
//! [`SECTIONS`] that names its check. Adding an equation is therefore
//! 1. its entry in `paper/equations.yaml` (and any new symbol in `paper/symbols.yaml`),
//! 2. its check function in the module of its paper section, reading the claimed side from the
//!    LaTeX through the harness ([`crate::harness::printed_relations`] and its kin), and
//! 3. one row `row(number, check)` in that module's `EQUATIONS`.
//!
//! [`from_latex`] (the equations the mutation suite judges by mutants of their printed text) and
//! the coverage test follow from these. The unit test `a_toy_equation_is_registered_from_its_row`
//! adds a toy equation this way.

pub mod air_film;
pub mod claims;
pub mod derivations;
mod disk_runs;
pub mod dissipation;
pub mod frictionless;
pub mod kinematics;
pub mod motion;
pub mod oscillation;
pub mod slippage;
pub mod spin_down_reference;
pub mod steady;
mod steady_reference;
#[cfg(test)]
mod tests;

use crate::finding::Finding;
/// The harness's bench, named here too for the registry's callers.
pub use crate::harness::{built_in_paper, Bench};

/// A check: the paper's claim against its reference, as a finding.
pub type Check = fn(&Bench) -> Finding;

/// One row of the registry: an equation's printed number and its check.
#[derive(Debug, Clone, Copy)]
pub struct Row {
    /// The printed number (1-85).
    pub number: u32,
    /// The check.
    pub check: Check,
}

/// A row: `row(29, eq29)`.
pub const fn row(number: u32, check: Check) -> Row {
    Row { number, check }
}

/// Every section's rows, in the paper's order.
pub const SECTIONS: &[&[Row]] = &[
    kinematics::EQUATIONS,
    motion::EQUATIONS,
    steady::EQUATIONS,
    slippage::EQUATIONS,
    oscillation::EQUATIONS,
    frictionless::EQUATIONS,
    dissipation::EQUATIONS,
    air_film::EQUATIONS,
];

/// One numbered equation and its check.
#[derive(Debug, Clone, Copy)]
pub struct Equation {
    /// The printed number (1-85).
    pub number: u32,
    /// The LaTeX label in the paper's source (from `paper/equations.yaml`).
    pub label: &'static str,
    /// The check.
    pub check: Check,
}

/// Why rows and a catalogue do not make a registry.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RegistryError {
    /// A row whose number no entry of the catalogue has.
    #[error("the row of eq {0} names an equation that paper/equations.yaml does not have: add its entry there or remove the row")]
    RowWithoutEntry(u32),
    /// Two rows for one equation.
    #[error("eq {0} has two rows: keep one")]
    TwoRows(u32),
}

/// The registry assembled from a catalogue's entries (printed number, label), in the
/// catalogue's order, and the sections' rows: each entry with a row becomes an [`Equation`];
/// an entry without one is unchecked (the coverage test then asks for it in
/// [`UNCHECKABLE_EQUATIONS`]).
pub fn assemble(
    entries: &[(u32, &'static str)],
    sections: &[&[Row]],
) -> Result<Vec<Equation>, RegistryError> {
    let rows: Vec<Row> = sections.concat();
    for (i, r) in rows.iter().enumerate() {
        if rows[..i].iter().any(|s| s.number == r.number) {
            return Err(RegistryError::TwoRows(r.number));
        }
        if !entries.iter().any(|(m, _)| *m == r.number) {
            return Err(RegistryError::RowWithoutEntry(r.number));
        }
    }
    Ok(entries
        .iter()
        .filter_map(|&(number, label)| {
            let r = rows.iter().find(|r| r.number == number)?;
            Some(Equation {
                number,
                label,
                check: r.check,
            })
        })
        .collect())
}

/// The built-in catalogue's entries: (printed number, label).
fn catalogue() -> Vec<(u32, &'static str)> {
    built_in_paper()
        .equations
        .iter()
        .map(|e| (e.entry.number, e.entry.label.as_str()))
        .collect()
}

/// Every registered equation check, in the order of `paper/equations.yaml`.
pub fn equations() -> Vec<Equation> {
    match assemble(&catalogue(), SECTIONS) {
        Ok(all) => all,
        // The rows and the built-in catalogue are compiled in together and tested together.
        Err(e) => panic!("the registry does not assemble (a defect of this build): {e}"),
    }
}

/// The equations whose checks take their claimed side from the paper's LaTeX: every registered
/// equation whose entry in `paper/equations.yaml` carries its LaTeX. Their checks are judged by
/// the mutants of their printed text (tests/mutation.rs).
pub fn from_latex() -> Vec<u32> {
    let paper = built_in_paper();
    equations()
        .iter()
        .map(|e| e.number)
        .filter(|&n| {
            paper
                .equations
                .iter()
                .any(|e| e.entry.number == n && !e.entry.latex.trim().is_empty())
        })
        .collect()
}

/// Whether an equation FOLLOWS from its printed premises (their LaTeX as the reference), as
/// opposed to whether it is true (its [`Equation::check`]); see [`derivations`].
#[derive(Debug, Clone, Copy)]
pub struct Derivation {
    /// The printed number of the equation derived.
    pub number: u32,
    /// The check.
    pub check: fn(&Bench) -> Finding,
}

/// Every registered derivation check, by number.
pub fn derivations() -> Vec<Derivation> {
    derivations::DERIVATIONS.to_vec()
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
pub const UNCHECKABLE_EQUATIONS: &[(u32, &str)] = &[];

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
        "fit-c-quarter",
        "a fit to the authors' unpublished data; the constant the other sec. 11 numbers are computed from",
    ),
    (
        "nutation-disappears-below-0p1",
        "the equations give no threshold at 0.1 rad: the beat ratio there is about 0.1, not small",
    ),
    (
        "contact-speed-exceeds-sound",
        "names no number; its content ($\\Omega$ unbounded) is checked by finite-time-singularity",
    ),
];

/// Every registered claim check.
pub fn claims() -> Vec<Claim> {
    claims::CLAIMS.to_vec()
}
