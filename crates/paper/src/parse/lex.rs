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
    /// `&`: an alignment point of an `eqnarray` or `align` row.
    Amp,
    /// `\\`: the end of a row of an `eqnarray` or `align`.
    RowEnd,
    /// `\begin{cases}`: the cases that follow are read as relations of their own.
    CasesBegin,
    /// `\end{cases}`.
    CasesEnd,
    /// The words of `\text{...}` (or `\mbox`, `\textrm`) as written.
    Text(String),
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

/// Commands whose braced argument is text, not mathematics: read whole, whatever it holds
/// (`\label{eq:energy}`, `\text{i.e. for } `). A label or a tag is dropped (the equation's
/// number comes from its place in the source); text is kept for the reader to judge.
const RAW: &[&str] = &["label", "tag", "text", "mbox", "textrm", "begin", "end"];

/// Environments nested in an equation that only align its rows: read as the rows they hold.
const ALIGNING: &[&str] = &["aligned", "split", "gathered", "alignedat"];

/// The raw text of the braced group after a command ending at `i` (a `*` after `\tag` and
/// spaces are skipped), and the index after its closing brace.
fn raw_group(chars: &[char], mut i: usize, col: usize) -> Result<(String, usize), ParseError> {
    while i < chars.len() && (chars[i] == '*' || chars[i].is_whitespace()) {
        i += 1;
    }
    if chars.get(i) != Some(&'{') {
        return Err(ParseError {
            column: col,
            message: "expected { after the command: write its argument in braces".into(),
        });
    }
    let mut depth = 0usize;
    let start = i + 1;
    while i < chars.len() {
        match chars[i] {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    return Ok((chars[start..i].iter().collect(), i + 1));
                }
            }
            _ => {}
        }
        i += 1;
    }
    Err(ParseError {
        column: col,
        message: "the braced argument is not closed: add its }".into(),
    })
}

/// Other spellings of a command the reader knows: `\dfrac` and `\tfrac` are `\frac`,
/// `\boldsymbol` and `\bm` are `\mathbf`, `\operatorname` is `\mathrm`, the old font switches
/// `{\bf x}` and `{\rm x}` are rewritten to these by the reader.
const SYNONYMS: &[(&str, &str)] = &[
    ("dfrac", "frac"),
    ("tfrac", "frac"),
    ("cfrac", "frac"),
    ("boldsymbol", "mathbf"),
    ("bm", "mathbf"),
    ("operatorname", "mathrm"),
    ("textrm", "mathrm"),
    ("vert", "|"),
    ("lvert", "|"),
    ("rvert", "|"),
    ("ne", "neq"),
    ("lesssim", "lsim"),
    ("gtrsim", "gsim"),
];

/// Characters that copying from a PDF or typing gives for a command or an ASCII character of
/// LaTeX: Greek letters, the minus sign U+2212, the multiplication signs and the relations.
pub(super) fn unicode(c: char) -> Option<&'static str> {
    Some(match c {
        'α' => "alpha",
        'β' => "beta",
        'γ' => "gamma",
        'δ' => "delta",
        'ε' | 'ϵ' => "epsilon",
        'ζ' => "zeta",
        'η' => "eta",
        'θ' | 'ϑ' => "theta",
        'κ' => "kappa",
        'λ' => "lambda",
        'μ' | 'µ' => "mu",
        'ν' => "nu",
        'ξ' => "xi",
        'π' => "pi",
        'ϖ' => "varpi",
        'ρ' => "rho",
        'σ' => "sigma",
        'τ' => "tau",
        'φ' | 'ϕ' => "phi",
        'χ' => "chi",
        'ψ' => "psi",
        'ω' => "omega",
        'Γ' => "Gamma",
        'Δ' => "Delta",
        'Θ' => "Theta",
        'Λ' => "Lambda",
        'Σ' => "Sigma",
        'Φ' => "Phi",
        'Ψ' => "Psi",
        'Ω' => "Omega",
        '×' => "times",
        '·' | '⋅' => "cdot",
        '≈' => "approx",
        '≡' => "equiv",
        '≤' | '⩽' => "leq",
        '≥' | '⩾' => "geq",
        '∝' => "propto",
        _ => return None,
    })
}

/// What to write instead of a command or character the reader does not know, where an author
/// may have meant something it does.
pub(super) fn hint(name: &str) -> Option<&'static str> {
    Some(match name {
        "over" => "put the quotient in braces, {numerator \\over denominator}, or write \\frac{numerator}{denominator}",
        "div" | "\u{f7}" => "write a quotient as \\frac{numerator}{denominator}",
        "lsim" | "gsim" | "mathrel" | "vcenter" | "hbox" | "neq" => {
            "the checks read the relations =, <, >, \\le, \\ge, \\approx, \\equiv and \\propto: write one of them here"
        }
        "text" | "textrm" | "mbox" => {
            "words in an equation are read after a relation ends it: put \\text{...} after the last relation, or write a symbol as \\mathrm{name}"
        }
        "ast" | "*" | "\u{d7}" | "\u{b7}" => "write a product as juxtaposition (k m) or with \\cdot",
        "exp" | "ln" | "log" => {
            "the reader has no exponential or logarithm (the paper uses none), so this equation cannot be checked as written; it knows \\sin, \\cos, \\tan, \\cot, \\sqrt and powers x^{n}"
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
                if name == "\\" {
                    out.push((Tok::RowEnd, col));
                    continue;
                }
                if RAW.contains(&name.as_str()) {
                    let (text, next) = raw_group(&chars, i, col)?;
                    i = next;
                    if (name == "begin" || name == "end") && text.trim() == "cases" {
                        let t = if name == "begin" {
                            Tok::CasesBegin
                        } else {
                            Tok::CasesEnd
                        };
                        out.push((t, col));
                        continue;
                    }
                    if (name == "begin" || name == "end") && !ALIGNING.contains(&text.trim()) {
                        return Err(ParseError {
                            column: col,
                            message: format!(
                                "the environment {} is not read inside an equation: write each \
                                 of its rows as a relation of its own (rows separated by \\\\, \
                                 or by commas)",
                                text.trim()
                            ),
                        });
                    }
                    if name == "text" || name == "mbox" || name == "textrm" {
                        out.push((Tok::Text(text), col));
                    }
                    continue;
                }
                let name = SYNONYMS
                    .iter()
                    .find(|(s, _)| *s == name)
                    .map_or(name, |(_, to)| to.to_string());
                if name == "|" {
                    out.push((Tok::Pipe, col));
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
            '&' => Tok::Amp,
            '\u{2212}' | '\u{2013}' => Tok::Minus,
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
            other if unicode(other).is_some() => {
                Tok::Cmd(unicode(other).map_or_else(String::new, str::to_string))
            }
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
pub const GREEK: &[&str] = &[
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

/// True for a token that relates two sides.
pub(super) fn is_relation(t: &Tok) -> bool {
    match t {
        Tok::Equals | Tok::Less | Tok::Greater => true,
        Tok::Cmd(c) => matches!(
            c.as_str(),
            "approx" | "equiv" | "leq" | "le" | "geq" | "ge" | "propto"
        ),
        _ => false,
    }
}
