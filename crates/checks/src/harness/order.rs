//! The worst of several fits of an approximation's order, as one finding.

use crate::finding::{Finding, Verdict};

/// The worst of several order fits: the first failing, else the largest order error.
pub fn worst_order(findings: Vec<(String, Finding)>) -> Finding {
    let mut best: Option<Finding> = None;
    for (label, mut f) in findings {
        f.at = format!("{label}: {}", f.at);
        best = Some(match best {
            None => f,
            Some(b) => {
                let bad = |x: &Finding| matches!(x.verdict, Verdict::Fails);
                if (bad(&f) && !bad(&b)) || (bad(&f) == bad(&b) && f.error > b.error) {
                    f
                } else {
                    b
                }
            }
        });
    }
    best.expect("at least one fit")
}
