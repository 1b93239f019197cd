//! What a claim's check computes (claims.yaml's `quantity`): in words, for a claim whose check is
//! written in Rust, or a quantity of the tool's catalogue named with its parameters
//! (`rolling-disk quantities` lists them), which the checks compute with no Rust written for the
//! claim:
//!
//! ```yaml
//! quantity: { name: vertical-spin-threshold, contact: frictionless, k: 0.25 }
//! ```
//!
//! The paper crate reads the name and the parameters as given, and where each stands in the file
//! (for messages); the catalogue that knows the names lives with the checks, which refuse an
//! unknown name or parameter naming the file, the line, the key and the nearest name.

use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// claims.yaml's `quantity`: words, or a quantity of the catalogue with its parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum ClaimQuantity {
    /// What must be computed, in words (a check written in Rust computes it).
    Words(String),
    /// A quantity of the catalogue, by name, with its parameters.
    Named(NamedQuantity),
}

impl ClaimQuantity {
    /// The named quantity, if the claim names one.
    pub fn named(&self) -> Option<&NamedQuantity> {
        match self {
            ClaimQuantity::Named(n) => Some(n),
            ClaimQuantity::Words(_) => None,
        }
    }
}

/// A quantity of the catalogue named by a claim: `{ name: NAME, PARAMETER: VALUE, ... }`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct NamedQuantity {
    /// The catalogue's name of the quantity.
    pub name: String,
    /// Its parameters as given, by name.
    #[serde(flatten)]
    pub parameters: BTreeMap<String, ParameterValue>,
    /// Where the entry stands in claims.yaml, for messages.
    #[serde(skip)]
    pub place: Place,
}

/// A parameter's value as written: a number, or a word (a choice such as `contact: rolling`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum ParameterValue {
    /// A number.
    Number(f64),
    /// A word.
    Word(String),
}

impl std::fmt::Display for ParameterValue {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ParameterValue::Number(x) => write!(f, "{x}"),
            ParameterValue::Word(w) => write!(f, "{w}"),
        }
    }
}

/// Where a named quantity stands: the file, the line of its `quantity` key, and the line of each
/// of its keys (`name` and the parameters); 0 where the line was not found.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Place {
    /// The file, as messages name it.
    pub file: String,
    /// The line (1-based) of the claim's `quantity` key.
    pub line: usize,
    /// The line of each key of the quantity's map.
    pub keys: BTreeMap<String, usize>,
}

impl Place {
    /// "FILE, line N" for the key `key` of the quantity (the `quantity` line where the key was
    /// not found on a line of its own).
    pub fn at(&self, key: &str) -> String {
        let line = self.keys.get(key).copied().unwrap_or(self.line);
        if line == 0 {
            self.file.clone()
        } else {
            format!("{}, line {line}", self.file)
        }
    }
}

/// Gives every claim of `claims` (read from `text`, the file `file`) that names a quantity of the
/// catalogue its place in the file; a claim whose quantity is words must say `how` it is
/// computed: why not, otherwise.
pub(crate) fn place_all(
    claims: &mut [crate::ClaimEntry],
    text: &str,
    file: &str,
) -> Result<(), String> {
    for c in claims {
        match &mut c.quantity {
            ClaimQuantity::Named(n) => n.place = place_in(text, &c.id, file),
            ClaimQuantity::Words(_) if c.how.trim().is_empty() => {
                return Err(format!(
                    "claim `{}`, key `how`: say how its quantity is computed independently, or \
                     name a quantity of the catalogue (`rolling-disk quantities`) as \
                     `quantity: {{ name: ..., ... }}`",
                    c.id
                ))
            }
            ClaimQuantity::Words(_) => {}
        }
    }
    Ok(())
}

