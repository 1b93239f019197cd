//! How a claim is judged against the number claims.yaml prints: by its rule (printed digits,
//! a relative distance, a factor, a range, a bound), with the comparison stated in the claim's unit.

use super::{Bench, Finding, Headline, Method, Tolerance, Worst};
use crate::finding::Verdict;

/// The unit a claim's comparison is shown in: claims.yaml keeps the paper's "Hz" where it
/// writes Hz, but those numbers are rad/s (claim `omega-units-hz-vs-rad-per-s`), and the
/// references compute rad/s.
pub(super) fn unit_of(yaml_unit: &str) -> String {
    if yaml_unit == "Hz" {
        "rad/s (printed as Hz)".into()
    } else {
        yaml_unit.into()
    }
}

/// Gives a claim's finding the comparison in the claim's own terms when its check did not: the
/// number claims.yaml prints, in its unit, against the reference, where the finding's claimed
/// value IS that printed number (read through [`Bench::claim`]). Findings that compare something
/// else (a fitted order, a derived threshold) keep their own rendering.
pub fn with_printed_headline(b: &Bench, id: &str, f: Finding) -> Finding {
    let Some(c) = b.paper.claims.iter().find(|c| c.id == id) else {
        return f;
    };
    let approximate = matches!(
        f.verdict,
        crate::finding::Verdict::HoldsApproximately { .. }
    );
    match c.claimed_value {
        Some(v) if f.headline.is_none() && !approximate && f.claimed == b.claim(v) => {
            let h = Headline::new(
                f.compared.clone(),
                v,
                &paper_is(c),
                f.reference,
                &unit_of(&c.unit),
                f.at.clone(),
            );
            f.with_headline(h)
        }
        _ => f,
    }
}

/// How the paper gives a claim's number, for its headline: "printed", "implied" (by its words,
/// claims.yaml's `implied`), or, for a range read from vague words, the reading itself (the
/// headline's value is then the range's lower end).
fn paper_is(c: &paper::ClaimEntry) -> String {
    match c
        .rule
        .as_ref()
        .and_then(|r| r.range.map(|range| (r, range)))
    {
        Some((r, [lo, hi])) => format!(
            "lower end of '{}', read as {lo} to {hi} {}",
            r.words,
            unit_of(&c.unit)
        ),
        None if c.implied => "implied".into(),
        None => "printed".into(),
    }
}

/// `x` rounded to `sig` significant digits.
pub(super) fn round_sig(x: f64, sig: i32) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let e = x.abs().log10().floor() as i32;
    let scale = 10f64.powi(sig - 1 - e);
    (x * scale).round() / scale
}

/// The printed-precision rule (see the module's doc).
pub(super) fn printed_tolerance(sig: i32) -> Tolerance {
    Tolerance {
        value: 1e-12,
        rule: format!(
            "printed precision: the computed value rounded to the paper's {sig} significant \
             digit(s) must equal the printed number (to round-off 1e-12)"
        ),
    }
}

/// Compares a computed value with a number printed to `sig` significant digits: the computed
/// value is rounded to that precision and must equal the (claimed) printed number.
pub(super) fn printed_precision(
    b: &Bench,
    method: Method,
    compared: &str,
    computed: f64,
    printed: f64,
    sig: i32,
    at: String,
) -> Finding {
    let mut w = Worst::default();
    let rounded = round_sig(computed, sig);
    w.add(b.claim(printed), rounded, printed.abs(), || {
        format!("{at}; computed {computed:.6} rounds to {rounded} at {sig} significant digit(s)")
    });
    Finding::from_worst(method, compared, w, printed_tolerance(sig))
}

/// Judges `computed` against the claim `id` as the bench's paper states it (paper/claims.yaml):
/// its printed value, moved by [`Bench::claim`] under the mutation test, read by the claim's
/// `rule` (to the printed digits, within a relative distance, within a factor, or inside a
/// range), and the rule's words become the tolerance's rule in the report. The number and its
/// reading live in the YAML only, so an author can restate either without touching Rust.
///
/// A claim missing from the paper, or without the `rule` or `claimed_value` its check needs, is
/// caught before the check runs (`check::missing_input`), which reports it as one that could
/// not run and names the key to add.
pub(super) fn stated(
    b: &Bench,
    id: &str,
    method: Method,
    compared: &str,
    computed: f64,
    at: String,
) -> Finding {
    let Some(c) = b.paper.claims.iter().find(|c| c.id == id) else {
        unreachable!("check::missing_input runs the check only when claims.yaml has `{id}`")
    };
    let f = judged(b, c, method, compared, computed, at.clone());
    if f.headline.is_some() {
        return f;
    }
    // The comparison in the claim's own unit: the number printed (the lower end of a printed
    // range) against the computed value, unrounded.
    let paper = c
        .rule
        .as_ref()
        .and_then(|r| r.range.map(|[lo, _]| lo))
        .or(c.claimed_value)
        .unwrap_or(f.claimed);
    let h = Headline::new(
        compared,
        paper,
        &paper_is(c),
        computed,
        &unit_of(&c.unit),
        at,
    );
    f.with_headline(h)
}

