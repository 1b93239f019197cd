//! The second reading every verdict that does not establish what it checks is given: the
//! tolerance it was judged by, or the reading of the paper's words ("about", "roughly", "of
//! order", "a few", "at most about", a number's printed digits), or an estimate's factor,
//! replaced by a reasonable looser one, and the verdict recomputed from the finding's own
//! numbers. A failure that survives it is robust to that choice; one that does not depends on
//! it ([`crate::robustness`]).
//!
//! The looser readings, fixed by rule and never per check:
//!
//! | as read | the alternative |
//! |---|---|
//! | within $w$ of the printed number | within $2w$ |
//! | within a factor $f$, either way | within a factor 10 (an order of magnitude; $f^2$ when $f \ge 10$) |
//! | to the printed digits | within 5 % of the printed number (the reading of "about" for a number the paper did not compute) |
//! | inside a range, each end within $w$ | each end within $2w$ (within 50 % when the range has no band) |
//! | no more than the printed number plus $s$ | plus $2s$ (plus 5 % when $s = 0$) |
//! | an approximation's fitted order within 0.25 | within 0.5 |
//! | two exponents within 5 % | within 10 % |
//! | a numerical tolerance (round-off, the solver's, a bisection's) | ten times it |
//! | an estimate's constant within a factor $f$ | within a factor 2 and within a factor 10 |

use crate::checked::{Checked, Subject};
use crate::finding::{Finding, Verdict};
use crate::harness::Bench;
use crate::robustness::{Alternative, Outcome};

/// A looser reading of the rule a finding was judged by: the choice it belongs to, the reading
/// in words, the error under it and the tolerance it allows.
struct Looser {
    choice: &'static str,
    alternative: String,
    error: f64,
    tolerance: f64,
}

/// Gives every outcome that does not establish what it checks (a failure of any kind, a verdict
/// that depends on a choice, an estimate) the verdict under the looser reading of its rule,
/// beside the reading it was made under. A verdict that rests on a premise that fails is left
/// to [`crate::agreement::attach_inherited`].
pub(crate) fn attach(bench: &Bench, checked: &mut [Checked]) {
    for c in checked.iter_mut() {
        let subject = c.subject.clone();
        let Ok(f) = c.finding.as_mut() else { continue };
        let alternatives = match f.as_read() {
            Verdict::Estimate {
                constant_ratio,
                factor,
            } => estimate_readings(f, constant_ratio, factor),
            v if Outcome::of(v) == Outcome::Fails => tolerance_readings(bench, &subject, f),
            _ => continue,
        };
        *f = f.clone().with_robustness(alternatives);
    }
}

/// An estimate read with its factor (equations.yaml's), then within a factor 2 and 10.
fn estimate_readings(f: &Finding, ratio: f64, factor: f64) -> Vec<Alternative> {
    let choice = "the reading of an estimate's constant";
    let mut out = Vec::new();
    if f.robustness.is_empty() {
        out.push(Alternative::new(
            choice,
            format!("as read: within a factor {factor}, either way"),
            f.reference,
            f.verdict,
        ));
    }
    for alt in [2.0, 10.0] {
        let within = ratio.is_finite() && ratio <= alt && ratio >= 1.0 / alt;
        out.push(Alternative::new(
            choice,
            format!("within a factor {alt}, either way (the constant is {ratio:.3} times the reference's)"),
            f.reference,
            if within {
                Verdict::Estimate {
                    constant_ratio: ratio,
                    factor: alt,
                }
            } else {
                Verdict::Fails
            },
        ));
    }
    out
}

/// A failing finding as read, then under the looser reading of its rule.
fn tolerance_readings(bench: &Bench, subject: &Subject, f: &Finding) -> Vec<Alternative> {
    let looser = looser(bench, subject, f);
    let read = f.as_read();
    // A finding that failed within its tolerance failed on something else (an error that does
    // not shrink, a witness that does not rise): no tolerance changes that.
    let by_error = f.error > f.tolerance.value;
    let verdict = if by_error && looser.error <= looser.tolerance {
        if f.unit == "order" {
            Verdict::HoldsApproximately {
                measured_order: f.reference,
                claimed_order: f.claimed,
            }
        } else {
            Verdict::Holds
        }
    } else {
        read
    };
    let mut out = Vec::new();
    if f.robustness.is_empty() {
        out.push(Alternative::new(
            looser.choice,
            format!("as read: {}", f.tolerance.rule),
            f.reference,
            read,
        ));
    }
    out.push(Alternative::new(
        looser.choice,
        format!(
            "{} (error {:.4e} against {:.4e})",
            looser.alternative, looser.error, looser.tolerance
        ),
        f.reference,
        verdict,
    ));
    out
}

