//! `check --paper DIR` as an author uses it: the claims read from an edited copy of the paper's
//! LaTeX, with no rebuild. A correction of a wrong equation makes it hold and says what follows
//! for the equations derived from it; a sign changed in a correct equation fails that equation
//! alone; an unchanged copy gives the built-in verdicts.

use checks::cause::Cause;
use checks::check::{run_checks, Selection, Subject};
use checks::equations::{equations, Bench};
use checks::finding::Verdict;
use paper::{Paper, PaperSource, Texts};

const EQUATIONS: &str = Texts::BUILT_IN.equations;
const CLAIMS: &str = Texts::BUILT_IN.claims;

fn paper(equations: &str) -> Paper {
    let texts = Texts {
        equations,
        ..Texts::BUILT_IN
    };
    Paper::from_texts(PaperSource::BuiltIn, texts).unwrap()
}

fn verdicts(p: &Paper, numbers: &[u32]) -> Vec<(u32, Verdict)> {
    let bench = Bench::with_paper(p);
    equations()
        .into_iter()
        .filter(|e| numbers.contains(&e.number))
        .map(|e| (e.number, (e.check)(&bench).verdict))
        .collect()
}

fn passes(v: &[(u32, Verdict)], n: u32) -> bool {
    v.iter().any(|(m, verdict)| *m == n && verdict.passes())
}

const EQ76: &str =
    r"\dot{\alpha} = - \frac{2 \epsilon}{5} \Omega^{\beta} \approx - \frac{2 \epsilon}{5}";

/// The causes `run_checks` gives to the selected equations of a paper.
fn causes(p: &Paper, numbers: &[u32]) -> Vec<(u32, bool, Option<Cause>)> {
    let bench = Bench::with_paper(p);
    let selection = Selection {
        numbers: Some(numbers.to_vec()),
        claims: Some(Vec::new()),
    };
    run_checks(&bench, &selection, 2, &|_, _| {})
        .unwrap()
        .into_iter()
        .filter_map(|c| match c.subject {
            Subject::Equation { number, .. } => Some((
                number,
                c.finding.as_ref().is_ok_and(|f| f.verdict.passes()),
                c.cause,
            )),
            Subject::Claim { .. } => None,
        })
        .collect()
}

fn root(v: &[(u32, bool, Option<Cause>)], n: u32) -> bool {
    v.iter()
        .any(|(m, _, c)| *m == n && matches!(c, Some(Cause::RootCause { .. })))
}

fn inherits_from(v: &[(u32, bool, Option<Cause>)], n: u32, roots: &[u32]) -> bool {
    v.iter().any(|(m, _, c)| {
        *m == n && matches!(c, Some(Cause::Inherits { roots: r, .. }) if r == roots)
    })
}

#[test]
fn correcting_eq_76_makes_it_hold_and_shows_what_follows() {
    let sec11 = [76, 77, 78, 79, 84];
    let printed = verdicts(&paper(EQUATIONS), &sec11);
    for n in sec11 {
        assert!(!passes(&printed, n), "eq {n} as printed: {printed:?}");
    }
    let c = causes(&paper(EQUATIONS), &sec11);
    for n in sec11 {
        assert!(inherits_from(&c, n, &[73]), "eq {n}: {c:?}");
    }

    // Only eq 76 corrected: it holds; eq 77 still fails, and is now the root cause (it no longer
    // follows from the eq 76 it cites); 78, 79 and 84 follow from 77 and inherit its error.
    assert!(EQUATIONS.contains(EQ76));
    let only76 = EQUATIONS.replace(EQ76, &EQ76.replace("{5}", "{3}"));
    let v = verdicts(&paper(&only76), &sec11);
    assert!(passes(&v, 76), "{v:?}");
    let c = causes(&paper(&only76), &sec11);
    assert!(root(&c, 77), "eq 77 should be the root cause now: {c:?}");
    for n in [78, 79, 84] {
        assert!(!passes(&v, n), "eq {n} should still fail: {v:?}");
        assert!(inherits_from(&c, n, &[77]), "eq {n}: {c:?}");
    }

    // The chain corrected: every one of them holds.
    let all = only76
        .replace(
            r"\frac{\epsilon (\beta + 2)}{5}",
            r"\frac{\epsilon (\beta + 2)}{3}",
        )
        .replace(r"\frac{5 g / \epsilon", r"\frac{3 g / \epsilon");
    let v = verdicts(&paper(&all), &sec11);
    for n in sec11 {
        assert!(passes(&v, n), "eq {n}: {v:?}");
    }
}

