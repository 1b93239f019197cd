//! A claim about a quantity the tool already computes is one entry of claims.yaml, with no Rust
//! and no rebuild: `check --paper DIR` checks it with a verdict and numbers, a wrong printed
//! number fails, a wrong name is refused where it stands, and the report records the same
//! outcome as `check`.

use checks::check::{run_checks, Selection};
use checks::equations::Bench;
use std::path::{Path, PathBuf};

const ID: &str = "rising-spin-threshold-uniform";

/// The claim, as an author adds it: sec. 10's premise that a uniform disk sleeps upright without
/// friction above sqrt(g/(a k)) = 2 sqrt(g/a).
fn entry(printed: &str) -> String {
    format!(
        "
- id: {ID}
  section: 10
  near_equation: 65
  claim: \"A uniform disk spinning about a vertical diameter sleeps without friction above sqrt(g/(a k)), 2 sqrt(g/a).\"
  claimed_value: {printed}
  unit: sqrt(g/a)
  quantity: {{ name: vertical-spin-threshold, contact: frictionless, k: 0.25 }}
"
    )
}

/// A copy of paper/ whose claims.yaml has `extra` appended.
fn paper_dir(tag: &str, extra: &str) -> PathBuf {
    let dir = crate::common::temp_dir("claims_yaml", tag);
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("paper");
    for name in [
        "equations.yaml",
        "symbols.yaml",
        "claims.yaml",
        "corrections.yaml",
    ] {
        std::fs::copy(root.join(name), dir.join(name)).unwrap();
    }
    let claims = std::fs::read_to_string(dir.join("claims.yaml")).unwrap();
    std::fs::write(dir.join("claims.yaml"), claims + extra).unwrap();
    dir
}

/// `check --paper DIR --only ID --json`'s record of the claim.
fn checked(dir: &Path) -> serde_json::Value {
    checked_as(dir, ID)
}

/// `check --paper DIR --only id --json`'s record of claim `id`.
fn checked_as(dir: &Path, id: &str) -> serde_json::Value {
    let (ok, out, err) =
        crate::common::cli_in(dir, &["check", "--paper", ".", "--only", id, "--json"]);
    assert!(ok, "check: {err}");
    let doc: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let checks = doc["checks"].as_array().expect("checks");
    assert_eq!(checks.len(), 1, "{checks:?}");
    assert_eq!(checks[0]["claim"], id);
    checks[0].clone()
}

/// The report's record of the claim, from the same paper.
fn reported(dir: &Path) -> serde_json::Value {
    reported_as(dir, ID)
}

/// The report's record of claim `id`, from the same paper.
fn reported_as(dir: &Path, id: &str) -> serde_json::Value {
    let paper = paper::Paper::from_dir(dir).expect("the paper reads");
    let bench = Bench::with_paper(&paper);
    let selection = Selection {
        numbers: Some(Vec::new()),
        claims: Some(vec![id.to_string()]),
    };
    let checked = run_checks(&bench, &selection, 2, &|_, _| {}).expect("runs");
    let settings = report::RunSettings {
        method: "DOP853".into(),
        rtol: bench.rtol,
        command: String::new(),
    };
    let records = report::document::Records {
        corrections: Vec::new(),
        parts: Default::default(),
    };
    let doc = report::document::document(&bench, &checked, None, &settings, &[], records);
    let claim = doc.claims.iter().find(|c| c.id == id).expect("listed");
    serde_json::to_value(&claim.outcome).unwrap()
}

