//! Tera filters for text written as a program writes its output: fixed-width columns of numbers
//! with a set number of decimals, and notes wrapped to the listing's width. Tera has none of
//! these (its `round` drops trailing zeros and it cannot pad), so they are written here; the
//! templates of a part's text (`templates/parts/NAME/*.txt.tera`) use them.

use std::collections::HashMap;
use tera::{Error, Result, Tera, Value};

/// Width of a listing's notes: [`wrap`] breaks lines at it (tables are narrower).
pub const WIDTH: usize = 100;

/// `text` wrapped at [`WIDTH`], words split on white space, continuation lines indented by four
/// spaces; no newline after the last line.
pub fn wrap(text: &str) -> String {
    let mut out = String::new();
    let mut line = String::new();
    for word in text.split_whitespace() {
        if !line.is_empty() && line.len() + 1 + word.len() > WIDTH {
            out.push_str(&line);
            out.push('\n');
            line = "    ".into();
        } else if !line.is_empty() && line != "    " {
            line.push(' ');
        }
        line.push_str(word);
    }
    out.push_str(&line);
    out
}

/// The filter's argument `name` as a whole number, or `default` without one.
fn whole(args: &HashMap<String, Value>, name: &str, default: usize) -> Result<usize> {
    match args.get(name) {
        None => Ok(default),
        Some(v) => v
            .as_u64()
            .map(|n| n as usize)
            .ok_or_else(|| Error::msg(format!("the argument {name} must be a whole number"))),
    }
}

/// The filter's value as a number, `None` for null (a value not computed).
fn number(value: &Value, filter: &str) -> Result<Option<f64>> {
    if value.is_null() {
        return Ok(None);
    }
    value
        .as_f64()
        .map(Some)
        .ok_or_else(|| Error::msg(format!("the {filter} filter needs a number, not {value}")))
}

/// `fixed(p=N)`: a number with `N` decimals; null (not computed) as `-`; `sign=true` writes
/// the sign of a positive number too (`+0.052`).
fn fixed(value: &Value, args: &HashMap<String, Value>) -> Result<Value> {
    let p = whole(args, "p", 0)?;
    let sign = args.get("sign").and_then(Value::as_bool).unwrap_or(false);
    Ok(Value::String(number(value, "fixed")?.map_or(
        "-".into(),
        |x| {
            if sign {
                format!("{x:+.p$}")
            } else {
                format!("{x:.p$}")
            }
        },
    )))
}

/// `sci(p=N)`: a number in Rust's scientific notation with `N` decimals (`1.20e-6`); null as `-`.
fn sci(value: &Value, args: &HashMap<String, Value>) -> Result<Value> {
    let p = whole(args, "p", 0)?;
    Ok(Value::String(
        number(value, "sci")?.map_or("-".into(), |x| format!("{x:.p$e}")),
    ))
}

/// `scale(by=F)`: a number times `F` (a unit's factor, 1000.0 for metres to millimetres).
fn scale(value: &Value, args: &HashMap<String, Value>) -> Result<Value> {
    let by = args
        .get("by")
        .and_then(Value::as_f64)
        .ok_or_else(|| Error::msg("the scale filter needs by=NUMBER"))?;
    Ok(number(value, "scale")?.map_or(Value::Null, |x| (x * by).into()))
}

/// `deg`: an angle in radians, in degrees.
fn deg(value: &Value, _: &HashMap<String, Value>) -> Result<Value> {
    Ok(number(value, "deg")?.map_or(Value::Null, |x| x.to_degrees().into()))
}

/// `pad(w=N)`: text (or a whole number) right-aligned in `N` columns; `pad(w=N, left=true)`
/// left-aligned.
fn pad(value: &Value, args: &HashMap<String, Value>) -> Result<Value> {
    let w = whole(args, "w", 0)?;
    let left = args.get("left").and_then(Value::as_bool).unwrap_or(false);
    let text = match value {
        Value::String(s) => s.clone(),
        Value::Number(n) if n.is_u64() || n.is_i64() => n.to_string(),
        other => {
            return Err(Error::msg(format!(
                "the pad filter needs text, not {other}: format the number first"
            )))
        }
    };
    Ok(Value::String(if left {
        format!("{text:<w$}")
    } else {
        format!("{text:>w$}")
    }))
}

