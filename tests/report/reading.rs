//! The report as a reader meets it: no program text (a Rust debug rendering, a number with a
//! dozen digits, a unit written twice), no long monospace block as a section's body, and, in
//! headless Chromium, no sideways scroll on an 800 px window.

use super::built;

/// The text a reader sees in the HTML, the figures' labels included: tags, styles and the
/// equations' TeX annotations removed.
fn visible(html: &str) -> String {
    let mut out = String::with_capacity(html.len() / 2);
    let mut rest = html;
    while let Some(open) = rest.find('<') {
        out.push_str(&rest[..open]);
        let after = &rest[open..];
        let skip_to = ["<style", "<annotation"]
            .iter()
            .zip(["</style>", "</annotation>"])
            .find(|(start, _)| after.starts_with(**start))
            .map(|(_, end)| end);
        rest = match skip_to {
            Some(end) => after.find(end).map_or("", |p| &after[p + end.len()..]),
            None => after.find('>').map_or("", |p| &after[p + 1..]),
        };
        out.push(' ');
    }
    out.push_str(rest);
    out.replace("&#x27;", "'").replace("&amp;", "&")
}

/// Rust debug renderings in `text`: `Some(..)`, `Ok(..)`, and records written as
/// `Name { field: ..`.
fn debug_dumps(text: &str) -> Vec<String> {
    let mut found: Vec<String> = ["Some(", "Ok(", "Err("]
        .iter()
        .filter(|p| text.contains(**p))
        .map(|p| p.to_string())
        .collect();
    let words: Vec<&str> = text.split_whitespace().collect();
    for w in words.windows(3) {
        let is_name = w[0].starts_with(|c: char| c.is_ascii_uppercase())
            && w[0].chars().all(|c| c.is_ascii_alphanumeric());
        let is_field = w[2].ends_with(':')
            && w[2].len() > 1
            && w[2][..w[2].len() - 1]
                .chars()
                .all(|c| c.is_ascii_lowercase() || c == '_');
        if is_name && w[1] == "{" && is_field {
            found.push(w.join(" "));
        }
    }
    found
}

/// Decimals of `text` with ten or more digits after the point.
fn long_decimals(text: &str) -> Vec<String> {
    let b = text.as_bytes();
    let mut found = Vec::new();
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'.' && i > 0 && b[i - 1].is_ascii_digit() {
            let mut j = i + 1;
            while j < b.len() && b[j].is_ascii_digit() {
                j += 1;
            }
            if j - i > 10 {
                found.push(text[i.saturating_sub(12)..j].to_string());
            }
            i = j;
        } else {
            i += 1;
        }
    }
    found
}

/// A unit or symbol written twice, as in `V (V)` or `rad/s (rad/s)`.
fn doubled_units(text: &str) -> Vec<String> {
    let words: Vec<&str> = text.split_whitespace().collect();
    words
        .windows(2)
        .filter(|w| {
            w[1].trim_end_matches([',', '.', ';', ':'])
                .strip_prefix('(')
                .and_then(|u| u.strip_suffix(')'))
                .is_some_and(|u| u == w[0] && !u.is_empty())
        })
        .map(|w| w.join(" "))
        .collect()
}

/// Everything program-like in `text`, each with what it is.
fn program_text(text: &str) -> Vec<String> {
    let mut bad: Vec<String> = debug_dumps(text)
        .into_iter()
        .map(|d| format!("debug rendering: {d}"))
        .collect();
    bad.extend(
        long_decimals(text)
            .into_iter()
            .map(|d| format!("long decimal: {d}")),
    );
    bad.extend(
        doubled_units(text)
            .into_iter()
            .map(|d| format!("doubled unit: {d}")),
    );
    bad
}

#[test]
fn the_scanners_find_what_they_must() {
    let dump = "k 0.9, Motion { alpha: 0.05, spin: 1 } at rtol 0.000000000001 and Some(3)";
    assert_eq!(debug_dumps(dump), vec!["Some(", "Motion { alpha:"]);
    assert_eq!(long_decimals(dump).len(), 1);
    assert_eq!(
        doubled_units("signal V (V), speed rad/s (rad/s), t (s)").len(),
        2
    );
    assert!(program_text("a scene's solver: { project: energy }, eq 10.2, 1e-12").is_empty());
    let seen = visible("<p>a<style>b</style>c<svg x=\"1.00000000001\"><text>d</text></svg>e</p>");
    assert_eq!(seen.split_whitespace().collect::<String>(), "acde");
}

#[test]
fn html_and_latex_hold_no_program_text() {
    let (html, tex, _, _) = built();
    let html_bad = program_text(&visible(html));
    assert!(html_bad.is_empty(), "report.html:\n{}", html_bad.join("\n"));
    let tex_bad = program_text(&tex.replace('\\', ""));
    assert!(tex_bad.is_empty(), "report.tex:\n{}", tex_bad.join("\n"));
}

