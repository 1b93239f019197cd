//! The LaTeX tokens the reader knows: commands, symbols, numbers, braces, and the Greek letters.

use super::ParseError;

#[derive(Debug, Clone, PartialEq)]
pub(super) enum Tok {
    Cmd(String),
    LBrace,
    RBrace,
    LParen,
    RParen,
    LBrack,
    RBrack,
    Caret,
    Under,
    Plus,
    Minus,
    Slash,
    Comma,
    Equals,
    Less,
    Greater,
    Pipe,
    /// `;`: between relations, or after the last.
    Semicolon,
    /// `.` not starting a number: after the last relation.
    Period,
    /// A number and its text as printed (`10`, `1.8`).
    Num(f64, String),
    Letter(char),
}

/// Commands that only make space or set the style, and the sizes of a delimiter (`\bigl(` is
/// `(`): the reader skips them.
pub(super) const SPACES: &[&str] = &[
    "quad",
    "qquad",
    ",",
    ";",
    "!",
    " ",
    ":",
    ">",
    "thinspace",
    "medspace",
    "thickspace",
    "enspace",
    "displaystyle",
    "textstyle",
    "nonumber",
    "notag",
    "big",
    "Big",
    "bigg",
    "Bigg",
    "bigl",
    "Bigl",
    "biggl",
    "Biggl",
    "bigr",
    "Bigr",
    "biggr",
    "Biggr",
    "bigm",
    "Bigm",
];

/// Other spellings of a command the reader knows: `\dfrac` and `\tfrac` are `\frac`.
const SYNONYMS: &[(&str, &str)] = &[("dfrac", "frac"), ("tfrac", "frac"), ("cfrac", "frac")];

/// What to write instead of a command or character the reader does not know, where an author
/// may have meant something it does.
pub(super) fn hint(name: &str) -> Option<&'static str> {
    Some(match name {
        "over" | "div" | "\u{f7}" => "write a quotient as \\frac{numerator}{denominator}",
        "ast" | "*" | "\u{d7}" | "\u{b7}" => "write a product as juxtaposition (k m) or with \\cdot",
        "exp" | "ln" | "log" => {
            "the reader knows \\sin, \\cos, \\tan, \\cot, \\sqrt and powers x^{n}, as the paper uses"
        }
        "tanh" | "sinh" | "cosh" | "arctan" | "arcsin" | "arccos" => {
            "the reader knows \\sin, \\cos, \\tan, \\cot and \\sqrt"
        }
        _ => return None,
    })
}

pub(super) fn lex(s: &str) -> Result<Vec<(Tok, usize)>, ParseError> {
    let chars: Vec<char> = s.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let col = i + 1;
        if c.is_whitespace() || c == '~' {
            i += 1;
            continue;
        }
        let tok = match c {
            '\\' => {
                let start = i + 1;
                let mut j = start;
                while j < chars.len() && chars[j].is_ascii_alphabetic() {
                    j += 1;
                }
                if j == start {
                    j = (start + 1).min(chars.len());
                }
                let name: String = chars[start..j].iter().collect();
                i = j;
                if name.is_empty() {
                    return Err(ParseError {
                        column: col,
                        message: "a backslash at the end".into(),
                    });
                }
                if SPACES.contains(&name.as_str()) {
                    continue;
                }
                let name = SYNONYMS
                    .iter()
                    .find(|(s, _)| *s == name)
                    .map_or(name, |(_, to)| to.to_string());
                out.push((Tok::Cmd(name), col));
                continue;
            }
            '{' => Tok::LBrace,
            '}' => Tok::RBrace,
            '(' => Tok::LParen,
            ')' => Tok::RParen,
            '[' => Tok::LBrack,
            ']' => Tok::RBrack,
            '^' => Tok::Caret,
            '_' => Tok::Under,
            '+' => Tok::Plus,
            '-' => Tok::Minus,
            '/' => Tok::Slash,
            ',' => Tok::Comma,
            '=' => Tok::Equals,
            '<' => Tok::Less,
            '>' => Tok::Greater,
            '|' => Tok::Pipe,
            ';' => Tok::Semicolon,
            '.' if !chars.get(i + 1).is_some_and(|d| d.is_ascii_digit()) => Tok::Period,
            d if d.is_ascii_digit() || d == '.' => {
                let mut j = i;
                // A full stop ends a number unless a digit follows (`\alpha_0.` ends a sentence).
                let digit = |k: usize| chars.get(k).is_some_and(|d| d.is_ascii_digit());
                while j < chars.len() && (digit(j) || (chars[j] == '.' && digit(j + 1))) {
                    j += 1;
                }
                let text: String = chars[i..j].iter().collect();
                let x: f64 = text.parse().map_err(|_| ParseError {
                    column: col,
                    message: format!(
                        "'{}' is not a number",
                        text.chars().take(40).collect::<String>()
                    ),
                })?;
                i = j;
                out.push((Tok::Num(x, text), col));
                continue;
            }
            l if l.is_ascii_alphabetic() => Tok::Letter(l),
            other => {
                let mut message =
                    format!("the character '{other}' is not part of the paper's notation");
                if let Some(h) = hint(&other.to_string()) {
                    message = format!("{message}: {h}");
                }
                return Err(ParseError {
                    column: col,
                    message,
                });
            }
        };
        out.push((tok, col));
        i += 1;
    }
    Ok(out)
}

/// Greek letters the paper uses as symbols (`\pi` is the constant).
pub(crate) const GREEK: &[&str] = &[
    "alpha",
    "beta",
    "gamma",
    "delta",
    "epsilon",
    "varepsilon",
    "zeta",
    "eta",
    "theta",
    "kappa",
    "lambda",
    "mu",
    "nu",
    "xi",
    "rho",
    "sigma",
    "tau",
    "phi",
    "varphi",
    "chi",
    "psi",
    "omega",
    "varpi",
    "Gamma",
    "Delta",
    "Theta",
    "Lambda",
    "Sigma",
    "Phi",
    "Psi",
    "Omega",
];
