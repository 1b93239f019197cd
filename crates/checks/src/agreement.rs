//! Verdicts that agree with each other: a finding that rests on a failing premise says so
//! ([`attach_premises`]), and a claim that restates a failing equation is counted once, at the
//! equation ([`attach_restated`]), and a claim that is a part of another's statement is counted
//! once, at that claim ([`attach_parts`]).

use crate::checked::{Checked, Subject};
use crate::harness::Bench;

/// What `subject` rests on besides its numbered premises: the `rests_on` of its entry.
fn rests_on<'a>(bench: &'a Bench, subject: &Subject) -> &'a [String] {
    match subject {
        Subject::Equation { number, .. } => &bench.paper.equation(*number).entry.rests_on,
        Subject::Claim { id } => bench
            .paper
            .claims
            .iter()
            .find(|c| c.id == *id)
            .map_or(&[], |c| c.rests_on.as_slice()),
    }
}

/// The name a `rests_on` list uses for `subject`: its claim id, or `eq N`.
fn premise_name(subject: &Subject) -> String {
    match subject {
        Subject::Equation { number, .. } => format!("eq {number}"),
        Subject::Claim { id } => id.to_string(),
    }
}

/// A finding that would pass but rests on a claim or equation that fails (or itself rests on
/// one) becomes [`Verdict::PremiseFails`], naming them; a failing finding keeps its verdict and
/// names them too. Premises that were not run leave it as it is. Repeated to a fixed point, so
/// a premise's premise counts.
pub(crate) fn attach_premises(bench: &Bench, checked: &mut [Checked]) {
    use crate::finding::Verdict;
    for _ in 0..checked.len() {
        let failing_names: Vec<String> = checked
            .iter()
            .filter(|c| {
                c.finding.as_ref().is_ok_and(|f| {
                    matches!(
                        f.verdict,
                        Verdict::Fails
                            | Verdict::PremiseFails
                            | Verdict::Restates { .. }
                            | Verdict::PartOf { .. }
                            | Verdict::UnitMisprint
                            | Verdict::DependsOn { .. }
                            | Verdict::DimensionalSlip
                    )
                })
            })
            .map(|c| premise_name(&c.subject))
            .collect();
        let mut changed = false;
        for c in checked.iter_mut() {
            let failing: Vec<String> = rests_on(bench, &c.subject)
                .iter()
                .filter(|p| failing_names.contains(p))
                .cloned()
                .collect();
            let Ok(f) = c.finding.as_mut() else { continue };
            if failing.is_empty() || f.premises_failing == failing {
                continue;
            }
            if f.verdict.passes() && f.verdict != Verdict::PremiseFails {
                f.verdict_alone = Some(f.verdict);
                f.verdict = Verdict::PremiseFails;
            }
            f.premises_failing = failing;
            changed = true;
        }
        if !changed {
            break;
        }
    }
}

/// A verdict that rests on a failing premise inherits that premise's alternatives: under each
/// reading of each failing premise (one premise's choice at a time, the others as read), it
/// holds as its own check found when that premise then passes and no other failing premise
/// fails under every reading, and rests on a failing premise otherwise. A premise that fails
/// under every reading leaves it robust; one whose verdict depends on a choice makes it depend
/// on the same choice. Run after every other verdict has its alternatives, and repeated to a
/// fixed point, so a premise's premise counts.
pub(crate) fn attach_inherited(checked: &mut [Checked]) {
    use crate::finding::Verdict;
    use crate::robustness::{Alternative, Outcome};
    let fails = |v: Verdict| Outcome::of(v) != Outcome::Passes;
    for _ in 0..checked.len() {
        let premises: Vec<(String, Vec<Alternative>, bool)> = checked
            .iter()
            .filter_map(|c| {
                let f = c.finding.as_ref().ok()?;
                let always = if f.robustness.is_empty() {
                    fails(f.verdict)
                } else {
                    f.robustness.iter().all(|a| fails(a.verdict))
                };
                Some((premise_name(&c.subject), f.robustness.clone(), always))
            })
            .collect();
        let mut changed = false;
        for c in checked.iter_mut() {
            let Ok(f) = c.finding.as_mut() else { continue };
            let Some(alone) = f.verdict_alone else {
                continue;
            };
            let mut alternatives = Vec::new();
            for p in &f.premises_failing {
                let Some((_, readings, _)) = premises.iter().find(|(n, ..)| n == p) else {
                    continue;
                };
                let others_fail = premises
                    .iter()
                    .any(|(n, _, always)| n != p && *always && f.premises_failing.contains(n));
                for a in readings {
                    let verdict = if fails(a.verdict) || others_fail {
                        Verdict::PremiseFails
                    } else {
                        alone
                    };
                    alternatives.push(Alternative::new(
                        a.choice,
                        format!("premise {p}: {}", a.alternative),
                        f.reference,
                        verdict,
                    ));
                }
            }
            if alternatives == f.robustness {
                continue;
            }
            f.robustness.clear();
            f.verdict = Verdict::PremiseFails;
            *f = f.clone().with_robustness(alternatives);
            changed = true;
        }
        if !changed {
            break;
        }
    }
}

