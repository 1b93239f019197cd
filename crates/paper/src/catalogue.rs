//! The entries of the paper's data files: `equations.yaml` (the 85 numbered equations),
//! `symbols.yaml` (what each symbol stands for) and `claims.yaml` (the prose claims), as
//! [`super::Paper`] reads them.

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
    /// Where the paper quotes an order-of-magnitude estimate (a law taken from elsewhere whose
    /// constant was never derived): how it is read. Its check then confirms the scaling and
    /// states the constant against the reference's instead of failing on it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub estimate: Option<EstimateReading>,
    /// Claims of the prose it rests on besides its numbered premises (ids of claims.yaml): a
    /// premise the paper states in words. When one fails, this equation can hold only as a
    /// consequence of something that is not so, and its verdict says that.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub rests_on: Vec<String>,
}

/// How an order-of-magnitude estimate is read: its scaling exactly, its constant within a
/// factor.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EstimateReading {
    /// Why the equation is read as an estimate, in words (shown beside the verdict).
    pub words: String,
    /// The factor, either way, within which its constant must lie (above 1).
    pub factor: f64,
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
    /// True when `claimed_value` is not a number the paper prints but one its words imply (the
    /// "only" constants of the motion: 0 more; "approaches the precession rate": a ratio of 1);
    /// the report then says "implied" instead of "printed".
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub implied: bool,
    /// Its unit as printed.
    pub unit: String,
    /// What must be computed: in words (a check written in Rust computes it), or a quantity of
    /// the checks' catalogue named with its parameters (`{ name: ..., k: 0.25 }`), checked with
    /// no Rust written for the claim ([`crate::quantity`]).
    pub quantity: crate::quantity::ClaimQuantity,
    /// How it is computed independently; may be left out where `quantity` names a quantity of
    /// the catalogue, whose method is then shown.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub how: String,
    /// How a loosely worded number ("about", "roughly", "a few") is judged, stated so a reader
    /// can disagree with it; absent where the check's own rule applies.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rule: Option<Rule>,
    /// Other places where the paper states the same fact (one claim per fact).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub also_at: Vec<Location>,
    /// What it rests on: ids of other claims, or `eq N` for a numbered equation. When one of
    /// them fails, this claim can hold only under a premise that is not so, and its verdict says
    /// that.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub rests_on: Vec<String>,
    /// The numbered equation whose fact it states again, if any: where both fail, the fact is
    /// counted once, at the equation, and the claim links to it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub restates: Option<u32>,
    /// The claim whose statement this one is a part of (the paper's "hence" drawn from the
    /// same number): one statement is one claim, so where both fail it is counted once, at
    /// that claim, and this one links to it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub part_of: Option<String>,
}

/// The reading of a loosely worded number: exactly one of `digits`, `within`, `factor`,
/// `at_most` and `range`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Rule {
    /// The paper's words the rule interprets ("about", "roughly", "a few").
    pub words: String,
    /// The number as printed to this many significant digits: the computed value, rounded to
    /// them, must equal it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub digits: Option<u32>,
    /// Within this relative distance of the printed number; with `range`, of the range's
    /// nearer end ("about 10 to 15 degrees").
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub within: Option<f64>,
    /// Within this factor of the printed number, either way ("of order").
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub factor: Option<f64>,
    /// A bound: no more than the printed number, plus this relative slack ("at most about").
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub at_most: Option<f64>,
    /// Inside this closed interval, in the claim's unit.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub range: Option<[f64; 2]>,
}

impl Rule {
    /// Why the rule is unusable, if it is: not exactly one reading, or a reading out of range.
    pub fn problem(&self) -> Option<String> {
        let set = [
            self.digits.is_some(),
            // With a range, `within` is the band around its ends, not a reading of its own.
            self.within.is_some() && self.range.is_none(),
            self.factor.is_some(),
            self.at_most.is_some(),
            self.range.is_some(),
        ];
        if set.iter().filter(|&&x| x).count() != 1 {
            return Some(
                "give exactly one of `digits`, `within`, `factor`, `at_most` and `range`".into(),
            );
        }
        if let Some(d) = self.digits.filter(|d| !(1..=15).contains(d)) {
            return Some(format!("`digits: {d}` must be 1 to 15"));
        }
        if let Some(w) = self.within.filter(|w| !(*w > 0.0 && *w < 1.0)) {
            return Some(format!("`within: {w}` must be a fraction between 0 and 1"));
        }
        if let Some(m) = self.at_most.filter(|m| !(*m >= 0.0 && *m < 1.0)) {
            return Some(format!("`at_most: {m}` must be a slack between 0 and 1"));
        }
        if let Some(f) = self.factor.filter(|f| !(f.is_finite() && *f > 1.0)) {
            return Some(format!("`factor: {f}` must be a finite number above 1"));
        }
        match self.range {
            Some([lo, hi]) if !(lo.is_finite() && hi.is_finite() && lo < hi) => Some(format!(
                "`range: [{lo}, {hi}]` must be two finite numbers, low first"
            )),
            _ => None,
        }
    }

    /// The rule in words, for the report: `'roughly' read as within 5 % of 60 deg`.
    pub fn describe(&self, printed: Option<f64>, unit: &str) -> String {
        let unit = if unit == "1" { "" } else { unit };
        let value = printed
            .map(|v| format!("{v} {unit}").trim_end().to_string())
            .unwrap_or_else(|| "the printed number".into());
        let reading = if let Some(d) = self.digits {
            format!(
                "as {value} printed to {d} significant digit{}: the computed value, rounded to \
                 that precision, must equal it",
                if d == 1 { "" } else { "s" }
            )
        } else if let (Some(w), None) = (self.within, self.range) {
            format!("as within {} % of {value}", w * 100.0)
        } else if let Some(f) = self.factor {
            format!("as within a factor {f} of {value}, either way")
        } else if let Some(m) = self.at_most {
            format!("as no more than {value} plus {} %", m * 100.0)
        } else if let Some([lo, hi]) = self.range {
            let band = self
                .within
                .map(|w| format!(", each end within {} %", w * 100.0))
                .unwrap_or_default();
            format!("as between {lo} and {hi} {unit}")
                .trim_end()
                .to_string()
                + &band
        } else {
            "(no reading)".into()
        };
        format!("'{}' read {reading}", self.words)
    }
}

/// Where in the paper a claim is (also) stated.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Location {
    /// Section of the paper.
    pub section: u32,
    /// The equation it is about or near.
    pub near_equation: u32,
    /// The statement there, in our words.
    pub claim: String,
}
