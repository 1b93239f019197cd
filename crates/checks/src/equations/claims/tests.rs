//! Tests of the claim checks.

use super::*;
use crate::finding::Verdict;
use serde::Deserialize;

#[derive(Deserialize)]
struct Entry {
    id: String,
}

#[test]
fn every_claim_id_is_in_claims_yaml() {
    let text = paper::Texts::BUILT_IN.claims;
    let entries: Vec<Entry> = serde_yaml::from_str(text).expect("claims.yaml parses");
    let mut ids: Vec<&str> = CLAIMS.iter().map(|c| c.id).collect();
    for id in &ids {
        assert!(
            entries.iter().any(|e| e.id == *id),
            "{id} is not in claims.yaml"
        );
    }
    ids.sort();
    ids.dedup();
    assert_eq!(ids.len(), CLAIMS.len(), "duplicate ids");
}

/// Expected unperturbed verdicts: true = passes, false = fails (the paper is wrong).
const EXPECTED: &[(&str, bool)] = &[
    ("k-rim-disk", true),
    ("k-uniform-disk", true),
    ("center-of-motion-constant", false),
    ("no-steady-motion-beyond-vertical", true),
    ("face-figure-rate-vanishes", true),
    ("slip-when-b-large", true),
    ("negative-b-friction-angle", false),
    ("bracket-negative-angle", false),
    ("positive-b-unstable-large-tilt", false),
    ("negative-b-always-stable", true),
    ("ratio-uniform-disk-077", true),
    ("ratio-hoop-one", true),
    ("b-of-order-a-alpha", false),
    ("coincidence-eq58", true),
    ("summary-nutation-10-15-deg", true),
    ("frictionless-threshold-uniform", true),
    ("rolling-threshold-uniform", true),
    ("thresholds-ratio", true),
    ("frictionless-constants", true),
    ("eq73-second-approximation-sign", false),
    ("drag-exponent-linear-force", true),
    ("drag-exponent-quadratic-air", true),
    ("drag-exponent-moffatt", true),
    ("finite-time-singularity", true),
    ("air-viscosity", false),
    ("omega-units-hz-vs-rad-per-s", false),
    ("one-period-remaining-omega", true),
    ("one-period-remaining-time", true),
    ("t0-after-last-peak", true),
    ("contact-loss-time", true),
    ("contact-loss-omega", true),
    ("disk-leaves-table", false),
    ("larger-t0-lowers-beta", true),
    ("rolling-extra-integrals", false),
    ("rattling-needs-more-friction", true),
    ("angular-momentum-near-vertical", false),
    ("limits-eq55-eq71", true),
    ("rising-needs-slip", true),
    ("summary-contact-lost-few-degrees", false),
];

