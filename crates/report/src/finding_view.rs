//! A finding as the report shows it: the card of an equation or claim (printed against true
//! first, then the comparison over the domain), and the rows of the claims table with their one
//! error measure, the relative error.

use super::{fmt_num, ClaimView, FindingView};
use checks::check::{Checked, Subject};
use checks::equations::{Bench, UNCHECKABLE_CLAIMS};
use checks::finding::{Finding, Verdict};

/// Claimed and reference values as a reader should see them, to the digits the check's
/// tolerance supports ([`crate::number::within`]; relative, as the findings' errors are): for
/// an approximation the claimed and the fitted orders, the fitted one to the place of the
/// tolerance on their difference.
pub(crate) fn values(f: &Finding) -> (String, String) {
    use crate::number::{to_place_of, within};
    let tolerance = f.tolerance.value;
    if is_order(f) {
        (
            format!("order {}", fmt_num(f.claimed)),
            format!("order {}", to_place_of(f.reference, tolerance)),
        )
    } else {
        // With the unit where the check knows it (none shown for a pure number).
        let unit = match f.unit.as_str() {
            "" | "1" | "order" => String::new(),
            u => format!(" {}", paper::unit_tex::unit_prose(u)),
        };
        (
            format!("{}{unit}", within(f.claimed, tolerance)),
            format!("{}{unit}", within(f.reference, tolerance)),
        )
    }
}

pub(crate) fn view(f: &Finding) -> FindingView {
    let (claimed, reference) = values(f);
    let class = match f.verdict {
        Verdict::Holds => "holds",
        Verdict::HoldsApproximately { .. } => "approx",
        Verdict::Definition => "definition",
        Verdict::Estimate { .. } => "estimate",
        Verdict::PremiseFails | Verdict::DependsOn { .. } => "premise",
        Verdict::Fails
        | Verdict::Restates { .. }
        | Verdict::PartOf { .. }
        | Verdict::UnitMisprint
        | Verdict::DimensionalSlip => "fails",
    };
    FindingView {
        method: f.method.to_string(),
        compared: crate::number::prose(&f.compared),
        claimed: claimed.clone(),
        reference: reference.clone(),
        error: crate::number::error(f.error),
        tolerance: crate::number::error(f.tolerance.value),
        rule: f.tolerance.rule.clone(),
        verdict: if f.premises_failing.is_empty() {
            f.verdict.to_string()
        } else {
            format!("{} (fails: {})", f.verdict, f.premises_failing.join(", "))
        },
        class: class.into(),
        at: crate::number::prose(&f.at),
        figure: f
            .shown_by
            .as_deref()
            .map(|s| s.trim_start_matches("figure ").to_string()),
        headline: f
            .headline
            .as_ref()
            .map(|h| headline_text(h, &format!("paper {{}} ({})", h.paper_is))),
        headline_at: f.headline.as_ref().map(|h| crate::number::prose(&h.at)),
        error_measure: if is_order(f) {
            "|fitted - claimed order|".into()
        } else {
            "error (the tolerance rule's measure)".into()
        },
        restates: match f.verdict {
            Verdict::Restates { equation } => Some(equation),
            _ => None,
        },
    }
}

/// True when a finding compares orders (an approximation's claimed and fitted order).
pub(crate) fn is_order(f: &Finding) -> bool {
    f.method == checks::finding::Method::Asymptotic || f.unit == "order"
}

/// The paper's value and the true one of the same quantity, with the unit: the headline's
/// where the check gives one, else the finding's own unless it compares orders.
pub(crate) fn printed_and_true(f: &Finding) -> Option<(f64, f64, String)> {
    match &f.headline {
        Some(h) => Some((h.paper, h.reference, h.unit.clone())),
        None if !is_order(f) => Some((f.claimed, f.reference, f.unit.clone())),
        None => None,
    }
}

/// |true - paper| / |paper|, formatted; a dash where the paper's value is 0 or either is not a
/// number.
pub(crate) fn relative_error(paper: f64, truth: f64) -> String {
    let r = (truth - paper).abs() / paper.abs();
    if paper != 0.0 && r.is_finite() {
        crate::number::error(r)
    } else {
        "-".into()
    }
}

