//! LaTeX to MathML for the HTML report (pulldown-latex): the browser renders MathML Core
//! natively, so the report needs no script and no font from anywhere.

use pulldown_latex::config::DisplayMode;
use pulldown_latex::{push_mathml, Parser, RenderConfig, Storage};

/// The MathML of a displayed equation, with the LaTeX kept as an annotation. An equation the
/// converter cannot parse comes back as its LaTeX source in a `<code>` element, never an error.
pub fn display_math(latex: &str) -> String {
    let storage = Storage::new();
    let parser = Parser::new(latex, &storage);
    let config = RenderConfig {
        display_mode: DisplayMode::Block,
        annotation: Some(latex),
        xml: true,
        ..RenderConfig::default()
    };
    let mut out = String::new();
    match push_mathml(&mut out, parser, config) {
        Ok(()) => out,
        Err(_) => format!("<code>{}</code>", escape_html(latex)),
    }
}

/// Escapes text for HTML.
pub fn escape_html(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn renders_mathml_with_its_source() {
        let m = display_math(r"\Omega_0^2 = \frac{g}{a k \sin\alpha_0}");
        assert!(m.starts_with("<math"), "{m}");
        assert!(m.contains("<mfrac>") && m.contains("annotation"), "{m}");
    }
}
