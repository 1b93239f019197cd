//! Verdicts under the choices the paper leaves open: where a check rests on something the paper
//! does not fix (the point or range where a claim is evaluated, where a dissipative torque
//! acts, the reading of "of order" or "about", a disk parameter), it recomputes its reference
//! under each reasonable alternative. A verdict that is the same under all of them is robust; one
//! that is not becomes [`Verdict::DependsOn`] the choice, with each alternative's value and
//! verdict beside it.

pub use crate::finding::Alternative;
use crate::finding::{Finding, Verdict};

/// The three kinds of outcome a verdict can have, for telling whether an alternative changes
/// it: it establishes what it checks (holds, holds approximately, a definition, an estimate),
/// it would but rests on a premise that fails, or it fails (as printed, as a restatement, as a
/// unit misprint or a dimensional slip).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Outcome {
    /// Establishes what it checks.
    Passes,
    /// Would pass, but rests on a premise that fails.
    PremiseFails,
    /// Fails.
    Fails,
}

impl Outcome {
    /// The kind of `v`; a verdict that depends on a choice counts as failing (it does not
    /// establish what it checks).
    pub fn of(v: Verdict) -> Self {
        match v {
            Verdict::PremiseFails => Outcome::PremiseFails,
            v if v.passes() => Outcome::Passes,
            _ => Outcome::Fails,
        }
    }
}

impl Finding {
    /// Adds the verdicts under `alternatives` to those already tried (the reading this finding
    /// was made under first, when there were none). When an alternative's verdict is of another
    /// kind ([`Outcome`]) than the verdict as read, the verdict becomes [`Verdict::DependsOn`]
    /// the first such alternative's choice; the verdict as read stays in the first entry.
    pub fn with_robustness(mut self, alternatives: Vec<Alternative>) -> Self {
        let read = self.as_read();
        self.robustness.extend(alternatives);
        let differs = self
            .robustness
            .iter()
            .find(|a| Outcome::of(a.verdict) != Outcome::of(read))
            .map(|a| a.choice);
        self.verdict = match differs {
            Some(choice) => Verdict::DependsOn { choice },
            None => read,
        };
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

    #[test]
    fn a_verdict_on_a_failing_premise_that_holds_under_an_alternative_depends_on_it() {
        let mut f = failing();
        f.verdict = Verdict::PremiseFails;
        let f = f.with_robustness(vec![
            Alternative::new("the point of evaluation", "a", 1.0, Verdict::PremiseFails),
            Alternative::new("the point of evaluation", "b", 1.0, Verdict::Holds),
        ]);
        assert_eq!(
            f.verdict,
            Verdict::DependsOn {
                choice: "the point of evaluation"
            }
        );
        assert_eq!(f.as_read(), Verdict::PremiseFails);
        // Added readings keep the first as the verdict as read.
        let f = f.with_robustness(vec![Alternative::new(
            "a tolerance",
            "c",
            1.0,
            Verdict::PremiseFails,
        )]);
        assert_eq!(f.as_read(), Verdict::PremiseFails);
        assert_eq!(f.robustness.len(), 3);
        assert_eq!(f.robust(), Some(false));
    }
}
