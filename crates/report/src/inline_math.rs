//! Prose with formulas: a sentence the report writes itself (a figure's caption) puts each
//! formula in LaTeX between dollar signs, `the tilt $\alpha_0 = 0.4$ rad`, and each format sets
//! it as mathematics from that one source: MathML in the HTML ([`html`]), TeX in the LaTeX
//! report ([`tex`]), plain Unicode text on a terminal ([`plain`]). A dollar sign without its
//! closing one is text.

use crate::mathml::inline_math;
use std::collections::HashMap;
use tera::{Tera, Value};

/// A run of prose: text, or a formula's LaTeX.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Piece<'a> {
    /// Text.
    Text(&'a str),
    /// A formula, without its dollar signs.
    Math(&'a str),
}

/// The runs of `prose`, in order.
pub fn pieces(prose: &str) -> Vec<Piece<'_>> {
    let mut out = Vec::new();
    let mut rest = prose;
    while let Some(open) = rest.find('$') {
        let Some(len) = rest[open + 1..].find('$') else {
            break;
        };
        if open > 0 {
            out.push(Piece::Text(&rest[..open]));
        }
        out.push(Piece::Math(&rest[open + 1..open + 1 + len]));
        rest = &rest[open + len + 2..];
    }
    if !rest.is_empty() {
        out.push(Piece::Text(rest));
    }
    out
}

/// `prose` in HTML: its text escaped as Tera escapes text, its formulas as inline MathML.
pub fn html(prose: &str) -> String {
    pieces(prose)
        .into_iter()
        .map(|p| match p {
            Piece::Text(t) => tera::escape_html(t),
            Piece::Math(m) => inline_math(m),
        })
        .collect()
}

/// `prose` in LaTeX: its text escaped as prose ([`crate::tex::escape`]), its formulas as they
/// are.
pub fn tex(prose: &str) -> String {
    pieces(prose)
        .into_iter()
        .map(|p| match p {
            Piece::Text(t) => crate::tex::escape(t),
            Piece::Math(m) => format!("${m}$"),
        })
        .collect()
}

/// `prose` as plain text: its text as it is, its formulas in Unicode
/// ([`crate::plain_math::plain_math`]).
pub fn plain(prose: &str) -> String {
    pieces(prose)
        .into_iter()
        .map(|p| match p {
            Piece::Text(t) => t.to_string(),
            Piece::Math(m) => crate::plain_math::plain_math(m),
        })
        .collect()
}

/// A Tera filter applying `render` to a string.
fn filter(
    render: fn(&str) -> String,
) -> impl Fn(&Value, &HashMap<String, Value>) -> tera::Result<Value> {
    move |value, _| match value {
        Value::String(s) => Ok(Value::String(render(s))),
        other => Ok(Value::String(render(&other.to_string()))),
    }
}

/// Registers the filters `prose_html` and `prose_tex`: `{{ caption | prose_html | safe }}`.
pub fn register(tera: &mut Tera) {
    tera.register_filter("prose_html", filter(html));
    tera.register_filter("prose_tex", filter(tex));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formulas_are_found_between_dollars() {
        assert_eq!(
            pieces(r"tilt $\alpha_0$ of $0.4$ rad"),
            vec![
                Piece::Text("tilt "),
                Piece::Math(r"\alpha_0"),
                Piece::Text(" of "),
                Piece::Math("0.4"),
                Piece::Text(" rad"),
            ]
        );
        assert_eq!(pieces("a $ alone"), vec![Piece::Text("a $ alone")]);
        assert_eq!(pieces(""), Vec::<Piece>::new());
    }

    #[test]
    fn each_format_sets_the_formula_as_mathematics() {
        let prose = r"the tilt $\alpha_0 < 1$ & more";
        let h = html(prose);
        assert!(h.starts_with("the tilt <math"), "{h}");
        assert!(
            h.contains("<mi>α</mi>") && h.ends_with("</math> &amp; more"),
            "{h}"
        );
        assert_eq!(tex(prose), r"the tilt $\alpha_0 < 1$ \& more");
        assert_eq!(plain(prose), "the tilt α₀ < 1 & more");
    }
}