/// `plain`: a number as Rust prints it (`3` for 3.0, `0.001`, `1.2e-6` as `0.0000012`).
fn plain(value: &Value, _: &HashMap<String, Value>) -> Result<Value> {
    Ok(Value::String(
        number(value, "plain")?.map_or("-".into(), |x| x.to_string()),
    ))
}

/// `measured(sigma=S)`: a measured value with its uncertainty `S`, as [`crate::number::measured`]
/// writes it (`2.003 ± 0.012`).
fn measured(value: &Value, args: &HashMap<String, Value>) -> Result<Value> {
    let sigma = args
        .get("sigma")
        .and_then(Value::as_f64)
        .ok_or_else(|| Error::msg("the measured filter needs sigma=NUMBER"))?;
    Ok(Value::String(
        number(value, "measured")?.map_or("-".into(), |x| crate::number::measured(x, sigma)),
    ))
}

/// `yes`: a yes-or-no answer as `yes` or `no`; null (not asked) as `-`.
fn yes(value: &Value, _: &HashMap<String, Value>) -> Result<Value> {
    match value {
        Value::Bool(b) => Ok(Value::String(if *b { "yes" } else { "no" }.into())),
        Value::Null => Ok(Value::String("-".into())),
        other => Err(Error::msg(format!(
            "the yes filter needs true or false, not {other}"
        ))),
    }
}

/// `wrap`: text wrapped as [`wrap`] does, for a listing's notes.
fn wrap_filter(value: &Value, _: &HashMap<String, Value>) -> Result<Value> {
    value
        .as_str()
        .map(|s| Value::String(wrap(s)))
        .ok_or_else(|| Error::msg("the wrap filter needs text"))
}

/// Registers the filters on `tera`.
pub fn register(tera: &mut Tera) {
    tera.register_filter("fixed", fixed);
    tera.register_filter("sci", sci);
    tera.register_filter("scale", scale);
    tera.register_filter("deg", deg);
    tera.register_filter("pad", pad);
    tera.register_filter("plain", plain);
    tera.register_filter("yes", yes);
    tera.register_filter("measured", measured);
    tera.register_filter("wrap", wrap_filter);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn render(source: &str, context: &tera::Context) -> String {
        let mut t = Tera::default();
        register(&mut t);
        t.add_raw_template("t", source).unwrap();
        t.render("t", context).unwrap()
    }

    #[test]
    fn columns_are_written_as_rust_formats_them() {
        let mut c = tera::Context::new();
        c.insert("x", &0.001234_f64);
        c.insert("none", &Option::<f64>::None);
        c.insert("n", &7_usize);
        assert_eq!(
            render("[{{ x | scale(by=1000.0) | fixed(p=3) | pad(w=7) }}]", &c),
            format!("[{:>7.3}]", 0.001234 * 1000.0)
        );
        assert_eq!(
            render("{{ x | sci(p=2) }}", &c),
            format!("{:.2e}", 0.001234)
        );
        assert_eq!(render("[{{ none | fixed(p=2) | pad(w=3) }}]", &c), "[  -]");
        assert_eq!(render("[{{ n | pad(w=3, left=true) }}]", &c), "[7  ]");
        assert_eq!(render("{{ 1.0 | deg | fixed(p=4) }}", &c), "57.2958");
        assert_eq!(
            render("{{ 3.0 | plain }} {{ 0.001 | plain }}", &c),
            "3 0.001"
        );
        assert_eq!(
            render("{{ true | yes }} {{ false | yes }} {{ none | yes }}", &c),
            "yes no -"
        );
    }

    #[test]
    fn notes_wrap_at_the_width_with_an_indent() {
        let long = "word ".repeat(30);
        let wrapped = wrap(&long);
        let lines: Vec<&str> = wrapped.lines().collect();
        assert_eq!(lines.len(), 2);
        assert!(lines[0].len() <= WIDTH && lines[1].starts_with("    word"));
        assert!(!wrapped.ends_with('\n'));
    }

    #[test]
    fn a_filter_given_the_wrong_kind_of_value_is_an_error_not_a_guess() {
        let mut t = Tera::default();
        register(&mut t);
        t.add_raw_template("t", "{{ 'a' | fixed(p=2) }}").unwrap();
        assert!(t.render("t", &tera::Context::new()).is_err());
        t.add_raw_template("u", "{{ 1.5 | pad(w=2) }}").unwrap();
        assert!(t.render("u", &tera::Context::new()).is_err());
    }
}