#[test]
fn a_sign_changed_in_a_correct_equation_fails_that_equation_alone() {
    // Eq 24: + (2k + 1) omega_1 ... becomes - (2k + 1) omega_1 ...
    let from = r"k \Omega^2 \sin\alpha \cos\alpha + (2k + 1) \omega_1";
    assert!(EQUATIONS.contains(from));
    let edited = EQUATIONS.replace(
        from,
        r"k \Omega^2 \sin\alpha \cos\alpha - (2k + 1) \omega_1",
    );
    let around = [22, 23, 24, 25, 26, 27, 61];
    let before = verdicts(&paper(EQUATIONS), &around);
    let after = verdicts(&paper(&edited), &around);
    for ((n, b), (_, a)) in before.iter().zip(&after) {
        if *n == 24 {
            assert_eq!(*a, Verdict::Fails, "eq 24 after the edit");
        } else {
            assert_eq!(a, b, "eq {n} changed with eq 24's sign");
        }
    }
}

#[test]
fn an_unchanged_copy_gives_the_built_in_verdicts() {
    let numbers: Vec<u32> = (1..=85).collect();
    let copy = paper(EQUATIONS);
    let a = verdicts(&copy, &numbers);
    let b: Vec<(u32, Verdict)> = equations()
        .into_iter()
        .map(|e| (e.number, (e.check)(&Bench::default()).verdict))
        .collect();
    assert_eq!(a, b);
}

/// The claim checks of an edited claims.yaml: one whose claim lost the `rule` its check judges
/// by, and one whose claim was deleted, are reported as checks that could not run, each naming
/// what to add; the others run as before.
#[test]
fn a_claim_missing_its_rule_or_its_entry_cannot_run_and_says_what_to_add() {
    let rule = "  rule: { words: about, within: 0.05 }\n";
    // The first claim with this rule is positive-b-unstable-large-tilt's.
    let first = CLAIMS.find(rule).unwrap();
    let owner = CLAIMS[..first].rfind("- id: ").unwrap();
    assert!(CLAIMS[owner..].starts_with("- id: positive-b-unstable-large-tilt"));
    let no_rule = CLAIMS.replacen(rule, "", 1);
    let start = CLAIMS.find("- id: k-rim-disk").unwrap();
    let end = start + CLAIMS[start..].find("\n\n").unwrap() + 2;
    let edited = format!("{}{}", &no_rule[..start], &no_rule[end..]);
    assert!(!edited.contains("k-rim-disk"));
    let p = Paper::from_texts(
        PaperSource::BuiltIn,
        Texts {
            claims: &edited,
            ..Texts::BUILT_IN
        },
    )
    .unwrap();
    let bench = Bench::with_paper(&p);
    let selection = Selection {
        numbers: Some(Vec::new()),
        claims: Some(vec![
            "positive-b-unstable-large-tilt".into(),
            "k-rim-disk".into(),
            "k-uniform-disk".into(),
        ]),
    };
    let checked = run_checks(&bench, &selection, 1, &|_, _| {}).unwrap();
    let outcome = |id: &str| {
        checked
            .iter()
            .find(|c| matches!(&c.subject, Subject::Claim { id: i } if i == id))
            .map(|c| c.finding.clone())
            .unwrap()
    };
    let e = outcome("positive-b-unstable-large-tilt").unwrap_err();
    assert!(
        e.contains("positive-b-unstable-large-tilt") && e.contains("add a `rule`"),
        "{e}"
    );
    let e = outcome("k-rim-disk").unwrap_err();
    assert!(e.contains("has no claim `k-rim-disk`"), "{e}");
    assert!(outcome("k-uniform-disk").unwrap().verdict.passes());

    // A reading added to a claim whose check makes its own comparison would be shown and not
    // applied: refused.
    let start = CLAIMS.find("- id: k-uniform-disk").unwrap();
    let end = start + CLAIMS[start..].find("\n\n").unwrap();
    let with_rule = format!(
        "{}\n  rule: {{ words: about, within: 0.1 }}{}",
        &CLAIMS[..end],
        &CLAIMS[end..]
    );
    let p = Paper::from_texts(
        PaperSource::BuiltIn,
        Texts {
            claims: &with_rule,
            ..Texts::BUILT_IN
        },
    )
    .unwrap();
    let bench = Bench::with_paper(&p);
    let selection = Selection {
        numbers: Some(Vec::new()),
        claims: Some(vec!["k-uniform-disk".into()]),
    };
    let checked = run_checks(&bench, &selection, 1, &|_, _| {}).unwrap();
    let e = checked[0].finding.clone().unwrap_err();
    assert!(
        e.contains("k-uniform-disk") && e.contains("reads no `rule`"),
        "{e}"
    );
}

