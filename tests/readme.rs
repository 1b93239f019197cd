//! The README's counts of verdicts are the tool's: its sentence on the equations and the claims
//! is read back and compared with `check --json`'s summary, so it cannot go stale.

use std::process::Command;

/// The number written just before `words` in `text` (the last one, if several).
fn count_before(text: &str, words: &str) -> Option<u64> {
    let at = text.find(words)?;
    text[..at]
        .trim_end()
        .trim_end_matches("**")
        .rsplit(|c: char| !c.is_ascii_digit())
        .next()?
        .parse()
        .ok()
}

#[test]
fn the_readmes_verdict_counts_are_the_checks() {
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md"))
        .expect("README.md")
        .replace("\n\n", "\u{0}")
        .replace('\n', " ")
        .replace('\u{0}', "\n\n");
    let start = readme
        .find("All 85 numbered equations are checked")
        .expect("the README's count sentence");
    let split = readme[start..]
        .find("claims in the prose")
        .map(|i| start + i)
        .expect("the README's claims sentence");
    let end = readme[split..]
        .find("\n\n")
        .map_or(readme.len(), |i| split + i);
    let (eqs, claims) = (&readme[start..split], &readme[split..end]);
    let out = Command::new(env!("CARGO_BIN_EXE_rolling-disk"))
        .args(["check", "--json"])
        .output()
        .expect("the binary runs");
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).expect("check --json");
    let summary = &doc["summary"];
    let cases = [
        (eqs, "equations", "holds", " hold,"),
        (
            eqs,
            "equations",
            "holds_approximately",
            " hold approximately",
        ),
        (
            eqs,
            "equations",
            "definitions",
            " are consistent definitions",
        ),
        (
            eqs,
            "equations",
            "estimates",
            " are order-of-magnitude estimates",
        ),
        (
            eqs,
            "equations",
            "premise_fails",
            " hold only under a premise",
        ),
        (eqs, "equations", "fails", " fail**"),
        (claims, "claims", "holds", " hold,"),
        (
            claims,
            "claims",
            "holds_approximately",
            " hold approximately",
        ),
        (
            claims,
            "claims",
            "premise_fails",
            " hold only under a premise",
        ),
        (claims, "claims", "fails", " fail**"),
    ];
    for (text, group, key, words) in cases {
        assert_eq!(
            count_before(text, words),
            summary[group][key].as_u64(),
            "README's {group} '{words}' against check --json's {key}"
        );
    }
}

#[test]
fn the_count_reader_reads_what_it_must() {
    assert_eq!(
        count_before("of 9 claims, 20 hold, and **11 fail**", " fail**"),
        Some(11)
    );
    assert_eq!(
        count_before("52 hold, 4 hold approximately", " hold approximately"),
        Some(4)
    );
    assert_eq!(count_before("no number here", " fail**"), None);
}
