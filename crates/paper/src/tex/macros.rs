//! The author's macros: `\def\name#1#2{body}`, `\newcommand{\name}[2]{body}` and
//! `\renewcommand`, collected from the source and expanded in an equation's text as TeX expands
//! them (an argument is a braced group or one token; `#1` in the body is replaced by it).

use std::collections::BTreeMap;

/// One macro: how many arguments it takes and its body.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Macro {
    /// Number of arguments (0 to 9).
    pub params: usize,
    /// The body, with `#1` ... `#9` where the arguments go.
    pub body: String,
    /// The 1-based line of its definition.
    pub line: usize,
}

/// The most expansions in one equation before the reader calls the macros recursive.
pub const MAX_EXPANSIONS: usize = 10_000;

/// The longest an equation's text may grow by expansion (the equation reader takes at most
/// [`crate::parse::MAX_CHARS`] characters).
pub const MAX_EXPANDED_BYTES: usize = 16 * crate::parse::MAX_CHARS;

/// A control word (`\name`, letters) starting at byte `i` of `s`: the name and the byte after.
fn control_word(s: &str, i: usize) -> Option<(&str, usize)> {
    let rest = s.get(i..)?.strip_prefix('\\')?;
    let len = rest
        .char_indices()
        .find(|(_, c)| !c.is_ascii_alphabetic())
        .map_or(rest.len(), |(k, _)| k);
    (len > 0).then(|| (&rest[..len], i + 1 + len))
}

/// The braced group opening at byte `i` (which must be `{`): its content and the byte after
/// its `}`; an escaped brace (`\{`) inside it is text.
pub(crate) fn group(s: &str, i: usize) -> Option<(&str, usize)> {
    if !s.get(i..)?.starts_with('{') {
        return None;
    }
    let mut depth = 0usize;
    let mut escaped = false;
    for (k, c) in s[i..].char_indices() {
        if escaped {
            escaped = false;
            continue;
        }
        match c {
            '\\' => escaped = true,
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    return Some((&s[i + 1..i + k], i + k + 1));
                }
            }
            _ => {}
        }
    }
    None
}

fn skip_spaces(s: &str, mut i: usize) -> usize {
    while s[i..].starts_with(|c: char| c.is_whitespace()) {
        i += s[i..].chars().next().map_or(1, char::len_utf8);
    }
    i
}

/// Every letter-named macro defined in `text` (comments already removed), the last definition
/// of a name winning.
pub fn collect(text: &str) -> BTreeMap<String, Macro> {
    let mut out = BTreeMap::new();
    let line_of = |i: usize| 1 + text[..i].matches('\n').count();
    let mut i = 0;
    while let Some(k) = text[i..].find('\\') {
        let at = i + k;
        let Some((word, after)) = control_word(text, at) else {
            i = at + 1;
            continue;
        };
        i = after;
        let defined = match word {
            "def" | "gdef" | "edef" => def(text, after),
            "newcommand" | "renewcommand" | "providecommand" => newcommand(text, after),
            _ => None,
        };
        if let Some((name, params, body, end)) = defined {
            out.insert(
                name,
                Macro {
                    params,
                    body,
                    line: line_of(at),
                },
            );
            i = end;
        }
    }
    out
}

/// `\def\name#1#2{body}` after `\def`.
fn def(text: &str, i: usize) -> Option<(String, usize, String, usize)> {
    let i = skip_spaces(text, i);
    let (name, mut j) = control_word(text, i)?;
    let mut params = 0;
    while text[j..].starts_with('#') {
        params += 1;
        j += 2.min(text.len() - j);
    }
    let j = skip_spaces(text, j);
    let (body, end) = group(text, j)?;
    Some((name.to_string(), params, body.to_string(), end))
}

/// `{\name}[n]{body}` or `\name[n]{body}` after `\newcommand`.
fn newcommand(text: &str, i: usize) -> Option<(String, usize, String, usize)> {
    let i = skip_spaces(text, i.min(text.len()));
    let (name, j) = match group(text, i) {
        Some((inner, end)) => (control_word(inner.trim(), 0)?.0.to_string(), end),
        None => {
            let (n, e) = control_word(text, i)?;
            (n.to_string(), e)
        }
    };
    let mut j = skip_spaces(text, j);
    let mut params = 0;
    if text[j..].starts_with('[') {
        let close = j + text[j..].find(']')?;
        params = text[j + 1..close].trim().parse().ok()?;
        j = skip_spaces(text, close + 1);
    }
    let (body, end) = group(text, j)?;
    Some((name, params.min(9), body.to_string(), end))
}

