//! A claim of claims.yaml that names a quantity of the catalogue ([`crate::quantities`]): no Rust
//! is written for it. The quantity is computed at the claim's parameters and judged against the
//! printed number by the claim's `rule` ([`super::judge`]), or, where the claim gives none, by
//! the quantity's own tolerance (its method's: a bisection's width, round-off, the solver's);
//! an order by the asymptotic rule of [`Finding::from_order`].

use super::judge::{single, stated, with_printed_headline};
use super::{Bench, Finding};

/// The check of claim `id`, which names a quantity of the catalogue. A claim that does not
/// (or names it wrongly: `check` refuses that before any check runs) gives a reference that is
/// not a number, which the runner reports as a check that could not run, with the reason.
pub fn catalogued(b: &Bench, id: &str) -> Finding {
    let found = b
        .paper
        .claims
        .iter()
        .find(|c| c.id == id)
        .ok_or_else(|| format!("claims.yaml has no claim `{id}`"))
        .and_then(|c| crate::quantities::of_claim(c).map(|q| (c, q)));
    let (c, (q, values)) = match found {
        Ok(x) => x,
        Err(why) => {
            return single(
                crate::finding::Method::Derivation,
                id,
                f64::NAN,
                f64::NAN,
                crate::finding::Tolerance::roundoff(),
                why,
            )
        }
    };
    let computed = (q.compute)(&values, b);
    let compared = format!("{} ({}), in {}", q.name, values.describe(), q.unit);
    let at = format!("{}; {}", computed.at, q.how);
    if c.rule.is_some() {
        return stated(b, id, q.method, &compared, computed.value, at);
    }
    let printed = c.claimed_value.unwrap_or(f64::NAN);
    if let Some((small, errors)) = &computed.series {
        let mut f = Finding::from_order(compared, small, errors, b.claim(printed));
        f.at = format!("{}; {at}", f.at);
        return with_printed_headline(b, id, f);
    }
    let f = single(
        q.method,
        &compared,
        b.claim(printed),
        computed.value,
        (q.tolerance)(b),
        at,
    )
    .in_unit(q.unit);
    with_printed_headline(b, id, f)
}
