//! The registry of checks against the catalogue, and the mutation sweep: every check must fail
//! when the paper's claimed side is perturbed by a relative 1e-3, in either direction.

use checks::equations::claims::{catalogued, mutation_moves};
use checks::equations::{claims, equations, from_latex, Bench};
use checks::finding::Verdict;
use paper::Paper;

#[test]
fn registered_checks_match_the_catalogue() {
    let cat: Vec<_> = Paper::built_in_shared()
        .equations
        .iter()
        .map(|e| &e.entry)
        .collect();
    let eqs = equations();
    let mut numbers: Vec<u32> = eqs.iter().map(|e| e.number).collect();
    numbers.dedup();
    assert_eq!(numbers.len(), eqs.len(), "an equation has two checks");
    for e in &eqs {
        let entry = &cat[e.number as usize - 1];
        assert_eq!(entry.label, e.label, "eq {}: label", e.number);
    }
    let ids: Vec<&str> = Paper::built_in_shared()
        .claims
        .iter()
        .map(|c| c.id.as_str())
        .collect();
    let checked = claims();
    for c in &checked {
        assert!(
            ids.contains(&c.id),
            "claim {} is not in paper/claims.yaml",
            c.id
        );
    }
    eprintln!(
        "{} of 85 equations and {} of {} claims have checks",
        eqs.len(),
        checked.len(),
        ids.len()
    );
}

#[test]
fn every_check_fails_when_its_claim_is_perturbed() {
    let mut survivors = Vec::new();
    for p in [1e-3, -1e-3] {
        let bench = Bench::perturbed(p);
        // Equations read from the LaTeX are mutated in their text instead (tests/mutation.rs).
        for e in equations()
            .into_iter()
            .filter(|e| !from_latex().contains(&e.number))
        {
            let f = (e.check)(&bench);
            if f.verdict != Verdict::Fails {
                survivors.push(format!(
                    "eq {} under {p:+e}: {} ({})",
                    e.number, f.verdict, f.at
                ));
            }
        }
    }
    // A claim's printed number: moved by 1e-3, or beyond a loose reading that holds
    // (`mutation_moves`).
    for c in claims() {
        let holds = (c.check)(&Bench::default()).verdict.passes();
        let rule = Paper::built_in_shared()
            .claims
            .iter()
            .find(|k| k.id == c.id)
            .and_then(|k| k.rule.as_ref());
        for p in mutation_moves(rule, holds) {
            let f = (c.check)(&Bench::perturbed(p));
            // A verdict that depends on a choice is judged under the reading it was made in.
            if f.as_read() != Verdict::Fails {
                survivors.push(format!("{} under {p:+e}: {}", c.id, f.verdict));
            }
        }
    }
    // A claim naming a quantity of the catalogue: its printed number moved in the same way.
    for c in Paper::built_in_shared().claims.iter() {
        if c.quantity.named().is_none() {
            continue;
        }
        let holds = catalogued(&Bench::default(), &c.id).verdict.passes();
        for p in mutation_moves(c.rule.as_ref(), holds) {
            let f = catalogued(&Bench::perturbed(p), &c.id);
            if f.as_read() != Verdict::Fails {
                survivors.push(format!("{} under {p:+e}: {}", c.id, f.verdict));
            }
        }
    }
    assert!(
        survivors.is_empty(),
        "checks that cannot fail:\n{}",
        survivors.join("\n")
    );
}

#[test]
fn every_equation_and_claim_is_checked_or_says_why_not() {
    use checks::equations::{UNCHECKABLE_CLAIMS, UNCHECKABLE_EQUATIONS};
    let eqs = equations();
    for n in 1..=85u32 {
        let checked = eqs.iter().filter(|e| e.number == n).count();
        let excused = UNCHECKABLE_EQUATIONS.iter().any(|(m, _)| *m == n);
        assert!(
            (checked == 1) != excused,
            "eq {n}: {checked} check(s), excused: {excused} (exactly one of the two)"
        );
    }
    let checked = claims();
    for c in &Paper::built_in_shared().claims {
        // A check written in Rust, or the catalogue's quantity the claim names.
        let has = checked.iter().filter(|k| k.id == c.id).count()
            + usize::from(c.quantity.named().is_some());
        let excused = UNCHECKABLE_CLAIMS.iter().any(|(id, _)| *id == c.id);
        assert!(
            (has == 1) != excused,
            "claim {}: {has} check(s), excused: {excused}",
            c.id
        );
    }
}

