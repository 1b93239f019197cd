//! A formula's LaTeX as plain text for a terminal: Unicode where it has the character, so that
//! `\dot\alpha^2` reads `α̇²`, `\alpha_0` reads `α₀`, `\frac{g}{a k}` reads `g/(ak)` and
//! `\sqrt{g/a}` reads `√(g/a)`. A script with no Unicode form is written `^(...)` or `_(...)`.
//!
//! The parsing is pulldown-latex's (the one the MathML of [`crate::mathml`] comes from); this
//! module only lays its events out as a line of text. A formula it cannot parse comes back as
//! its LaTeX source, never an error.

use pulldown_latex::event::{
    Content, Event, Grouping, RelationContent, ScriptPosition, ScriptType, Visual,
};
use pulldown_latex::{Parser, Storage};

/// A formula as a tree: what the event stream's prefix notation stands for.
#[derive(Debug, Clone)]
enum Node {
    /// A letter or symbol set as an identifier.
    Letter(String),
    /// A number, or text set upright (a function's name, `\text{...}`).
    Word(String),
    /// A relation or a binary operator, set with a space either side.
    Operator(String),
    /// A delimiter or a punctuation mark, set as it is.
    Mark(String),
    /// Elements set side by side.
    Row(Vec<Node>),
    /// A numerator over a denominator.
    Fraction(Box<Node>, Box<Node>),
    /// A square root.
    Root(Box<Node>),
    /// A base with scripts: right of it (sub, super) or above and below it (an accent).
    Scripts {
        base: Box<Node>,
        sub: Option<Box<Node>>,
        sup: Option<Box<Node>>,
        above: bool,
    },
}

/// `latex` as one line of plain text.
pub fn plain_math(latex: &str) -> String {
    let storage = Storage::new();
    let events: Result<Vec<Event<'_>>, _> = Parser::new(latex, &storage).collect();
    let Ok(events) = events else {
        return latex.to_string();
    };
    let mut at = 0;
    let mut items = Vec::new();
    while at < events.len() {
        match element(&events, &mut at) {
            Some(node) => items.push(node),
            None => return latex.to_string(),
        }
    }
    let mut out = String::new();
    write_row(&items, &mut out);
    out.trim().to_string()
}

