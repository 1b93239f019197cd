//! Root causes and inherited errors: dependency-aware verdicts over the premises graph of
//! `paper/equations.yaml`.
//!
//! An equation's own check says whether it is TRUE (against an independent reference). That
//! alone cannot say whose fault a failure is: eq 79 fails, but only because eq 76 does. So each
//! failing equation is classified from three facts:
//!
//! - whether its direct premises (the `premises` of its entry) pass their own checks;
//! - whether it FOLLOWS from its premises as printed (a derivation check,
//!   [`crate::equations::derivations`]), where one is registered;
//! - the classification of the failing premises (for the root causes behind them).
//!
//! The rules, applied to every failing equation:
//!
//! | premises | follows from them? | classification |
//! |---|---|---|
//! | all hold | (cannot: true premises give true conclusions) | root cause |
//! | some fail | no | root cause, which also inherits from the failing premises |
//! | some fail | yes | inherits from the failing premises |
//! | some fail | not checked | undetermined, said so |
//!
//! "How much of the error is inherited": where the equation follows from its printed premises,
//! all of it (its derivation error is reported, at round-off or solver tolerance); where it does
//! not, the derivation check's error is its own share and is reported beside the total.

pub mod graph;

use crate::finding::Finding;
use serde::Serialize;
use std::collections::{BTreeMap, BTreeSet};

/// Why an equation fails.
#[derive(Debug, Clone, PartialEq, Serialize, schemars::JsonSchema)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Cause {
    /// Its premises hold, or it does not follow from them: the error starts here.
    RootCause {
        /// Failing direct premises it ALSO carries errors from (empty when they all hold).
        also_inherits_from: Vec<u32>,
        /// The error of the step from its printed premises (its own share), when checked.
        own_error: Option<f64>,
    },
    /// It follows from its printed premises, some of which fail: the error is theirs.
    Inherits {
        /// The failing direct premises.
        from: Vec<u32>,
        /// The root causes upstream.
        roots: Vec<u32>,
        /// The error of the step from its printed premises (within its tolerance).
        derivation_error: f64,
    },
    /// Some premise fails and no check says whether it follows from them.
    Undetermined {
        /// The failing direct premises.
        failed_premises: Vec<u32>,
    },
}

impl Cause {
    /// One line for a reader: "root cause", "inherits from eq 76 (root: eq 73)", ...
    pub fn describe(&self) -> String {
        let eqs = |v: &[u32]| {
            v.iter()
                .map(|n| format!("eq {n}"))
                .collect::<Vec<_>>()
                .join(", ")
        };
        match self {
            Cause::RootCause {
                also_inherits_from,
                own_error,
            } => {
                let mut s = "root cause".to_string();
                if !also_inherits_from.is_empty() {
                    s.push_str(&format!(
                        ": it does not follow from its printed premises (own error {}), which fail too ({})",
                        own_error.map_or("-".into(), short),
                        eqs(also_inherits_from)
                    ));
                }
                s
            }
            Cause::Inherits { from, roots, .. } => format!(
                "inherits from {}: follows from its printed premises, so the error is theirs (root cause{}: {})",
                eqs(from),
                if roots.len() == 1 { "" } else { "s" },
                eqs(roots)
            ),
            Cause::Undetermined { failed_premises } => format!(
                "undetermined: its premises {} fail, and whether it follows from them is not checked",
                eqs(failed_premises)
            ),
        }
    }
}

/// What the classification needs of one equation.
#[derive(Debug, Clone)]
pub struct Node<'a> {
    /// Its direct premises (printed numbers).
    pub premises: &'a [u32],
    /// Its own check's finding (None if not checked or could not run).
    pub truth: Option<&'a Finding>,
    /// Its derivation check's finding, if one is registered and ran.
    pub derivation: Option<&'a Finding>,
}

/// The numbers of `nodes` with every premise before the equations that cite it (a premise may
/// carry a larger number: eq 3 cites eq 4). A cycle, which a transcription could hold by
/// mistake, is broken where it closes.
pub fn premises_first(premises: &dyn Fn(u32) -> Vec<u32>, numbers: &[u32]) -> Vec<u32> {
    fn visit(
        n: u32,
        premises: &dyn Fn(u32) -> Vec<u32>,
        seen: &mut BTreeSet<u32>,
        out: &mut Vec<u32>,
    ) {
        if !seen.insert(n) {
            return;
        }
        for p in premises(n) {
            visit(p, premises, seen, out);
        }
        out.push(n);
    }
    let (mut seen, mut out) = (BTreeSet::new(), Vec::new());
    for &n in numbers {
        visit(n, premises, &mut seen, &mut out);
    }
    out
}

