//! The YAML reader's complaints said in the tool's terms.
//!
//! serde speaks of fields, variants, maps, `f64` and `struct SceneSpec`; a scene's author writes
//! keys, names, mappings and numbers. [`translate`] rewrites each kind of complaint into one
//! sentence that names the key (by its dotted path), what was expected and what was found, and
//! for a misspelt key or name the nearest valid one ("did you mean"). Values quoted from the file
//! are cut to [`MAX_VALUE_CHARS`] characters so that a 10 MB value is never echoed whole.

/// Longest value quoted back from a scene file, in characters.
pub const MAX_VALUE_CHARS: usize = 40;

/// Longest message, in characters (a safety net after the values are cut).
const MAX_MESSAGE_CHARS: usize = 600;

/// `value` cut to [`MAX_VALUE_CHARS`] characters, saying how long it was when cut, with control
/// characters (a line break inside a YAML key, say) escaped so that a message stays one line.
pub fn cut(value: &str) -> String {
    let n = value.chars().count();
    let escape = |s: &str| -> String {
        s.chars()
            .map(|c| {
                if c.is_control() {
                    c.escape_default().to_string()
                } else {
                    c.to_string()
                }
            })
            .collect()
    };
    if n <= MAX_VALUE_CHARS {
        return escape(value);
    }
    let head: String = value.chars().take(MAX_VALUE_CHARS).collect();
    format!("{}... ({n} characters)", escape(&head))
}

/// Every value between backticks or double quotes in `msg` cut by [`cut`].
fn cut_values(msg: &str) -> String {
    let mut out = String::with_capacity(msg.len().min(MAX_MESSAGE_CHARS + 64));
    let mut rest = msg;
    while let Some(i) = rest.find(['`', '"']) {
        let quote = rest[i..].chars().next().unwrap_or('"');
        out.push_str(&rest[..=i]);
        let after = &rest[i + 1..];
        match after.find(quote) {
            Some(j) => {
                out.push_str(&cut(&after[..j]));
                out.push(quote);
                rest = &after[j + 1..];
            }
            None => {
                out.push_str(&cut(after));
                rest = "";
            }
        }
    }
    out.push_str(rest);
    if out.chars().count() > MAX_MESSAGE_CHARS {
        out = out.chars().take(MAX_MESSAGE_CHARS).collect::<String>() + "...";
    }
    out
}

/// Every number in `msg` written with more than 17 characters (`1e308` prints as 309 digits)
/// rewritten in exponent form, so that no message grows with the size of a number.
pub fn compact_numbers(msg: &str) -> String {
    rewrite_tokens(
        msg,
        |c, token| c.is_ascii_digit() || (c == '.' && !token.is_empty()),
        |token| match token.parse::<f64>() {
            Ok(x) if token.len() > 17 => format!("{x:e}"),
            _ => token.to_string(),
        },
    )
}

/// `text` with each token (a longest run of characters that `extends` accepts, given the token
/// so far) replaced by `rewrite` of it; every other character kept.
pub fn rewrite_tokens(
    text: &str,
    extends: impl Fn(char, &str) -> bool,
    rewrite: impl Fn(&str) -> String,
) -> String {
    let mut out = String::with_capacity(text.len().min(1024));
    let mut token = String::new();
    for c in text.chars() {
        if extends(c, &token) {
            token.push(c);
        } else {
            if !token.is_empty() {
                out.push_str(&rewrite(&token));
                token.clear();
            }
            out.push(c);
        }
    }
    if !token.is_empty() {
        out.push_str(&rewrite(&token));
    }
    out
}

/// The words between backticks in `text`, in order.
fn ticked(text: &str) -> Vec<&str> {
    text.split('`').skip(1).step_by(2).collect()
}

