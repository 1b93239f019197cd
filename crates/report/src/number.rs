//! How the report writes a number, in one place: six significant digits for a value, two for an
//! error or a tolerance, scientific notation as `1e-12` (never `0.000000000001`), and the
//! numbers inside sentences that the checks and studies compose brought to the same form.

use std::collections::HashMap;
use tera::{Result, Value};

/// Significant digits of a value.
const VALUE_DIGITS: usize = 6;

/// A value with six significant digits, trailing zeros dropped: plain between 1e-3 and 1e5,
/// scientific outside (`1.5e-7`).
pub fn significant(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else if !x.is_finite() {
        format!("{x}")
    } else if (1e-3..1e5).contains(&x.abs()) {
        let digits = (VALUE_DIGITS as i32 - 1 - x.abs().log10().floor() as i32).max(0) as usize;
        trim_fraction(&format!("{x:.digits$}"))
    } else {
        scientific(x, VALUE_DIGITS)
    }
}

/// `x` in scientific notation with `digits` significant digits, trailing zeros of the mantissa
/// dropped: `8.12e-16`, `1e-12`.
pub fn scientific(x: f64, digits: usize) -> String {
    if x == 0.0 {
        return "0".into();
    }
    if !x.is_finite() {
        return format!("{x}");
    }
    let places = digits.saturating_sub(1);
    let s = format!("{x:.places$e}");
    match s.split_once('e') {
        Some((mantissa, exponent)) => format!("{}e{exponent}", trim_fraction(mantissa)),
        None => s,
    }
}

/// An error or a tolerance: three significant digits, in scientific notation below 1e-3 and
/// from 1e4 on (`0.0245`, `1.39`, `8.12e-16`).
pub fn error(x: f64) -> String {
    if (1e-3..1e4).contains(&x.abs()) {
        let places = (2 - x.abs().log10().floor() as i32).max(0) as usize;
        trim_fraction(&format!("{x:.places$}"))
    } else {
        scientific(x, 3)
    }
}

