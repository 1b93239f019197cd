//! What a check was about and what it found: the records that running the checks produces and
//! that the agreement between findings, the causes and the report read.

use crate::cause::Cause;
use crate::finding::Finding;
use serde::Serialize;

/// What was checked.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Subject {
    /// A numbered equation.
    Equation {
        /// Printed number.
        number: u32,
        /// LaTeX label.
        label: &'static str,
    },
    /// A prose claim.
    Claim {
        /// Its id in paper/claims.yaml.
        id: String,
    },
}

impl Subject {
    /// "eq 29" or the claim's id.
    pub fn name(&self) -> String {
        match self {
            Subject::Equation { number, .. } => format!("eq {number}"),
            Subject::Claim { id } => id.clone(),
        }
    }
}

/// One check's outcome.
#[derive(Debug, Clone, Serialize)]
pub struct Checked {
    /// What was checked.
    pub subject: Subject,
    /// The paper's section.
    pub section: u32,
    /// The finding, or why the check could not run.
    pub finding: Result<Finding, String>,
    /// For an equation with a derivation check: whether it follows from its printed premises.
    pub derivation: Option<Result<Finding, String>>,
    /// For a failing equation: root cause, inherited, or undetermined ([`crate::cause`]).
    pub cause: Option<Cause>,
    /// Its dimensional analysis: `consistent`, or where and how it is not
    /// ([`crate::dimensions`]).
    pub dimensions: String,
}
