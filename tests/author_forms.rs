//! An author's order and forms cannot change an outcome. Every one of the 85 printed equations
//! is written with the sides of each of its chains swapped (`b = a` for `a = b`, an inequality
//! turned), and then rewritten in the author forms of `paper::forms::FORMS` (generated from the
//! text, not listed by hand), two families at a time; every check (equations with their
//! derivations and causes, and claims) must give the outcome it gives on the printed paper: the
//! same verdicts, causes and numbers, to the bit. The texts that quote a relation as written (a
//! finding's `compared` and `at`) are left out of the comparison, as a chain with a lone symbol
//! at neither end is quoted in the order written.
//!
//! The suite swaps the chains with a lone symbol at an end (which `paper::orient` reads in one
//! order) and samples six pairs of families with a seeded generator; the full product of pairs is
//! an ignored test (a full check run takes about four seconds). Swapping the chains with a lone
//! symbol at neither end is the third, ignored, test: it fails today on eq 22.

use checks::check::{run_checks, Selection};
use checks::equations::Bench;
use paper::forms::FORMS;
use paper::notation::{write, Notation, Quotient};
use paper::{Chain, EquationEntry, Expr, Paper, PaperSource, Texts};
use rand::seq::SliceRandom;
use rand::SeedableRng;
use serde_json::Value;

/// The paper's own notation, as the writer gives it.
const PRINTED: Notation = Notation {
    name: "as printed",
    product: " ",
    quotient: Quotient::Frac("frac"),
    group: ("(", ")"),
    space: "",
    braces: false,
    reorder: false,
    separator: r", \qquad ",
    end: "",
};

/// Each chain with its sides in the other order (`all`), or only each chain with a lone symbol
/// of a quantity at an end, the chains `paper::orient` reads in one order.
fn swapped(chains: &[Chain], all: bool) -> Vec<Chain> {
    let lone = |e: &Expr| matches!(e, Expr::Sym(s) if s.base != "constant");
    chains
        .iter()
        .map(|c| {
            let ends = (c.sides.first(), c.sides.last());
            let defined = matches!(ends, (Some(a), Some(b)) if lone(a) || lone(b));
            if !(all || defined) {
                return c.clone();
            }
            Chain {
                sides: c.sides.iter().rev().cloned().collect(),
                rels: c.rels.iter().rev().map(|r| r.reversed()).collect(),
            }
        })
        .collect()
}

/// The built-in paper with every equation's LaTeX given by `latex`.
fn rewritten(latex: &dyn Fn(&paper::Equation) -> String) -> Paper {
    let built_in = Paper::built_in_shared();
    let entries: Vec<EquationEntry> = built_in
        .equations
        .iter()
        .map(|e| EquationEntry {
            latex: latex(e),
            ..e.entry.clone()
        })
        .collect();
    let yaml = serde_yaml::to_string(&entries).unwrap();
    let texts = Texts {
        equations: &yaml,
        ..Texts::BUILT_IN
    };
    Paper::from_texts(PaperSource::BuiltIn, texts).unwrap_or_else(|e| panic!("{e}"))
}

/// Every check's outcome on `paper`, as JSON, as [`without_quotes`] leaves it.
fn outcomes(paper: &Paper) -> Value {
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    let checked = run_checks(
        &Bench::with_paper(paper),
        &Selection::default(),
        threads,
        &|_, _| {},
    )
    .unwrap();
    let mut v = serde_json::to_value(&checked).unwrap();
    without_quotes(&mut v);
    v
}