/// The `<pre>` blocks of `html` longer than `most` lines that are not inside a `<details>`
/// disclosure, each as its first line.
fn long_open_blocks(html: &str, most: usize) -> Vec<String> {
    let mut found = Vec::new();
    let mut depth = 0usize;
    let mut rest = html;
    while let Some(p) = rest.find('<') {
        rest = &rest[p..];
        if rest.starts_with("<details") {
            depth += 1;
        } else if rest.starts_with("</details>") {
            depth = depth.saturating_sub(1);
        } else if rest.starts_with("<pre") {
            let end = rest.find("</pre>").unwrap_or(rest.len());
            let block = &rest[..end];
            if depth == 0 && block.lines().count() > most {
                found.push(block.lines().next().unwrap_or("").to_string());
            }
        }
        rest = &rest[1..];
    }
    found
}

#[test]
fn no_long_monospace_block_is_a_sections_body() {
    let twenty_one = format!("<pre>{}</pre>", "x\n".repeat(21));
    assert_eq!(long_open_blocks(&twenty_one, 20).len(), 1);
    let hidden = format!("<details><summary>s</summary>{twenty_one}</details>");
    assert!(long_open_blocks(&hidden, 20).is_empty());
    let long = long_open_blocks(&built().0, 20);
    assert!(
        long.is_empty(),
        "<pre> blocks over 20 lines outside <details>:\n{}",
        long.join("\n")
    );
}

/// The numbers `html` gives what follows `opening` (`Table N.` or `Figure N.` opening a
/// caption), in the order they appear.
fn numbered(html: &str, opening: &str) -> Vec<usize> {
    html.match_indices(opening)
        .filter_map(|(i, _)| {
            let rest = &html[i + opening.len()..];
            let end = rest.find(|c: char| !c.is_ascii_digit())?;
            rest[..end].parse().ok()
        })
        .collect()
}

/// Whether `paragraphs` cite number `n` of `kind` (as `Table 3`, or within a range
/// `Tables 2–7`).
fn cited(paragraphs: &str, kind: &str, n: usize) -> bool {
    paragraphs.contains(&format!("{kind} {n})"))
        || paragraphs.contains(&format!("{kind} {n},"))
        || paragraphs.contains(&format!("{kind} {n} "))
        || paragraphs.contains(&format!("{kind} {n}."))
        || paragraphs
            .match_indices(&format!("{kind}s "))
            .any(|(i, m)| {
                let rest = &paragraphs[i + m.len()..];
                let range: Vec<usize> = rest
                    .split(|c: char| !c.is_ascii_digit())
                    .take(2)
                    .filter_map(|x| x.parse().ok())
                    .collect();
                matches!(range[..], [a, b] if (a..=b).contains(&n))
            })
}

/// The paragraphs of `html`: its `<p>` elements' text.
fn paragraphs(html: &str) -> String {
    html.match_indices("<p>")
        .map(|(i, _)| {
            let rest = &html[i..];
            &rest[..rest.find("</p>").unwrap_or(rest.len())]
        })
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn tables_and_figures_are_numbered_in_order_and_cited_from_the_text() {
    let (html, tex, figures, _) = built();
    let tables = numbered(html, "<figcaption><strong>Table ");
    assert!(tables.len() >= 9, "{} numbered tables", tables.len());
    assert_eq!(tables, (1..=tables.len()).collect::<Vec<_>>());
    assert_eq!(
        html.matches("<table class=\"study\"").count(),
        tables.len(),
        "a study table without a number"
    );
    let text = paragraphs(html);
    let uncited: Vec<usize> = tables
        .iter()
        .copied()
        .filter(|&n| !cited(&text, "Table", n))
        .collect();
    assert!(uncited.is_empty(), "tables no paragraph cites: {uncited:?}");
    // That the LaTeX numbers each table as the HTML does is tests/report/tables.rs's.
    assert_eq!(
        tex.matches("\\caption{").count() - figures.len(),
        tables.len()
    );
    let figure_numbers = numbered(html, "<figcaption><strong>Figure ");
    assert_eq!(figure_numbers, (1..=figures.len()).collect::<Vec<_>>());
    // The scanners can fail: a gap in the numbers, and a table no paragraph cites.
    let gap = numbered(
        "<figcaption><strong>Table 1.</strong><figcaption><strong>Table 3.</strong>",
        "<figcaption><strong>Table ",
    );
    assert_eq!(gap, vec![1, 3]);
    assert_ne!(gap, (1..=gap.len()).collect::<Vec<_>>());
    assert!(!cited(
        "<p>as Table 2 shows, and Tables 4–6</p>",
        "Table",
        3
    ));
    assert!(cited("<p>as Table 2 shows, and Tables 4–6</p>", "Table", 5));
}
