//! Tests of the catalogue and of how a claim naming a quantity is read and checked.

use super::*;
use crate::equations::claims::catalogued;
use crate::harness::Bench;

/// The built-in claims.yaml with `entry` appended.
fn paper_with(entry: &str) -> paper::Paper {
    let claims = format!("{}\n{entry}", paper::Texts::BUILT_IN.claims);
    paper::Paper::from_texts(
        paper::PaperSource::BuiltIn,
        paper::Texts {
            claims: &claims,
            ..paper::Texts::BUILT_IN
        },
    )
    .expect("the claims parse")
}

/// The line of claims.yaml `entry` starts on once appended (its first line).
fn first_line() -> usize {
    paper::Texts::BUILT_IN.claims.lines().count() + 2
}

const RISING: &str = "\
- id: rising-spin-threshold-uniform
  section: 10
  near_equation: 65
  claim: \"A uniform disk sleeps upright without friction above sqrt(g/(a k)) = 2 sqrt(g/a).\"
  claimed_value: 2
  unit: sqrt(g/a)
  quantity: { name: vertical-spin-threshold, contact: frictionless, k: 0.25 }
";

#[test]
fn names_are_unique_and_every_parameter_default_is_in_its_kind() {
    let mut names: Vec<&str> = QUANTITIES.iter().map(|q| q.name).collect();
    names.sort_unstable();
    names.dedup();
    assert_eq!(names.len(), QUANTITIES.len());
    for q in QUANTITIES {
        for p in q.parameters {
            match (p.kind, p.default) {
                (Kind::Number { above, below, .. }, Some(Value::Number(x))) => {
                    assert!(x > above && x < below, "{}.{}", q.name, p.name)
                }
                (Kind::Choice(words), Some(Value::Word(w))) => assert!(words.contains(&w)),
                (_, None) => {}
                _ => panic!("{}.{}: a default of another kind", q.name, p.name),
            }
        }
    }
}

#[test]
fn a_claim_naming_a_quantity_is_checked_and_a_wrong_number_fails() {
    let paper = paper_with(RISING);
    validate(&paper).expect("the claim reads");
    let f = catalogued(&Bench::with_paper(&paper), "rising-spin-threshold-uniform");
    assert!(f.verdict.passes(), "{f:#?}");
    assert!((f.reference - 2.0).abs() < 1e-10, "{}", f.reference);
    let wrong = paper_with(&RISING.replace("claimed_value: 2", "claimed_value: 2.1"));
    let f = catalogued(&Bench::with_paper(&wrong), "rising-spin-threshold-uniform");
    assert_eq!(f.verdict, crate::finding::Verdict::Fails, "{f:#?}");
    // The printed number moved by 1e-3 fails too: the check can fail.
    let f = catalogued(
        &Bench {
            perturbation: 1e-3,
            ..Bench::with_paper(&paper)
        },
        "rising-spin-threshold-uniform",
    );
    assert_eq!(f.verdict, crate::finding::Verdict::Fails);
}

#[test]
fn a_rule_reads_the_printed_number() {
    let about = RISING
        .replace("claimed_value: 2", "claimed_value: 2.08")
        .replace(
            "  quantity:",
            "  rule: { words: about, within: 0.05 }\n  quantity:",
        );
    let f = catalogued(
        &Bench::with_paper(&paper_with(&about)),
        "rising-spin-threshold-uniform",
    );
    assert!(f.verdict.passes(), "{f:#?}");
    assert!(
        f.tolerance.rule.contains("'about' read as within 5 %"),
        "{}",
        f.tolerance.rule
    );
}

