//! The paper as data: `paper/equations.yaml` (the 85 numbered equations) and
//! `paper/claims.yaml` (the prose claims), compiled into the binary.

use serde::{Deserialize, Serialize};

/// One numbered equation of the paper.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EquationEntry {
    /// Printed number, 1-85.
    pub number: u32,
    /// LaTeX label in the paper's source.
    pub label: String,
    /// Section of the paper.
    pub section: u32,
    /// The mathematics, transcribed.
    pub latex: String,
    /// What it says, in our words.
    pub says: String,
    /// definition, kinematic identity, equation of motion, ...
    pub kind: String,
    /// Printed numbers of the equations it follows from.
    pub premises: Vec<u32>,
    /// For approximations: the small parameter.
    pub small_parameter: Option<String>,
    /// For approximations: the claimed order of the relative error.
    pub claimed_order: Option<f64>,
    /// Symbols whose meaning in this equation differs from paper/symbols.yaml (LaTeX -> what it
    /// stands for).
    #[serde(default, skip_serializing_if = "std::collections::BTreeMap::is_empty")]
    pub symbols: std::collections::BTreeMap<String, SymbolInfo>,
}

/// What a symbol of the paper stands for (paper/symbols.yaml, or an equation's `symbols`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SymbolInfo {
    /// The quantity a check binds to it.
    pub quantity: String,
    /// What it means, in words.
    pub means: String,
    /// Its unit.
    pub unit: String,
}

/// One claim of the paper's prose.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ClaimEntry {
    /// Identifier.
    pub id: String,
    /// Section of the paper.
    pub section: u32,
    /// The equation it is about or near.
    pub near_equation: u32,
    /// The claim, in our words.
    pub claim: String,
    /// The number as printed, if any.
    pub claimed_value: Option<f64>,
    /// Its unit as printed.
    pub unit: String,
    /// What must be computed.
    pub quantity: String,
    /// How it is computed independently.
    pub how: String,
}

/// The 85 equations, in order.
pub fn equations() -> Vec<EquationEntry> {
    serde_yaml::from_str(include_str!("../paper/equations.yaml"))
        .expect("paper/equations.yaml is checked by the tests")
}

/// The prose claims.
pub fn claims() -> Vec<ClaimEntry> {
    serde_yaml::from_str(include_str!("../paper/claims.yaml"))
        .expect("paper/claims.yaml is checked by the tests")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_catalogue_has_all_85_equations_in_order_and_unique_claims() {
        let eqs = equations();
        assert_eq!(eqs.len(), 85);
        for (i, e) in eqs.iter().enumerate() {
            assert_eq!(e.number as usize, i + 1);
            assert!(e.premises.iter().all(|p| (1..=85).contains(p)));
            assert_eq!(
                e.kind == "approximation",
                e.claimed_order.is_some(),
                "eq {}",
                e.number
            );
        }
        let claims = claims();
        let mut ids: Vec<&str> = claims.iter().map(|c| c.id.as_str()).collect();
        ids.sort();
        ids.dedup();
        assert_eq!(ids.len(), claims.len());
    }
}
