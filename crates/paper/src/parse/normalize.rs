//! The tokens of an author's LaTeX rewritten into the forms the grammar reads, before parsing:
//! every rewrite keeps the mathematics and only changes how it is spelled.
//!
//! - The old font switches: `{\bf x}` is `\mathbf{x}`, `{\rm cm}` is `\mathrm{cm}`; `{\it x}`
//!   and `{\cal x}` are `{x}`.
//! - Upright words that are not symbols: `\mathrm{d}` (and `{\rm d}`, `\operatorname{d}`) is the
//!   `d` of a derivative; `\mathrm{sin}` and `\operatorname{sin}` are `\sin` (and the other
//!   functions the reader knows).
//! - Arguments without braces: `\frac12` is `\frac{1}{2}`, `\frac ba` is `\frac{b}{a}`,
//!   `\sqrt2` is `\sqrt{2}` (TeX takes one token, one digit of a number, per argument).
//! - Plain TeX's quotient: a group `{a \over b}` is `{\frac{a}{b}}`.
//! - `cases`: one relation per case, its condition kept apart ([`super::cases`]).
//! - Rows and alignment points (`&`, `&=&`, `\\`): a row whose first cell is empty continues
//!   the row before it (`& = & ...` continues a chain, `& & + ...` a side); any other row starts
//!   a new chain. A comma before a relation (`b, = c`) continues the chain too.
//! - Text: `\text{for } b > 0` after a relation states a condition, kept apart from the claim
//!   ([`Normalized::conditions`]); text that is only words (`\text{ (steady motion)}`) is
//!   ignored, and separates two relations it stands between; `\text{constant}`, one word, is an
//!   upright symbol like `\mathrm{constant}`.

use super::lex::{is_relation, Tok};
use super::ParseError;

/// Tokens after the rewrites, and the conditions split off them.
pub(super) struct Normalized {
    /// The claim's tokens.
    pub toks: Vec<(Tok, usize)>,
    /// Each condition's tokens (what follows `\text{for }`, `\text{if }`, ... up to the end of
    /// its relation).
    pub conditions: Vec<Vec<(Tok, usize)>>,
}

/// Tokens with their columns.
type Toks = Vec<(Tok, usize)>;

/// Words that open a condition when a `\text{...}` starts with one.
const CONDITION_WORDS: &[&str] = &[
    "for", "if", "when", "where", "with", "provided", "as", "at", "while", "whenever", "unless",
];

/// Functions whose name may be written upright (`\mathrm{sin}`).
const FUNCTIONS: &[&str] = &["sin", "cos", "tan", "cot", "sqrt"];

/// Applies every rewrite of the module's documentation; a `cases` environment that cannot be
/// written out as relations ([`super::cases`]) is the error.
pub(super) fn normalize(toks: Vec<(Tok, usize)>) -> Result<Normalized, ParseError> {
    let toks = super::cases::cases(toks)?;
    let toks = font_switches(toks);
    let toks = upright_words(toks);
    let toks = bare_arguments(toks);
    let toks = overs(toks);
    let toks = rows(toks);
    let toks = commas_before_relations(toks);
    Ok(texts(toks))
}

/// `{\bf x}` -> `\mathbf{x}`, `{\rm x}` -> `\mathrm{x}`, `{\it x}` -> `{x}`.
fn font_switches(toks: Vec<(Tok, usize)>) -> Vec<(Tok, usize)> {
    let mut out = Vec::with_capacity(toks.len());
    let mut i = 0;
    while i < toks.len() {
        if toks[i].0 == Tok::LBrace {
            if let Some((Tok::Cmd(c), col)) = toks.get(i + 1) {
                let to = match c.as_str() {
                    "bf" => Some(Some("mathbf")),
                    "rm" => Some(Some("mathrm")),
                    "it" | "cal" | "sl" | "mit" => Some(None),
                    _ => None,
                };
                if let Some(to) = to {
                    if let Some(cmd) = to {
                        out.push((Tok::Cmd(cmd.to_string()), *col));
                    }
                    out.push(toks[i].clone());
                    i += 2;
                    continue;
                }
            }
        }
        out.push(toks[i].clone());
        i += 1;
    }
    out
}