/// [`stated`] for the claim `c`, without its headline.
fn judged(
    b: &Bench,
    c: &paper::ClaimEntry,
    method: Method,
    compared: &str,
    computed: f64,
    at: String,
) -> Finding {
    let id = &c.id;
    let Some(rule) = &c.rule else {
        unreachable!("check::missing_input runs the check only when `{id}` has its rule")
    };
    let unit = unit_of(&c.unit);
    let tolerance = |value: f64| Tolerance {
        value,
        rule: rule.describe(c.claimed_value, &c.unit),
    };
    if let Some([lo, hi]) = rule.range {
        let (lo, hi) = (b.claim(lo), b.claim(hi));
        let (end, outside) = if !computed.is_finite() {
            (lo, f64::INFINITY)
        } else if computed < lo {
            (lo, lo - computed)
        } else if computed > hi {
            (hi, computed - hi)
        } else {
            (computed, 0.0)
        };
        let w = Worst {
            error: outside / end.abs().max(f64::MIN_POSITIVE),
            claimed: end,
            reference: computed,
            at: format!("{at}; the stated range is {lo} to {hi}"),
            points: 1,
            unit: unit.clone(),
        };
        // The relative band around the ends, where the rule gives one ("about 10 to 15").
        return Finding::from_worst(method, compared, w, tolerance(rule.within.unwrap_or(0.0)));
    }
    let Some(printed) = c.claimed_value else {
        unreachable!("check::missing_input runs the check only when `{id}` has its number")
    };
    let claimed = b.claim(printed);
    let mut w = Worst::default();
    if let Some(digits) = rule.digits {
        let rounded = round_sig(computed, digits as i32);
        w.add_in(claimed, rounded, printed.abs(), &unit, || {
            format!(
                "{at}; computed {computed:.6} rounds to {rounded} at {digits} significant digit(s)"
            )
        });
        return Finding::from_worst(method, compared, w, tolerance(1e-12));
    }
    if let Some(f) = rule.factor {
        let error = (computed / claimed).ln().abs();
        let w = Worst {
            error: if error.is_finite() {
                error
            } else {
                f64::INFINITY
            },
            claimed,
            reference: computed,
            at: format!(
                "{at}; error is $|\\ln(\\text{{computed}} / \\text{{printed}})|$, a factor {:.3}",
                error.exp()
            ),
            points: 1,
            unit: unit.clone(),
        };
        return Finding::from_worst(method, compared, w, tolerance(f.ln()));
    }
    if let Some(slack) = rule.at_most {
        let limit = claimed * (1.0 + slack);
        let over = (computed - limit) / claimed.abs();
        let w = Worst {
            error: if over.is_nan() {
                f64::INFINITY
            } else {
                over.max(0.0)
            },
            claimed,
            reference: computed,
            at: format!("{at}; the bound with its slack is {limit:.6e}"),
            points: 1,
            unit: unit.clone(),
        };
        return Finding::from_worst(method, compared, w, tolerance(0.0));
    }
    let within = rule.within.unwrap_or(0.0);
    w.add_in(claimed, computed, claimed.abs(), &unit, || at);
    Finding::from_worst(method, compared, w, tolerance(within))
}

/// The number claim `id` prints, as the bench's paper's claims.yaml gives it (so an author's
/// edit reaches the check); `check::missing_input` runs a check only when it is there.
pub(super) fn printed(b: &Bench, id: &str) -> f64 {
    b.paper
        .claims
        .iter()
        .find(|c| c.id == id)
        .and_then(|c| c.claimed_value)
        .unwrap_or_else(|| {
            unreachable!("check::missing_input runs the check only when `{id}` has its number")
        })
}

/// One comparison of a claimed value with a reference, relative, under `tol`.
pub(super) fn single(
    method: Method,
    compared: &str,
    claimed: f64,
    reference: f64,
    tol: Tolerance,
    at: String,
) -> Finding {
    let mut w = Worst::default();
    w.add(claimed, reference, reference.abs(), || at);
    Finding::from_worst(method, compared, w, tol)
}

/// One class for unit misprints: `printed` reads the number in the unit printed beside it,
/// `meant` in the unit the text means. Wrong as printed and right as meant is a
/// [`Verdict::UnitMisprint`]; wrong both ways stays a failure; right as printed is no misprint.
/// Either way the finding's `at` gives the second reading, so neither is silent.
pub(super) fn unit_misprint(printed: Finding, meant: Finding) -> Finding {
    if printed.verdict.passes() {
        return printed;
    }
    let mut f = printed;
    f.at = format!(
        "{}; in the unit meant: {} {} against {} ({}, error {:.3e})",
        f.at, meant.compared, meant.claimed, meant.reference, meant.verdict, meant.error
    );
    if meant.verdict.passes() {
        f.verdict = Verdict::UnitMisprint;
    }
    f
}

/// The failing one of two findings, or the first when both pass (its `at` names the second).
pub(super) fn worse(first: Finding, second: Finding) -> Finding {
    match (first.verdict.passes(), second.verdict.passes()) {
        (true, false) => second,
        (false, _) => first,
        (true, true) => {
            let mut f = first;
            f.at = format!(
                "{}; also {} ({}: error {:.3e}, {})",
                f.at, second.compared, second.verdict, second.error, second.at
            );
            f
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_headline_says_how_the_paper_gives_its_number() {
        let paper = paper::Paper::built_in().unwrap();
        let claim = |id: &str| paper.claims.iter().find(|c| c.id == id).unwrap().clone();
        assert_eq!(paper_is(&claim("k-uniform-disk")), "printed");
        assert_eq!(paper_is(&claim("rolling-extra-integrals")), "implied");
        assert_eq!(
            paper_is(&claim("summary-contact-lost-few-degrees")),
            "lower end of 'a few', read as 1 to 9 deg"
        );
        let mut edited = claim("k-uniform-disk");
        edited.implied = true;
        assert_eq!(paper_is(&edited), "implied");
    }
}
