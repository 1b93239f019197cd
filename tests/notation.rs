//! Notation cannot change a verdict. Every one of the 85 printed equations of
//! paper/equations.yaml is rewritten in other notations, generated from its parsed LaTeX by
//! `paper::notation` (not listed by hand): `\cdot` or `\times` between scalar
//! factors, `\dfrac` and `\tfrac`, `/`, `\left( \right)`, `\bigl( \bigr)`, `\Big(`, `[ ]`, thin,
//! thick, negative and control spaces and `~`, redundant braces around every factor, term and
//! side, factors and terms in the other order, a full stop, comma or semicolon at the end; and
//! the printed text itself retouched (`\dfrac`, `\left( \right)`, `\,=\,`, a full stop). Each
//! notation is written, all 85 at once, to a paper directory read as `check --paper DIR` reads
//! it, and every check (equations with their derivations and causes, and claims) must give the
//! same outcome as on the unmodified paper: the same verdicts, causes and numbers, to the bit.
//!
//! The reordered notation is compared without the two texts that quote the relation as it was
//! written (a finding's `compared` and `at`), which show the new order; everything else, numbers
//! included, must still be the same to the bit.

use checks::check::{run_checks, Selection};
use checks::equations::Bench;
use paper::notation::{retouch, write, NOTATIONS};
use paper::EquationEntry;
use paper::Paper;
use serde_json::Value;
use std::path::PathBuf;

const EQUATIONS: &str = include_str!("../paper/equations.yaml");

fn entries() -> Vec<EquationEntry> {
    serde_yaml::from_str(EQUATIONS).unwrap()
}

/// A paper directory holding `entries` as its equations.yaml (the built-in symbols and claims).
fn paper_dir(tag: &str, entries: &[EquationEntry]) -> PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "rolling-disk-notation-{tag}-{}",
        std::process::id()
    ));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(
        dir.join("equations.yaml"),
        serde_yaml::to_string(entries).unwrap(),
    )
    .unwrap();
    dir
}

/// Every check's outcome on `paper`, as JSON.
fn outcomes(paper: &Paper, selection: &Selection) -> Value {
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    let checked = run_checks(&Bench::with_paper(paper), selection, threads, &|_, _| {}).unwrap();
    serde_json::to_value(&checked).unwrap()
}

/// `v` without the texts that quote a relation as written.
fn without_quotes(v: &mut Value) {
    match v {
        Value::Object(map) => {
            map.remove("compared");
            map.remove("at");
            map.values_mut().for_each(without_quotes);
        }
        Value::Array(items) => items.iter_mut().for_each(without_quotes),
        _ => {}
    }
}

/// The first check whose outcome differs, both outcomes shown.
fn first_difference(a: &Value, b: &Value) -> Option<String> {
    let (a, b) = (a.as_array()?, b.as_array()?);
    if a.len() != b.len() {
        return Some(format!("{} checks against {}", a.len(), b.len()));
    }
    a.iter()
        .zip(b)
        .find(|(x, y)| x != y)
        .map(|(x, y)| format!("unmodified:\n{x}\nrewritten:\n{y}"))
}

#[test]
fn every_equation_in_every_notation_gives_the_same_verdicts_causes_and_numbers() {
    let printed = entries();
    assert_eq!(printed.len(), 85);
    let base_paper = Paper::from_dir(&paper_dir("unmodified", &printed)).unwrap();
    let all = Selection::default();
    let base = outcomes(&base_paper, &all);
    let mut base_unquoted = base.clone();
    without_quotes(&mut base_unquoted);

    let mut notations: Vec<(String, bool, Vec<EquationEntry>)> = NOTATIONS
        .iter()
        .map(|n| {
            let rewritten = printed
                .iter()
                .zip(&base_paper.equations)
                .map(|(e, parsed)| EquationEntry {
                    latex: write(&parsed.chains, n),
                    ..e.clone()
                })
                .collect();
            (n.name.to_string(), n.reorder, rewritten)
        })
        .collect();
    notations.push((
        "the printed text retouched".into(),
        false,
        printed
            .iter()
            .map(|e| EquationEntry {
                latex: retouch(&e.latex),
                ..e.clone()
            })
            .collect(),
    ));
    assert!(notations.len() >= 5);

    for (i, (name, reordered, rewritten)) in notations.iter().enumerate() {
        let dir = paper_dir(&format!("n{i}"), rewritten);
        let paper = Paper::from_dir(&dir).unwrap_or_else(|e| panic!("{name}: {e}"));
        for ((old, new), parsed) in printed.iter().zip(rewritten).zip(&paper.equations) {
            assert_ne!(old.latex, new.latex, "{name}: eq {} unchanged", old.number);
            if !reordered {
                let want = &base_paper.equation(old.number).chains;
                assert_eq!(
                    &parsed.chains, want,
                    "{name}: eq {} reads differently: {}",
                    old.number, new.latex
                );
            }
        }
        let mut got = outcomes(&paper, &all);
        let want = if *reordered {
            without_quotes(&mut got);
            &base_unquoted
        } else {
            &base
        };
        if let Some(d) = first_difference(want, &got) {
            panic!("{name}: a check's outcome changed with the notation:\n{d}");
        }
        std::fs::remove_dir_all(&dir).ok();
    }
}

/// The comparison can tell papers apart: a real change (eq 31's sine made a cosine) changes the
/// outcome, so the equalities above are not vacuous.
#[test]
fn a_change_of_mathematics_does_change_the_outcome() {
    let p = Paper::from_dir(&paper_dir("control", &entries())).unwrap();
    let only31 = Selection {
        numbers: Some(vec![31]),
        claims: Some(Vec::new()),
    };
    let cosine = p
        .with_latex(31, r"\Omega_0^2 = \frac{g}{a k \cos\alpha_0}")
        .unwrap();
    assert_ne!(outcomes(&p, &only31), outcomes(&cosine, &only31));
}

/// The cases the referee met: eq 31 written `\frac{g}{k \cdot a \sin(\alpha_{0})}` or with
/// `g \cdot 1` evaluated to nothing and failed, a root cause for eqs 76-83. Now they give eq 31's
/// verdict and every cause downstream unchanged.
#[test]
fn eq_31_written_with_cdot_keeps_its_verdict_and_the_causes_downstream() {
    let p = Paper::from_dir(&paper_dir("eq31", &entries())).unwrap();
    let selection = Selection {
        numbers: Some(vec![31, 73, 76, 79, 83]),
        claims: Some(Vec::new()),
    };
    let verdicts = |paper: &Paper| {
        let checked = run_checks(&Bench::with_paper(paper), &selection, 2, &|_, _| {}).unwrap();
        checked
            .iter()
            .map(|c| {
                let f = c.finding.as_ref().map_err(Clone::clone).unwrap();
                assert!(f.claimed.is_finite(), "{}: {f:?}", c.subject.name());
                (c.subject.name(), f.verdict, c.cause.clone())
            })
            .collect::<Vec<_>>()
    };
    let want = verdicts(&p);
    for latex in [
        r"\Omega_0^2 = \frac{g}{k \cdot a \sin(\alpha_{0})}",
        r"\Omega_0^2 = \frac{g \cdot 1}{a \times k \sin\alpha_0}",
        r"\Omega_{0}^{2} = \dfrac{g}{\left( a k \right) \bigl( \sin\alpha_0 \bigr)} .",
    ] {
        let edited = p.with_latex(31, latex).unwrap();
        assert_eq!(verdicts(&edited), want, "{latex}");
    }
}
