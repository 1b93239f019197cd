//! LaTeX to MathML for the HTML report: the browser renders MathML Core natively, so the report
//! needs no script and no font from anywhere.
//!
//! The parsing is pulldown-latex's; its output is then read back as XML (roxmltree) and written
//! out again with three repairs, because some of what it emits is not MathML a browser (or a
//! referee) reads as the paper prints it:
//!
//! 1. **Function powers.** `\cos^2\alpha` (eqs 26, 49, 50, 54, 55, 63, 69, 70) comes out as an
//!    `msup` with three children, the thin space, `cos` and `2`: an `msup` takes exactly two, and
//!    Chromium draws it as a small "cos2". The leading spaces are moved out in front, leaving
//!    `<msup><mi>cos</mi><mn>2</mn></msup>`, which is $\cos^2$.
//! 2. **Signs.** A sign after a relation (`= - \Omega`) comes out as an identifier; it becomes a
//!    prefix operator, which Chromium sets tight against its operand as TeX does.
//! 3. **Solidus.** `\beta/2` in an exponent is spaced like a binary operator; TeX sets `/` as an
//!    ordinary symbol, so its spaces are set to zero.
//! 4. **Mu.** `\mu` comes out as U+00B5, the micro sign of units; in mathematics it is the Greek
//!    letter U+03BC ([`greek_mu`]).
//!
//! Accents (`\dot\alpha`, `\hat{\mathbf{1}}`, `\vec\omega`), primes (`\alpha'`), `\left( \right)`
//! and subscripts on bold vectors (`\mathbf{r}_{\mathrm{cm}}`) come out well formed already, and
//! Chromium sets them as printed (marking the accents `accent="true"` was tried: Chromium then
//! draws the dot of $\dot\alpha$ into the letter); the tests below hold them to that.
//!
//! Writing a whole LaTeX-to-MathML emitter for the 85 equations would duplicate pulldown-latex;
//! the repairs are local rewrites of a tree, each checked by a test.

use crate::error::ReportError;
use pulldown_latex::config::DisplayMode;
use pulldown_latex::{push_mathml, Parser, RenderConfig, Storage};

/// The MathML namespace.
pub const MATHML_NS: &str = "http://www.w3.org/1998/Math/MathML";

/// How many children each MathML Core element with a fixed arity takes.
pub fn arity(tag: &str) -> Option<usize> {
    Some(match tag {
        "msup" | "msub" | "mfrac" | "mover" | "munder" | "mroot" => 2,
        "msubsup" | "munderover" => 3,
        _ => return None,
    })
}

/// The MathML of a displayed equation, with the LaTeX kept as an annotation. An equation the
/// converter cannot parse comes back as its LaTeX source in a `<code>` element, never an error.
pub fn display_math(latex: &str) -> String {
    math(latex, DisplayMode::Block)
}

/// The MathML of a formula within a sentence, as [`display_math`] writes a displayed one.
pub fn inline_math(latex: &str) -> String {
    math(latex, DisplayMode::Inline)
}

/// The MathML of `latex` set in `display_mode`, or its source in a `<code>` element.
fn math(latex: &str, display_mode: DisplayMode) -> String {
    let storage = Storage::new();
    let parser = Parser::new(latex, &storage);
    // The annotation is added here, escaped: pulldown-latex copies it verbatim, so a `<` in
    // the source would make the XML malformed.
    let config = RenderConfig {
        display_mode,
        annotation: None,
        xml: true,
        ..RenderConfig::default()
    };
    let mut raw = String::new();
    if push_mathml(&mut raw, parser, config).is_err() {
        return format!("<code>{}</code>", escape_html(latex));
    }
    match repair(&raw, latex) {
        Some(fixed) => fixed,
        None => format!("<code>{}</code>", escape_html(latex)),
    }
}