/// Finds where the `quantity` of claim `id` stands in `text` (claims.yaml): the line of the
/// claim's `quantity` key after its `id`, and of each key of the map, written inline
/// (`quantity: { name: x, k: 0.25 }`, every key on that line) or as a block (one key a line,
/// indented below it).
pub(crate) fn place_in(text: &str, id: &str, file: &str) -> Place {
    let mut place = Place {
        file: file.to_string(),
        ..Place::default()
    };
    let lines: Vec<&str> = text.lines().collect();
    let is_id = |l: &str| {
        let l = l.trim_start().trim_start_matches('-').trim();
        l.strip_prefix("id:").is_some_and(|v| {
            let v = v.split('#').next().unwrap_or("").trim();
            v.trim_matches(|c| c == '\'' || c == '"') == id
        })
    };
    let Some(start) = lines.iter().position(|l| is_id(l)) else {
        return place;
    };
    let entry_end = lines[start + 1..]
        .iter()
        .position(|l| l.starts_with('-'))
        .map_or(lines.len(), |i| start + 1 + i);
    let Some(q) = (start..entry_end).find(|&i| lines[i].trim_start().starts_with("quantity:"))
    else {
        return place;
    };
    place.line = q + 1;
    let indent = |l: &str| l.len() - l.trim_start().len();
    let key_of = |l: &str| {
        let l = l.trim().trim_start_matches(['{', ',']).trim();
        l.split_once(':')
            .map(|(k, _)| k.trim().to_string())
            .filter(|k| !k.is_empty() && !k.contains(' '))
    };
    let rest = lines[q].trim_start().trim_start_matches("quantity:").trim();
    if rest.starts_with('{') {
        for part in rest.trim_matches(|c| c == '{' || c == '}').split(',') {
            if let Some(k) = key_of(part) {
                place.keys.insert(k, q + 1);
            }
        }
    } else {
        let own = indent(lines[q]);
        for (i, l) in lines.iter().enumerate().take(entry_end).skip(q + 1) {
            if l.trim().is_empty() || l.trim_start().starts_with('#') {
                continue;
            }
            if indent(l) <= own {
                break;
            }
            if let Some(k) = key_of(l) {
                place.keys.insert(k, i + 1);
            }
        }
    }
    place
}

#[cfg(test)]
mod tests {
    use super::*;

    const TEXT: &str = "\
- id: first
  quantity: \"words\"

- id: inline
  section: 8
  quantity: { name: vertical-spin-threshold, k: 0.25 }

- id: 'block'
  quantity:
    name: steady-precession-rate
    # a comment
    alpha0: 0.3
  how: x
";

    #[test]
    fn the_lines_of_a_quantity_and_its_keys_are_found() {
        let p = place_in(TEXT, "inline", "claims.yaml");
        assert_eq!(p.line, 6);
        assert_eq!(p.keys.get("name"), Some(&6));
        assert_eq!(p.keys.get("k"), Some(&6));
        let p = place_in(TEXT, "block", "claims.yaml");
        assert_eq!(p.line, 9);
        assert_eq!(p.keys.get("name"), Some(&10));
        assert_eq!(p.keys.get("alpha0"), Some(&12));
        assert_eq!(p.keys.get("how"), None);
        assert_eq!(p.at("alpha0"), "claims.yaml, line 12");
        assert_eq!(p.at("missing"), "claims.yaml, line 9");
        assert_eq!(place_in(TEXT, "absent", "f").at("k"), "f");
    }

    #[test]
    fn words_and_a_named_quantity_read_apart() {
        let words: ClaimQuantity = serde_yaml::from_str("\"a threshold\"").unwrap();
        assert_eq!(words.named(), None);
        let named: ClaimQuantity =
            serde_yaml::from_str("{ name: q, k: 0.25, n: 2, contact: rolling }").unwrap();
        let n = named.named().expect("a named quantity");
        assert_eq!(n.name, "q");
        assert_eq!(n.parameters["k"], ParameterValue::Number(0.25));
        assert_eq!(n.parameters["n"], ParameterValue::Number(2.0));
        assert_eq!(
            n.parameters["contact"],
            ParameterValue::Word("rolling".into())
        );
    }
}
