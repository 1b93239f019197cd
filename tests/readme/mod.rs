//! The numbers of the README and of `docs/` are the tool's: each is read back from the text and
//! compared with what the tool prints or with the files it stores and reads, so that none can go
//! stale. Here the README's, against `check --json` and `snapshots/mutants.json`,
//! `paper/claims.yaml`, `paper/corrections.yaml`; `docs.rs` holds those of `docs/`.

mod docs;
mod toy;
mod written;

use serde_json::Value;
use written::{
    agrees, check_json, check_named, checks, count_before, equation_list,
    equations_in_parentheses_after, equations_with, is_date, last_number, number_after, prose,
    range_after, raw, verdict,
};

#[test]
fn the_readmes_verdict_counts_are_the_checks() {
    let readme = prose("README.md");
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
    let summary = &check_json()["summary"];
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
        (eqs, "equations", "depends", " depend on a choice"),
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
        (
            claims,
            "claims",
            "restated",
            " fails as the equation it restates",
        ),
        (
            claims,
            "claims",
            "parts",
            " fails as a part of another claim's statement",
        ),
        (claims, "claims", "unit_misprints", " are unit misprints"),
        (
            claims,
            "claims",
            "depends",
            " of them the verdict depends on a choice",
        ),
        (
            claims,
            "claims",
            "dimensional_slips",
            " is a dimensional slip",
        ),
    ];
    for (text, group, key, words) in cases {
        let written = count_before(text, words);
        let counted = summary[group][key].as_u64();
        // A class with no member is not named; one with members is, with its count.
        assert!(
            written == counted || (written.is_none() && counted == Some(0)),
            "README's {group} '{words}' ({written:?}) against check --json's {key} ({counted:?})"
        );
    }
    let equations = checks().iter().filter(|c| c["equation"].is_u64()).count();
    let claims_checked = checks().iter().filter(|c| c["claim"].is_string()).count();
    let claims_listed = raw("paper/claims.yaml")
        .lines()
        .filter(|l| l.starts_with("- id:"))
        .count();
    assert_eq!(
        count_before(eqs, " numbered equations are checked"),
        Some(equations as u64),
        "README's count of equations against check --json's"
    );
    assert_eq!(
        count_before(&readme[start..], " claims in the prose"),
        Some(claims_listed as u64),
        "README's count of claims against paper/claims.yaml"
    );
    assert_eq!(
        count_before(claims, " are checked"),
        Some(claims_checked as u64),
        "README's count of checked claims against check --json's"
    );
    assert_eq!(
        equations_in_parentheses_after(eqs, " are order-of-magnitude estimates"),
        equations_with("estimate"),
        "README's estimates against check --json's"
    );
    assert_eq!(
        equations_in_parentheses_after(eqs, " hold only under a premise"),
        equations_with("premise_fails"),
        "README's equations under a failing premise against check --json's"
    );
    assert_eq!(
        equations_in_parentheses_after(eqs, " depend on a choice"),
        equations_with("depends"),
        "README's equations that depend on a choice against check --json's"
    );
}

#[test]
fn the_readmes_root_causes_are_the_checks() {
    let readme = prose("README.md");
    let summary = &check_json()["summary"];
    let tool_roots: Vec<(u32, Vec<u32>)> = summary["root_causes"]
        .as_array()
        .expect("check --json's root causes")
        .iter()
        .map(|r| {
            let mut heirs: Vec<u32> = r["consequences"]
                .as_array()
                .expect("a root cause's consequences")
                .iter()
                .map(|n| n.as_u64().expect("an equation number") as u32)
                .collect();
            heirs.sort_unstable();
            let root = r["equation"].as_u64().expect("an equation number") as u32;
            (root, heirs)
        })
        .collect();
    assert_eq!(
        count_before(&readme, " failing equations come from"),
        summary["equations"]["fails"].as_u64(),
        "README's failing equations against check --json's"
    );
    assert_eq!(
        count_before(&readme, " root causes."),
        Some(tool_roots.len() as u64),
        "README's number of root causes against check --json's"
    );
    let at = readme
        .find(" root causes.")
        .expect("the root causes' sentence");
    let after = &readme[at..];
    let list = &after[after.find("\n\n").expect("the list of root causes") + 2..];
    let list = &list[..list.find("\n\n").unwrap_or(list.len())];
    let mut listed = Vec::new();
    for item in list.split("- **eq ").skip(1) {
        let root: u32 = item
            .split("**")
            .next()
            .and_then(|n| n.trim().parse().ok())
            .unwrap_or_else(|| panic!("a root cause's number: {item}"));
        let heirs = match item.find("**Inherited by eqs ") {
            Some(i) => {
                let rest = &item[i + "**Inherited by eqs ".len()..];
                equation_list(&rest[..rest.find("**").expect("the end of the bold list")])
            }
            None => Vec::new(),
        };
        listed.push((root, heirs));
    }
    assert_eq!(
        listed, tool_roots,
        "README's root causes and their heirs against check --json's"
    );
}