/// The looser reading of the rule `f` was judged by (the module's table).
fn looser(bench: &Bench, subject: &Subject, f: &Finding) -> Looser {
    let rule = match subject {
        Subject::Claim { id } => bench
            .paper
            .claims
            .iter()
            .find(|c| c.id == *id)
            .and_then(|c| c.rule.clone())
            .filter(|r| f.tolerance.rule == r.describe(c_value(bench, id), &c_unit(bench, id))),
        Subject::Equation { .. } => None,
    };
    if let Some(r) = rule {
        return worded(&r, f);
    }
    let rule = f.tolerance.rule.as_str();
    if rule.starts_with("printed precision") {
        return about_not_digits(f, "the reading of a printed number");
    }
    if rule.starts_with("asymptotic") {
        return Looser {
            choice: "a tolerance",
            alternative: "the fitted order within 0.5 of the claimed order".into(),
            error: f.error,
            tolerance: 0.5,
        };
    }
    if rule.starts_with("scaling") {
        return Looser {
            choice: "a tolerance",
            alternative: "log-log slopes within 10 % of each other".into(),
            error: f.error,
            tolerance: 2.0 * f.tolerance.value,
        };
    }
    Looser {
        choice: "a tolerance",
        alternative: format!(
            "ten times the rule's tolerance, {:e}",
            10.0 * f.tolerance.value
        ),
        error: f.error,
        tolerance: 10.0 * f.tolerance.value,
    }
}

fn c_value(bench: &Bench, id: &str) -> Option<f64> {
    bench
        .paper
        .claims
        .iter()
        .find(|c| c.id == id)
        .and_then(|c| c.claimed_value)
}

fn c_unit(bench: &Bench, id: &str) -> String {
    bench
        .paper
        .claims
        .iter()
        .find(|c| c.id == id)
        .map(|c| c.unit.clone())
        .unwrap_or_default()
}

/// The choice a reading of the paper's `words` belongs to.
fn choice_of(words: &str) -> &'static str {
    match words {
        "about" => "the reading of 'about'",
        "roughly" => "the reading of 'roughly'",
        "of order" => "the reading of 'of order'",
        "a few" => "the reading of 'a few'",
        "at most about" => "the reading of 'at most about'",
        _ => "the reading of the paper's words",
    }
}

/// The looser reading of a claim's rule (the module's table).
fn worded(r: &paper::Rule, f: &Finding) -> Looser {
    let choice = choice_of(&r.words);
    if r.digits.is_some() {
        return about_not_digits(f, choice);
    }
    if let Some([lo, hi]) = r.range {
        let band = r.within.map_or(0.5, |w| 2.0 * w);
        return Looser {
            choice,
            alternative: format!(
                "'{}' read as between {lo} and {hi}, each end within {} %",
                r.words,
                band * 100.0
            ),
            error: f.error,
            tolerance: band,
        };
    }
    if let Some(factor) = r.factor {
        let wider = if factor < 10.0 { 10.0 } else { factor * factor };
        return Looser {
            choice,
            alternative: format!("'{}' read as within a factor {wider}, either way", r.words),
            error: f.error,
            tolerance: wider.ln(),
        };
    }
    if let Some(slack) = r.at_most {
        let wider = if slack > 0.0 { 2.0 * slack } else { 0.05 };
        return Looser {
            choice,
            alternative: format!(
                "'{}' read as no more than the printed number plus {} %",
                r.words,
                wider * 100.0
            ),
            error: f.error,
            tolerance: wider - slack,
        };
    }
    let within = r.within.unwrap_or(0.0);
    let wider = if within > 0.0 { 2.0 * within } else { 0.05 };
    Looser {
        choice,
        alternative: format!("'{}' read as within {} %", r.words, wider * 100.0),
        error: f.error,
        tolerance: wider,
    }
}

/// A number read to its printed digits, read instead as within 5 % of the printed number: the
/// computed value unrounded (the headline's, where the finding's reference is rounded).
fn about_not_digits(f: &Finding, choice: &'static str) -> Looser {
    let computed = f.headline.as_ref().map_or(f.reference, |h| h.reference);
    Looser {
        choice,
        alternative: "read as within 5 % of the printed number, not to its digits".into(),
        error: ((computed - f.claimed) / f.claimed).abs(),
        tolerance: 0.05,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::finding::{Method, Tolerance, Worst};

    fn failing_by(error: f64) -> Checked {
        let mut w = Worst::default();
        w.add(1.0, 1.0 + error, 1.0, || "a point".into());
        Checked {
            subject: Subject::Equation {
                number: 3,
                label: "e4",
            },
            section: 3,
            finding: Ok(Finding::from_worst(
                Method::Identity,
                "a closed form",
                w,
                Tolerance::roundoff(),
            )),
            derivation: None,
            cause: None,
            dimensions: "consistent".into(),
        }
    }

    #[test]
    fn a_failure_inside_the_looser_tolerance_depends_on_it_and_one_far_outside_is_robust() {
        let bench = Bench::with_paper(paper::Paper::built_in_shared());
        let mut checked = [failing_by(5e-12), failing_by(0.5)];
        attach(&bench, &mut checked);
        let near = checked[0].finding.as_ref().unwrap();
        assert_eq!(
            near.verdict,
            Verdict::DependsOn {
                choice: "a tolerance"
            }
        );
        assert_eq!(near.robustness.len(), 2);
        assert_eq!(near.robustness[0].verdict, Verdict::Fails);
        assert_eq!(near.robustness[1].verdict, Verdict::Holds);
        let far = checked[1].finding.as_ref().unwrap();
        assert_eq!(far.verdict, Verdict::Fails);
        assert_eq!(far.robust(), Some(true));
        assert_eq!(far.robustness.len(), 2);
    }
}