/// Reads pulldown-latex's MathML and writes it again with the repairs of the module's doc and
/// the LaTeX source as an annotation; `None` when it is not well-formed XML.
fn repair(raw: &str, latex: &str) -> Option<String> {
    // pulldown-latex writes a less-than sign unescaped (`<mo><</mo>`), which is not XML.
    let raw = raw.replace("><</", ">&lt;</");
    let doc = roxmltree::Document::parse(&raw).ok()?;
    let root = doc.root_element();
    let mut out = String::with_capacity(raw.len() + latex.len() + 128);
    open(root, &mut out, true, &[]);
    out.push_str("<semantics><mrow>");
    for c in root.children().filter(|c| c.is_element()) {
        write_node(c, &mut out, false);
    }
    out.push_str("</mrow><annotation encoding=\"application/x-tex\">");
    out.push_str(&escape_html(latex));
    out.push_str("</annotation></semantics>");
    close(root.tag_name().name(), &mut out);
    Some(out)
}

/// The characters pulldown-latex puts above a base as accents.
pub fn is_accent_mark(s: &str) -> bool {
    matches!(
        s,
        "˙" | "¨" | "^" | "ˆ" | "→" | "⃗" | "~" | "˜" | "¯" | "‾" | "ˇ" | "˘" | "´" | "`"
    )
}

fn element_children<'a>(n: roxmltree::Node<'a, 'a>) -> Vec<roxmltree::Node<'a, 'a>> {
    n.children().filter(|c| c.is_element()).collect()
}

fn write_node(n: roxmltree::Node, out: &mut String, root: bool) {
    let tag = n.tag_name().name();
    let kids = element_children(n);
    // Repair 1: spaces pushed into a script's base position.
    if let Some(want) = arity(tag) {
        let extra = kids.len().saturating_sub(want);
        if extra > 0
            && kids[..extra]
                .iter()
                .all(|k| k.tag_name().name() == "mspace")
        {
            for k in &kids[..extra] {
                write_node(*k, out, false);
            }
            open(n, out, root, &[]);
            for k in &kids[extra..] {
                write_node(*k, out, false);
            }
            close(tag, out);
            return;
        }
    }
    // Repair 2: a minus sign set as an identifier.
    if tag == "mi" && n.text() == Some("−") {
        out.push_str("<mo form=\"prefix\">−</mo>");
        return;
    }
    // Repair 3: the solidus as an ordinary symbol.
    if tag == "mo" && n.text() == Some("/") && n.attribute("lspace").is_none() {
        out.push_str("<mo lspace=\"0\" rspace=\"0\">/</mo>");
        return;
    }
    open(n, out, root, &[]);
    for c in n.children() {
        if c.is_element() {
            write_node(c, out, false);
        } else if c.is_text() {
            out.push_str(&escape_html(&greek_mu(c.text().unwrap_or(""))));
        }
    }
    close(tag, out);
}

/// `s` with the micro sign (U+00B5), which pulldown-latex writes for `\mu`, as the Greek
/// letter mu (U+03BC) that TeX sets for it.
pub fn greek_mu(s: &str) -> std::borrow::Cow<'_, str> {
    if s.contains('\u{b5}') {
        s.replace('\u{b5}', "\u{3bc}").into()
    } else {
        s.into()
    }
}

fn open(n: roxmltree::Node, out: &mut String, root: bool, extra: &[(&str, &str)]) {
    out.push('<');
    out.push_str(n.tag_name().name());
    for a in n.attributes() {
        if extra.iter().any(|(k, _)| *k == a.name()) {
            continue;
        }
        out.push_str(&format!(" {}=\"{}\"", a.name(), escape_html(a.value())));
    }
    for (k, v) in extra {
        out.push_str(&format!(" {k}=\"{v}\""));
    }
    if root {
        out.push_str(&format!(" xmlns=\"{MATHML_NS}\""));
    }
    out.push('>');
}

fn close(tag: &str, out: &mut String) {
    out.push_str("</");
    out.push_str(tag);
    out.push('>');
}