/// A failing claim that restates a numbered equation (`restates:` in claims.yaml) whose
/// finding fails too becomes [`Verdict::Restates`]: the fact is counted once, at the equation.
/// A claim that disagrees with its equation (one fails, the other passes) keeps its verdict, so
/// the disagreement shows.
pub(crate) fn attach_restated(bench: &Bench, checked: &mut [Checked]) {
    use crate::finding::Verdict;
    let fails = |n: u32, checked: &[Checked]| {
        checked.iter().any(|c| {
            matches!(c.subject, Subject::Equation { number, .. } if number == n)
                && c.finding
                    .as_ref()
                    .is_ok_and(|f| f.verdict == Verdict::Fails)
        })
    };
    let restating: Vec<(usize, u32)> = checked
        .iter()
        .enumerate()
        .filter_map(|(i, c)| match &c.subject {
            Subject::Claim { id } => bench
                .paper
                .claims
                .iter()
                .find(|e| e.id == *id)
                .and_then(|e| e.restates)
                .map(|n| (i, n)),
            Subject::Equation { .. } => None,
        })
        .filter(|&(_, n)| fails(n, checked))
        .collect();
    for (i, equation) in restating {
        if let Ok(f) = checked[i].finding.as_mut() {
            if f.verdict == Verdict::Fails {
                f.verdict = Verdict::Restates { equation };
            }
        }
    }
}

/// A failing claim that is a part of another claim's statement (`part_of:` in claims.yaml)
/// whose finding fails too becomes [`Verdict::PartOf`]: one statement, counted once, at that
/// claim. A part that fails where the claim it belongs to passes keeps its verdict, so the
/// disagreement shows; so does a part whose claim was not run.
pub(crate) fn attach_parts(bench: &Bench, checked: &mut [Checked]) {
    use crate::finding::Verdict;
    // The claim a part is counted at is named by its check's id in the table of checks (a
    // verdict holds no owned text); a claim checked from the catalogue alone has none there, so
    // a part of one keeps its own verdict.
    let failing: Vec<&'static str> = checked
        .iter()
        .filter_map(|c| match &c.subject {
            Subject::Claim { id } if c.finding.as_ref().is_ok_and(|f| !f.verdict.passes()) => {
                crate::equations::claims::CLAIMS
                    .iter()
                    .find(|k| k.id == id.as_str())
                    .map(|k| k.id)
            }
            _ => None,
        })
        .collect();
    for c in checked.iter_mut() {
        let Subject::Claim { id } = &c.subject else {
            continue;
        };
        let Some(whole) = bench
            .paper
            .claims
            .iter()
            .find(|e| e.id == *id)
            .and_then(|e| e.part_of.as_deref())
        else {
            continue;
        };
        let Some(&claim) = failing.iter().find(|f| **f == whole) else {
            continue;
        };
        if let Ok(f) = c.finding.as_mut() {
            if f.verdict == Verdict::Fails {
                f.verdict = Verdict::PartOf { claim };
            }
        }
    }
}
