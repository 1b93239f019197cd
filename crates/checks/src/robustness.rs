//! Verdicts under the choices the paper leaves open: where a check rests on something the paper
//! does not fix (the point or range where a claim is evaluated, where a dissipative torque
//! acts, the reading of "of order" or "about", a disk parameter), it recomputes its reference
//! under each reasonable alternative. A verdict that is the same under all of them is robust; one
//! that is not becomes [`Verdict::DependsOn`] the choice, with each alternative's value and
//! verdict beside it.

use crate::finding::{Finding, Verdict};
use serde::Serialize;

/// One reasonable reading of a choice the paper leaves open, and the verdict under it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Alternative {
    /// The choice the paper leaves open, in words ("the point of evaluation").
    pub choice: &'static str,
    /// This reading of it, in words, with its parameters.
    pub alternative: String,
    /// The reference's value under it, in the finding's unit.
    pub reference: f64,
    /// The verdict under it.
    pub verdict: Verdict,
}

impl Alternative {
    /// An alternative reading of `choice`.
    pub fn new(
        choice: &'static str,
        alternative: impl Into<String>,
        reference: f64,
        verdict: Verdict,
    ) -> Self {
        Self {
            choice,
            alternative: alternative.into(),
            reference,
            verdict,
        }
    }
}

impl Finding {
    /// Attaches the verdicts under the alternatives (the reading this finding was made under
    /// first, then the others). When an alternative's verdict passes where this finding's does
    /// not, or the reverse, the verdict becomes [`Verdict::DependsOn`] that alternative's
    /// choice; the verdict the finding was made under stays in the first entry.
    pub fn with_robustness(mut self, alternatives: Vec<Alternative>) -> Self {
        let differs = alternatives
            .iter()
            .find(|a| a.verdict.passes() != self.verdict.passes())
            .map(|a| a.choice);
        if let Some(choice) = differs {
            self.verdict = Verdict::DependsOn { choice };
        }
        self.robustness = alternatives;
        self
    }

    /// Whether the verdict is the same under every alternative the check tried; `None` when it
    /// tried none.
    pub fn robust(&self) -> Option<bool> {
        (!self.robustness.is_empty()).then_some(!matches!(self.verdict, Verdict::DependsOn { .. }))
    }

    /// The verdict under the reading the finding was made under: the first alternative's for a
    /// verdict that depends on a choice, else the verdict itself.
    pub fn as_read(&self) -> Verdict {
        match (self.verdict, self.robustness.first()) {
            (Verdict::DependsOn { .. }, Some(a)) => a.verdict,
            (v, _) => v,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::finding::{Method, Tolerance, Worst};

    fn failing() -> Finding {
        let mut w = Worst::default();
        w.add(1.0, 0.25, 0.25, || "alpha0 -> 0".into());
        Finding::from_worst(Method::Derivation, "a ratio", w, Tolerance::roundoff())
    }

    #[test]
    fn a_verdict_that_changes_under_an_alternative_depends_on_its_choice() {
        let f = failing().with_robustness(vec![
            Alternative::new(
                "the point of evaluation",
                "alpha0 -> 0",
                0.25,
                Verdict::Fails,
            ),
            Alternative::new(
                "the point of evaluation",
                "alpha0 = 0.2 rad",
                0.357,
                Verdict::Holds,
            ),
        ]);
        assert_eq!(
            f.verdict,
            Verdict::DependsOn {
                choice: "the point of evaluation"
            }
        );
        assert_eq!(f.robust(), Some(false));
        assert_eq!(f.as_read(), Verdict::Fails);
        assert!(!f.verdict.passes());
    }

    #[test]
    fn a_verdict_the_same_under_every_alternative_is_robust() {
        let f = failing().with_robustness(vec![
            Alternative::new("a disk parameter", "k = 1/4", 0.25, Verdict::Fails),
            Alternative::new("a disk parameter", "k = 1/2", 0.5, Verdict::Fails),
        ]);
        assert_eq!(f.verdict, Verdict::Fails);
        assert_eq!(f.robust(), Some(true));
        assert_eq!(failing().robust(), None);
    }
}