/// `latex` with every macro of `macros` expanded, or the name of the macro that would not stop
/// expanding (or that lacks an argument).
pub fn expand(latex: &str, macros: &BTreeMap<String, Macro>) -> Result<String, String> {
    let mut s = latex.to_string();
    let mut i = 0;
    let mut count = 0;
    while let Some(k) = s.get(i..).and_then(|r| r.find('\\')) {
        let at = i + k;
        if s[at + 1..].starts_with('\\') {
            i = at + 2;
            continue;
        }
        let Some((name, after)) = control_word(&s, at) else {
            i = at + 1;
            continue;
        };
        let Some(m) = macros.get(name) else {
            i = after;
            continue;
        };
        count += 1;
        if count > MAX_EXPANSIONS || s.len() > MAX_EXPANDED_BYTES {
            return Err(format!(
                "\\{name} (defined at line {}) keeps expanding: it calls itself; write what it \
                 stands for in the equation instead",
                m.line
            ));
        }
        let mut args = Vec::new();
        let mut j = after;
        for _ in 0..m.params {
            j = skip_spaces(&s, j);
            if let Some((g, end)) = group(&s, j) {
                args.push(g.to_string());
                j = end;
            } else if let Some((w, end)) = control_word(&s, j) {
                args.push(format!("\\{w}"));
                j = end;
            } else if let Some(c) = s[j..].chars().next() {
                args.push(c.to_string());
                j += c.len_utf8();
            } else {
                return Err(format!(
                    "\\{name} (defined at line {}) takes {} arguments: give each in braces",
                    m.line, m.params
                ));
            }
        }
        let body = substitute(&m.body, &args);
        // A space keeps a control word in the body from running into a following letter.
        s = format!("{}{body} {}", &s[..at], &s[j..]);
        i = at;
    }
    Ok(s)
}

/// The body with `#n` replaced by the n-th argument; a space is put between a control word of
/// the body and an argument that starts with a letter (`\vert#1` with `b` is `\vert b`, as TeX,
/// which reads tokens, never merges them).
fn substitute(body: &str, args: &[String]) -> String {
    let mut out = String::with_capacity(body.len());
    let mut chars = body.chars().peekable();
    while let Some(c) = chars.next() {
        let n = match (c, chars.peek()) {
            ('#', Some(d)) if d.is_ascii_digit() => d.to_digit(10).unwrap_or(0) as usize,
            _ => {
                out.push(c);
                continue;
            }
        };
        chars.next();
        let Some(arg) = n.checked_sub(1).and_then(|k| args.get(k)) else {
            continue;
        };
        if out.ends_with(|p: char| p.is_ascii_alphabetic())
            && arg.starts_with(|p: char| p.is_ascii_alphabetic())
        {
            out.push(' ');
        }
        out.push_str(arg);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn definitions_are_read_and_expanded() {
        let src = r"\def\frac#1#2{{#1 \over #2}}
\def\abs#1{\left\vert#1\right\vert}
\newcommand{\half}{\frac{1}{2}}
\renewcommand\vv[1]{\mathbf{#1}}";
        let m = collect(src);
        assert_eq!(m["frac"].params, 2);
        assert_eq!(m["vv"].line, 4);
        let e = expand(r"\half \abs{b} \vv a", &m).unwrap();
        assert!(e.contains(r"{1 \over 2}"), "{e}");
        assert!(e.contains(r"\left\vert b\right\vert"), "{e}");
        assert!(e.contains(r"\left\vert b\right\vert"), "{e}");
        assert!(e.contains(r"\mathbf{a}"), "{e}");
        let looping = collect(r"\def\x{\x}");
        assert!(expand(r"\x", &looping)
            .unwrap_err()
            .contains("calls itself"));
    }
}
