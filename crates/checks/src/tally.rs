//! Counts of verdicts, and the closing line that says them.

use crate::checked::Checked;
use serde::Serialize;

/// Counts of verdicts.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, schemars::JsonSchema)]
#[schemars(rename = "Counts")]
pub struct Tally {
    /// Hold.
    pub holds: usize,
    /// Hold approximately, at the order they claim.
    pub holds_approximately: usize,
    /// Definitions consistent with the rest.
    pub definitions: usize,
    /// Order-of-magnitude estimates whose scaling holds and whose constant is within the
    /// estimate's reading.
    pub estimates: usize,
    /// Would hold, but only under a premise that fails.
    pub premise_fails: usize,
    /// Fail.
    pub fails: usize,
    /// Claims that fail as the numbered equation they restate fails: one fact, counted at the
    /// equation (their outcome's `restates` names it).
    pub restated: usize,
    /// Claims that fail as a part of another claim's statement that fails: one statement,
    /// counted at that claim (their outcome's `part_of` names it).
    pub parts: usize,
    /// Numbers wrong in the unit printed beside them and right in the unit the text means.
    pub unit_misprints: usize,
    /// Verdicts that change under a reasonable alternative to a choice the paper leaves open.
    pub depends: usize,
    /// Printed relations right up to a dropped factor with a dimension.
    pub dimensional_slips: usize,
    /// Could not run.
    pub not_run: usize,
}

impl Tally {
    /// How many were counted.
    pub fn total(&self) -> usize {
        self.holds
            + self.holds_approximately
            + self.definitions
            + self.estimates
            + self.premise_fails
            + self.fails
            + self.restated
            + self.parts
            + self.unit_misprints
            + self.depends
            + self.dimensional_slips
            + self.not_run
    }

    /// The counts in words, every verdict named, each in the singular for 1 and the plural
    /// otherwise; restatements, unit misprints, verdicts that depend on a choice, dimensional
    /// slips and those that could not run only when there are some.
    pub fn sentence(&self) -> String {
        let said =
            |n: usize, one: &str, many: &str| format!("{n} {}", if n == 1 { one } else { many });
        let mut parts = vec![
            said(self.holds, "holds", "hold"),
            said(
                self.holds_approximately,
                "holds approximately",
                "hold approximately",
            ),
            said(self.definitions, "definition", "definitions"),
            said(
                self.estimates,
                "estimate (scaling confirmed)",
                "estimates (scaling confirmed)",
            ),
            said(
                self.premise_fails,
                "holds only under a premise that fails",
                "hold only under a premise that fails",
            ),
            said(self.fails, "fails", "fail"),
        ];
        for (n, one, many) in [
            (
                self.restated,
                "fails as the equation it restates (counted there)",
                "fail as the equation they restate (counted there)",
            ),
            (
                self.parts,
                "fails as a part of another claim's statement (counted there)",
                "fail as a part of another claim's statement (counted there)",
            ),
            (self.unit_misprints, "unit misprint", "unit misprints"),
            (
                self.depends,
                "depends on a choice the paper leaves open",
                "depend on a choice the paper leaves open",
            ),
            (
                self.dimensional_slips,
                "dimensional slip",
                "dimensional slips",
            ),
            (self.not_run, "could not run", "could not run"),
        ] {
            if n > 0 {
                parts.push(said(n, one, many));
            }
        }
        parts.join(", ")
    }

    /// Counts the outcomes.
    pub fn of<'a>(checked: impl IntoIterator<Item = &'a Checked>) -> Self {
        use crate::finding::Verdict;
        let mut t = Tally::default();
        for c in checked {
            match &c.finding {
                Err(_) => t.not_run += 1,
                Ok(f) => match f.verdict {
                    Verdict::Holds => t.holds += 1,
                    Verdict::HoldsApproximately { .. } => t.holds_approximately += 1,
                    Verdict::Definition => t.definitions += 1,
                    Verdict::Estimate { .. } => t.estimates += 1,
                    Verdict::PremiseFails => t.premise_fails += 1,
                    Verdict::Fails => t.fails += 1,
                    Verdict::Restates { .. } => t.restated += 1,
                    Verdict::PartOf { .. } => t.parts += 1,
                    Verdict::UnitMisprint => t.unit_misprints += 1,
                    Verdict::DependsOn { .. } => t.depends += 1,
                    Verdict::DimensionalSlip => t.dimensional_slips += 1,
                },
            }
        }
        t
    }
}

#[cfg(test)]
mod tests {
    use super::Tally;

    #[test]
    fn the_closing_line_says_one_in_the_singular_and_none_or_many_in_the_plural() {
        let one = Tally {
            holds: 1,
            fails: 1,
            depends: 1,
            dimensional_slips: 1,
            unit_misprints: 1,
            restated: 1,
            ..Tally::default()
        };
        let s = one.sentence();
        for said in [
            "1 holds,",
            "0 hold approximately",
            "0 definitions",
            "1 fails,",
            "1 fails as the equation it restates",
            "1 unit misprint,",
            "1 depends on a choice",
            "1 dimensional slip",
        ] {
            assert!(s.contains(said), "{said:?} in {s}");
        }
        assert!(!s.contains("slips") && !s.contains("misprints"), "{s}");
        let many = Tally {
            depends: 2,
            dimensional_slips: 3,
            ..Tally::default()
        }
        .sentence();
        assert!(many.contains("2 depend on a choice"), "{many}");
        assert!(many.contains("3 dimensional slips"), "{many}");
        assert!(!many.contains("unit misprint"), "{many}");
    }
}