/// A headline in words: its quantity, the paper's value as `paper` phrases it (`{}` stands for
/// the number) and the true value, each with the unit.
pub(crate) fn headline_text(h: &checks::finding::Headline, paper: &str) -> String {
    let unit = if h.unit == "1" {
        String::new()
    } else {
        format!(" {}", paper::unit_tex::unit_prose(&h.unit))
    };
    let paper = paper.replacen("{}", &format!("{}{unit}", fmt_num(h.paper)), 1);
    format!(
        "{}: {paper}, true {}{unit}",
        h.quantity,
        fmt_num(h.reference)
    )
}

pub(crate) fn error_view(message: &str) -> FindingView {
    FindingView {
        method: "-".into(),
        compared: "-".into(),
        claimed: "-".into(),
        reference: "-".into(),
        error: "-".into(),
        tolerance: "-".into(),
        rule: "-".into(),
        verdict: "could not run".into(),
        class: "error".into(),
        at: message.into(),
        figure: None,
        headline: None,
        headline_at: None,
        error_measure: "error".into(),
        restates: None,
    }
}

pub(crate) fn finding_of(c: &Checked) -> FindingView {
    match &c.finding {
        Ok(f) => view(f),
        Err(e) => error_view(e),
    }
}

/// The computed value of a claim's quantity, with its unit: the headline's true value, else the
/// finding's reference (an approximation's fitted order).
pub(crate) fn computed_text(f: &Finding) -> String {
    match printed_and_true(f) {
        Some((_, t, unit)) => match unit.as_str() {
            "" | "1" => fmt_num(t),
            u => format!("{} {}", fmt_num(t), paper::unit_tex::unit_prose(u)),
        },
        None => values(f).1,
    }
}

/// Every prose claim's view, and the claims with no check and why.
pub(crate) fn claim_views(
    bench: &Bench,
    checked: &[Checked],
) -> (Vec<ClaimView>, Vec<(String, String)>) {
    let mut claims = Vec::new();
    let mut unchecked_claims = Vec::new();
    for c in &bench.paper.claims {
        let found = checked
            .iter()
            .find(|k| matches!(&k.subject, Subject::Claim { id } if *id == c.id));
        let why = UNCHECKABLE_CLAIMS
            .iter()
            .find(|(id, _)| *id == c.id)
            .map(|(_, why)| why.to_string());
        if found.is_none() {
            unchecked_claims.push((
                c.id.clone(),
                why.clone().unwrap_or_else(|| "no check yet".into()),
            ));
        }
        claims.push(ClaimView {
            anchor: format!("claim-{}", c.id),
            id: c.id.clone(),
            section: c.section,
            near_equation: c.near_equation,
            claim: c.claim.clone(),
            printed: match c.claimed_value {
                Some(v) if c.unit == "1" => fmt_num(v),
                Some(v) => format!("{} {}", fmt_num(v), paper::unit_tex::unit_prose(&c.unit)),
                None => "(qualitative)".into(),
            },
            how: crate::number::prose(&how_of(c)),
            rule: c
                .rule
                .as_ref()
                .map(|r| r.describe(c.claimed_value, &c.unit)),
            also: c
                .also_at
                .iter()
                .map(|l| format!("sec. {} (eq {}): {}", l.section, l.near_equation, l.claim))
                .collect(),
            computed: found
                .and_then(|k| k.finding.as_ref().ok())
                .map(computed_text)
                .unwrap_or_default(),
            relative_error: found
                .and_then(|k| k.finding.as_ref().ok())
                .filter(|_| c.claimed_value.is_some())
                .and_then(printed_and_true)
                .map_or_else(|| "-".into(), |(p, t, _)| relative_error(p, t)),
            finding: found.map(finding_of),
            uncheckable: why,
        });
    }

    (claims, unchecked_claims)
}

/// How a claim is computed: its `how`, or, where it names a quantity of the catalogue and says
/// nothing more, the quantity's method.
fn how_of(c: &paper::ClaimEntry) -> String {
    match checks::quantities::of_claim(c) {
        Ok((q, values)) if c.how.trim().is_empty() => {
            format!("{} ({}): {}", q.name, values.describe(), q.how)
        }
        _ => c.how.clone(),
    }
}