#[test]
fn a_new_claim_in_yaml_is_checked_with_a_verdict_and_numbers() {
    let dir = paper_dir("holds", &entry("2"));
    let c = checked(&dir);
    let outcome = &c["outcome"];
    assert_eq!(outcome["status"], "checked", "{outcome}");
    assert_eq!(outcome["verdict"], "holds", "{outcome}");
    assert_eq!(outcome["claimed"], 2.0, "{outcome}");
    let reference = outcome["reference"].as_f64().unwrap();
    assert!((reference - 2.0).abs() < 1e-10, "{outcome}");
    assert_eq!(outcome["method"], "linearization", "{outcome}");
    assert_eq!(c["section"], 10);
    assert_eq!(reported(&dir), *outcome, "check and report agree");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_wrong_printed_value_fails() {
    let dir = paper_dir("fails", &entry("2.2"));
    let c = checked(&dir);
    let outcome = &c["outcome"];
    assert_eq!(outcome["verdict"], "fails", "{outcome}");
    assert_eq!(outcome["claimed"], 2.2, "{outcome}");
    let reference = outcome["reference"].as_f64().unwrap();
    assert!((reference - 2.0).abs() < 1e-10, "{outcome}");
    assert!(outcome["error"].as_f64().unwrap() > 0.09, "{outcome}");
    assert_eq!(reported(&dir), *outcome, "check and report agree");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_misspelled_quantity_is_refused_with_its_line_and_the_nearest_name() {
    let dir = paper_dir(
        "misspelled",
        &entry("2").replace("vertical-spin-threshold", "vertical-spin-treshold"),
    );
    let lines = std::fs::read_to_string(dir.join("claims.yaml"))
        .unwrap()
        .lines()
        .count();
    let (ok, out, err) = crate::common::cli_in(&dir, &["check", "--paper", ".", "--json"]);
    assert!(!ok, "{out}");
    assert!(out.is_empty(), "nothing written: {out}");
    let wanted = format!(
        "claims.yaml, line {lines}: claim `{ID}`, key `quantity.name`: `vertical-spin-treshold` \
         is not a quantity of the catalogue (did you mean `vertical-spin-threshold`?)"
    );
    assert!(err.contains(&wanted), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Sec. 11's premise read for one drag and one start: the toy disk's least contact force
/// (epsilon = 1.2e-6 s is 1.94087e-5 sqrt(a/g) for a = 37.5 mm), printed to two digits.
const LEAST: &str = "
- id: toy-least-force
  section: 11
  near_equation: 80
  claim: \"From steady rolling at 0.15 rad, the toy disk's contact force falls no lower than 0.83 m g.\"
  claimed_value: PRINTED
  unit: m g
  rule: { words: \"no lower than\", digits: 2 }
  quantity: { name: least-contact-force, k: 0.25, alpha0: 0.15, epsilon: 1.94087e-5 }
";

/// Eq 56's small-tilt limit of the frequency ratio, claimed second order in alpha_0.
const ORDER: &str = "
- id: eq56-order
  section: 7
  near_equation: 56
  claim: \"The frequency ratio tends to sqrt(3k/(k+1)) at order PRINTED in alpha_0.\"
  claimed_value: PRINTED
  unit: order
  quantity: { name: approximation-order, equation: 56, exact: nutation-ratio, k: 0.25 }
";

/// The least F_z over a run, added from a temporary folder: holds at the right value, fails
/// at a planted wrong one; check and report agree.
#[test]
fn a_least_contact_force_claim_holds_and_a_wrong_one_fails() {
    for (printed, verdict) in [("0.83", "holds"), ("0.9", "fails")] {
        let dir = paper_dir(
            &format!("least-{printed}"),
            &LEAST.replace("PRINTED", printed),
        );
        let c = checked_as(&dir, "toy-least-force");
        let outcome = &c["outcome"];
        assert_eq!(outcome["verdict"], verdict, "{outcome}");
        assert_eq!(outcome["method"], "integration", "{outcome}");
        // Read to the printed digits: the computed value is the headline's reference.
        let reference = outcome["headline"]["reference"].as_f64().unwrap();
        assert!((reference - 0.832).abs() < 1e-3, "{outcome}");
        assert_eq!(reported_as(&dir, "toy-least-force"), *outcome);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

/// The order of an approximation, added from a temporary folder: eq 56 is second order in
/// alpha_0; a planted first order fails; check and report agree.
#[test]
fn an_approximation_order_claim_holds_and_a_wrong_one_fails() {
    for (printed, verdict) in [("2", "holds_approximately"), ("1", "fails")] {
        let dir = paper_dir(
            &format!("order-{printed}"),
            &ORDER.replace("PRINTED", printed),
        );
        let c = checked_as(&dir, "eq56-order");
        let outcome = &c["outcome"];
        assert_eq!(outcome["verdict"], verdict, "{outcome}");
        assert_eq!(outcome["method"], "asymptotic", "{outcome}");
        let order = outcome["reference"].as_f64().unwrap();
        assert!((order - 2.0).abs() < 0.05, "{outcome}");
        assert_eq!(reported_as(&dir, "eq56-order"), *outcome);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

/// `rolling-disk quantities` lists the catalogue, as text and as JSON, the same names.
#[test]
fn the_catalogue_is_listed() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let (ok, text, err) = crate::common::cli_in(root, &["quantities"]);
    assert!(ok, "{err}");
    let (ok, json, err) = crate::common::cli_in(root, &["quantities", "--json"]);
    assert!(ok, "{err}");
    let doc: serde_json::Value = serde_json::from_str(&json).unwrap();
    let names: Vec<&str> = doc
        .as_array()
        .unwrap()
        .iter()
        .map(|q| q["name"].as_str().unwrap())
        .collect();
    let catalogue: Vec<&str> = checks::quantities::QUANTITIES
        .iter()
        .map(|q| q.name)
        .collect();
    assert_eq!(names, catalogue);
    for q in doc.as_array().unwrap() {
        let name = q["name"].as_str().unwrap();
        assert!(text.contains(&format!("{name} [{}]", q["unit"].as_str().unwrap())));
        assert!(!q["tolerance"].as_str().unwrap().is_empty(), "{q}");
        assert!(!q["parameters"].as_array().unwrap().is_empty(), "{q}");
    }
}

/// docs/paper-input.md's table of the catalogue is the catalogue: one row per quantity, in its
/// order, with its unit and its parameters.
#[test]
fn the_docs_table_is_the_catalogue() {
    let doc =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/paper-input.md"))
            .unwrap();
    let rows: Vec<Vec<&str>> = doc
        .lines()
        .filter(|l| l.starts_with("| `"))
        .map(|l| l.split(" | ").map(|c| c.trim_matches(['|', ' '])).collect())
        .collect();
    let catalogue = checks::quantities::QUANTITIES;
    assert_eq!(rows.len(), catalogue.len(), "{rows:?}");
    for (row, q) in rows.iter().zip(catalogue) {
        assert_eq!(row[0], format!("`{}`", q.name));
        assert_eq!(row[1], q.unit, "{}", q.name);
        for p in q.parameters {
            assert!(
                row[2].contains(&format!("`{}`", p.name)),
                "{}: {}",
                q.name,
                p.name
            );
        }
    }
}
