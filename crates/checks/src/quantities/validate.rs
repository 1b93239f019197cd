//! A claim naming a quantity of the catalogue is read before any check runs: an unknown name or
//! parameter, a missing one, a value out of its range, a unit other than the quantity's, or a
//! claim that has its own check in Rust, is refused in one sentence naming the file, the line,
//! the key, the nearest name and the fix.

use super::{find, Kind, Quantity, Value, Values, QUANTITIES};
use paper::{ClaimEntry, NamedQuantity, Paper, ParameterValue};
use physics::nearest::nearest;

/// Reads every claim of `paper` that names a quantity of the catalogue; the first problem, as a
/// sentence, if any.
pub fn validate(paper: &Paper) -> Result<(), String> {
    for c in &paper.claims {
        if let Some(named) = c.quantity.named() {
            claim(c, named)?;
        }
    }
    Ok(())
}

/// The quantity and the values a claim names ([`validate`] has read it).
pub fn of_claim(c: &ClaimEntry) -> Result<(&'static Quantity, Values), String> {
    let named = c
        .quantity
        .named()
        .ok_or_else(|| format!("claim `{}` names no quantity of the catalogue", c.id))?;
    claim(c, named)
}

/// " (did you mean X?)" for the name nearest to `name` among `names`.
fn hint<'n>(name: &str, names: impl IntoIterator<Item = &'n str>) -> String {
    nearest(name, names).map_or(String::new(), |n| format!(" (did you mean `{n}`?)"))
}

fn claim(c: &ClaimEntry, named: &NamedQuantity) -> Result<(&'static Quantity, Values), String> {
    let id = &c.id;
    let at = |key: &str| format!("{}: claim `{id}`", named.place.at(key));
    if crate::equations::claims().iter().any(|k| k.id == id) {
        return Err(format!(
            "{}, key `quantity`: this claim has its own check, written in Rust, which reads its \
             own quantity; write its `quantity` in words, or give the claim another id",
            at("name")
        ));
    }
    let Some(q) = find(&named.name) else {
        return Err(format!(
            "{}, key `quantity.name`: `{}` is not a quantity of the catalogue{}; \
             `rolling-disk quantities` lists them",
            at("name"),
            named.name,
            hint(&named.name, QUANTITIES.iter().map(|q| q.name))
        ));
    };
    let mut values = Vec::new();
    if let Some(unknown) = named
        .parameters
        .keys()
        .find(|k| !q.parameters.iter().any(|p| p.name == k.as_str()))
    {
        let names: Vec<&str> = q.parameters.iter().map(|p| p.name).collect();
        return Err(format!(
            "{}, key `quantity.{unknown}`: `{}` has no parameter `{unknown}`{}; its parameters \
             are {}",
            at(unknown),
            q.name,
            hint(unknown, names.iter().copied()),
            names.join(", ")
        ));
    }
    for p in q.parameters {
        let key = format!("quantity.{}", p.name);
        let value = match (named.parameters.get(p.name), p.default) {
            (None, Some(d)) => d,
            (None, None) => {
                return Err(format!(
                    "{}, key `quantity`: `{}` needs its parameter `{}` ({}): add `{}: ...`",
                    at("name"),
                    q.name,
                    p.name,
                    p.means,
                    p.name
                ))
            }
            (Some(given), _) => value_of(p.kind, given)
                .map_err(|why| format!("{}, key `{key}`: {why}", at(p.name)))?,
        };
        values.push((p.name, value));
    }
    if c.unit != q.unit {
        return Err(format!(
            "{}, key `unit`: `{}` is computed in {}, not {}: write `unit: '{}'` and the printed \
             number in it",
            at("name"),
            q.name,
            q.unit,
            c.unit,
            q.unit
        ));
    }
    if q.method == crate::finding::Method::Asymptotic && c.rule.is_some() {
        return Err(format!(
            "{}, key `rule`: `{}` is an order, judged by the asymptotic rule (the fitted order \
             within {} of the printed one); remove the `rule`",
            at("name"),
            q.name,
            crate::finding::Tolerance::order().value
        ));
    }
    let range = c.rule.as_ref().is_some_and(|r| r.range.is_some());
    if c.claimed_value.is_none() && !range {
        return Err(format!(
            "{}, key `claimed_value`: a claim about `{}` is judged against the number the paper \
             prints: give `claimed_value` (in {})",
            at("name"),
            q.name,
            q.unit
        ));
    }
    Ok((q, Values(values)))
}

/// A parameter's value as given, read as its kind asks; why not otherwise.
fn value_of(kind: Kind, given: &ParameterValue) -> Result<Value, String> {
    match (kind, given) {
        (
            Kind::Number {
                unit,
                above,
                below,
                whole,
            },
            ParameterValue::Number(x),
        ) => {
            if whole && x.fract() != 0.0 {
                Err(format!("{x} is not a whole number: give one (in {unit})"))
            } else if x.is_finite() && *x > above && *x < below {
                Ok(Value::Number(*x))
            } else {
                Err(format!(
                    "{x} is out of range: give a number between {above} and {below} (in {unit}, \
                     both excluded)"
                ))
            }
        }
        (Kind::Number { unit, .. }, ParameterValue::Word(w)) => {
            Err(format!("`{w}` is not a number: give one (in {unit})"))
        }
        (Kind::Choice(words), ParameterValue::Word(w)) => words
            .iter()
            .find(|c| **c == w.as_str())
            .map(|c| Value::Word(c))
            .ok_or_else(|| {
                format!(
                    "`{w}` is not one of {}{}",
                    words.join(", "),
                    hint(w, words.iter().copied())
                )
            }),
        (Kind::Choice(words), ParameterValue::Number(x)) => Err(format!(
            "{x} is not one of {}: give one of those words",
            words.join(", ")
        )),
    }
}
