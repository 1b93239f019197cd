//! Formulas in the prose the tool shows are mathematics: in every equation's `says`, every
//! claim of `paper/claims.yaml` (and the places it is also stated) and every caption template
//! of a figure or a table, a formula is LaTeX between dollar signs, which the HTML sets as
//! MathML, the LaTeX report as TeX and a terminal as Unicode (`report::inline_math`). Outside
//! the dollar signs, ASCII math (`alpha_0`, `Omega^2`, `sqrt(`, a Greek letter's name, `-dot`)
//! fails here, named with where it is.

use checks::equations::built_in_paper;
use report::inline_math::{pieces, Piece};
use std::path::Path;

/// A Greek letter's name (every one the paper's LaTeX may use as a symbol, `paper::parse::GREEK`)
/// or `sqrt` spelled out as a word: ASCII math.
fn spelled_out(word: &str) -> bool {
    paper::parse::GREEK.contains(&word) || word == "sqrt"
}

/// Whether a word is a path of the repository (`crates/studies/src/sliding/contact_loss.rs`),
/// whose underscores are not subscripts.
fn is_path(word: &str) -> bool {
    word.contains('/')
        && word.contains('.')
        && word
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "_./-".contains(c))
}

/// The first piece of ASCII math in `text` outside its formulas, if any.
fn ascii_math(text: &str) -> Option<String> {
    for piece in pieces(text) {
        let Piece::Text(t) = piece else { continue };
        let words: Vec<&str> = t.split_whitespace().filter(|w| !is_path(w)).collect();
        let t = words.join(" ");
        let chars: Vec<char> = t.chars().collect();
        for (i, &c) in chars.iter().enumerate() {
            let before = i.checked_sub(1).map(|j| chars[j]);
            let after = chars.get(i + 1).copied();
            let subscript = c == '_'
                && before.is_some_and(|b| b.is_ascii_alphabetic())
                && after.is_some_and(|a| a.is_ascii_alphanumeric() || a == '{');
            if c == '^' || subscript {
                let from = i.saturating_sub(12);
                return Some(chars[from..(i + 12).min(chars.len())].iter().collect());
            }
        }
        let words = t.split(|c: char| !c.is_ascii_alphabetic() && c != '-');
        for word in words {
            let bare = word.trim_matches('-');
            if spelled_out(bare) || word.ends_with("-dot") {
                return Some(word.to_string());
            }
        }
    }
    None
}

#[test]
fn ascii_math_is_found_and_formulas_are_not() {
    assert_eq!(
        ascii_math("rate alpha_dot^2 here").as_deref(),
        Some("rate alpha_dot^2 here")
    );
    assert_eq!(
        ascii_math("at rate alpha-dot about").as_deref(),
        Some("alpha-dot")
    );
    assert_eq!(ascii_math("the rate Omega of").as_deref(), Some("Omega"));
    assert!(ascii_math("the test in contact_loss.rs").is_some());
    assert_eq!(
        ascii_math("the test in crates/studies/src/contact_loss.rs runs"),
        None
    );
    assert_eq!(ascii_math(r"the rate $\dot\alpha^2$ and $\Omega_0$"), None);
    assert_eq!(ascii_math("in eq 30, with b < 0 and k = 1/4"), None);
}

#[test]
fn says_and_claims_write_formulas_as_latex() {
    let paper = built_in_paper();
    let mut found = Vec::new();
    for e in &paper.equations {
        if let Some(bad) = ascii_math(&e.entry.says) {
            found.push(format!(
                "paper/equations.yaml, eq {} `says`: {bad:?}",
                e.entry.number
            ));
        }
    }
    for c in &paper.claims {
        let texts = std::iter::once(&c.claim).chain(c.also_at.iter().map(|l| &l.claim));
        for text in texts {
            if let Some(bad) = ascii_math(text) {
                found.push(format!(
                    "paper/claims.yaml, claim {} `claim`: {bad:?}",
                    c.id
                ));
            }
        }
    }
    assert!(
        found.is_empty(),
        "ASCII math outside $...$; write it as LaTeX between dollar signs:\n{}",
        found.join("\n")
    );
}

/// A caption template's prose: its Tera tags (`{{ x }}`, `{% if %}`, `{# #}`) left out.
fn prose_of_template(text: &str) -> String {
    let mut out = String::new();
    let mut rest = text;
    while let Some(open) = rest.find('{') {
        let close = match rest[open..].chars().nth(1) {
            Some('{') => "}}",
            Some('%') => "%}",
            Some('#') => "#}",
            _ => {
                out.push_str(&rest[..=open]);
                rest = &rest[open + 1..];
                continue;
            }
        };
        out.push_str(&rest[..open]);
        match rest[open..].find(close) {
            Some(end) => rest = &rest[open + end + 2..],
            None => rest = "",
        }
    }
    out.push_str(rest);
    out
}

#[test]
fn captions_write_formulas_as_latex() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("templates");
    let mut files = Vec::new();
    let figures = std::fs::read_dir(root.join("figures")).unwrap();
    files.extend(figures.map(|f| f.unwrap().path()));
    for part in std::fs::read_dir(root.join("parts")).unwrap() {
        for f in std::fs::read_dir(part.unwrap().path()).unwrap() {
            let path = f.unwrap().path();
            let name = path.file_name().unwrap().to_string_lossy().into_owned();
            if name.starts_with("table-") {
                files.push(path);
            }
        }
    }
    files.sort();
    assert!(files.len() > 10, "caption templates found: {files:?}");
    let mut found = Vec::new();
    for path in files
        .iter()
        .filter(|p| p.to_string_lossy().ends_with(".txt.tera"))
    {
        let text = std::fs::read_to_string(path).unwrap();
        if let Some(bad) = ascii_math(&prose_of_template(&text)) {
            found.push(format!("{}: {bad:?}", path.display()));
        }
    }
    assert!(
        found.is_empty(),
        "ASCII math outside $...$ in a caption; write it as LaTeX between dollar signs:\n{}",
        found.join("\n")
    );
}