#[test]
fn the_readmes_table_of_failures_is_the_checks() {
    let readme = raw("README.md");
    let mut rows = 0;
    for line in readme.lines().filter(|l| l.starts_with("| `")) {
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        assert_eq!(cells.len(), 7, "a row of five cells: {line}");
        let name = cells[1].trim_matches('`');
        let outcome = &check_named(name)["outcome"];
        assert_eq!(
            outcome["verdict"], "fails",
            "README lists {name} as failing"
        );
        for (printed, key) in [(cells[3], "claimed"), (cells[4], "reference")] {
            let value = outcome[key]
                .as_f64()
                .unwrap_or_else(|| panic!("{name} has no {key} value"));
            assert!(
                agrees(printed, value),
                "README's {name}: {key} {printed} against check --json's {value}"
            );
        }
        rows += 1;
    }
    assert!(rows > 0, "the README's table of what fails");
    let start = readme
        .find("## What the paper gets wrong")
        .expect("the README's section on what the paper gets wrong");
    let section = &readme[start..];
    let section = &section[..section[3..].find("\n## ").map_or(section.len(), |i| i + 3)];
    for c in checks() {
        if let (
            Some(id),
            Some(
                "fails" | "restates" | "part_of" | "unit_misprint" | "depends" | "dimensional_slip",
            ),
        ) = (c["claim"].as_str(), verdict(c))
        {
            assert!(
                section.contains(&format!("`{id}`")),
                "the README does not name the failing claim {id}"
            );
        }
    }
}

/// Each verdict that depends on a choice the paper leaves open is named in the README's section
/// on what the paper gets wrong, on a line of its own (`- `id` ...`) that gives the choice and
/// the reference's value under each alternative (to the digits written), as `check --json` has
/// them; a robust verdict given such a line is held to its values the same way.
#[test]
fn the_readmes_verdicts_that_depend_on_a_choice_are_the_checks() {
    let readme = raw("README.md");
    let mut named = 0;
    for c in checks()
        .iter()
        .filter(|c| c["outcome"]["robustness"].is_array())
    {
        let id = c["claim"]
            .as_str()
            .map_or_else(|| format!("eq {}", c["equation"]), str::to_string);
        let depends = verdict(c) == Some("depends");
        // The bullet and its indented continuation lines.
        let bullet = readme
            .lines()
            .skip_while(|l| !l.starts_with(&format!("- `{id}`")));
        let mut lines = bullet.take_while(|l| !l.trim().is_empty());
        let Some(first) = lines.next() else {
            assert!(
                !depends,
                "the README has no line `- `{id}`...` for its verdict"
            );
            continue;
        };
        let rest: Vec<&str> = lines.take_while(|l| l.starts_with("  ")).collect();
        let line = format!("{first} {}", rest.join(" "));
        let outcome = &c["outcome"];
        if depends {
            // The choice's formulas as the README writes them: in Unicode.
            let choice =
                report::inline_math::plain(outcome["depends_on"].as_str().expect("the choice"));
            assert!(
                line.contains(&choice),
                "{id}: the choice {choice} in: {line}"
            );
        }
        let alternatives = outcome["robustness"].as_array().expect("its alternatives");
        assert!(alternatives.len() >= 2, "{id}: {alternatives:?}");
        for a in alternatives {
            let value = a["reference"].as_f64().expect("a reference value");
            let written = line
                .split(|ch: char| !(ch.is_ascii_digit() || ch == '.'))
                .filter(|w| w.contains('.'))
                .any(|w| agrees(w.trim_end_matches('.'), value));
            assert!(
                written,
                "{id}: the value {value} under {} in: {line}",
                a["alternative"]
            );
        }
        named += 1;
    }
    assert!(
        named > 0,
        "the README names the verdicts that depend on a choice"
    );
}

#[test]
fn the_readmes_estimate_constants_are_the_checks() {
    let readme = prose("README.md");
    for (equation, words) in [("eq 82", "eq 82's constant is "), ("eq 83", "eq 83's ")] {
        let printed = number_after(&readme, words)
            .unwrap_or_else(|| panic!("README: {words:?} and a number"));
        let ratio = check_named(equation)["outcome"]["estimate"]["constant_ratio"]
            .as_f64()
            .unwrap_or_else(|| panic!("{equation} is not an estimate in check --json"));
        assert!(
            agrees(printed, ratio),
            "README's {equation} constant {printed} against check --json's {ratio}"
        );
    }
}

