//! The `cases` environment: one relation per case, each with its condition.
//!
//! `f = \begin{cases} A & b > 0 \\ B & \text{if } b < 0 \\ C & \text{otherwise} \end{cases}`
//! states $f = A$ for $b > 0$, $f = B$ for $b < 0$ and $f = C$: it reads as
//! `f = A \text{for } b > 0, \qquad f = B \text{if } b < 0, \qquad f = C`, each case a relation
//! of its own with the text of its row before the environment (`f =`) in front of it, and its
//! condition kept apart from the claim as `\text{for } ...` is (a condition that is only words,
//! such as `\text{otherwise}`, is dropped). The tokens keep the columns they were written at, so a
//! message about a case points into the case as printed.
//!
//! Refused, each with its location and a fix that reads: a `cases` inside another, one without
//! its `\end{cases}` (or an `\end{cases}` without its `\begin`), one that follows no relation on
//! its row, and a condition that states no relation and is not words in `\text{...}`.

use super::lex::is_relation;
use super::lex::Tok;
use super::ParseError;

/// Tokens with their columns.
type Toks = Vec<(Tok, usize)>;

/// The tokens with every `cases` environment written out as one relation per case.
pub(super) fn cases(toks: Toks) -> Result<Toks, ParseError> {
    let mut toks = toks;
    while let Some(begin) = toks.iter().position(|(t, _)| *t == Tok::CasesBegin) {
        let opened = toks[begin].1;
        if let Some((_, col)) = toks[..begin].iter().find(|(t, _)| *t == Tok::CasesEnd) {
            return Err(ParseError {
                column: *col,
                message: "\\end{cases} without its \\begin{cases}: remove it".into(),
            });
        }
        let Some(end) = toks[begin + 1..]
            .iter()
            .position(|(t, _)| matches!(t, Tok::CasesBegin | Tok::CasesEnd))
            .map(|i| begin + 1 + i)
        else {
            return Err(ParseError {
                column: opened,
                message: "\\begin{cases} without its \\end{cases}: add \\end{cases} after the \
                          last case"
                    .into(),
            });
        };
        if toks[end].0 == Tok::CasesBegin {
            return Err(ParseError {
                column: toks[end].1,
                message: "a cases environment inside another is not read: write the inner \
                          cases as relations of their own, one a row, each with its condition \
                          after it as \\text{for } b > 0"
                    .into(),
            });
        }
        let row_start = toks[..begin]
            .iter()
            .rposition(|(t, _)| *t == Tok::RowEnd)
            .map_or(0, |i| i + 1);
        let lead: Toks = toks[row_start..begin].to_vec();
        if !lead.iter().any(|(t, _)| is_relation(t)) {
            return Err(ParseError {
                column: opened,
                message: "a cases environment is read after a relation on its row, as in \
                          f = \\begin{cases} ... \\end{cases}: write the quantity and the relation \
                          before it"
                    .into(),
            });
        }
        let mut written: Toks = Vec::new();
        for (n, case) in split(&toks[begin + 1..end], &Tok::RowEnd)
            .into_iter()
            .filter(|c| !c.is_empty())
            .enumerate()
        {
            if n > 0 {
                written.push((Tok::RowEnd, case[0].1));
            }
            written.extend(lead.iter().cloned());
            written.extend(one_case(case, opened)?);
        }
        let mut out: Toks = toks[..row_start].to_vec();
        out.extend(written);
        out.extend(toks[end + 1..].iter().cloned());
        toks = out;
    }
    if let Some((_, col)) = toks.iter().find(|(t, _)| *t == Tok::CasesEnd) {
        return Err(ParseError {
            column: *col,
            message: "\\end{cases} without its \\begin{cases}: remove it".into(),
        });
    }
    Ok(toks)
}

/// `tokens` split at each `at` outside braces.
fn split<'a>(tokens: &'a [(Tok, usize)], at: &Tok) -> Vec<&'a [(Tok, usize)]> {
    let mut parts = Vec::new();
    let (mut depth, mut start) = (0usize, 0usize);
    for (i, (t, _)) in tokens.iter().enumerate() {
        match t {
            Tok::LBrace => depth += 1,
            Tok::RBrace => depth = depth.saturating_sub(1),
            t if t == at && depth == 0 => {
                parts.push(&tokens[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(&tokens[start..]);
    parts
}

/// A case's value and its condition (the value's trailing punctuation dropped), the condition
/// as the reader reads one: `\text{for }` in front of a relation written bare.
fn one_case(case: &[(Tok, usize)], opened: usize) -> Result<Toks, ParseError> {
    let cells = split(case, &Tok::Amp);
    let punctuation = |t: &Tok| matches!(t, Tok::Comma | Tok::Period | Tok::Semicolon);
    let trimmed = |cell: &[(Tok, usize)]| -> Toks {
        let mut cell = cell.to_vec();
        while cell.last().is_some_and(|(t, _)| punctuation(t)) {
            cell.pop();
        }
        cell
    };
    let value = trimmed(cells[0]);
    let Some(&(_, at)) = case.first() else {
        return Ok(Vec::new());
    };
    if value.is_empty() {
        return Err(ParseError {
            column: at,
            message: "a case without a value: write the value before its & and its condition \
                      after it, as 1 & b > 0"
                .into(),
        });
    }
    let condition = cells
        .get(1..)
        .map_or(Vec::new(), |rest| trimmed(&rest.concat()));
    let mut out = value;
    let words_only = condition.iter().all(|(t, _)| matches!(t, Tok::Text(_)));
    let states = condition.iter().any(|(t, _)| is_relation(t));
    // Whether the condition opens with words, and its column.
    let first = condition
        .first()
        .map(|(t, col)| (matches!(t, Tok::Text(_)), *col));
    match first {
        None => {}
        Some(_) if words_only => {}
        Some((true, _)) if states => out.extend(condition),
        Some((false, col)) if states => {
            out.push((Tok::Text("for ".into()), col));
            out.extend(condition);
        }
        Some((_, col)) => {
            return Err(ParseError {
                column: col.max(opened),
                message: "a case's condition states no relation: write it as one, b > 0 (or \
                          \\text{for } b > 0), or as words in \\text{...}"
                    .into(),
            })
        }
    }
    Ok(out)
}