/// Classifies every failing equation of `nodes` (keyed by printed number), premises first. A
/// premise that is not in `nodes` (unchecked, like eq 82) is not counted as failing.
pub fn classify(nodes: &BTreeMap<u32, Node<'_>>) -> BTreeMap<u32, Cause> {
    let mut out: BTreeMap<u32, Cause> = BTreeMap::new();
    // A finding whose claimed value is not a number is no verdict (the claim could not be
    // evaluated): it neither fails nor decides a derivation.
    let evaluated = |f: &&Finding| f.claimed.is_finite();
    let fails = |n: u32| {
        nodes
            .get(&n)
            .and_then(|x| x.truth)
            .filter(evaluated)
            .is_some_and(|f| !f.verdict.passes())
    };
    let numbers: Vec<u32> = nodes.keys().copied().collect();
    let premises = |n: u32| nodes.get(&n).map_or(Vec::new(), |x| x.premises.to_vec());
    for n in premises_first(&premises, &numbers) {
        let Some(node) = nodes.get(&n) else {
            continue;
        };
        let derivation = node.derivation.filter(evaluated);
        if !fails(n) {
            continue;
        }
        let failed: Vec<u32> = node
            .premises
            .iter()
            .copied()
            .filter(|&p| fails(p))
            .collect();
        let cause = if failed.is_empty() {
            Cause::RootCause {
                also_inherits_from: Vec::new(),
                own_error: derivation.map(|d| d.error),
            }
        } else {
            match derivation {
                Some(d) if d.verdict.passes() => {
                    let mut roots = BTreeSet::new();
                    for p in &failed {
                        match out.get(p) {
                            Some(Cause::Inherits { roots: r, .. }) => roots.extend(r),
                            _ => {
                                roots.insert(*p);
                            }
                        }
                    }
                    Cause::Inherits {
                        from: failed,
                        roots: roots.into_iter().collect(),
                        derivation_error: d.error,
                    }
                }
                Some(d) => Cause::RootCause {
                    also_inherits_from: failed,
                    own_error: Some(d.error),
                },
                None => Cause::Undetermined {
                    failed_premises: failed,
                },
            }
        };
        out.insert(n, cause);
    }
    out
}

/// The consequences of each root cause: the equations whose roots include it, in order.
pub fn consequences(causes: &BTreeMap<u32, Cause>) -> BTreeMap<u32, Vec<u32>> {
    let mut out: BTreeMap<u32, Vec<u32>> = BTreeMap::new();
    for (&n, c) in causes {
        match c {
            Cause::RootCause { .. } => {
                out.entry(n).or_default();
            }
            Cause::Inherits { roots, .. } => {
                for r in roots {
                    out.entry(*r).or_default().push(n);
                }
            }
            Cause::Undetermined { .. } => {}
        }
    }
    out
}

/// `x` to three significant digits, in plain notation where that is short (2.000, 0.0312),
/// else in scientific (1.23e-7).
fn short(x: f64) -> String {
    if (1e-3..1e4).contains(&x.abs()) {
        let decimals = (2 - x.abs().log10().floor() as i32).max(0) as usize;
        format!("{x:.decimals$}")
    } else {
        format!("{x:.2e}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::finding::{Method, Tolerance, Worst};

    fn finding(ok: bool) -> Finding {
        let mut w = Worst::default();
        w.add(if ok { 1.0 } else { 2.0 }, 1.0, 1.0, || "here".into());
        Finding::from_worst(Method::Identity, "x", w, Tolerance::roundoff())
    }

    /// The chain of section 11, by hand: 72 fails with true premises; 73 fails and does not
    /// follow from 72; 76 follows from 73 and 75; 77 from 76; 80 holds.
    #[test]
    fn the_section_11_chain_is_classified_as_a_referee_would() {
        let (pass, fail) = (finding(true), finding(false));
        let mut nodes = BTreeMap::new();
        let premises: Vec<(u32, Vec<u32>, bool, Option<bool>)> = vec![
            (18, vec![], true, None),
            (72, vec![18], false, None),
            (73, vec![72], false, Some(false)),
            (75, vec![], true, None),
            (76, vec![73, 75], false, Some(true)),
            (77, vec![76], false, Some(true)),
            (78, vec![77], false, None),
            (80, vec![77], true, None),
        ];
        for (n, p, ok, der) in &premises {
            nodes.insert(
                *n,
                Node {
                    premises: p,
                    truth: Some(if *ok { &pass } else { &fail }),
                    derivation: der.map(|d| if d { &pass } else { &fail }),
                },
            );
        }
        let c = classify(&nodes);
        assert!(
            matches!(&c[&72], Cause::RootCause { also_inherits_from, .. } if also_inherits_from.is_empty())
        );
        assert!(
            matches!(&c[&73], Cause::RootCause { also_inherits_from, .. } if also_inherits_from == &[72])
        );
        assert!(
            matches!(&c[&76], Cause::Inherits { from, roots, .. } if from == &[73] && roots == &[73])
        );
        assert!(matches!(&c[&77], Cause::Inherits { roots, .. } if roots == &[73]));
        assert!(
            matches!(&c[&78], Cause::Undetermined { failed_premises } if failed_premises == &[77])
        );
        assert!(!c.contains_key(&80));
        let q = consequences(&c);
        assert_eq!(q[&73], vec![76, 77]);
        assert_eq!(q[&72], Vec::<u32>::new());
    }

    /// A premise with a larger number than its consequence (eq 3 cites eq 4) is settled first.
    #[test]
    fn a_premise_printed_later_is_classified_first() {
        let fail = finding(false);
        let der = finding(true);
        let mut nodes = BTreeMap::new();
        let (p3, p4) = (vec![4], vec![]);
        nodes.insert(
            3,
            Node {
                premises: &p3,
                truth: Some(&fail),
                derivation: Some(&der),
            },
        );
        nodes.insert(
            4,
            Node {
                premises: &p4,
                truth: Some(&fail),
                derivation: None,
            },
        );
        let c = classify(&nodes);
        assert!(matches!(&c[&3], Cause::Inherits { roots, .. } if roots == &[4]));
        assert!(matches!(&c[&4], Cause::RootCause { .. }));
    }

    #[test]
    fn an_own_error_is_written_to_three_digits() {
        assert_eq!(short(2.0), "2.00");
        assert_eq!(short(0.031234), "0.0312");
        assert_eq!(short(1234.5), "1234");
        assert_eq!(short(1.234e-7), "1.23e-7");
    }
}