#[test]
fn the_readmes_corrected_equations_are_those_of_the_corrections_file() {
    let readme = prose("README.md");
    let words = "corrected LaTeX for eqs ";
    let rest = &readme[readme.find(words).expect("the README's corrections") + words.len()..];
    let listed = equation_list(&rest[..rest.find('.').expect("the end of the sentence")]);
    let stored: Vec<u32> = raw("paper/corrections.yaml")
        .lines()
        .filter_map(|l| l.strip_prefix("- number:"))
        .map(|n| n.trim().parse().expect("an equation number"))
        .collect();
    assert_eq!(listed, stored, "README against paper/corrections.yaml");
}

#[test]
fn the_mutation_score_written_is_the_stored_one() {
    let stored: Value =
        serde_json::from_str(&raw("snapshots/mutants.json")).expect("snapshots/mutants.json");
    let (mut made, mut killed, mut unevaluated) = (0u64, 0u64, 0u64);
    let (mut within, mut unscored, mut by_derivation) = (Vec::new(), Vec::new(), Vec::new());
    for s in stored["scores"].as_array().expect("the stored scores") {
        let n = s["equation"].as_u64().expect("an equation number") as u32;
        if s["printed_fails"].as_bool() == Some(true) {
            unscored.push(n);
            continue;
        }
        let accepted = s["within_reading"].as_array().map_or(0, Vec::len) as u64;
        unevaluated += s["unevaluated"].as_array().map_or(0, Vec::len) as u64;
        made += s["mutants"].as_u64().expect("mutants") - accepted;
        killed += s["killed"].as_u64().expect("killed");
        if accepted > 0 {
            within.push((n, accepted));
        }
        if s["judged_by"] == "derivation" {
            by_derivation.push(n);
        }
    }
    let readme = prose("README.md");
    let at = readme
        .find(" mutants killed")
        .expect("the README's mutation score");
    let (k, m) = readme[..at]
        .rsplit_once(" of ")
        .expect("'K of M mutants killed'");
    assert_eq!(
        (last_number(k), m.trim().parse::<u64>().ok()),
        (Some(killed), Some(made)),
        "README's mutants killed against snapshots/mutants.json"
    );
    assert_eq!(
        count_before(&readme, " more could not be evaluated by their check"),
        Some(unevaluated),
        "README's mutants their check could not evaluate against snapshots/mutants.json"
    );
    let equation = number_after(&readme, " more, of eq ").and_then(|n| n.parse::<u32>().ok());
    let accepted = count_before(&readme, " more, of eq ");
    assert_eq!(
        vec![(
            equation.expect("the README's estimate mutants"),
            accepted.expect("their count")
        )],
        within,
        "README's mutants within an estimate's reading against snapshots/mutants.json"
    );
    let at = readme
        .find(" have no score")
        .expect("the README's unscored equations");
    let (_, list) = readme[..at]
        .rsplit_once("Eqs ")
        .expect("'Eqs ... have no score'");
    assert_eq!(equation_list(list), unscored, "README's unscored equations");
    assert_eq!(
        equations_in_parentheses_after(&prose("docs/paper-input.md"), "judged by its derivation"),
        by_derivation,
        "docs/paper-input.md's equations judged by their derivation"
    );
}

#[test]
fn the_readers_read_what_they_must() {
    assert_eq!(
        count_before("of 9 claims, 20 hold, and **11 fail**", " fail**"),
        Some(11)
    );
    assert_eq!(
        count_before("52 hold, 4 hold approximately", " hold approximately"),
        Some(4)
    );
    assert_eq!(count_before("no number here", " fail**"), None);
    assert_eq!(
        equation_list("43, 72, 73, 76-79, 82 and 83"),
        vec![43, 72, 73, 76, 77, 78, 79, 82, 83]
    );
    assert_eq!(
        number_after("at most 1,000,000 rows.", "at most "),
        Some("1,000,000")
    );
    assert_eq!(number_after("calls it on **0** of them", "on "), Some("0"));
    assert_eq!(
        number_after("eq 83's 1.084 times.", "eq 83's "),
        Some("1.084")
    );
    assert_eq!(number_after("nothing after", "after"), None);
    assert!(agrees("52.2", 52.2388));
    assert!(!agrees("52.2", 52.26));
    assert!(agrees("0.250", 0.250038));
    assert!(!agrees("0.250", 0.2506));
    assert!(agrees("60", 60.0));
    assert!(!agrees("6O", 60.0));
    assert_eq!(
        range_after("| radius 1e-6 to 1e3 m, mass", " radius "),
        Some((1e-6, 1e3))
    );
    assert_eq!(
        range_after(
            "outside the supported range 1e-6 to 1e0: a thin",
            "supported range "
        ),
        Some((1e-6, 1.0))
    );
    assert_eq!(range_after("radius 1e-6 up to 1e3", "radius "), None);
    assert_eq!(
        equations_in_parentheses_after("2 are estimates (eqs 82-83), 4", " are estimates"),
        vec![82, 83]
    );
    assert!(is_date(b"2026-11-26"));
    assert!(!is_date(b"1e-12 s, a"));
}
