//! `--json` on `simulate` and `scenes`: each document follows its published schema
//! (`schemas/simulate.schema.json`, `schemas/scenes.schema.json`), and says what the text
//! output says.

use crate::common::{cli_status, last_row, temp_dir};
use serde_json::Value;

fn schema(name: &str) -> Value {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("schemas")
        .join(name);
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn valid(schema_file: &str, doc: &Value) {
    let validator = jsonschema::validator_for(&schema(schema_file)).unwrap();
    let errors: Vec<String> = validator.iter_errors(doc).map(|e| e.to_string()).collect();
    assert!(errors.is_empty(), "{schema_file}: {errors:?}\n{doc}");
}

#[test]
fn simulate_json_follows_its_schema_and_says_what_the_summary_says() {
    let dir = temp_dir("json", "simulate");
    let (code, json, err) = cli_status(&dir, &["simulate", "nutating-coin", "--json"]);
    assert_eq!(code, 0, "{err}");
    let doc: Value = serde_json::from_str(&json).expect("stdout is one JSON document");
    valid("simulate.schema.json", &doc);
    let (code, text, err) = cli_status(&dir, &["simulate", "nutating-coin", "--csv", "run.csv"]);
    assert_eq!(code, 0, "{err}");
    let csv = std::fs::read_to_string(dir.join("run.csv")).unwrap();
    assert_eq!(doc["rows"].as_u64(), Some(csv.lines().count() as u64 - 1));
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    assert_eq!(doc["columns"], serde_json::json!(header));
    let last = last_row(&csv);
    assert_eq!(doc["stop"]["t"].as_f64(), Some(last[0]));
    assert_eq!(doc["stop"]["complete"], true);
    assert!(
        text.contains(&format!(
            "ended       {}",
            doc["stop"]["reason"].as_str().unwrap()
        )),
        "{text}"
    );
    let alpha = doc["final"]["alpha"].as_f64().unwrap();
    assert!(text.contains(&format!("alpha = {alpha:.12} rad")), "{text}");
    assert_eq!(doc["events"].as_array().map(Vec::len), Some(0));
    assert_eq!(doc["scene"]["source"], "builtin:nutating-coin");

    // The sliding model's events are listed as the text lists them.
    let (code, json, err) = cli_status(&dir, &["simulate", "coin-bounce", "--json"]);
    assert_eq!(code, 0, "{err}");
    let doc: Value = serde_json::from_str(&json).unwrap();
    valid("simulate.schema.json", &doc);
    let (_, text, _) = cli_status(&dir, &["simulate", "coin-bounce"]);
    let n = doc["events"].as_array().unwrap().len();
    assert!(
        text.contains(&format!("contact     {n} switches and impacts")),
        "{text}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn scenes_json_follows_its_schema_and_lists_every_scene() {
    let dir = temp_dir("json", "scenes");
    let (code, json, err) = cli_status(&dir, &["scenes", "--json"]);
    assert_eq!(code, 0, "{err}");
    let doc: Value = serde_json::from_str(&json).unwrap();
    valid("scenes.schema.json", &doc);
    let (_, table, _) = cli_status(&dir, &["scenes"]);
    let names: Vec<&str> = table
        .lines()
        .map(|l| l.split_whitespace().next().unwrap())
        .collect();
    let listed: Vec<&str> = doc["scenes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["name"].as_str().unwrap())
        .collect();
    assert_eq!(listed, names);
    assert_eq!(listed.len(), physics::scene::builtin::BUILTIN.len());
    for s in doc["scenes"].as_array().unwrap() {
        let line = table
            .lines()
            .find(|l| l.split_whitespace().next() == s["name"].as_str())
            .unwrap();
        let first = s["description"]
            .as_str()
            .unwrap()
            .split(". ")
            .next()
            .unwrap();
        assert!(line.contains(first.trim()), "{line} / {first}");
    }
    // A schema that a wrong document fails: the test can fail.
    let mut wrong = doc.clone();
    wrong["scenes"][0]["name"] = Value::from(3);
    let validator = jsonschema::validator_for(&schema("scenes.schema.json")).unwrap();
    assert!(!validator.is_valid(&wrong));
    let _ = std::fs::remove_dir_all(&dir);
}