/// A printed inequality that can be evaluated and points the wrong way is a failure with its
/// explanation, never a check that could not run: `check --paper DIR` with eq 30's `>`
/// reversed reports eq 30 as failing and exits 0.
#[test]
fn a_reversed_inequality_fails_and_says_why() {
    let dir = crate::common::temp_dir("registry", "reversed-30");
    let printed = "latex: 'b > - \\frac{a k \\cos\\alpha_0}{2k + 1}'";
    let yaml = paper::Texts::BUILT_IN.equations;
    assert!(yaml.contains(printed), "eq 30 as printed");
    let reversed = yaml.replacen(printed, &printed.replacen(" > ", " < ", 1), 1);
    std::fs::write(dir.join("equations.yaml"), reversed).unwrap();
    let (ok, out, err) =
        crate::common::cli_in(&dir, &["check", "--paper", ".", "--only", "30", "--json"]);
    assert!(ok, "exit status: {err}");
    let doc: serde_json::Value = serde_json::from_str(&out).unwrap();
    let eq30 = doc["checks"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["equation"] == 30)
        .expect("eq 30 in check --json");
    let outcome = &eq30["outcome"];
    assert_eq!(outcome["status"], "checked", "{outcome}");
    assert_eq!(outcome["verdict"], "fails", "{outcome}");
    let at = outcome["at"].as_str().unwrap();
    assert!(
        at.contains("the printed inequality holds below the edge and fails above it"),
        "{at}"
    );
    assert!(
        outcome["error"].as_f64().is_some_and(f64::is_finite),
        "{outcome}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Every outcome of `check --json` that does not establish what it checks (any verdict but
/// holds, holds approximately and definition) carries the verdicts under at least two readings
/// of the choices it rests on and says whether it is robust: robust exactly when no reading's
/// verdict is of another kind than the verdict as read (the first entry), and a verdict that
/// depends on a choice names the choice of a reading that changes it. The set is the output's,
/// not a list.
#[test]
fn every_verdict_but_a_pass_says_how_it_fares_under_the_papers_open_choices() {
    let (ok, out, err) = crate::common::cli_in(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")),
        &["check", "--json"],
    );
    assert!(ok, "check --json: {err}");
    let doc: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let kind = |v: &str| match v {
        "holds" | "holds_approximately" | "definition" | "estimate" => "passes",
        "premise_fails" => "premise",
        _ => "fails",
    };
    let mut seen = 0;
    let mut depends = 0;
    for c in doc["checks"].as_array().expect("checks") {
        let outcome = &c["outcome"];
        let Some(verdict) = outcome["verdict"].as_str() else {
            continue;
        };
        if matches!(verdict, "holds" | "holds_approximately" | "definition") {
            continue;
        }
        let name = &c["name"];
        let readings = outcome["robustness"]
            .as_array()
            .unwrap_or_else(|| panic!("{name} ({verdict}) has no robustness"));
        assert!(readings.len() >= 2, "{name}: {readings:?}");
        let robust = outcome["robust"]
            .as_bool()
            .unwrap_or_else(|| panic!("{name} does not say whether it is robust"));
        let as_read = readings[0]["verdict"].as_str().expect("a verdict");
        let changed: Vec<&serde_json::Value> = readings
            .iter()
            .filter(|a| kind(a["verdict"].as_str().unwrap_or("")) != kind(as_read))
            .collect();
        assert_eq!(robust, changed.is_empty(), "{name}: {readings:?}");
        assert_eq!(robust, verdict != "depends", "{name}");
        if verdict == "depends" {
            depends += 1;
            assert_eq!(
                outcome["depends_on"], changed[0]["choice"],
                "{name} names the choice that changes it"
            );
        } else {
            assert_eq!(kind(verdict), kind(as_read), "{name}");
        }
        for a in readings {
            assert!(
                a["choice"].as_str().is_some_and(|s| !s.is_empty())
                    && a["alternative"].as_str().is_some_and(|s| !s.is_empty())
                    && a["reference"].as_f64().is_some_and(f64::is_finite),
                "{name}: {a}"
            );
        }
        seen += 1;
    }
    assert!(seen > 0, "no outcome other than a pass");
    let counted: u64 = ["equations", "claims"]
        .iter()
        .map(|g| doc["summary"][g]["depends"].as_u64().expect("a count"))
        .sum();
    assert_eq!(counted, depends, "the summary counts the depends apart");
}
