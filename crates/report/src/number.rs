//! How the report writes a number, in one place (the HTML and the LaTeX; `report.json` keeps
//! every number whole):
//!
//! - a value with a stated uncertainty σ ([`measured`]): σ to two significant digits and the
//!   value to the same decimal place, `1.953 ± 0.048` (not `1.95312 ± 0.0481`);
//! - a value compared within a relative tolerance r ([`within`]): to the ⌈−log₁₀ r⌉ + 1
//!   significant digits the tolerance supports (the last one the first the tolerance can move),
//!   at least two and at most the default six;
//! - a value with neither ([`significant`]): the default, six significant digits, trailing
//!   zeros dropped;
//! - an error or a tolerance ([`error`]): three significant digits;
//! - a table's column of inputs ([`places`]): a fixed number of decimals, so that it aligns;
//!
//! scientific notation as `1e-12` (never `0.000000000001`), and the numbers inside sentences
//! that the checks and studies compose brought to the same form ([`prose`]).

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

/// Significant digits of a stated uncertainty.
const UNCERTAINTY_DIGITS: usize = 2;

/// The fewest significant digits a value compared within a tolerance is shown with.
const FEWEST_DIGITS: usize = 2;

/// The exponent of `x` in scientific notation once rounded to `digits` significant digits
/// (`9.96` to two digits is `1.0e1`: exponent 1).
fn exponent(x: f64, digits: usize) -> i32 {
    let places = digits.saturating_sub(1);
    format!("{x:.places$e}")
        .split_once('e')
        .and_then(|(_, e)| e.parse().ok())
        .unwrap_or(0)
}

/// `x` rounded to the decimal place `10^place`, written plainly (`place` -3 gives three
/// decimals; a positive place rounds to tens, hundreds, ..).
fn plain_at(x: f64, place: i32) -> String {
    let s = if place < 0 {
        let decimals = (-place) as usize;
        format!("{x:.decimals$}")
    } else {
        let unit = 10f64.powi(place);
        format!("{:.0}", (x / unit).round() * unit)
    };
    // A small negative value rounded to zero is zero, not "-0.0".
    match s.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_string(),
        _ => s,
    }
}

/// `x` rounded to the decimal place `10^place`: plainly when it lies between 1e-3 and 1e5 and
/// the place is between units and six decimals, else as a mantissa and a power of ten
/// (`4.80e-7`, `1.23e3`: a plain `1230` would not say whether its zero is a digit). Trailing
/// zeros are kept: they are digits the uncertainty or tolerance supports.
pub fn at_place(x: f64, place: i32) -> String {
    if !x.is_finite() {
        return format!("{x}");
    }
    let plain = |magnitude: i32| (-3..5).contains(&magnitude) && (-6..=0).contains(&place);
    let magnitude = exponent(x, 17);
    let digits = magnitude - place + 1;
    if x == 0.0 || digits < 1 {
        // Below the place's unit: it rounds to zero or to one unit of the place.
        return if (-6..=0).contains(&place) {
            plain_at(x, place)
        } else {
            format!(
                "{}e{place}",
                (x / 10f64.powi(place)).round().abs() * x.signum()
            )
        };
    }
    let s = format!("{x:.*e}", (digits - 1) as usize);
    let (mantissa, rounded) = s.split_once('e').unwrap_or((&s, "0"));
    let rounded: i32 = rounded.parse().unwrap_or(magnitude);
    if plain(rounded) {
        return plain_at(x, place);
    }
    // A carry into a new leading digit (9.96e-8 to two digits is 1.0e-7) keeps the place: one
    // more digit.
    let mut mantissa = mantissa.to_string();
    if rounded > magnitude {
        mantissa.push_str(if mantissa.contains('.') { "0" } else { ".0" });
    }
    format!("{mantissa}e{rounded}")
}

/// A value with its stated standard uncertainty `sigma`: σ to two significant digits and the
/// value to the same decimal place, `1.953 ± 0.048`; outside 1e-3..1e5, or when σ is 10 or
/// more, with one power of ten, `(4.80 ± 0.13)e-7`, `(1.235 ± 0.048)e4`. Without a usable σ (zero, negative, not finite) the value alone, as
/// [`significant`] writes it.
pub fn measured(value: f64, sigma: f64) -> String {
    if !(sigma.is_finite() && sigma > 0.0 && value.is_finite()) {
        return significant(value);
    }
    let place = exponent(sigma, UNCERTAINTY_DIGITS) - (UNCERTAINTY_DIGITS as i32 - 1);
    let scale = exponent(value.abs().max(sigma), 17);
    if (-3..5).contains(&scale) && (-6..=0).contains(&place) {
        return format!("{} ± {}", plain_at(value, place), plain_at(sigma, place));
    }
    let unit = 10f64.powi(scale);
    let mantissa = scale - place;
    format!(
        "({} ± {})e{scale}",
        plain_at(value / unit, -mantissa),
        plain_at(sigma / unit, -mantissa)
    )
}