/// The candidate nearest to `word`, when it is near enough to be a likely misspelling.
pub fn did_you_mean<'c>(word: &str, candidates: &[&'c str]) -> Option<&'c str> {
    let w = word.to_lowercase().replace('-', "_");
    candidates
        .iter()
        .map(|&c| (c, strsim::normalized_damerau_levenshtein(&w, c)))
        .filter(|&(_, score)| score >= 0.5)
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(c, _)| c)
}

/// serde's name for a type, in the tool's words.
fn expected(what: &str) -> String {
    let w = what.trim();
    match w {
        "f64" | "f32" => "a number".into(),
        "u32" | "u64" | "usize" | "u8" | "u16" => "a whole number of at least 0".into(),
        "i32" | "i64" => "a whole number".into(),
        "a string" => "text".into(),
        "a boolean" => "true or false".into(),
        "a sequence" => "a list such as [alpha, spin]".into(),
        _ if w.starts_with("struct ") => "a mapping of keys such as { key: value }".into(),
        _ if w.starts_with("enum ") || w.starts_with("variant identifier") => "a name".into(),
        _ => w.to_string(),
    }
}

/// serde's description of what it found, in the tool's words.
fn found(what: &str) -> String {
    let w = what.trim();
    if let Some(s) = w.strip_prefix("string ") {
        return format!("the text {s}");
    }
    if let Some(s) = w.strip_prefix("integer ") {
        return format!("the number {}", s.trim_matches('`'));
    }
    if let Some(s) = w.strip_prefix("floating point ") {
        return format!("the number {}", s.trim_matches('`'));
    }
    if let Some(s) = w.strip_prefix("boolean ") {
        return s.trim_matches('`').to_string();
    }
    match w {
        "map" => "a mapping (key: value pairs)".into(),
        "sequence" => "a list".into(),
        "unit value" | "null" => "nothing (an empty value)".into(),
        _ => w.to_string(),
    }
}

/// The 1-based line where a top-level key named in a "duplicate field" complaint (`raw`, with
/// no key path before it) appears for the second time in `src`.
pub fn repeated_top_key(raw: &str, src: &str) -> Option<usize> {
    let key = ticked(raw.strip_prefix("duplicate field ")?)
        .first()
        .copied()?;
    src.lines()
        .enumerate()
        .filter(|(_, l)| {
            l.strip_prefix(key)
                .is_some_and(|rest| rest.trim_start().starts_with(':'))
        })
        .nth(1)
        .map(|(i, _)| i + 1)
}