/// `v` without the texts that quote a relation, and with an identity's two sides in one order:
/// an identity compares two printed sides, and which of them a finding calls `claimed` is the
/// order written where neither side is a lone symbol (the verdict and the error do not depend
/// on it).
fn without_quotes(v: &mut Value) {
    match v {
        Value::Object(map) => {
            map.remove("compared");
            map.remove("at");
            if map.get("method").and_then(Value::as_str) == Some("identity") {
                let (c, r) = (map.get("claimed").cloned(), map.get("reference").cloned());
                if let (Some(Value::Number(c)), Some(Value::Number(r))) = (c, r) {
                    let (x, y) = (c.as_f64().unwrap_or(0.0), r.as_f64().unwrap_or(0.0));
                    map.insert("claimed".into(), x.min(y).into());
                    map.insert("reference".into(), x.max(y).into());
                }
            }
            map.values_mut().for_each(without_quotes);
        }
        Value::Array(items) => items.iter_mut().for_each(without_quotes),
        _ => {}
    }
}

/// The first check whose outcome differs, both shown.
fn first_difference(a: &Value, b: &Value) -> Option<String> {
    let (a, b) = (a.as_array()?, b.as_array()?);
    if a.len() != b.len() {
        return Some(format!("{} checks against {}", a.len(), b.len()));
    }
    a.iter()
        .zip(b)
        .find(|(x, y)| x != y)
        .map(|(x, y)| format!("printed:\n{x}\nrewritten:\n{y}"))
}

/// Every pair of families (a family with itself included), in order.
fn pairs() -> Vec<(usize, usize)> {
    (0..FORMS.len())
        .flat_map(|i| (i..FORMS.len()).map(move |j| (i, j)))
        .collect()
}

/// The outcome of the paper with every chain swapped and written in families `i` and `j`.
fn check_pair(base: &Value, (i, j): (usize, usize), all: bool) {
    let (a, b) = (&FORMS[i], &FORMS[j]);
    let paper = rewritten(&|e| {
        let text = write(&swapped(&e.chains, all), &PRINTED);
        (b.rewrite)(&(a.rewrite)(&text))
    });
    let got = outcomes(&paper);
    if let Some(d) = first_difference(base, &got) {
        panic!(
            "sides swapped, in {} + {}: a check's outcome changed:\n{d}",
            a.name, b.name
        );
    }
}

#[test]
fn sides_swapped_and_author_forms_two_at_a_time_give_the_printed_outcomes() {
    let base = outcomes(Paper::built_in_shared());
    // Sides swapped alone, in every chain with a lone symbol at an end.
    let swapped_paper = rewritten(&|e| write(&swapped(&e.chains, false), &PRINTED));
    if let Some(d) = first_difference(&base, &outcomes(&swapped_paper)) {
        panic!("sides swapped: a check's outcome changed:\n{d}");
    }
    // Pairs of families, drawn with a fixed seed.
    let mut all = pairs();
    all.shuffle(&mut rand_chacha::ChaCha8Rng::seed_from_u64(46));
    for pair in all.into_iter().take(6) {
        check_pair(&base, pair, false);
    }
}

#[test]
#[ignore = "every pair of author forms: 105 full check runs, about 6.5 minutes on two cores"]
fn every_pair_of_author_forms_gives_the_printed_outcomes() {
    let base = outcomes(Paper::built_in_shared());
    for pair in pairs() {
        check_pair(&base, pair, false);
    }
}

/// Fails today: a chain with a lone symbol at neither end is read as written, and eq 22's check
/// (`checks::equations::kinematics::mass::eq22`) compares its residual, left side minus right,
/// with the reference's signed residual and scales it by the left side: written the other way
/// round, eq 22 FAILS as a root cause. Its checks, and those of the other such chains, must
/// compare the relation's residual up to its sign and scale by both sides before this holds.
#[test]
#[ignore = "fails today on eq 22 (see the doc comment): the checks of chains with no lone symbol at an end depend on the order written"]
fn every_chain_swapped_gives_the_printed_outcomes() {
    let base = outcomes(Paper::built_in_shared());
    let paper = rewritten(&|e| write(&swapped(&e.chains, true), &PRINTED));
    if let Some(d) = first_difference(&base, &outcomes(&paper)) {
        panic!("every chain swapped: a check's outcome changed:\n{d}");
    }
}