/// The element starting at `events[*at]`, moving `at` past it; `None` on a stream this reader
/// does not follow (an alignment, an unmatched group's end).
fn element(events: &[Event<'_>], at: &mut usize) -> Option<Node> {
    let event = events.get(*at)?;
    *at += 1;
    Some(match event {
        Event::Content(content) => leaf(content),
        Event::Begin(grouping) => {
            let mut items = Vec::new();
            while !matches!(events.get(*at)?, Event::End) {
                items.push(element(events, at)?);
            }
            *at += 1;
            if matches!(grouping, Grouping::LeftRight(..)) {
                let (open, close) = match grouping {
                    Grouping::LeftRight(open, close) => (*open, *close),
                    _ => (None, None),
                };
                let mut row = Vec::new();
                row.extend(open.map(|c| Node::Mark(c.to_string())));
                row.extend(items);
                row.extend(close.map(|c| Node::Mark(c.to_string())));
                Node::Row(row)
            } else {
                Node::Row(items)
            }
        }
        Event::Visual(Visual::SquareRoot) => Node::Root(Box::new(element(events, at)?)),
        Event::Visual(Visual::Root) => {
            let radicand = element(events, at)?;
            let index = element(events, at)?;
            Node::Row(vec![
                Node::Scripts {
                    base: Box::new(Node::Word(String::new())),
                    sub: None,
                    sup: Some(Box::new(index)),
                    above: false,
                },
                Node::Root(Box::new(radicand)),
            ])
        }
        Event::Visual(Visual::Fraction(_)) => {
            let numerator = element(events, at)?;
            let denominator = element(events, at)?;
            Node::Fraction(Box::new(numerator), Box::new(denominator))
        }
        Event::Visual(Visual::Negation) => {
            let negated = element(events, at)?;
            Node::Row(vec![negated, Node::Mark("\u{338}".into())])
        }
        Event::Script { ty, position } => {
            let base = Box::new(element(events, at)?);
            let (sub, sup) = match ty {
                ScriptType::Subscript => (Some(Box::new(element(events, at)?)), None),
                ScriptType::Superscript => (None, Some(Box::new(element(events, at)?))),
                ScriptType::SubSuperscript => {
                    let sub = element(events, at)?;
                    (Some(Box::new(sub)), Some(Box::new(element(events, at)?)))
                }
            };
            let above = !matches!(position, ScriptPosition::Right);
            Node::Scripts {
                base,
                sub,
                sup,
                above,
            }
        }
        Event::Space { .. } | Event::StateChange(_) => Node::Row(Vec::new()),
        Event::End | Event::EnvironmentFlow(_) => return None,
    })
}

/// The node of one piece of content.
fn leaf(content: &Content<'_>) -> Node {
    match content {
        Content::Text(t) | Content::Number(t) | Content::Function(t) => Node::Word(t.to_string()),
        Content::Ordinary { content, .. } => {
            Node::Letter(crate::mathml::greek_mu(&content.to_string()).into_owned())
        }
        Content::LargeOp { content, .. } => Node::Letter(content.to_string()),
        Content::BinaryOp { content: '/', .. } => Node::Mark("/".to_string()),
        Content::BinaryOp { content, .. } => Node::Operator(match content {
            '-' => "−".to_string(),
            '*' | '⋅' => "·".to_string(),
            c => c.to_string(),
        }),
        Content::Relation { content, .. } => Node::Operator(relation(content)),
        Content::Delimiter { content, .. } => Node::Mark(content.to_string()),
        Content::Punctuation(c) => Node::Mark(c.to_string()),
    }
}

/// A relation's characters.
fn relation(content: &RelationContent) -> String {
    let mut buffer = [0u8; 8];
    String::from_utf8_lossy(content.encode_utf8_to_buf(&mut buffer)).into_owned()
}

/// Writes the elements of a row: an operator with a space either side (a sign in front, after
/// another operator or an opening mark, without), two letter-like elements with a space between.
fn write_row(items: &[Node], out: &mut String) {
    let mut previous: Option<&Node> = None;
    for item in items {
        match item {
            Node::Row(inner) if inner.is_empty() => continue,
            Node::Operator(op) => {
                let sign = match previous {
                    None => true,
                    Some(Node::Operator(_)) => true,
                    Some(Node::Mark(m)) => m.ends_with(['(', '[', '{', ',']),
                    _ => false,
                };
                if sign {
                    out.push_str(op);
                } else {
                    out.push(' ');
                    out.push_str(op);
                    out.push(' ');
                }
            }
            _ => {
                if let Some(p) = previous {
                    if needs_space(p, item) {
                        out.push(' ');
                    }
                }
                write_node(item, out);
            }
        }
        previous = Some(item);
    }
}

/// Whether two elements side by side take a space: a word (a function's name, a number after a
/// letter), a fraction and a letter with scripts or an accent are kept apart from their
/// neighbours; single letters sit together as TeX sets them.
fn needs_space(left: &Node, right: &Node) -> bool {
    let word_like = |n: &Node, first: bool| match n {
        Node::Word(w) => {
            !(w.is_empty() || first && w.chars().all(|c| c.is_ascii_digit() || c == '.'))
        }
        Node::Fraction(..) | Node::Scripts { .. } => true,
        _ => false,
    };
    match (left, right) {
        (_, Node::Scripts { base, above, .. }) if !above && matches!(**base, Node::Mark(_)) => {
            needs_space(left, base)
        }
        (_, Node::Mark(m)) if m.starts_with([')', ']', '}', ',', '.', ';', '/', '\u{338}']) => {
            false
        }
        (Node::Mark(m), _) if m.ends_with(['(', '[', '{', '/']) => false,
        (Node::Operator(_), _) => false,
        (Node::Word(w), Node::Mark(m)) if m.starts_with('(') => w.is_empty(),
        _ => word_like(left, false) || word_like(right, true),
    }
}

/// Writes one node.
fn write_node(node: &Node, out: &mut String) {
    match node {
        Node::Letter(s) | Node::Word(s) | Node::Mark(s) => out.push_str(s),
        Node::Operator(s) => {
            out.push(' ');
            out.push_str(s);
            out.push(' ');
        }
        Node::Row(items) => write_row(items, out),
        Node::Fraction(numerator, denominator) => {
            write_operand(numerator, out);
            out.push('/');
            write_operand(denominator, out);
        }
        Node::Root(radicand) => {
            out.push('√');
            write_operand(radicand, out);
        }
        Node::Scripts {
            base,
            sub,
            sup,
            above,
        } => write_scripts(base, sub.as_deref(), sup.as_deref(), *above, out),
    }
}

/// Writes a base with its scripts: an accent above a letter as a combining mark, a script as
/// Unicode sub- or superscript characters where every character has one.
fn write_scripts(
    base: &Node,
    sub: Option<&Node>,
    sup: Option<&Node>,
    above: bool,
    out: &mut String,
) {
    if above {
        write_node(base, out);
        if let Some(accent) = sup.map(text_of).and_then(|a| combining(&a)) {
            out.push(accent);
            return;
        }
        for (mark, script) in [("_", sub), ("^", sup)] {
            if let Some(s) = script {
                out.push_str(mark);
                write_operand(s, out);
            }
        }
        return;
    }
    write_node(base, out);
    if let Some(s) = sub {
        write_script(s, '_', subscript, out);
    }
    if let Some(s) = sup {
        write_script(s, '^', superscript, out);
    }
}

/// Writes a script in Unicode script characters, or after `mark` as an operand.
fn write_script(script: &Node, mark: char, map: fn(char) -> Option<char>, out: &mut String) {
    let mut text = String::new();
    write_node(script, &mut text);
    let text = text.replace(' ', "");
    match text.chars().map(map).collect::<Option<String>>() {
        Some(mapped) if !mapped.is_empty() => out.push_str(&mapped),
        _ => {
            out.push(mark);
            let atomic = text.chars().count() == 1 || text.chars().all(char::is_alphanumeric);
            if atomic {
                out.push_str(&text);
            } else {
                out.push('(');
                out.push_str(&text);
                out.push(')');
            }
        }
    }
}

/// Writes a node as an operand of `/`, `√` or a script: in parentheses unless it is one
/// letter, one word or a number.
fn write_operand(node: &Node, out: &mut String) {
    let mut text = String::new();
    write_node(node, &mut text);
    let atomic = !text.contains([' ', '/', '+', '−', '-', '=', '<', '>'])
        && (text.chars().count() == 1 || !matches!(node, Node::Row(items) if items.len() > 1));
    let bracketed =
        text.starts_with('(') && text.ends_with(')') && balanced(&text[1..text.len() - 1]);
    if atomic || bracketed {
        out.push_str(&text);
    } else {
        out.push('(');
        out.push_str(&text);
        out.push(')');
    }
}

/// Whether the parentheses of `s` balance (so that outer ones around it enclose it whole).
fn balanced(s: &str) -> bool {
    let mut depth = 0i32;
    for c in s.chars() {
        match c {
            '(' => depth += 1,
            ')' => depth -= 1,
            _ => {}
        }
        if depth < 0 {
            return false;
        }
    }
    depth == 0
}

/// The characters of a node, as text.
fn text_of(node: &Node) -> String {
    let mut text = String::new();
    write_node(node, &mut text);
    text
}

/// The combining mark of an accent drawn above a letter (`\dot`, `\ddot`, `\hat`, `\vec`,
/// `\bar`, `\tilde`).
fn combining(accent: &str) -> Option<char> {
    Some(match accent {
        "˙" | "." | "\u{307}" => '\u{307}',
        "¨" | "\u{308}" => '\u{308}',
        "^" | "ˆ" | "\u{302}" => '\u{302}',
        "→" | "\u{20d7}" => '\u{20d7}',
        "¯" | "‾" | "\u{304}" | "\u{305}" => '\u{304}',
        "~" | "˜" | "\u{303}" => '\u{303}',
        _ => return None,
    })
}

/// The superscript form of a character, where Unicode has one.
fn superscript(c: char) -> Option<char> {
    const FROM: &str = "0123456789+−-=()nijk";
    const TO: &str = "⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻⁻⁼⁽⁾ⁿⁱʲᵏ";
    FROM.chars()
        .position(|f| f == c)
        .and_then(|i| TO.chars().nth(i))
}

/// The subscript form of a character, where Unicode has one.
fn subscript(c: char) -> Option<char> {
    const FROM: &str = "0123456789+−-=()aehijklmnoprstuvxβγρφχ";
    const TO: &str = "₀₁₂₃₄₅₆₇₈₉₊₋₋₌₍₎ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓᵦᵧᵨᵩᵪ";
    FROM.chars()
        .position(|f| f == c)
        .and_then(|i| TO.chars().nth(i))
}

#[cfg(test)]
mod tests {
    use super::plain_math;

    #[test]
    fn symbols_scripts_and_accents_are_unicode() {
        assert_eq!(plain_math(r"\dot\alpha^2"), "α̇²");
        assert_eq!(plain_math(r"\alpha_0"), "α₀");
        assert_eq!(plain_math(r"\omega_1 \Omega"), "ω₁ Ω");
        assert_eq!(plain_math(r"\ddot\alpha"), "α̈");
        assert_eq!(plain_math(r"\Omega^{\beta+3}"), "Ω^(β+3)");
        assert_eq!(plain_math(r"\mu_k"), "\u{3bc}ₖ");
    }

    #[test]
    fn fractions_and_roots_are_written_on_one_line() {
        assert_eq!(plain_math(r"\frac{g}{a k}"), "g/(ak)");
        assert_eq!(plain_math(r"\sqrt{g/a}"), "√(g/a)");
        assert_eq!(
            plain_math(r"\frac{1}{2} k m a^2 \dot\alpha^2"),
            "1/2 km a² α̇²"
        );
        assert_eq!(
            plain_math(r"\Omega^2 = \frac{g}{a k \sin\alpha_0}"),
            "Ω² = g/(ak sin α₀)"
        );
        assert_eq!(
            plain_math(r"\alpha = A (t_0 - t)^{2/(\beta+2)}"),
            "α = A(t₀ − t)^(2/(β+2))"
        );
    }

    #[test]
    fn signs_and_relations_are_spaced_as_printed() {
        assert_eq!(plain_math(r"-\Omega \hat{\mathbf 3}"), "−Ω 3̂");
        assert_eq!(plain_math(r"b \approx \alpha_0 a"), "b ≈ α₀ a");
        assert_eq!(plain_math(r"F_z = 0"), "F_z = 0");
    }

    #[test]
    fn what_it_cannot_parse_is_its_source() {
        assert_eq!(plain_math(r"\frac{1}"), r"\frac{1}");
    }
}
