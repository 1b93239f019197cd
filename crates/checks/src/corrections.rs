//! The numbers a referee writes back: for each equation the checks find wrong at the root, a
//! corrected form as LaTeX (`corrections.yaml`, read with the paper: [`Paper::corrections`]), checked by the equation's own check
//! against the same reference as the printed form, and the numbers downstream that change.
//!
//! A correction is not taken on trust either: it is substituted into the paper
//! ([`Paper::with_latex`]), all of them at once so that a corrected equation's premises are the
//! corrected ones, and the checks run on both papers. [`Verified`] holds both verdicts; a
//! correction that does not hold is reported as such.
//!
//! Downstream, the constant $C$ of eq 79 is what the experiment of sec. 11 fits, so a corrected
//! eq 79 changes the dissipation strength $\epsilon$ that a fitted $C$ means:
//! [`epsilon_from_fit`] reads $\epsilon$ off eq 79's definition of $C$,
//! $C = 5g/\epsilon(\beta + 2)ak$ as printed, for the paper's fit
//! ($\beta = 2$, $C^{-1/4} = 0.0055$ s).

use crate::check::{run_findings, Checked, Selection, Subject};
use crate::finding::{Finding, Headline, Verdict};
use crate::harness::{solve_printed, Bench};
use paper::{Bindings, Correction, Paper, PaperError};
use serde::Serialize;

/// Why the corrections could not be checked.
#[derive(Debug, thiserror::Error)]
pub enum CorrectionError {
    /// A corrected LaTeX does not parse or uses an unknown symbol.
    #[error("corrections.yaml: {0}")]
    Latex(#[from] PaperError),
    /// The checks could not run.
    #[error("the checks of the corrected equations could not run: {0}")]
    Checks(crate::check::CheckError),
}

/// What a check found for one form (printed or corrected).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Outcome {
    /// The verdict (`holds`, `fails`, ...), or `could not run`.
    pub verdict: String,
    /// True when the form holds (exactly or approximately) or is a definition.
    pub holds: bool,
    /// The comparison in the paper's terms, where the check gives one.
    pub headline: Option<Headline>,
    /// What was compared, the error and the tolerance, in words.
    pub detail: String,
}

/// A correction and what the checks say of the printed and the corrected form.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Verified {
    /// The printed number.
    pub number: u32,
    /// The printed LaTeX.
    pub printed_latex: String,
    /// The corrected LaTeX.
    pub corrected_latex: String,
    /// Why.
    pub why: String,
    /// The printed form's check.
    pub printed: Outcome,
    /// The corrected form's check.
    pub corrected: Outcome,
}

/// The dissipation strength a fit of eq 79 means, as printed and as corrected.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Downstream {
    /// The fit: $\beta$.
    pub beta: f64,
    /// The fit: $C^{-1/(\beta+2)}$ (s).
    pub c_inv_root: f64,
    /// The disk: radius (m) and inertia factor, and g (m/s^2).
    pub a: f64,
    /// Inertia factor.
    pub k: f64,
    /// Gravity.
    pub g: f64,
    /// $\epsilon$ from the printed eq 79.
    pub epsilon_printed: f64,
    /// $\epsilon$ from the corrected eq 79.
    pub epsilon_corrected: f64,
}

/// `paper` with every correction substituted.
pub fn apply(paper: &Paper, corrections: &[Correction]) -> Result<Paper, CorrectionError> {
    corrections.iter().try_fold(paper.clone(), |p, c| {
        p.with_latex(c.number, &c.latex)
            .map_err(CorrectionError::from)
    })
}

/// Runs the check of every corrected equation on `bench`'s paper as it is and with all the
/// corrections substituted.
pub fn verify(
    bench: &Bench,
    corrections: &[Correction],
    threads: usize,
) -> Result<Vec<Verified>, CorrectionError> {
    let before =
        run_findings(bench, &selection(corrections), threads).map_err(CorrectionError::Checks)?;
    let after = check_corrected(bench, corrections, threads)?;
    Ok(assemble(bench.paper, corrections, &before, &after))
}

/// The checks of the corrected equations only.
fn selection(corrections: &[Correction]) -> Selection {
    // The claims are not re-run on the corrected paper: the study reads the corrected
    // equations' findings alone.
    Selection {
        numbers: Some(corrections.iter().map(|c| c.number).collect()),
        claims: Some(Vec::new()),
    }
}

/// Runs the check of every corrected equation on `bench`'s paper with all the corrections
/// substituted (the printed forms' checks are the report's own). Only the findings are read,
/// so their premises are not re-run and no causes are attached.
pub fn check_corrected(
    bench: &Bench,
    corrections: &[Correction],
    threads: usize,
) -> Result<Vec<Checked>, CorrectionError> {
    let corrected = apply(bench.paper, corrections)?;
    let after_bench = Bench {
        paper: &corrected,
        ..*bench
    };
    run_findings(&after_bench, &selection(corrections), threads).map_err(CorrectionError::Checks)
}