/// `\mathrm{d}` -> `d`, `\mathrm{sin}` -> `\sin`.
fn upright_words(toks: Vec<(Tok, usize)>) -> Vec<(Tok, usize)> {
    let mut out = Vec::with_capacity(toks.len());
    let mut i = 0;
    while i < toks.len() {
        if matches!(&toks[i].0, Tok::Cmd(c) if c == "mathrm") {
            let col = toks[i].1;
            let (word, end) = upright_word(&toks, i + 1);
            if word == "d" {
                out.push((Tok::Letter('d'), col));
                i = end;
                continue;
            }
            if FUNCTIONS.contains(&word.as_str()) {
                out.push((Tok::Cmd(word), col));
                i = end;
                continue;
            }
        }
        out.push(toks[i].clone());
        i += 1;
    }
    out
}

/// The letters of `{word}` (or of one letter) starting at `i`, and the index after it; an empty
/// word where it is not letters only.
fn upright_word(toks: &[(Tok, usize)], i: usize) -> (String, usize) {
    match toks.get(i).map(|t| &t.0) {
        Some(Tok::Letter(l)) => (l.to_string(), i + 1),
        Some(Tok::LBrace) => {
            let mut w = String::new();
            let mut j = i + 1;
            while let Some((Tok::Letter(l), _)) = toks.get(j) {
                w.push(*l);
                j += 1;
            }
            if toks.get(j).map(|t| &t.0) == Some(&Tok::RBrace) {
                (w, j + 1)
            } else {
                (String::new(), i)
            }
        }
        _ => (String::new(), i),
    }
}

/// `\frac12` -> `\frac{1}{2}`, `\frac ba` -> `\frac{b}{a}`, `\sqrt2` -> `\sqrt{2}`.
fn bare_arguments(toks: Vec<(Tok, usize)>) -> Vec<(Tok, usize)> {
    let mut out: Vec<(Tok, usize)> = Vec::with_capacity(toks.len());
    let mut pending: Vec<(Tok, usize)> = toks.into_iter().rev().collect();
    while let Some((t, col)) = pending.pop() {
        let args = match &t {
            Tok::Cmd(c) if c == "frac" => 2,
            Tok::Cmd(c) if c == "sqrt" => 1,
            _ => 0,
        };
        out.push((t, col));
        for _ in 0..args {
            let Some((next, c)) = pending.pop() else {
                break;
            };
            match next {
                Tok::LBrace => {
                    // A braced argument: copied by the main loop.
                    pending.push((Tok::LBrace, c));
                    break;
                }
                Tok::Num(_, ref text) if text.chars().count() > 1 && !text.contains('.') => {
                    let (first, rest) = text.split_at(1);
                    let x = first.parse().unwrap_or(0.0);
                    let y = rest.parse().unwrap_or(0.0);
                    out.extend([
                        (Tok::LBrace, c),
                        (Tok::Num(x, first.to_string()), c),
                        (Tok::RBrace, c),
                    ]);
                    pending.push((Tok::Num(y, rest.to_string()), c + 1));
                }
                Tok::Num(..) | Tok::Letter(_) | Tok::Cmd(_) => {
                    out.extend([(Tok::LBrace, c), (next, c), (Tok::RBrace, c)]);
                }
                other => {
                    pending.push((other, c));
                    break;
                }
            }
        }
    }
    out
}

