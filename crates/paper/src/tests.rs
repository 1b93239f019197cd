//! The paper reader's own tests: the built-in paper reads whole, and each kind of error names
//! its file, equation and column.

use super::load::EQUATIONS;
use super::*;

#[test]
fn the_built_in_paper_reads_whole() {
    let p = Paper::built_in().unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(p.equations.len(), 85);
    let total: usize = p.equations.iter().map(|e| e.relations().len()).sum();
    assert!(total >= 100, "{total} relations");
    // eq 3 prints two equalities, eq 18 two chains.
    assert_eq!(p.equation(3).relations().len(), 2);
    assert_eq!(p.equation(18).chains.len(), 2);
}

/// The sentence that refuses the built-in paper with eq 1's LaTeX replaced by `latex`.
fn eq1_refused_as(latex: &str) -> String {
    let eqs = EQUATIONS.replacen(r"'\mathbf{a} = a \hat{\mathbf{3}}'", latex, 1);
    let texts = Texts {
        equations: &eqs,
        ..Texts::BUILT_IN
    };
    match Paper::from_texts(PaperSource::BuiltIn, texts) {
        Ok(_) => String::from("accepted"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn an_unknown_symbol_names_the_equation_and_column() {
    let msg = eq1_refused_as(r"'\mathbf{a} = q \hat{\mathbf{3}}'");
    assert!(
        msg.contains("eq 1: column 14") && msg.contains("symbol q"),
        "{msg}"
    );
}

#[test]
fn bad_latex_names_the_equation_and_column() {
    let msg = eq1_refused_as(r"'\mathbf{a} = \frac{a}{'");
    assert!(msg.contains("eq 1: column"), "{msg}");
}

#[test]
fn evaluation_follows_the_symbol_tables() {
    let p = Paper::built_in().unwrap_or_else(|e| panic!("{e}"));
    // eq 31: Omega_0^2 = g / (a k sin alpha_0).
    let eq = p.equation(31);
    let r = eq.relations()[0];
    let b = Bindings::new()
        .scalar("g", 9.81)
        .scalar("a", 0.0375)
        .scalar("k", 0.25)
        .scalar("alpha_0", 0.3);
    let rhs = eq.scalar(r.rhs, &b).unwrap();
    let want = 9.81 / (0.0375 * 0.25 * 0.3_f64.sin());
    assert!((rhs - want).abs() < 1e-12 * want);
    let err = eq.scalar(r.lhs, &b).unwrap_err();
    assert!(err.to_string().contains("Omega_0"), "{err}");
}

/// The paper's own source, beside the checkout in CI (`../shared/paper/`), read through the
/// LaTeX reader: its 85 equations found by label. Skipped with a message where it is absent.
#[test]
fn the_papers_source_gives_its_85_equations() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../..");
    let source = root.join("shared/paper/000_b5819d499ad0b272.txt");
    if !source.exists() {
        eprintln!("skipped: the paper's source {} is absent", source.display());
        return;
    }
    let p = crate::Paper::from_path(&source).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(p.equations.len(), 85);
    // Every equation reads as the same tree as its transcription in equations.yaml.
    assert!(p.notes.is_empty(), "{:#?}", p.notes);
}