/// Escapes text for HTML.
pub fn escape_html(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// Every element of a MathML fragment whose number of children is not its arity, as
/// `(tag, children)`; `Err` when the fragment is not well-formed XML.
pub fn arity_defects(mathml: &str) -> Result<Vec<(String, usize)>, ReportError> {
    let doc = roxmltree::Document::parse(mathml).map_err(|e| ReportError::Input(e.to_string()))?;
    let mut bad = Vec::new();
    for n in doc.descendants().filter(|n| n.is_element()) {
        let tag = n.tag_name().name();
        let count = n.children().filter(|c| c.is_element()).count();
        let ok = match tag {
            // msqrt takes any number of children (an inferred mrow), but at least one.
            "msqrt" => count >= 1,
            _ => arity(tag).is_none_or(|a| a == count),
        };
        if !ok {
            bad.push((tag.to_string(), count));
        }
    }
    Ok(bad)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn clean(latex: &str) -> String {
        let m = display_math(latex);
        assert!(m.starts_with("<math"), "{latex}: {m}");
        assert_eq!(arity_defects(&m).ok(), Some(vec![]), "{latex}: {m}");
        m
    }

    #[test]
    fn renders_mathml_with_its_source() {
        let m = clean(r"\Omega_0^2 = \frac{g}{a k \sin\alpha_0}");
        assert!(m.contains("<mfrac>") && m.contains("annotation"), "{m}");
    }

    #[test]
    fn mu_is_the_greek_letter_not_the_micro_sign() {
        // Guards the repair's reason: pulldown-latex writes the micro sign for `\mu`.
        let mut raw = String::new();
        let storage = Storage::new();
        let parser = Parser::new(r"\mu", &storage);
        push_mathml(&mut raw, parser, RenderConfig::default()).unwrap();
        assert!(raw.contains('\u{b5}'), "{raw}");
        let m = clean(r"\mu_k < \mu");
        assert!(
            !m.contains('\u{b5}') && m.matches('\u{3bc}').count() == 2,
            "{m}"
        );
    }

    #[test]
    fn a_power_of_a_function_is_a_power_of_its_name() {
        let m = clean(r"k \Omega^2 \sin^2\alpha + \cos^2\alpha_0");
        assert!(m.contains("<msup><mi>sin</mi><mn>2</mn></msup>"), "{m}");
        assert!(m.contains("<msup><mi>cos</mi><mn>2</mn></msup>"), "{m}");
    }

    #[test]
    fn the_raw_converter_output_has_the_defect_the_repair_removes() {
        // Guards the repair's reason: if pulldown-latex stops emitting the 3-child msup, this
        // fails and the repair can go.
        let storage = Storage::new();
        let mut raw = String::new();
        let config = RenderConfig {
            xml: true,
            ..RenderConfig::default()
        };
        push_mathml(&mut raw, Parser::new(r"k \cos^2\alpha", &storage), config).unwrap();
        assert_eq!(
            arity_defects(&raw).ok(),
            Some(vec![("msup".to_string(), 3)])
        );
    }

    #[test]
    fn accents_are_an_mover_with_their_mark() {
        for (src, mark) in [
            (r"\dot{\alpha}", "˙"),
            (r"\hat{\mathbf{1}}", "^"),
            (r"\vec{\omega}_{123}", "→"),
        ] {
            let m = clean(src);
            assert!(m.contains("<mover>") && m.contains(mark), "{src}: {m}");
            assert!(is_accent_mark(mark));
        }
    }

    #[test]
    fn primes_delimiters_and_subscripted_bold_vectors_are_well_formed() {
        let m = clean(r"\alpha' + f''(x) = \left( \frac{g}{a k} \right)^{\beta/2}");
        assert!(m.contains('′'), "{m}");
        assert!(m.contains("<mo lspace=\"0\" rspace=\"0\">/</mo>"), "{m}");
        let m = clean(r"\mathbf{r}_{\mathrm{cm}} = \mathbf{L}_{\mathrm{cm}}^2");
        assert!(m.contains("<msub>") || m.contains("<msubsup>"), "{m}");
        let m = clean(r"= - \Omega");
        assert!(
            m.contains("<mo form=\"prefix\">−</mo>") && !m.contains("<mi>−</mi>"),
            "{m}"
        );
    }

    #[test]
    fn the_annotation_keeps_the_source_escaped() {
        let m = clean(r"a < b");
        assert!(m.contains("<mo>&lt;</mo>"), "{m}");
        assert!(m.contains("a &lt; b</annotation>"), "{m}");
    }
}