/// Each correction with the printed form's check (from `printed`, the checks of `paper`) and
/// the corrected form's (from `corrected`).
pub fn assemble(
    paper: &Paper,
    corrections: &[Correction],
    printed: &[Checked],
    corrected: &[Checked],
) -> Vec<Verified> {
    corrections
        .iter()
        .map(|c| Verified {
            number: c.number,
            printed_latex: paper.equation(c.number).entry.latex.clone(),
            corrected_latex: c.latex.clone(),
            why: c.why.clone(),
            printed: outcome(printed, c.number),
            corrected: outcome(corrected, c.number),
        })
        .collect()
}

fn outcome(checked: &[Checked], number: u32) -> Outcome {
    let found = checked
        .iter()
        .find(|c| matches!(c.subject, Subject::Equation { number: n, .. } if n == number));
    match found.map(|c| &c.finding) {
        Some(Ok(f)) => Outcome {
            verdict: f.verdict.to_string(),
            holds: !matches!(f.verdict, Verdict::Fails),
            headline: f.headline.clone(),
            detail: detail(f),
        },
        Some(Err(e)) => Outcome {
            verdict: "could not run".into(),
            holds: false,
            headline: None,
            detail: e.clone(),
        },
        None => Outcome {
            verdict: "not checked".into(),
            holds: false,
            headline: None,
            detail: format!("eq {number} has no check"),
        },
    }
}

fn detail(f: &Finding) -> String {
    format!(
        "{}: error {:.3e} (tolerance {:.1e}); {}",
        f.compared, f.error, f.tolerance.value, f.at
    )
}

/// $\epsilon$ from eq 79 in `paper` for a fit $(\beta, C^{-1/(\beta+2)})$ of a disk $(a, k)$
/// under gravity $g$: the $\epsilon$ at which the chain's first relation (the printed formula
/// for $\Omega$ with $\epsilon$ in it) gives the fitted $\Omega = (C/(t_0 - t))^{1/(\beta+2)}$
/// one second before $t_0$. No formula for $\epsilon$ is written here: eq 79's LaTeX is solved.
pub fn epsilon_from_fit(
    paper: &Paper,
    beta: f64,
    c_inv_root: f64,
    (a, k, g): (f64, f64, f64),
) -> Option<f64> {
    let eq = paper.equation(79);
    let relations = eq.relations();
    let first = relations.first()?;
    let c = c_inv_root.powf(-(beta + 2.0));
    let omega = (c / 1.0).powf(1.0 / (beta + 2.0));
    let bind = Bindings::new()
        .scalar("beta", beta)
        .scalar("a", a)
        .scalar("k", k)
        .scalar("g", g)
        .scalar("Omega", omega)
        .scalar("t", 0.0)
        .scalar("t_0", 1.0)
        .scalar("C", c);
    solve_printed(eq, first, "dissipation", &bind, 1e-12, 1e6)
}

/// [`epsilon_from_fit`] on the printed and the corrected paper, for the printed paper's fit
/// (sec. 11, [`paper::Fit`]: $\beta = 2$, $C^{-1/4} = 0.0055$ s) and disk `(a, k, g)`.
pub fn downstream(
    printed: &Paper,
    corrected: &Paper,
    (a, k, g): (f64, f64, f64),
) -> Option<Downstream> {
    let (beta, c_inv_root) = (printed.fit.beta, printed.fit.c_inv_root);
    Some(Downstream {
        beta,
        c_inv_root,
        a,
        k,
        g,
        epsilon_printed: epsilon_from_fit(printed, beta, c_inv_root, (a, k, g))?,
        epsilon_corrected: epsilon_from_fit(corrected, beta, c_inv_root, (a, k, g))?,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::harness::built_in_paper;

    #[test]
    fn the_built_in_corrections_read_and_substitute() {
        let cs = built_in_paper().corrections.clone();
        assert!(cs.len() >= 6, "{}", cs.len());
        let p = apply(built_in_paper(), &cs).unwrap();
        for c in &cs {
            assert_eq!(p.equation(c.number).entry.latex, c.latex);
        }
        assert_ne!(p.hash, built_in_paper().hash);
    }

    #[test]
    fn a_bad_correction_is_refused_with_the_equation_and_column() {
        let bad = "- number: 76\n  latex: '\\dot{\\alpha} = - \\frac{2 \\zeta}{3}'\n  why: x\n";
        let cs = paper::correction::parse(bad).unwrap();
        let e = apply(built_in_paper(), &cs).unwrap_err().to_string();
        assert!(e.contains("eq 76") && e.contains("column"), "{e}");
    }

    #[test]
    fn the_corrected_eq_79_means_three_fifths_of_the_papers_epsilon() {
        let cs = &built_in_paper().corrections;
        let corrected = apply(built_in_paper(), cs).unwrap();
        let d = downstream(built_in_paper(), &corrected, (0.0375, 0.25, 9.81)).unwrap();
        // As printed: epsilon = 5 g C^{-1} / ((beta + 2) a k), C = 0.0055^-4.
        let c = 0.0055f64.powi(-4);
        let expected = 5.0 * 9.81 / (c * 4.0 * 0.0375 * 0.25);
        assert!(
            (d.epsilon_printed - expected).abs() < 1e-9 * expected,
            "{} vs {expected}",
            d.epsilon_printed
        );
        let ratio = d.epsilon_corrected / d.epsilon_printed;
        assert!((ratio - 0.6).abs() < 1e-9, "{ratio}");
    }
}
