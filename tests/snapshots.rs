//! Snapshots of every finding, so that a change in a derived result shows up in review
//! (`cargo insta review`). Values are rounded so that they are stable across machines: claimed
//! and reference values to 6 significant digits, errors to their decade, orders to 0.01.

use checks::check::{run_checks, Selection};
use checks::equations::Bench;
use checks::finding::Verdict;
use std::fmt::Write;

fn sig(x: f64, digits: usize) -> String {
    if x.abs() < 1e-10 {
        return "~0".into();
    }
    if !x.is_finite() {
        return format!("{x}");
    }
    format!("{:.*e}", digits - 1, x)
}

fn decade(x: f64) -> String {
    if x < 1e-12 {
        return "<1e-12".into();
    }
    if !x.is_finite() {
        return format!("{x}");
    }
    format!("1e{}", x.log10().floor() as i32)
}

#[test]
fn findings_of_every_equation_and_claim() {
    let checked = run_checks(&Bench::default(), &Selection::default(), 2, &|_, _| {}).unwrap();
    let mut out = String::new();
    for c in &checked {
        let name = c.subject.name();
        match &c.finding {
            Err(e) => writeln!(out, "{name}: could not run: {e}").unwrap(),
            Ok(f) => {
                let verdict = match f.verdict {
                    Verdict::HoldsApproximately {
                        measured_order,
                        claimed_order,
                    } => format!(
                        "holds approximately (order {measured_order:.2}, claimed {claimed_order})"
                    ),
                    v => v.to_string(),
                };
                writeln!(
                    out,
                    "{name} [{}] {verdict}: claimed {} reference {} error ~{} (tolerance {:e})",
                    f.method,
                    sig(f.claimed, 6),
                    sig(f.reference, 6),
                    decade(f.error),
                    f.tolerance.value
                )
                .unwrap();
            }
        }
        if let Some(Ok(d)) = &c.derivation {
            writeln!(
                out,
                "  follows from its printed premises? {} (error ~{}, tolerance {:e})",
                d.verdict,
                decade(d.error),
                d.tolerance.value
            )
            .unwrap();
        }
        if let Some(cause) = &c.cause {
            writeln!(out, "  cause: {}", cause.describe()).unwrap();
        }
    }
    insta::with_settings!({ snapshot_path => "../snapshots", prepend_module_to_snapshot => false }, {
        insta::assert_snapshot!("findings", out);
    });
}
