//! Formulas in the prose the tool shows are mathematics: in every equation's `says`, every
//! claim of `paper/claims.yaml` (and the places it is also stated), every caption template of a
//! figure or a table, every paragraph of a report part, every description of one of the paper's
//! figures and every text of a finding in `check --json`, a formula is LaTeX between dollar
//! signs, which the HTML sets as MathML, the LaTeX report as TeX and a terminal as Unicode
//! (`report::inline_math`). Outside the dollar signs, ASCII math (`alpha_0`, `Omega^2`,
//! `sqrt(`, `a*b`, a Greek letter's name, `-dot`) fails here, named with where it is; code
//! between backticks is not prose.

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

/// `text` without its code spans (between backticks).
fn without_code(text: &str) -> String {
    text.split('`').step_by(2).collect::<Vec<_>>().join(" ")
}

/// The first piece of ASCII math in `text` outside its formulas, if any.
pub(crate) fn ascii_math(text: &str) -> Option<String> {
    for piece in pieces(text) {
        let Piece::Text(t) = piece else { continue };
        let t = without_code(t);
        let words: Vec<&str> = t.split_whitespace().filter(|w| !is_path(w)).collect();
        let t = words.join(" ");
        let chars: Vec<char> = t.chars().collect();
        for (i, &c) in chars.iter().enumerate() {
            let before = i.checked_sub(1).map(|j| chars[j]);
            let after = chars.get(i + 1).copied();
            let subscript = c == '_'
                && before.is_some_and(|b| b.is_ascii_alphabetic())
                && after.is_some_and(|a| a.is_ascii_alphanumeric() || a == '{');
            let product = c == '*'
                && before.is_some_and(|b| b.is_ascii_alphanumeric())
                && after.is_some_and(|a| a.is_ascii_alphanumeric());
            if c == '^' || subscript || product {
                let from = i.saturating_sub(12);
                return Some(chars[from..(i + 12).min(chars.len())].iter().collect());
            }
        }
        let words = t.split(|c: char| !c.is_ascii_alphabetic() && c != '-');
        for word in words {
            let bare = word.trim_matches('-');
            if spelled_out(bare) || word.ends_with("-dot") || word.ends_with("-hat") {
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
    assert_eq!(
        ascii_math("the force a*b here").as_deref(),
        Some("the force a*b here")
    );
    assert!(ascii_math("it reads sqrt(g/a)").is_some());
    assert_eq!(ascii_math("runs `check::missing_input` first"), None);
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

/// The fields of a finding in `check --json` that are identifiers or data, not prose: names
/// and ids (`eq 29`, a claim's id, a figure's name, the equations in `premises_failing`), the
/// values of an enumeration (`status`, `verdict`, `method`, a cause's `kind`), and units,
/// which are written in the notation the paper's files use and `paper::dimensions` reads back
/// (`s^-1`, `sqrt(g/a)`).
const DATA_FIELDS: &[&str] = &[
    "name",
    "claim",
    "status",
    "verdict",
    "method",
    "kind",
    "unit",
    "shown_by",
    "premises_failing",
];

/// Every string of `value` with the path of keys that leads to it, data fields left out.
fn prose_strings(value: &serde_json::Value, path: &str, out: &mut Vec<(String, String)>) {
    match value {
        serde_json::Value::String(s) => out.push((path.to_string(), s.clone())),
        serde_json::Value::Array(items) => {
            for (i, v) in items.iter().enumerate() {
                prose_strings(v, &format!("{path}[{i}]"), out);
            }
        }
        serde_json::Value::Object(map) => {
            for (k, v) in map {
                if !DATA_FIELDS.contains(&k.as_str()) {
                    prose_strings(v, &format!("{path}.{k}"), out);
                }
            }
        }
        _ => {}
    }
}

/// The ASCII math in the prose of `check --json`'s findings: (check, field, what was found).
pub(crate) fn ascii_math_of_findings(json: &str) -> Vec<String> {
    let v: serde_json::Value = serde_json::from_str(json).expect("check --json is JSON");
    let mut found = Vec::new();
    for c in v["checks"].as_array().expect("a list of checks") {
        let mut strings = Vec::new();
        prose_strings(c, "", &mut strings);
        for (field, text) in strings {
            if let Some(bad) = ascii_math(&text) {
                found.push(format!("{} {field}: {bad:?}", c["name"]));
            }
        }
    }
    found
}

#[test]
fn findings_write_formulas_as_latex() {
    let dir = crate::common::temp_dir("math-markup", "findings");
    let (ok, json, err) = crate::common::cli_in(&dir, &["check", "--json"]);
    assert!(ok, "{err}");
    let found = ascii_math_of_findings(&json);
    assert!(
        found.is_empty(),
        "ASCII math outside $...$ in {} texts of check --json; write it as LaTeX between \
         dollar signs in the check's text (crates/checks) or through paper's Expr::to_tex:\n{}",
        found.len(),
        found.join("\n")
    );
}

/// Whether a finding's ASCII math would be found: a finding whose text is written as it used
/// to be, in plain words, fails.
#[test]
fn findings_in_plain_words_are_found() {
    let old = r#"{"checks": [{"name": "eq 29", "verdict": "holds_approximately",
        "outcome": {"at": "eq 29 relation 1 ((Omega_0)^{2} = (g cot(alpha_0))/(k a)): k = 0.1",
        "unit": "rad^2/s^2", "robustness": [{"alternative": "alpha_dot kept"}]}}]}"#;
    let found = ascii_math_of_findings(old);
    assert_eq!(found.len(), 2, "{found:?}");
    assert!(found[0].contains(".outcome.at"), "{found:?}");
    assert!(
        found[1].contains(".outcome.robustness[0].alternative"),
        "{found:?}"
    );
}

#[test]
fn paragraphs_and_paper_figure_descriptions_write_formulas_as_latex() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("templates");
    let mut files = Vec::new();
    for part in std::fs::read_dir(root.join("parts")).unwrap() {
        for f in std::fs::read_dir(part.unwrap().path()).unwrap() {
            let path = f.unwrap().path();
            let name = path.file_name().unwrap().to_string_lossy().into_owned();
            // A listing (`listing.txt.tera`) is set in a fixed-width block, column by column:
            // not prose.
            if name.ends_with(".txt.tera")
                && !name.starts_with("table-")
                && name != "listing.txt.tera"
            {
                files.push(path);
            }
        }
    }
    let described = std::fs::read_dir(root.join("paper-figures")).unwrap();
    files.extend(described.map(|f| f.unwrap().path()));
    files.sort();
    assert!(
        files.len() >= 12,
        "paragraphs and descriptions found: {files:?}"
    );
    let mut found = Vec::new();
    for path in &files {
        let text = std::fs::read_to_string(path).unwrap();
        if let Some(bad) = ascii_math(&prose_of_template(&text)) {
            found.push(format!("{}: {bad:?}", path.display()));
        }
    }
    assert!(
        found.is_empty(),
        "ASCII math outside $...$ in a paragraph or a figure's description; write it as LaTeX \
         between dollar signs:\n{}",
        found.join("\n")
    );
}

