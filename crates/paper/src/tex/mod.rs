//! The paper's LaTeX source read as the author wrote it: every numbered equation found in
//! `equation`, `eqnarray`, `align`, `gather` and `multline` (starred or not; `aligned`, `split`
//! and `gathered` nested inside read as one equation), numbered as LaTeX numbers them, with its
//! `\label`, and the preamble's `\def`, `\newcommand` and `\renewcommand` expanded.
//!
//! Numbering follows LaTeX: an `equation` takes one number, an `eqnarray` or `align` one per
//! row; a starred environment, `\nonumber` or `\notag` takes none, and `\tag{...}` prints its
//! own mark without taking a number. A row of an `eqnarray` without a number whose next row's
//! first cell is empty (`& = & ...`, `& & + ...`) belongs to that next row's equation: the
//! number LaTeX prints at the end of a relation written over several rows.

pub mod macros;

/// One numbered (or tagged) equation of the source.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TexEquation {
    /// The number LaTeX prints, or `None` for an equation with a `\tag`.
    pub number: Option<u32>,
    /// Its `\label`, if any.
    pub label: Option<String>,
    /// Its text, macros expanded, rows joined with `\\`.
    pub latex: String,
    /// The 1-based line of the source where it ends (where LaTeX prints its number).
    pub line: usize,
}

/// The environments that hold displayed equations, and whether each row is numbered.
const ENVIRONMENTS: &[(&str, bool)] = &[
    ("equation", false),
    ("eqnarray", true),
    ("align", true),
    ("gather", true),
    ("multline", false),
    ("flalign", true),
    ("alignat", true),
];

/// The text without its comments (`%` to the end of the line, unless escaped), lines kept.
pub fn strip_comments(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for line in text.split_inclusive('\n') {
        let mut escaped = false;
        let mut cut = None;
        for (k, c) in line.char_indices() {
            match c {
                '\\' => escaped = !escaped,
                '%' if !escaped => {
                    cut = Some(k);
                    break;
                }
                _ => escaped = false,
            }
        }
        match cut {
            Some(k) => {
                out.push_str(&line[..k]);
                if line.ends_with('\n') {
                    out.push('\n');
                }
            }
            None => out.push_str(line),
        }
    }
    out
}

/// Every numbered or tagged equation of `source`, in order, or a sentence naming the line of
/// what cannot be read.
pub fn equations(source: &str) -> Result<Vec<TexEquation>, String> {
    let text = strip_comments(source);
    let macros = macros::collect(&text);
    let line_of = |i: usize| 1 + text[..i].matches('\n').count();
    let body_start = text.find(r"\begin{document}").unwrap_or(0);
    let mut out = Vec::new();
    let mut counter = 0u32;
    let mut i = body_start;
    while let Some(k) = text[i..].find(r"\begin{") {
        let at = i + k;
        let name_end = match text[at + 7..].find('}') {
            Some(e) => at + 7 + e,
            None => break,
        };
        let env = &text[at + 7..name_end];
        let base = env.trim_end_matches('*');
        let Some(&(_, per_row)) = ENVIRONMENTS.iter().find(|(n, _)| *n == base) else {
            i = name_end;
            continue;
        };
        let starred = env.ends_with('*');
        let end_tag = format!(r"\end{{{env}}}");
        let Some(close) = text[name_end..].find(&end_tag).map(|e| name_end + e) else {
            return Err(format!(
                "line {}: \\begin{{{env}}} has no \\end{{{env}}}: close the environment",
                line_of(at)
            ));
        };
        let mut body = &text[name_end + 1..close];
        if base == "alignat" {
            // `\begin{alignat}{2}`: the column count is not mathematics.
            if let Some(rest) = body.trim_start().strip_prefix('{') {
                body = rest.split_once('}').map_or(rest, |(_, r)| r);
            }
        }
        let rows: Vec<(String, usize)> = if per_row {
            split_rows(body, name_end + 1, &line_of)
        } else {
            vec![(body.to_string(), line_of(close))]
        };
        let mut pending: Vec<String> = Vec::new();
        for (k, (row, line)) in rows.iter().enumerate() {
            let tag = has_any(row, &[r"\tag"]);
            let numbered = tag || (!starred && !has_any(row, &[r"\nonumber", r"\notag"]));
            let next_continues = rows.get(k + 1).is_some_and(|(r, _)| first_cell_empty(r));
            pending.push(row.clone());
            if !numbered {
                if !next_continues || !per_row {
                    pending.clear();
                }
                continue;
            }
            if !tag {
                counter += 1;
            }
            let joined = pending.join(r" \\ ");
            pending.clear();
            let latex =
                macros::expand(&joined, &macros).map_err(|e| format!("line {line}: {e}"))?;
            out.push(TexEquation {
                number: (!tag).then_some(counter),
                label: label(row).or_else(|| label(&joined)),
                latex,
                line: *line,
            });
        }
        i = close + end_tag.len();
    }
    Ok(out)
}

