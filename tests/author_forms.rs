//! An author's order and forms cannot change an outcome. Every one of the 85 printed equations
//! is written with the sides of each of its chains swapped (`b = a` for `a = b`, an inequality
//! turned), and then rewritten in the author forms of `paper::forms::FORMS` (generated from the
//! text, not listed by hand), two families at a time; every check (equations with their
//! derivations and causes, and claims) must give the outcome it gives on the printed paper: the
//! same verdicts, causes and numbers, to the bit. The texts that quote a relation as written (a
//! finding's `compared` and `at`) are left out of the comparison, as a chain with a lone symbol
//! at neither end is quoted in the order written.
//!
//! Every chain is swapped, those with a lone symbol at an end (which `paper::orient` reads in
//! one order) and those with none (eq 22, the equations of motion, eq 54, whose checks read
//! either order). The full product of pairs of families runs in the suite by reading: a pair
//! that reads as the printed relations node for node gives their outcomes (the checks see a
//! paper only through its relations and symbols), so only a pair that reads otherwise would need
//! its checks run. Six pairs drawn with a fixed seed are run through the checks in the suite
//! too, and all 105 in an ignored test.

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

/// `v` without the texts that quote a relation, and with a comparison's two values in one
/// order: where a relation has a formula on both sides (eq 22, the equations of motion, eq 54,
/// the identities), which side a finding calls `claimed` and which `reference` is the order
/// written, and swapping them swaps the two numbers and nothing else (the verdict and the error
/// do not depend on it). A check that read a side differently would still show: its numbers, its
/// error or its verdict would differ.
fn without_quotes(v: &mut Value) {
    match v {
        Value::Object(map) => {
            map.remove("compared");
            map.remove("at");
            let (c, r) = (map.get("claimed").cloned(), map.get("reference").cloned());
            if let (Some(Value::Number(c)), Some(Value::Number(r))) = (c, r) {
                let (x, y) = (c.as_f64().unwrap_or(0.0), r.as_f64().unwrap_or(0.0));
                map.insert("claimed".into(), x.min(y).into());
                map.insert("reference".into(), x.max(y).into());
                // A reading inherited from a premise keeps the finding's own reference: one of
                // the two sides, whichever the order written calls the reference.
                if let Some(Value::Array(readings)) = map.get_mut("robustness") {
                    for reading in readings.iter_mut() {
                        let side = reading.get("reference").and_then(Value::as_f64);
                        if side.is_some_and(|z| z == x || z == y) {
                            reading["reference"] = "one of the two sides".into();
                        }
                    }
                }
            }
            map.values_mut().for_each(without_quotes);
        }
        Value::Array(items) => items.iter_mut().for_each(without_quotes),
        _ => {}
    }
}

/// Every check whose outcome differs, both shown (all of them, so that one run names every
/// check that depends on the order or form written).
fn differences(a: &Value, b: &Value) -> Option<String> {
    let (a, b) = (a.as_array()?, b.as_array()?);
    if a.len() != b.len() {
        return Some(format!("{} checks against {}", a.len(), b.len()));
    }
    let all: Vec<String> = a
        .iter()
        .zip(b)
        .filter(|(x, y)| x != y)
        .map(|(x, y)| format!("printed:\n{x}\nrewritten:\n{y}"))
        .collect();
    (!all.is_empty()).then(|| format!("{} checks:\n{}", all.len(), all.join("\n\n")))
}

/// Every pair of families (a family with itself included), in order.
fn pairs() -> Vec<(usize, usize)> {
    (0..FORMS.len())
        .flat_map(|i| (i..FORMS.len()).map(move |j| (i, j)))
        .collect()
}

/// The paper with every chain swapped (`all`, or only those with a lone symbol at an end) and
/// written in families `i` and `j`.
fn pair_paper((i, j): (usize, usize), all: bool) -> Paper {
    let (a, b) = (&FORMS[i], &FORMS[j]);
    rewritten(&|e| {
        let text = write(&swapped(&e.chains, all), &PRINTED);
        (b.rewrite)(&(a.rewrite)(&text))
    })
}

/// The outcome of the paper with every chain swapped and written in families `i` and `j`.
fn check_pair(base: &Value, (i, j): (usize, usize), all: bool) {
    let (a, b) = (&FORMS[i], &FORMS[j]);
    let got = outcomes(&pair_paper((i, j), all));
    if let Some(d) = differences(base, &got) {
        panic!(
            "sides swapped, in {} + {}: a check's outcome changed:\n{d}",
            a.name, b.name
        );
    }
}

/// True when two papers read as the same mathematics: every equation's relations node for node,
/// and every symbol with the same quantity and unit. The checks read a paper through these (its
/// relations, evaluated with its symbols' quantities), so two papers that read the same give
/// the same outcomes; only the texts that quote the LaTeX as written, and the columns of
/// messages, can differ.
fn same_reading(a: &Paper, b: &Paper) -> bool {
    a.equations.len() == b.equations.len()
        && a.equations.iter().zip(&b.equations).all(|(x, y)| {
            x.chains == y.chains
                && x.symbols.len() == y.symbols.len()
                && x.symbols.iter().all(|(s, i)| {
                    y.symbols
                        .get(s)
                        .is_some_and(|j| (&i.quantity, &i.unit) == (&j.quantity, &j.unit))
                })
        })
}

/// Every equation's every chain swapped, in either reading (`paper::orient` for the chains with
/// a lone symbol at an end, the checks themselves for the others: eq 22, the equations of
/// motion, eq 54), gives the printed outcomes; and every pair of author families (a family with
/// itself included, 105 pairs of 14) written on it reads as it does, node for node. A pair that
/// did not read the same would have its checks run and compared; none does, so the full product
/// costs two check runs and 105 readings of the paper.
#[test]
fn every_chain_swapped_and_every_pair_of_author_forms_give_the_printed_outcomes() {
    let base = outcomes(Paper::built_in_shared());
    for all in [false, true] {
        let swapped_paper = rewritten(&|e| write(&swapped(&e.chains, all), &PRINTED));
        if let Some(d) = differences(&base, &outcomes(&swapped_paper)) {
            panic!("sides swapped (all chains: {all}): a check's outcome changed:\n{d}");
        }
    }
    let reference = rewritten(&|e| write(&swapped(&e.chains, true), &PRINTED));
    let mut run = 0;
    for pair in pairs() {
        if !same_reading(&pair_paper(pair, true), &reference) {
            run += 1;
            check_pair(&base, pair, true);
        }
    }
    assert_eq!(
        run, 0,
        "{run} pairs of families read differently from the printed relations (their checks \
         gave the printed outcomes)"
    );
}

/// A sample of the pairs run through the checks whatever their reading, with a fixed seed: the
/// claim of [`same_reading`] (same reading, same outcomes) tested on the checks themselves.
#[test]
fn six_pairs_of_author_forms_run_through_the_checks_give_the_printed_outcomes() {
    let base = outcomes(Paper::built_in_shared());
    let mut all = pairs();
    all.shuffle(&mut rand_chacha::ChaCha8Rng::seed_from_u64(46));
    for pair in all.into_iter().take(6) {
        check_pair(&base, pair, true);
    }
}

#[test]
#[ignore = "every pair of author forms through the checks: 105 full check runs, 387 s on two shared cores"]
fn every_pair_of_author_forms_run_through_the_checks_gives_the_printed_outcomes() {
    let base = outcomes(Paper::built_in_shared());
    for pair in pairs() {
        check_pair(&base, pair, true);
    }
}