#[test]
fn verdicts_unperturbed_and_perturbed() {
    assert_eq!(EXPECTED.len(), CLAIMS.len());
    let mut bad = Vec::new();
    for c in CLAIMS {
        let expected = EXPECTED
            .iter()
            .find(|(id, _)| *id == c.id)
            .unwrap_or_else(|| panic!("no expectation for {}", c.id))
            .1;
        let f = (c.check)(&Bench::default());
        if f.verdict.passes() != expected {
            bad.push(format!("{}: unperturbed {:?} {f:#?}", c.id, f.verdict));
        }
        let moves = mutation_moves(rule_of(c.id), expected);
        for eps in moves {
            let p = (c.check)(&Bench::perturbed(eps));
            // A verdict that depends on a choice is judged under the reading it was made in.
            if p.as_read() != Verdict::Fails {
                bad.push(format!("{}: perturbed {eps} {:?} {p:#?}", c.id, p.verdict));
            }
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

/// The paper with `claims` as its claims.yaml (the built-in equations and symbols).
fn paper_with_claims(claims: &str) -> Result<paper::Paper, paper::PaperError> {
    let built_in = paper::Texts::BUILT_IN;
    paper::Paper::from_texts(
        paper::PaperSource::BuiltIn,
        paper::Texts { claims, ..built_in },
    )
}

/// The built-in claim `id`'s reading, if it has one.
fn rule_of(id: &str) -> Option<&'static paper::Rule> {
    let paper = paper::Paper::built_in_shared();
    paper.claims.iter().find(|c| c.id == id)?.rule.as_ref()
}

/// The printed number and its reading come from claims.yaml: a looser reading of "about
/// 60 degrees" (within 25 %) lets the onset, 71.4 deg, pass, another printed number fails it
/// again (the verdict as read, on the onset; the fall's readings are held in
/// `the_fall_depends_on_whether_the_contact_can_slide`).
#[test]
fn a_rule_or_number_edited_in_claims_yaml_changes_the_verdict() {
    let text = paper::Texts::BUILT_IN.claims;
    let rule = "rule: { words: about, within: 0.05 }";
    let verdict = |claims: &str| {
        let paper = paper_with_claims(claims).expect("the edited claims parse");
        positive_b_unstable_large_tilt(&Bench::with_paper(&paper)).as_read()
    };
    assert_eq!(verdict(text), Verdict::Fails);
    let at = text.find("id: positive-b-unstable-large-tilt").unwrap();
    let at = at + text[at..].find(rule).expect("its rule");
    let looser = format!(
        "{}rule: {{ words: about, within: 0.25 }}{}",
        &text[..at],
        &text[at + rule.len()..]
    );
    assert!(verdict(&looser).passes(), "71.4 is within 25 % of 60");
    let block = &looser[looser.find("id: positive-b-unstable-large-tilt").unwrap()..];
    let moved = looser.replacen(
        block,
        &block.replacen("claimed_value: 60", "claimed_value: 50", 1),
        1,
    );
    assert_eq!(
        verdict(&moved),
        Verdict::Fails,
        "71.4 is not within 25 % of 50"
    );
}

#[test]
fn an_unusable_rule_is_refused_naming_the_claim_and_the_key() {
    let text = paper::Texts::BUILT_IN.claims.replace(
        "rule: { words: about, within: 0.05 }",
        "rule: { words: about, within: 0.05, digits: 2 }",
    );
    let Err(e) = paper_with_claims(&text) else {
        panic!("two readings must be refused")
    };
    let msg = e.to_string();
    assert!(
        msg.contains("claims.yaml")
            && msg.contains("positive-b-unstable-large-tilt")
            && msg.contains("`rule`")
            && msg.contains("exactly one"),
        "{msg}"
    );
}

#[test]
fn linearization_has_one_oscillating_pair() {
    // varpi^2 = -tr(J^2)/2 assumes the other eigenvalues vanish: check it.
    for &(k, al, beta) in &[(0.25, 0.3, 0.1), (0.5, 1.0, -0.1), (0.25, 1.3, 0.6)] {
        let disk = unit_disk(k);
        let m = steady_motion(&disk, al, beta).unwrap();
        let j = rolling_jacobian(&disk, &m);
        let ev = eigenvalues(&j);
        let w2 = varpi2(&j);
        let big: Vec<_> = ev.iter().filter(|z| z.norm() > 1e-6).collect();
        assert_eq!(big.len(), 2, "{ev:?}");
        let lam2 = big[0] * big[0];
        assert!((lam2.re + w2).abs() < 1e-9 * w2.abs(), "{lam2} vs {w2}");
        assert!((q_linearized(k, al, beta) - q_eq54(&Bench::default(), k, al, beta)).abs() < 1e-9);
    }
}

/// Every claim whose built-in entry states a reading is judged by it: with the reading replaced
/// by a range that holds everything the check passes, by one that holds nothing it fails.
#[test]
fn every_stated_reading_is_the_one_applied() {
    let text = paper::Texts::BUILT_IN.claims;
    let claims = &paper::Paper::built_in_shared().claims;
    let mut tried = 0;
    for entry in claims.iter().filter(|c| c.rule.is_some()) {
        let check = CLAIMS
            .iter()
            .find(|c| c.id == entry.id)
            .expect("a claim with a reading has a check");
        let start = text.find(&format!("- id: {}\n", entry.id)).unwrap();
        let end = start + text[start..].find("\n\n").unwrap_or(text.len() - start);
        let block = &text[start..end];
        let line = block
            .lines()
            .find(|l| l.starts_with("  rule:"))
            .expect("the rule's line");
        let verdict = |rule: &str| {
            let edited = format!(
                "{}{}{}",
                &text[..start],
                block.replace(line, rule),
                &text[end..]
            );
            let paper = paper_with_claims(&edited).expect("the edited claims parse");
            (check.check)(&Bench::with_paper(&paper)).verdict
        };
        let all = verdict("  rule: { words: test, range: [-1.0e300, 1.0e300] }");
        assert!(
            all.passes(),
            "{}: a range holding everything gives {all}",
            entry.id
        );
        let none = verdict("  rule: { words: test, range: [1.0e299, 1.0e300] }");
        assert_eq!(
            none,
            Verdict::Fails,
            "{}: a range holding nothing",
            entry.id
        );
        tried += 1;
    }
    assert_eq!(tried, 13);
}

/// A printed number edited in claims.yaml reaches a check that makes its own comparison too:
/// k = 0.3 for a uniform disk fails, and a claim whose number was deleted is not run.
#[test]
fn a_printed_number_edited_in_claims_yaml_reaches_the_check() {
    let text = paper::Texts::BUILT_IN.claims;
    let start = text.find("- id: k-uniform-disk").unwrap();
    let end = start + text[start..].find("\n\n").unwrap();
    let block = &text[start..end];
    let run = |edited_block: &str| {
        let edited = format!("{}{}{}", &text[..start], edited_block, &text[end..]);
        let paper = paper_with_claims(&edited).expect("the edited claims parse");
        crate::check::run_checks(
            &Bench::with_paper(&paper),
            &crate::check::Selection {
                numbers: Some(Vec::new()),
                claims: Some(vec!["k-uniform-disk".into()]),
            },
            1,
            &|_, _| {},
        )
        .expect("the selection is valid")
        .remove(0)
        .finding
    };
    assert!(run(block).unwrap().verdict.passes());
    let wrong = block.replace("claimed_value: 0.25", "claimed_value: 0.3");
    assert_ne!(wrong, block);
    assert_eq!(run(&wrong).unwrap().verdict, Verdict::Fails);
    let gone = block.replace("claimed_value: 0.25", "claimed_value: null");
    let e = run(&gone).unwrap_err();
    assert!(e.contains("give `claimed_value`"), "{e}");
}

/// "About" and "roughly" have one reading for a number the paper did not compute: a relative
/// band of 5 %; only the numbers the paper computed are read to their printed digits.
#[test]
fn about_has_one_reading() {
    const COMPUTED: &[&str] = &[
        "ratio-uniform-disk-077",
        "rolling-threshold-uniform",
        "one-period-remaining-omega",
        "one-period-remaining-time",
        "contact-loss-time",
        "contact-loss-omega",
    ];
    let paper = paper::Paper::built_in_shared();
    let mut read = 0;
    for c in &paper.claims {
        let Some(r) = c.rule.as_ref() else { continue };
        if !["about", "roughly"].contains(&r.words.as_str()) {
            continue;
        }
        read += 1;
        if COMPUTED.contains(&c.id.as_str()) {
            assert!(
                r.digits.is_some(),
                "{}: a computed number, to its digits",
                c.id
            );
        } else {
            assert_eq!(r.within, Some(0.05), "{}: 'about' is within 5 %", c.id);
        }
    }
    assert_eq!(read, COMPUTED.len() + 4, "every 'about' and 'roughly' read");
}

/// "Falls to below about 60 degrees" read as what the fall does: rolling without slip no start
/// settles into a lower rolling; on the smoothest table ($\mu = 0.2$) every start slides and settles
/// below 60 deg; on the roughest ($\mu = 1$) none slides. The verdict depends on whether the contact
/// can slide, the onset's failure kept as the verdict as read.
#[test]
fn the_fall_depends_on_whether_the_contact_can_slide() {
    let f = positive_b_unstable_large_tilt(&Bench::default());
    assert_eq!(
        f.verdict,
        Verdict::DependsOn {
            choice: super::fall::SLIDES
        }
    );
    assert_eq!(f.as_read(), Verdict::Fails, "the onset, 71.4 deg");
    let table = |words: &str| {
        f.robustness
            .iter()
            .find(|a| a.alternative.starts_with(words))
            .unwrap_or_else(|| panic!("no alternative {words}: {:?}", f.robustness))
    };
    let rolling = table("rolling without slip");
    assert_eq!(rolling.verdict, Verdict::Fails);
    assert!(rolling.reference > 63.0, "{rolling:?}");
    let smooth = table(r"the sliding model on a table with $\mu = 0.2$");
    assert_eq!(smooth.verdict, Verdict::Holds);
    assert!(smooth.reference < 60.0, "{smooth:?}");
    assert_eq!(
        table(r"the sliding model on a table with $\mu = 1$").verdict,
        Verdict::Fails
    );
}

/// One statement is counted once: where every reading of the part fails (its printed tilt
/// edited to 30, below where any run settles), the part is counted at the bracket's claim when
/// both fail; where the bracket's claim passes (its printed number edited to 52), the part keeps
/// its own failure. As printed, the part depends on a choice and is counted apart.
#[test]
fn one_statement_is_counted_once() {
    use crate::check::{run_checks, Selection};
    use crate::checked::Subject;
    use crate::tally::Tally;
    let run = |claims: &str| {
        let paper = paper_with_claims(claims).expect("the claims parse");
        let selection = Selection {
            numbers: Some(Vec::new()),
            claims: Some(vec![
                "bracket-negative-angle".into(),
                "positive-b-unstable-large-tilt".into(),
            ]),
        };
        let checked = run_checks(&Bench::with_paper(&paper), &selection, 1, &|_, _| {})
            .expect("the two claims run");
        let part = checked
            .iter()
            .find(|c| matches!(&c.subject, Subject::Claim { id } if id == "positive-b-unstable-large-tilt"))
            .and_then(|c| c.finding.as_ref().ok())
            .map(|f| f.verdict);
        (part, Tally::of(&checked))
    };
    let edit = |text: &str, id: &str, from: &str, to: &str| {
        let block = &text[text.find(&format!("id: {id}")).unwrap()..];
        text.replacen(block, &block.replacen(from, to, 1), 1)
    };
    let text = paper::Texts::BUILT_IN.claims;
    let (part, tally) = run(text);
    assert_eq!(
        part,
        Some(Verdict::DependsOn {
            choice: super::fall::SLIDES
        })
    );
    assert_eq!(
        (tally.fails, tally.parts, tally.depends),
        (1, 0, 1),
        "{tally:?}"
    );
    let part_at_30 = edit(
        text,
        "positive-b-unstable-large-tilt",
        "claimed_value: 60",
        "claimed_value: 30",
    );
    let (part, tally) = run(&part_at_30);
    assert_eq!(
        part,
        Some(Verdict::PartOf {
            claim: "bracket-negative-angle"
        })
    );
    assert_eq!((tally.fails, tally.parts), (1, 1), "{tally:?}");
    let edited = edit(
        &part_at_30,
        "bracket-negative-angle",
        "claimed_value: 60",
        "claimed_value: 52",
    );
    let (part, tally) = run(&edited);
    assert_eq!(
        part,
        Some(Verdict::Fails),
        "the bracket's claim passes at 52"
    );
    assert_eq!((tally.fails, tally.parts), (1, 0), "{tally:?}");
}

#[test]
fn a_part_of_an_unknown_claim_is_refused_naming_the_key() {
    let text = paper::Texts::BUILT_IN.claims.replace(
        "part_of: bracket-negative-angle",
        "part_of: bracket-negative-angles",
    );
    let Err(e) = paper_with_claims(&text) else {
        panic!("a part of no claim must be refused")
    };
    let msg = e.to_string();
    assert!(
        msg.contains("positive-b-unstable-large-tilt") && msg.contains("`part_of`"),
        "{msg}"
    );
}
