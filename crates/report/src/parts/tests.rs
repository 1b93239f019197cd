//! The table of parts is complete: every part's folder, here and in `templates/parts/`, is a
//! registered part, every file of its templates' folder is one of its registered templates, and
//! every registered part renders its section in HTML and in LaTeX and has its record in the
//! published schema.

use super::*;
use std::path::Path;

/// The folders under `dir`, sorted.
fn folders(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .filter_map(Result::ok)
        .filter(|e| e.path().is_dir())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

fn registered() -> Vec<String> {
    let mut names: Vec<String> = PARTS.iter().map(|p| p.name().to_string()).collect();
    names.sort();
    names
}

#[test]
fn every_part_folder_is_a_registered_part() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    assert_eq!(folders(&root.join("src/parts")), registered());
    assert_eq!(folders(&root.join("../../templates/parts")), registered());
}

/// Every file of `templates/parts/NAME/` is one of the part's registered templates (the same
/// text), and every registered paragraph is a template Tera reads.
#[test]
fn every_template_file_of_a_part_is_registered() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../templates/parts");
    for p in PARTS {
        let own = p.templates();
        let mut registered: Vec<(String, &str)> = vec![
            ("section.html.tera".into(), own.html),
            ("section.tex.tera".into(), own.tex),
        ];
        registered.extend(own.text.iter().map(|(n, t)| (format!("{n}.txt.tera"), *t)));
        registered.sort();
        let dir = root.join(p.name());
        let mut files: Vec<(String, String)> = std::fs::read_dir(&dir)
            .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
            .filter_map(Result::ok)
            .map(|e| {
                let name = e.file_name().to_string_lossy().into_owned();
                (name, std::fs::read_to_string(e.path()).unwrap_or_default())
            })
            .collect();
        files.sort();
        let file_names: Vec<&str> = files.iter().map(|f| f.0.as_str()).collect();
        let registered_names: Vec<&str> = registered.iter().map(|f| f.0.as_str()).collect();
        assert_eq!(file_names, registered_names, "{}", p.name());
        for ((file, text), (_, own)) in files.iter().zip(&registered) {
            assert_eq!(text, own, "{}/{file} is not the registered text", p.name());
        }
        for (name, text) in own.text {
            tera::Tera::default()
                .add_raw_template(name, text)
                .unwrap_or_else(|e| panic!("{}/{name}: {e:?}", p.name()));
        }
    }
}

#[test]
fn every_part_has_its_own_name() {
    let mut names = registered();
    names.dedup();
    assert_eq!(names.len(), PARTS.len(), "{names:?}");
    assert!(PARTS.iter().all(|p| part(p.name()).is_some()));
}

/// A part's view with a marked section and one table.
fn marked(name: &str) -> PartView {
    let mut table = StudyTable::new("marker caption", &["marker column"]);
    table.number = 7;
    table.row(vec!["marker cell".into()]);
    PartView {
        name: name.into(),
        contents: None,
        section: StudySection {
            title: "marker title".into(),
            summary: "marker summary".into(),
            tables: vec![table],
            output: "marker output".into(),
            output_title: "marker output title".into(),
        },
        values: BTreeMap::from([("paper_numbers", "marker numbers".to_string())]),
    }
}

#[test]
fn every_registered_part_renders_in_both_formats() {
    for p in PARTS {
        for format in ["html", "tex"] {
            let text = crate::render::part(&marked(p.name()), format)
                .unwrap_or_else(|e| panic!("{} in {format}: {e}", p.name()));
            for marker in ["marker summary", "marker caption", "marker cell"] {
                assert!(
                    text.contains(marker),
                    "{} in {format} lacks {marker:?}:\n{text}",
                    p.name()
                );
            }
        }
        let html = crate::render::part(&marked(p.name()), "html").unwrap();
        assert!(
            html.contains(&format!("id=\"{}\"", p.name())),
            "{} has no anchor of its name",
            p.name()
        );
    }
}

/// The published schema of `report.json` has every registered part's record under `parts`, and
/// nothing else there.
#[test]
fn the_schema_has_every_part_record() {
    let schema: serde_json::Value =
        serde_json::from_str(&crate::json::schema().expect("the schema")).expect("JSON");
    let parts = &schema["$defs"]["PartRecords"]["properties"];
    let mut names: Vec<String> = parts
        .as_object()
        .expect("PartRecords has properties")
        .keys()
        .cloned()
        .collect();
    names.sort();
    assert_eq!(names, registered());
    for (name, record) in parts.as_object().unwrap() {
        assert!(
            record.get("$ref").is_some() || record.get("type").is_some(),
            "part {name}'s record has no schema: {record}"
        );
    }
}