/// Eq 29's card (its worst case names the printed relation, written by `Expr::to_tex`) reaches
/// the HTML as MathML and the LaTeX report as math, and the terminal as Unicode.
#[test]
fn a_cards_formula_is_set_as_mathematics_in_every_format() {
    let (html, tex, _, _) = crate::report::built();
    let card = |doc: &str, from: &str| -> String {
        let start = doc.find(from).expect("eq 29's card");
        let at = start + doc[start..].find("Worst case: ").expect("its worst case");
        doc[at..at + 600.min(doc.len() - at)].to_string()
    };
    let h = card(html, "id=\"eq-29\"");
    assert!(h.starts_with("Worst case: eq 29 relation 1 (<math"), "{h}");
    assert!(h.contains(">Ω</mi>"), "{h}");
    let t = card(tex, "Eq.~29 ");
    assert!(
        t.starts_with(r"Worst case: eq 29 relation 1 ($\Omega_{0}^{2} = \frac{g \cot\alpha_{0}}"),
        "{t}"
    );
    assert!(
        !tex.contains(r"\$"),
        "a dollar sign escaped in the LaTeX report"
    );
    let dir = crate::common::temp_dir("math-markup", "text");
    let (_, out, err) = crate::common::cli_in(&dir, &["check", "--only", "29,76"]);
    assert!(out.contains("Ω₀²") || out.contains("α"), "{out}{err}");
    let commands = out.lines().filter(|l| {
        l.contains('$')
            || l.split('\\')
                .skip(1)
                .any(|w| w.starts_with(char::is_alphabetic))
    });
    let commands: Vec<&str> = commands.collect();
    assert!(
        commands.is_empty(),
        "LaTeX in the terminal's text: {commands:?}"
    );
}
