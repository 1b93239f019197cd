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
    /// A number and its text as printed (`10`, `1.8`).
    Num(f64, String),
    Letter(char),
}

/// Commands that only make space.
pub(super) const SPACES: &[&str] = &["quad", "qquad", ",", ";", "!", " ", ":"];

pub(super) fn lex(s: &str) -> Result<Vec<(Tok, usize)>, ParseError> {
    let chars: Vec<char> = s.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let col = i + 1;
        if c.is_whitespace() {
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
            d if d.is_ascii_digit() || d == '.' => {
                let mut j = i;
                while j < chars.len() && (chars[j].is_ascii_digit() || chars[j] == '.') {
                    j += 1;
                }
                let text: String = chars[i..j].iter().collect();
                let x: f64 = text.parse().map_err(|_| ParseError {
                    column: col,
                    message: format!("'{text}' is not a number"),
                })?;
                i = j;
                out.push((Tok::Num(x, text), col));
                continue;
            }
            l if l.is_ascii_alphabetic() => Tok::Letter(l),
            other => {
                return Err(ParseError {
                    column: col,
                    message: format!("the character '{other}' is not part of the paper's notation"),
                })
            }
        };
        out.push((tok, col));
        i += 1;
    }
    Ok(out)
}

/// Greek letters the paper uses as symbols (`\pi` is the constant).
pub(super) const GREEK: &[&str] = &[
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