/// `report --paper DIR` with eq 76's 5 made a 3: the HTML (its MathML's LaTeX annotation), the
/// LaTeX and the JSON all show the edited equation, and none shows the printed one. The
/// corrections of the built-in paper are read from the same directory, so the printed form of
/// eq 76 appears nowhere.
#[test]
fn a_report_on_an_edited_paper_shows_the_edit_everywhere() {
    let printed = r"\frac{2 \epsilon}{5}";
    let edited = r"\frac{2 \epsilon}{3}";
    assert_eq!(
        EQUATIONS.matches(printed).count(),
        2,
        "eq 76 prints it twice"
    );
    let root = std::env::temp_dir().join(format!("rolling-disk-edited-{}", std::process::id()));
    let dir = root.join("paper");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(
        dir.join("equations.yaml"),
        EQUATIONS.replace(printed, edited),
    )
    .unwrap();
    let out = root.join("report");
    let status = std::process::Command::new(env!("CARGO_BIN_EXE_rolling-disk"))
        .args(["report", "--format", "all", "--paper"])
        .arg(&dir)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    assert!(
        status.status.success(),
        "{}",
        String::from_utf8_lossy(&status.stderr)
    );
    let read = |f: &str| std::fs::read_to_string(out.join(f)).unwrap();
    let (html, tex) = (read("report.html"), read("report.tex"));
    let json: serde_json::Value = serde_json::from_str(&read("report.json")).unwrap();
    let mut strings = Vec::new();
    collect_strings(&json, &mut strings);
    let in_json = |needle: &str| strings.iter().filter(|s| s.contains(needle)).count();
    std::fs::remove_dir_all(&root).unwrap();
    for (what, printed_seen, edited_seen) in [
        (
            "HTML",
            html.matches(printed).count(),
            html.matches(edited).count(),
        ),
        (
            "LaTeX",
            tex.matches(printed).count(),
            tex.matches(edited).count(),
        ),
        ("JSON", in_json(printed), in_json(edited)),
    ] {
        assert_eq!(printed_seen, 0, "{what} shows the printed eq 76");
        assert!(edited_seen > 0, "{what} does not show the edited eq 76");
    }
    assert_eq!(json["paper"]["source"].as_str(), dir.to_str());
}

fn collect_strings(v: &serde_json::Value, out: &mut Vec<String>) {
    match v {
        serde_json::Value::String(s) => out.push(s.clone()),
        serde_json::Value::Array(a) => a.iter().for_each(|x| collect_strings(x, out)),
        serde_json::Value::Object(o) => o.values().for_each(|x| collect_strings(x, out)),
        _ => {}
    }
}