/// `value` to the decimal place of an uncertainty or an absolute tolerance `sigma` it is
/// compared with, without the ±: the place of σ's second significant digit (a fitted order
/// within 0.25 of the claimed one, a column of values beside one with their uncertainties).
/// Without a usable σ, as [`significant`] writes it.
pub fn to_place_of(value: f64, sigma: f64) -> String {
    if !(sigma.is_finite() && sigma > 0.0) {
        return significant(value);
    }
    at_place(
        value,
        exponent(sigma, UNCERTAINTY_DIGITS) - (UNCERTAINTY_DIGITS as i32 - 1),
    )
}

/// The significant digits a relative tolerance `r` supports: ⌈−log₁₀ r⌉ + 1, at least two and
/// at most the default six (a tolerance of 5 % supports three: 52.2, not 52.2388).
pub fn digits_within(r: f64) -> usize {
    if !(r.is_finite() && r > 0.0) {
        return VALUE_DIGITS;
    }
    // The small slack keeps exact powers of ten (log10(0.01) may be -1.9999999999999996) on
    // their digit.
    let supported = (-r.log10() - 1e-9).ceil() + 1.0;
    (supported.max(FEWEST_DIGITS as f64) as usize).min(VALUE_DIGITS)
}

/// A value compared within the relative tolerance `r`, to the digits `r` supports
/// ([`digits_within`]), trailing zeros kept. Where `r` supports the default six digits or
/// more, and for an integer (a printed number such as the paper's 60°, or an exact order),
/// as [`significant`] writes it.
pub fn within(value: f64, r: f64) -> String {
    let digits = digits_within(r);
    let integer = value.fract() == 0.0 && value.abs() < 1e6;
    if digits >= VALUE_DIGITS || integer || !value.is_finite() {
        return significant(value);
    }
    at_place(value, exponent(value, digits) - (digits as i32 - 1))
}

