//! Escaping for the LaTeX report: a tera filter for prose (which must not be read as TeX), and a
//! guard for the transcribed mathematics (which is TeX already).

use std::collections::HashMap;
use tera::{Result, Value};

/// Escapes prose for LaTeX: the ten special characters, and unicode symbols used in our own
/// sentences spelled as TeX.
pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 16);
    let mut chars = s.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            // A command's `--option` must not become TeX's en or em dash.
            '-' if chars.peek() == Some(&'-') => out.push_str("-{}"),
            '\\' => out.push_str(r"\textbackslash{}"),
            '&' | '%' | '$' | '#' | '_' | '{' | '}' => {
                out.push('\\');
                out.push(c);
            }
            '~' => out.push_str(r"\textasciitilde{}"),
            '^' => out.push_str(r"\textasciicircum{}"),
            '<' => out.push_str(r"\textless{}"),
            '>' => out.push_str(r"\textgreater{}"),
            // Prose names formulas such as d^2(1/Omega^2)/dt^2: let a line break after a slash
            // rather than run into the margin.
            '/' => out.push_str(r"/\allowbreak{}"),
            _ => match unicode_symbol(c) {
                Some(tex) => out.push_str(tex),
                None => out.push(c),
            },
        }
    }
    out
}

/// TeX for the unicode symbols our prose and captions use, which pdflatex's utf8 input does
/// not know.
fn unicode_symbol(c: char) -> Option<&'static str> {
    Some(match c {
        'α' => r"$\alpha$",
        'β' => r"$\beta$",
        'γ' => r"$\gamma$",
        'δ' => r"$\delta$",
        'ε' => r"$\epsilon$",
        'η' => r"$\eta$",
        'μ' => r"$\mu$",
        'π' => r"$\pi$",
        'ρ' => r"$\rho$",
        'σ' => r"$\sigma$",
        'τ' => r"$\tau$",
        'ϖ' => r"$\varpi$",
        'ψ' => r"$\psi$",
        'φ' => r"$\phi$",
        'ω' => r"$\omega$",
        'Ω' => r"$\Omega$",
        'Δ' => r"$\Delta$",
        '≈' => r"$\approx$",
        '≤' => r"$\leq$",
        '≥' => r"$\geq$",
        '±' => r"$\pm$",
        '×' => r"$\times$",
        '·' => r"$\cdot$",
        '−' => "-",
        '°' => r"$^\circ$",
        '√' => r"$\surd$",
        '∝' => r"$\propto$",
        '→' => r"$\to$",
        '²' => r"$^2$",
        '³' => r"$^3$",
        '₀' => r"$_0$",
        '₁' => r"$_1$",
        'ᵢ' => r"$_i$",
        '₊' => r"$_+$",
        '…' => r"\ldots{}",
        _ => return None,
    })
}

/// The tera filter `tex`: `{{ text | tex }}`.
pub fn filter(value: &Value, _: &HashMap<String, Value>) -> Result<Value> {
    match value {
        Value::String(s) => Ok(Value::String(escape(s))),
        other => Ok(Value::String(escape(&other.to_string()))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spells_greek_and_symbols_as_tex() {
        assert_eq!(escape("α ≈ 60°"), r"$\alpha$ $\approx$ 60$^\circ$");
    }

    #[test]
    fn a_slash_may_end_a_line() {
        assert_eq!(escape("1/2"), r"1/\allowbreak{}2");
    }

    #[test]
    fn double_hyphens_stay_two_hyphens() {
        assert_eq!(
            escape("cargo test --release -- --ignored"),
            "cargo test -{}-release -{}- -{}-ignored"
        );
        assert_eq!(escape("a - b, x-y, ---"), "a - b, x-y, -{}-{}-");
    }

    #[test]
    fn escapes_every_special_character() {
        assert_eq!(
            escape("a_b 5% & $x$ #1 {y} ~ ^ \\"),
            r"a\_b 5\% \& \$x\$ \#1 \{y\} \textasciitilde{} \textasciicircum{} \textbackslash{}"
        );
    }
}