/// Drops the trailing zeros of a decimal fraction, and the point when nothing follows it.
fn trim_fraction(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

/// A sentence composed elsewhere (a check's worst case, a study's note) with its numbers
/// written as the report writes them: a decimal with more than six significant digits is
/// rounded to six, and a record written as `Name { field: value, .. }` becomes
/// `symbol = value unit, ..` in the paper's symbols.
pub fn prose(text: &str) -> String {
    records(&decimals(text))
}

/// Rounds every decimal of `text` that carries more than six significant digits.
fn decimals(text: &str) -> String {
    let bytes = text.as_bytes();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    while i < bytes.len() {
        let starts = bytes[i].is_ascii_digit()
            && (i == 0 || !(bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'.'));
        if !starts {
            let c = text[i..].chars().next().unwrap_or(' ');
            out.push(c);
            i += c.len_utf8();
            continue;
        }
        let end = number_end(bytes, i);
        let token = &text[i..end];
        out.push_str(&rounded(token));
        i = end;
    }
    out
}

/// The end of the number starting at `start`: digits, one point, digits, an optional exponent.
fn number_end(bytes: &[u8], start: usize) -> usize {
    let digits = |mut j: usize| {
        while j < bytes.len() && bytes[j].is_ascii_digit() {
            j += 1;
        }
        j
    };
    let mut j = digits(start);
    if j + 1 < bytes.len() && bytes[j] == b'.' && bytes[j + 1].is_ascii_digit() {
        j = digits(j + 1);
        if j + 1 < bytes.len() && bytes[j] == b'e' {
            let k = if bytes[j + 1] == b'-' { j + 2 } else { j + 1 };
            if k < bytes.len() && bytes[k].is_ascii_digit() {
                j = digits(k);
            }
        }
    }
    // A version or a section number ("0.1.0", "10.2.3") is left whole.
    if j + 1 < bytes.len() && bytes[j] == b'.' && bytes[j + 1].is_ascii_digit() {
        return digits(j + 1);
    }
    j
}

/// `token` itself, or rounded to six significant digits when it is a decimal with more.
fn rounded(token: &str) -> String {
    let mantissa = token.split('e').next().unwrap_or(token);
    if !mantissa.contains('.') || token.matches('.').count() > 1 {
        return token.to_string();
    }
    // A power of ten a reader would not write (`3.2074e1`, `2.0000e0`) as the report writes it.
    if mantissa.len() < token.len() {
        return token
            .parse::<f64>()
            .map_or_else(|_| token.to_string(), significant);
    }
    let figures = mantissa
        .chars()
        .filter(char::is_ascii_digit)
        .collect::<String>()
        .trim_start_matches('0')
        .len();
    match token.parse::<f64>() {
        Ok(x) if figures > VALUE_DIGITS => significant(x),
        _ => token.to_string(),
    }
}

/// The paper's symbol and the unit of a field of a state record.
fn symbol(field: &str) -> (&str, &'static str) {
    match field {
        "alpha" => ("alpha", " rad"),
        "alpha_dot" => ("alpha_dot", " rad/s"),
        "precession" => ("Omega", " rad/s"),
        "spin" => ("omega_1", " rad/s"),
        other => (other, ""),
    }
}

/// Rewrites each `Name { field: value, .. }` of `text` as `symbol = value unit, ..`.
fn records(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(open) = rest.find(" { ") {
        let name_start = rest[..open]
            .rfind(|c: char| !c.is_ascii_alphanumeric() && c != '_')
            .map_or(0, |p| p + 1);
        let name = &rest[name_start..open];
        let close = rest[open..].find(" }").map(|p| open + p);
        let fields = close.and_then(|c| record_fields(&rest[open + 3..c]));
        match (name.chars().next(), close, fields) {
            (Some(first), Some(close), Some(fields)) if first.is_ascii_uppercase() => {
                out.push_str(&rest[..name_start]);
                out.push_str(&fields);
                rest = &rest[close + 2..];
            }
            _ => {
                out.push_str(&rest[..open + 3]);
                rest = &rest[open + 3..];
            }
        }
    }
    out.push_str(rest);
    out
}

/// `field: value, ..` as `symbol = value unit, ..`, or None when it is not a record's fields.
fn record_fields(body: &str) -> Option<String> {
    let parts: Option<Vec<String>> = body
        .split(", ")
        .map(|part| {
            let (field, value) = part.split_once(": ")?;
            let simple = !field.is_empty()
                && field.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
                && value.parse::<f64>().is_ok();
            simple.then(|| {
                let (symbol, unit) = symbol(field);
                format!("{symbol} = {value}{unit}")
            })
        })
        .collect();
    parts.map(|p| p.join(", "))
}

/// The tera filter `num`: a number as [`significant`] writes it.
pub fn filter(value: &Value, _: &HashMap<String, Value>) -> Result<Value> {
    match value.as_f64() {
        Some(x) => Ok(Value::String(significant(x))),
        None => Err(tera::Error::msg(format!(
            "the num filter needs a number, not {value}"
        ))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_and_errors_are_written_as_a_physicist_writes_them() {
        assert_eq!(significant(1e-12), "1e-12");
        assert_eq!(significant(1.915291), "1.91529");
        assert_eq!(significant(-30.0), "-30");
        assert_eq!(significant(2.5e7), "2.5e7");
        assert_eq!(error(8.1234e-16), "8.12e-16");
        assert_eq!(error(1e-12), "1e-12");
        assert_eq!(error(0.02449), "0.0245");
        assert_eq!(error(1.39), "1.39");
    }

    #[test]
    fn sentences_lose_their_long_decimals_and_record_dumps() {
        assert_eq!(
            prose("k 0.9, Motion { alpha: 0.05978412879850955, alpha_dot: 17.778814092951272, precession: -30.61048371006373, spin: -46.961570275632866 } (worst of 600 points)"),
            "k 0.9, alpha = 0.0597841 rad, alpha_dot = 17.7788 rad/s, Omega = -30.6105 rad/s, omega_1 = -46.9616 rad/s (worst of 600 points)"
        );
        assert_eq!(
            prose("3 -> 3.0029999999999997 at t = 13.569437099558 s"),
            "3 -> 3.003 at t = 13.5694 s"
        );
        assert_eq!(
            prose("rolling-disk 0.1.0, eq 10.2, x 0.029376030"),
            "rolling-disk 0.1.0, eq 10.2, x 0.029376"
        );
        assert_eq!(
            prose("mu needed 3.2074e1, error 8.1e-16"),
            "mu needed 32.074, error 8.1e-16"
        );
        assert_eq!(
            prose("a solver: { project: energy }"),
            "a solver: { project: energy }"
        );
    }
}