/// A column's value with a fixed number of decimals (`places`), so that a table's inputs align.
pub fn places(x: f64, places: usize) -> String {
    format!("{x:.places$}")
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
/// rounded to six.
pub fn prose(text: &str) -> String {
    decimals(text)
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
    fn sentences_lose_their_long_decimals() {
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

    #[test]
    fn a_value_is_written_to_the_digits_its_uncertainty_or_tolerance_supports() {
        let cases: Vec<(&str, String, &str)> = vec![
            (
                "σ to two digits, the value to its place",
                measured(1.95312, 0.0481),
                "1.953 ± 0.048",
            ),
            (
                "zeros the uncertainty supports are kept",
                measured(2.0, 0.12),
                "2.00 ± 0.12",
            ),
            (
                "σ rounding up to a new digit",
                measured(3.0, 0.0996),
                "3.00 ± 0.10",
            ),
            ("a negative value", measured(-30.61048, 1.5), "-30.6 ± 1.5"),
            (
                "a negative value that rounds to zero",
                measured(-0.004, 9.6),
                "0.0 ± 9.6",
            ),
            (
                "σ of tens: one power of ten",
                measured(12345.6, 480.0),
                "(1.235 ± 0.048)e4",
            ),
            (
                "a small value: one power of ten",
                measured(4.8012e-7, 1.27e-8),
                "(4.80 ± 0.13)e-7",
            ),
            (
                "no uncertainty: the default",
                measured(0.0123456789, 0.0),
                "0.0123457",
            ),
            (
                "an unusable uncertainty: the default",
                measured(1.5, f64::NAN),
                "1.5",
            ),
            (
                "5 % supports three digits",
                within(52.23875609352411, 0.05),
                "52.2",
            ),
            ("an integer is exact", within(60.0, 0.05), "60"),
            (
                "1.3e-4 supports five digits",
                within(17.047998919996346, 1.28e-4),
                "17.048",
            ),
            (
                "a small value within 3.6 %",
                within(0.006158361541386154, 0.0362),
                "0.00616",
            ),
            (
                "a tight tolerance: the default six",
                within(1.9881334659624084, 1e-12),
                "1.98813",
            ),
            ("scientific within 5 %", within(1.85175e-7, 0.05), "1.85e-7"),
            ("a carry keeps the digits", within(0.99996, 0.05), "1.00"),
            (
                "tens within 5 %: one power of ten",
                within(1234.5, 0.05),
                "1.23e3",
            ),
            (
                "a carry in scientific notation",
                at_place(9.96e-8, -9),
                "1.00e-7",
            ),
            (
                "a value to the place of σ",
                to_place_of(1.95312, 0.0481),
                "1.953",
            ),
            ("an error: three digits", error(0.0481234), "0.0481"),
            ("a column of inputs", places(0.15, 2), "0.15"),
            (
                "below the place, rounding up",
                to_place_of(0.0075961, 0.25),
                "0.01",
            ),
            (
                "below the place, rounding down",
                to_place_of(-0.0024, 0.25),
                "0.00",
            ),
        ];
        for (what, got, want) in cases {
            assert_eq!(got, want, "{what}");
        }
        let digits: Vec<usize> = [0.01, 0.1, 0.5, 1e-3, 1e-12, 2.0, 0.05]
            .map(digits_within)
            .to_vec();
        assert_eq!(digits, [3, 2, 2, 4, 6, 2, 3]);
    }

    /// The significant digits of a written number: its mantissa's digits without the sign, the
    /// point and the leading zeros.
    fn figures(s: &str) -> String {
        let mantissa = s.split('e').next().unwrap_or(s);
        mantissa
            .chars()
            .filter(char::is_ascii_digit)
            .collect::<String>()
            .trim_start_matches('0')
            .to_string()
    }

    /// The value's and the uncertainty's digits of a `value ± sigma` as written.
    fn parts(s: &str) -> (String, String) {
        let s = s.trim_start_matches('(');
        let (v, rest) = s.split_once(" ± ").expect("a value and its uncertainty");
        let sigma = rest.split(')').next().unwrap_or(rest);
        (figures(v), figures(sigma))
    }

    /// Whether `write` keeps the digits of every case when value and σ are scaled by a power of
    /// ten (a change of unit: m to mm, s to ms, to μs).
    fn keeps_digits_across_units(write: &dyn Fn(f64, f64) -> String, cases: &[(f64, f64)]) -> bool {
        cases.iter().all(|&(v, sigma)| {
            let here = parts(&write(v, sigma));
            (-6..=6).all(|k| {
                let s = 10f64.powi(k);
                parts(&write(v * s, sigma * s)) == here
            })
        })
    }

    const MEASURED: [(f64, f64); 6] = [
        (1.95312, 0.0481),
        (-30.61048, 1.53),
        (0.0637, 0.0021),
        (2.0, 0.12),
        (4.8012e-7, 1.27e-8),
        (587.3, 41.7),
    ];

    #[test]
    fn the_same_value_in_other_units_keeps_its_digits() {
        assert!(keeps_digits_across_units(&measured, &MEASURED));
        // The test can fail: fixed decimals write 1.9531 ± 0.0481 in m but 1953.1200 ±
        // 48.1000 in mm.
        let fixed = |v: f64, s: f64| format!("{v:.4} ± {s:.4}");
        assert!(!keeps_digits_across_units(&fixed, &MEASURED));
        // Any other scale (degrees to radians, feet to metres): σ keeps two digits, and the
        // value's count moves by at most the one digit a decimal carry adds.
        for (v, sigma) in MEASURED {
            let (v0, s0) = parts(&measured(v, sigma));
            for scale in [std::f64::consts::PI / 180.0, 0.3048, 7.0, 1.0 / 3.0] {
                let (v1, s1) = parts(&measured(v * scale, sigma * scale));
                assert_eq!(s1.len(), 2, "{v} ± {sigma} times {scale}");
                assert!(
                    s0.len() == 2 && v1.len().abs_diff(v0.len()) <= 1,
                    "{v} ± {sigma} times {scale}"
                );
            }
        }
        // Within a tolerance the count depends on the tolerance alone: any scale keeps it.
        for v in [
            52.23875609352411,
            0.006158361541386154,
            17.047998919996346,
            1.85175e-7,
        ] {
            for r in [0.05, 0.0362, 1.28e-4, 0.25] {
                let n = figures(&within(v, r)).len();
                assert_eq!(n, digits_within(r), "{v} within {r}");
                for scale in [1e3, 1e-6, std::f64::consts::PI / 180.0, 0.3048, 7.0] {
                    assert_eq!(
                        figures(&within(v * scale, r)).len(),
                        n,
                        "{v} times {scale} within {r}"
                    );
                }
            }
        }
    }
}
