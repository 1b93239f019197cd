//! Verdicts that agree with each other: every claim and equation that rests on a premise stated
//! in the prose (`rests_on` in claims.yaml and equations.yaml) is walked, and none may simply
//! hold while one of its premises fails; each premise it names as failing must fail.

use checks::check::{run_checks, Checked, Selection, Subject};
use checks::equations::Bench;
use checks::finding::Verdict;
use paper::Paper;

fn name(c: &Checked) -> String {
    match &c.subject {
        Subject::Equation { number, .. } => format!("eq {number}"),
        Subject::Claim { id } => id.to_string(),
    }
}

fn failing(v: &Verdict) -> bool {
    matches!(v, Verdict::Fails | Verdict::PremiseFails)
}

#[test]
fn no_verdict_holds_on_a_premise_that_fails() {
    let paper = Paper::built_in_shared();
    let checked = run_checks(
        &Bench::with_paper(paper),
        &Selection::default(),
        2,
        &|_, _| {},
    )
    .expect("the checks run");
    let verdict = |n: &str| {
        checked
            .iter()
            .find(|c| name(c) == n)
            .and_then(|c| c.finding.as_ref().ok())
            .map(|f| f.verdict)
    };
    let mut walked = 0;
    let mut wrong = Vec::new();
    for c in &checked {
        let rests: &[String] = match &c.subject {
            Subject::Equation { number, .. } => &paper.equation(*number).entry.rests_on,
            Subject::Claim { id } => paper
                .claims
                .iter()
                .find(|e| e.id == *id)
                .map_or(&[], |e| e.rests_on.as_slice()),
        };
        let Ok(f) = &c.finding else { continue };
        for p in rests {
            walked += 1;
            let premise_fails = verdict(p).is_some_and(|v| failing(&v));
            if premise_fails && !failing(&f.verdict) {
                wrong.push(format!("{} {} though {p} fails", name(c), f.verdict));
            }
            if f.premises_failing.contains(p) != premise_fails {
                wrong.push(format!("{}: premise {p} named wrongly", name(c)));
            }
        }
    }
    // Eleven premises are named; the two of the uncheckable summary-nutation-10-15-deg claim are
    // not walked.
    assert!(walked >= 9, "only {walked} premises walked");
    assert!(wrong.is_empty(), "{wrong:#?}");
    // The examples that motivated the rule.
    for n in [
        "eq 57",
        "eq 58",
        "eq 80",
        "eq 81",
        "coincidence-eq54",
        "coincidence-eq58",
    ] {
        assert_eq!(verdict(n), Some(Verdict::PremiseFails), "{n}");
    }
}

/// A verdict does not depend on what else was selected: eq 80 alone, or a coincidence claim
/// alone, still runs the premise it rests on (silently) and says it fails.
#[test]
fn a_selection_runs_the_premises_its_subjects_rest_on() {
    let paper = Paper::built_in_shared();
    let bench = Bench::with_paper(paper);
    for (numbers, claims, shown) in [
        (Some(vec![80]), Some(Vec::new()), "eq 80"),
        (
            Some(Vec::new()),
            Some(vec!["coincidence-eq54".to_string()]),
            "coincidence-eq54",
        ),
    ] {
        let selection = Selection { numbers, claims };
        let checked = run_checks(&bench, &selection, 2, &|_, _| {}).expect("the checks run");
        assert_eq!(checked.len(), 1, "only {shown} is shown");
        let f = checked[0].finding.as_ref().expect("it runs");
        assert_eq!(f.verdict, Verdict::PremiseFails, "{shown}");
        assert!(!f.premises_failing.is_empty(), "{shown}");
    }
}