/// One sentence in the tool's terms for a complaint of the YAML reader. `raw` is the reader's
/// message without its trailing position.
pub fn translate(raw: &str) -> String {
    // "disk.k: invalid type: ..." names the key path first; a bare complaint is about the top.
    let (path, msg) = match raw.split_once(": ") {
        Some((p, m)) if !p.contains(' ') && !p.is_empty() => (p.to_string(), m),
        _ => (String::new(), raw),
    };
    let place = |what: &str| {
        if path.is_empty() {
            what.to_string()
        } else {
            format!("{path}: {what}")
        }
    };
    let sentence = if let Some(rest) = msg.strip_prefix("unknown field ") {
        let words = ticked(rest);
        let (bad, valid) = words.split_first().map_or(("", &[][..]), |(b, v)| (*b, v));
        let hint = did_you_mean(bad, valid)
            .map(|c| format!("did you mean `{c}`? "))
            .unwrap_or_default();
        let list = if valid.is_empty() {
            "this place takes no keys".to_string()
        } else {
            format!("the keys here are {}", valid.join(", "))
        };
        place(&format!("unknown key `{bad}`: {hint}{list}"))
    } else if let Some(rest) = msg.strip_prefix("unknown variant ") {
        let words = ticked(rest);
        let (bad, valid) = words.split_first().map_or(("", &[][..]), |(b, v)| (*b, v));
        let hint = did_you_mean(bad, valid)
            .map(|c| format!("did you mean `{c}`? "))
            .unwrap_or_default();
        place(&format!(
            "`{bad}` is not a name this key takes: {hint}use one of {}",
            valid.join(", ")
        ))
    } else if let Some(rest) = msg.strip_prefix("missing field ") {
        let key = ticked(rest).first().copied().unwrap_or(rest);
        let whole = if path.is_empty() {
            "the scene".to_string()
        } else {
            path.clone()
        };
        format!("{whole} needs the key `{key}`: add it")
    } else if let Some(rest) = msg.strip_prefix("duplicate field ") {
        let key = ticked(rest).first().copied().unwrap_or(rest);
        place(&format!("the key `{key}` is given twice: keep one"))
    } else if let Some(rest) = msg
        .strip_prefix("invalid type: ")
        .or_else(|| msg.strip_prefix("invalid value: "))
    {
        match rest.rsplit_once(", expected ") {
            // Decimal whole numbers are read as numbers; only 0x, 0o and 0b forms come here.
            Some((got, want)) if expected(want) == "a number" && got.starts_with("integer ") => {
                place(&format!(
                    "expected a number written in decimal (such as 0.0375 or 3.75e-2), found a \
                     whole number in another base ({}, written 0x, 0o or 0b): write it in decimal",
                    found(got).trim_start_matches("the number ")
                ))
            }
            Some((got, want)) => place(&format!(
                "expected {}, found {}",
                expected(want),
                found(got)
            )),
            None => place(rest),
        }
    } else if msg.contains("tab character") {
        place(&format!("{msg}: indent with spaces, not tabs"))
    } else if msg.contains("recursion limit") {
        place("the scene nests too deeply: a scene needs at most four levels of keys")
    } else {
        place(msg)
    };
    cut_values(&sentence)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unknown_keys_and_names_suggest_the_nearest() {
        let m =
            translate("disk: unknown field `radiu`, expected one of `radius`, `k`, `mass`, `g`");
        assert_eq!(
            m,
            "disk: unknown key `radiu`: did you mean `radius`? the keys here are radius, k, mass, g"
        );
        let m = translate(
            "solver.method: unknown variant `dop85`, expected one of `rk4`, `dopri5`, `dop853`",
        );
        assert!(m.contains("did you mean `dop853`?"), "{m}");
        let m = translate(
            "stop: unknown field `lift-off`, expected one of `time`, `alpha_below`, `lift_off`",
        );
        assert!(m.contains("did you mean `lift_off`?"), "{m}");
        let m = translate("unknown field `zzzzzz`, expected one of `name`, `disk`");
        assert!(!m.contains("did you mean"), "{m}");
    }

    #[test]
    fn no_serde_jargon_is_left() {
        for (raw, want) in [
            (
                "disk.k: invalid type: map, expected f64",
                "disk.k: expected a number, found a mapping (key: value pairs)",
            ),
            (
                "disk.k: invalid type: string \"abc\", expected f64",
                "disk.k: expected a number, found the text \"abc\"",
            ),
            (
                "invalid type: sequence, expected struct SceneSpec",
                "expected a mapping of keys such as { key: value }, found a list",
            ),
            (
                "solver.max_steps: invalid value: integer `-1`, expected u32",
                "solver.max_steps: expected a whole number of at least 0, found the number -1",
            ),
            (
                "missing field `disk`",
                "the scene needs the key `disk`: add it",
            ),
        ] {
            assert_eq!(translate(raw), want);
        }
    }

    #[test]
    fn long_numbers_are_written_with_an_exponent() {
        let m = compact_numbers(&format!("radius = {} m, k = 0.25.", 1e308));
        assert_eq!(m, "radius = 1e308 m, k = 0.25.");
        assert_eq!(compact_numbers(&format!("{}", 1e-300)), "1e-300");
    }

    #[test]
    fn long_values_are_cut() {
        let long = "x".repeat(10_000_000);
        let m = translate(&format!(
            "disk.k: invalid type: string \"{long}\", expected f64"
        ));
        assert!(m.len() < 200, "{} characters", m.len());
        assert!(m.contains("(10000000 characters)"), "{m}");
    }
}