fn has_any(text: &str, commands: &[&str]) -> bool {
    commands.iter().any(|c| {
        text.match_indices(c)
            .any(|(k, _)| !text[k + c.len()..].starts_with(|ch: char| ch.is_ascii_alphabetic()))
    })
}

/// The argument of the row's `\label{...}`.
fn label(row: &str) -> Option<String> {
    let k = row.find(r"\label")?;
    let rest = row[k + 6..].trim_start().strip_prefix('{')?;
    let end = rest.find('}')?;
    Some(rest[..end].trim().to_string())
}

/// True when a row's first cell holds nothing but spaces and commands that only space.
fn first_cell_empty(row: &str) -> bool {
    let Some((first, _)) = row.split_once('&') else {
        return false;
    };
    first
        .replace(r"\nonumber", "")
        .replace(r"\notag", "")
        .trim()
        .is_empty()
}

/// The rows of an environment's body split at `\\` outside braces and nested environments, each
/// with the line where it ends.
fn split_rows(body: &str, offset: usize, line_of: &dyn Fn(usize) -> usize) -> Vec<(String, usize)> {
    let mut rows = Vec::new();
    let (mut depth, mut nested) = (0i32, 0i32);
    let mut start = 0;
    let bytes = body.as_bytes();
    let mut k = 0;
    while k < bytes.len() {
        match bytes[k] {
            b'{' => depth += 1,
            b'}' => depth -= 1,
            b'\\' => {
                let rest = &body[k..];
                if rest.starts_with(r"\begin{") {
                    nested += 1;
                } else if rest.starts_with(r"\end{") {
                    nested -= 1;
                } else if rest.starts_with(r"\\") {
                    if depth == 0 && nested == 0 {
                        rows.push((body[start..k].to_string(), line_of(offset + k)));
                        start = k + 2;
                    }
                    k += 2;
                    continue;
                }
                k += 1;
                // Skip the escaped character (`\{`, `\}`, `\%`).
            }
            _ => {}
        }
        k += 1;
    }
    let last = &body[start..];
    if !last.trim().is_empty() {
        rows.push((last.to_string(), line_of(offset + body.len())));
    }
    rows
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_and_labels_as_latex_gives_them() {
        let src = r"\def\half{{1 \over 2}}
\begin{document}
\begin{equation} a = \half b \label{one} \end{equation}
% \begin{equation} x = y \label{gone} \end{equation}
\begin{eqnarray}
c & = & d, \label{two} \\
e & = & f \nonumber \\
& & + g \label{three}
\end{eqnarray}
\begin{equation*} u = v \end{equation*}
\begin{align}
p &= q \tag{A} \label{tagged} \\
r &= s \label{four}
\end{align}
\begin{equation}
\begin{aligned} h &= i \\ &= j \end{aligned} \label{five}
\end{equation}";
        let eqs = equations(src).unwrap();
        let got: Vec<(Option<u32>, Option<&str>)> =
            eqs.iter().map(|e| (e.number, e.label.as_deref())).collect();
        assert_eq!(
            got,
            vec![
                (Some(1), Some("one")),
                (Some(2), Some("two")),
                (Some(3), Some("three")),
                (None, Some("tagged")),
                (Some(4), Some("four")),
                (Some(5), Some("five")),
            ]
        );
        assert!(eqs[0].latex.contains(r"\over 2"), "{}", eqs[0].latex);
        assert!(eqs[2].latex.contains("e & = & f"), "{}", eqs[2].latex);
        assert_eq!(eqs[1].line, 6);
    }
}