/// Each wrong entry is refused naming the file, the line, the key and the nearest name.
#[test]
fn a_wrong_name_parameter_value_or_unit_is_refused_where_it_stands() {
    let line = first_line() + 6;
    let cases = [
        (
            RISING.replace("vertical-spin-threshold", "vertical-spin-treshold"),
            "key `quantity.name`: `vertical-spin-treshold` is not a quantity of the catalogue (did you mean `vertical-spin-threshold`?)",
        ),
        (
            RISING.replace("k: 0.25", "kk: 0.25"),
            "key `quantity.kk`: `vertical-spin-threshold` has no parameter `kk` (did you mean `k`?)",
        ),
        (
            RISING.replace(", k: 0.25", ""),
            "needs its parameter `k`",
        ),
        (
            RISING.replace("k: 0.25", "k: -1"),
            "key `quantity.k`: -1 is out of range",
        ),
        (
            RISING.replace("frictionless", "frictonless"),
            "`frictonless` is not one of rolling, frictionless (did you mean `frictionless`?)",
        ),
        (
            RISING.replace("unit: sqrt(g/a)", "unit: rad/s"),
            "key `unit`: `vertical-spin-threshold` is computed in sqrt(g/a), not rad/s",
        ),
        (
            RISING.replace("claimed_value: 2", "claimed_value: null"),
            "key `claimed_value`",
        ),
        (
            RISING.replace("rising-spin-threshold-uniform", "k-uniform-disk-again"),
            "",
        ),
    ];
    for (entry, wanted) in cases {
        let paper = paper_with(&entry);
        let got = validate(&paper);
        if wanted.is_empty() {
            assert!(got.is_ok(), "{got:?}");
            continue;
        }
        let why = got.expect_err(wanted);
        assert!(why.contains(wanted), "{why}");
        assert!(
            why.starts_with(&format!(
                "paper/claims.yaml (built in), line {line}: claim `"
            )),
            "{why}"
        );
    }
}

#[test]
fn a_claim_with_its_own_check_cannot_name_a_quantity() {
    let text = paper::Texts::BUILT_IN.claims.replace(
        r"  quantity: '$\sqrt{1/k}$ at $k = 1/4$ from eq 65'",
        "  quantity: { name: vertical-spin-threshold, contact: frictionless, k: 0.25 }",
    );
    let paper = paper::Paper::from_texts(
        paper::PaperSource::BuiltIn,
        paper::Texts {
            claims: &text,
            ..paper::Texts::BUILT_IN
        },
    )
    .expect("parses");
    let why = validate(&paper).expect_err("refused");
    assert!(
        why.contains("claim `frictionless-threshold-uniform`"),
        "{why}"
    );
    assert!(why.contains("has its own check, written in Rust"), "{why}");
}

const ORDER: &str = "\
- id: eq56-order
  section: 7
  near_equation: 56
  claim: \"The frequency ratio tends to sqrt(3k/(k+1)) at second order in alpha_0.\"
  claimed_value: 2
  unit: order
  quantity: { name: approximation-order, equation: 56, exact: nutation-ratio, k: 0.25 }
";

/// An order is judged as the equations' orders are: eq 56 holds approximately at 2, a planted
/// 1 fails, and an equation's number must be whole and the order take no `rule`.
#[test]
fn an_order_claim_is_judged_and_its_entry_read() {
    let f = catalogued(&Bench::with_paper(&paper_with(ORDER)), "eq56-order");
    assert!(
        matches!(
            f.verdict,
            crate::finding::Verdict::HoldsApproximately { .. }
        ),
        "{f:#?}"
    );
    let wrong = paper_with(&ORDER.replace("claimed_value: 2", "claimed_value: 1"));
    let f = catalogued(&Bench::with_paper(&wrong), "eq56-order");
    assert_eq!(f.verdict, crate::finding::Verdict::Fails, "{f:#?}");
    for (entry, wanted) in [
        (
            ORDER.replace("order, equation: 56", "order, equation: 56.5"),
            "key `quantity.equation`: 56.5 is not a whole number",
        ),
        (
            ORDER.replace(
                "  quantity:",
                "  rule: { words: about, digits: 1 }\n  quantity:",
            ),
            "key `rule`: `approximation-order` is an order",
        ),
        (
            ORDER.replace("nutation-ratio", "approximation-order"),
            "`approximation-order` is not one of",
        ),
    ] {
        let why = validate(&paper_with(&entry)).expect_err(wanted);
        assert!(why.contains(wanted), "{why}");
    }
}