/// `{a \over b}` -> `{\frac{a}{b}}`, innermost groups first.
fn overs(toks: Vec<(Tok, usize)>) -> Vec<(Tok, usize)> {
    // Stack of groups being built: each a list of tokens and the position of its first
    // top-level \over.
    let mut stack: Vec<(Toks, Option<usize>)> = vec![(Vec::new(), None)];
    for (t, col) in toks {
        match t {
            Tok::LBrace => stack.push((vec![(Tok::LBrace, col)], None)),
            Tok::RBrace if stack.len() > 1 => {
                let (mut group, over) = stack.pop().unwrap_or_default();
                if let Some(at) = over {
                    let denominator = group.split_off(at + 1);
                    group.pop();
                    let open = group.remove(0);
                    let mut frac = vec![open.clone(), (Tok::Cmd("frac".into()), open.1)];
                    frac.push((Tok::LBrace, open.1));
                    frac.extend(group);
                    frac.push((Tok::RBrace, col));
                    frac.push((Tok::LBrace, col));
                    frac.extend(denominator);
                    frac.push((Tok::RBrace, col));
                    group = frac;
                }
                group.push((Tok::RBrace, col));
                if let Some(top) = stack.last_mut() {
                    top.0.extend(group);
                }
            }
            Tok::Cmd(ref c) if c == "over" && stack.len() > 1 => {
                if let Some(top) = stack.last_mut() {
                    if top.1.is_none() {
                        top.1 = Some(top.0.len());
                    }
                    top.0.push((t, col));
                }
            }
            t => {
                if let Some(top) = stack.last_mut() {
                    top.0.push((t, col));
                }
            }
        }
    }
    // Groups left open are kept as written: the parser names the brace that is not closed.
    let mut out = Vec::new();
    for (group, _) in stack {
        out.extend(group);
    }
    out
}

/// Rows and alignment points: see the module's documentation.
fn rows(toks: Vec<(Tok, usize)>) -> Vec<(Tok, usize)> {
    let mut out: Vec<(Tok, usize)> = Vec::with_capacity(toks.len());
    let (mut at_row_start, mut in_first_cell) = (true, true);
    let mut depth = 0usize;
    for (t, col) in toks {
        match t {
            Tok::LBrace => depth += 1,
            Tok::RBrace => depth = depth.saturating_sub(1),
            _ => {}
        }
        match t {
            Tok::RowEnd if depth == 0 => (at_row_start, in_first_cell) = (true, true),
            Tok::Amp => in_first_cell = false,
            t => {
                if at_row_start && !out.is_empty() {
                    let ended = matches!(out.last(), Some((Tok::Comma | Tok::Period, _)));
                    if in_first_cell {
                        // A new chain: its own relation on a row of its own.
                        if matches!(out.last(), Some((Tok::Period, _))) {
                            out.pop();
                        }
                        if !matches!(out.last(), Some((Tok::Comma | Tok::Semicolon, _))) {
                            out.push((Tok::Comma, col));
                        }
                    } else if ended {
                        // The row before continues: its comma or full stop did not end it.
                        out.pop();
                    }
                }
                at_row_start = false;
                out.push((t, col));
            }
        }
    }
    out
}

/// `b, = c` -> `b = c`: a comma before a relation does not end the chain.
fn commas_before_relations(toks: Vec<(Tok, usize)>) -> Vec<(Tok, usize)> {
    let mut out: Vec<(Tok, usize)> = Vec::with_capacity(toks.len());
    for (t, col) in toks {
        if is_relation(&t) && matches!(out.last(), Some((Tok::Comma, _))) {
            out.pop();
        }
        out.push((t, col));
    }
    out
}

/// Splits the conditions off, drops words, keeps one-word text as an upright symbol.
fn texts(toks: Vec<(Tok, usize)>) -> Normalized {
    let mut out = Vec::with_capacity(toks.len());
    let mut conditions = Vec::new();
    let mut i = 0;
    while i < toks.len() {
        let (t, col) = &toks[i];
        let Tok::Text(words) = t else {
            out.push(toks[i].clone());
            i += 1;
            continue;
        };
        let trimmed = words.trim();
        let one_word = !trimmed.is_empty()
            && trimmed.chars().all(|c| c.is_ascii_alphabetic())
            && trimmed == words.as_str();
        let first = trimmed
            .split_whitespace()
            .next()
            .unwrap_or("")
            .to_ascii_lowercase();
        if one_word && !CONDITION_WORDS.contains(&first.as_str()) {
            out.push((Tok::Cmd("mathrm".into()), *col));
            out.push((Tok::LBrace, *col));
            out.extend(trimmed.chars().map(|c| (Tok::Letter(c), *col)));
            out.push((Tok::RBrace, *col));
            i += 1;
            continue;
        }
        // The tokens up to the end of this relation: a separator at depth 0, or the end.
        let mut j = i + 1;
        let mut depth = 0usize;
        while j < toks.len() {
            match &toks[j].0 {
                Tok::LBrace | Tok::LParen | Tok::LBrack => depth += 1,
                Tok::RBrace | Tok::RParen | Tok::RBrack => depth = depth.saturating_sub(1),
                Tok::Comma | Tok::Semicolon | Tok::Text(_) if depth == 0 => break,
                Tok::Period if depth == 0 && j + 1 == toks.len() => break,
                _ => {}
            }
            j += 1;
        }
        let after: Vec<(Tok, usize)> = toks[i + 1..j].to_vec();
        let states = after.iter().any(|(t, _)| is_relation(t));
        if CONDITION_WORDS.contains(&first.as_str()) && states {
            conditions.push(after);
            i = j;
            continue;
        }
        // Words: between two relations they separate them; at the end they are dropped.
        let rest_is_empty = toks[i + 1..]
            .iter()
            .all(|(t, _)| matches!(t, Tok::Comma | Tok::Semicolon | Tok::Period));
        if !rest_is_empty && !matches!(out.last(), Some((Tok::Comma | Tok::Semicolon, _))) {
            out.push((Tok::Comma, *col));
        }
        i += 1;
    }
    // A separator left at the end by a condition split off is the end of the last relation.
    Normalized {
        toks: out,
        conditions,
    }
}

#[cfg(test)]
mod tests {
    use super::super::lex::lex;
    use super::*;

    /// Both read as the same relations.
    #[track_caller]
    fn same(a: &str, b: &str) {
        let read = |x: &str| {
            super::super::parse(x)
                .unwrap_or_else(|e| panic!("{x}: {e:?}"))
                .0
        };
        assert_eq!(read(a), read(b), "{a} vs {b}");
    }

    #[test]
    fn spellings_of_the_same_tokens() {
        same(r"\frac12", r"\frac{1}{2}");
        same(r"\frac ba", r"\frac{b}{a}");
        same(r"{\bf v}_{\rm cm}", r"\mathbf{v}_{\mathrm{cm}}");
        same(r"{a \over b}", r"{\frac{a}{b}}");
        same(r"\mathrm{sin} x", r"\sin x");
        same(r"\operatorname{cos} x", r"\cos x");
        same(r"\frac{\mathrm{d} x}{\mathrm{d}t}", r"\frac{d x}{dt}");
        same(r"a &=& b \\ &=& c", r"a = b = c");
        same(r"a &= b + c \\ & \quad + d", r"a = b + c + d");
        same(r"a &= b, \\ c &= d", r"a = b, c = d");
        same(r"a = b, = c", r"a = b = c");
        same(r"a = b \label{eq:x:1} \nonumber", r"a = b");
        same(r"a = \text{constant}", r"a = \mathrm{constant}");
        same(r"a = b \quad \text{(steady motion)}", r"a = b");
        same("α − β", r"\alpha - \beta");
    }

    #[test]
    fn a_condition_is_split_off_the_claim() {
        let n = normalize(lex(r"a = b, \quad \text{for } b > 0").unwrap()).unwrap();
        assert_eq!(n.conditions.len(), 1);
        let n2 = normalize(lex(r"a = b,").unwrap()).unwrap();
        assert_eq!(
            n.toks.iter().map(|t| &t.0).collect::<Vec<_>>(),
            n2.toks.iter().map(|t| &t.0).collect::<Vec<_>>()
        );
    }
}
