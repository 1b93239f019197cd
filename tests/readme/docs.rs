//! The numbers of `docs/` are the tool's: each is read back from the text and compared with the
//! files the tool stores (`snapshots/coverage.json`, `snapshots/model_choice.json`) or with what it
//! prints (`scenes --show`, its refusals of values beyond a limit, `--help`). The links of the
//! README and `docs/` lead somewhere, and they hold no development history.

use super::written::{
    agrees, built_in_scene, count_before, is_date, number_after, prose, range_after, raw, refusal,
    row, tool, ROOT,
};
use serde_json::Value;

#[test]
fn the_coverage_table_is_the_stored_studies() {
    let doc = raw("docs/experiment.md");
    let stored: Value =
        serde_json::from_str(&raw("snapshots/coverage.json")).expect("snapshots/coverage.json");
    let studies = stored.as_array().expect("the stored studies");
    assert!(!studies.is_empty(), "no stored coverage study");
    for study in studies {
        let name = study["recordings"].as_str().expect("the study's name");
        let c = &study["coverage"];
        let line = row(&doc, name);
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        assert_eq!(cells.len(), 10, "a row of eight cells: {line}");
        let runs = c["runs"].as_u64().expect("runs");
        let inside = |key: &str, z: f64| {
            c[key]
                .as_array()
                .expect("the stored pulls")
                .iter()
                .filter(|p| p.as_f64().is_some_and(|p| p.abs() <= z))
                .count() as u64
        };
        assert_eq!(cells[2].parse::<u64>().ok(), Some(runs), "{name}: runs");
        assert_eq!(
            cells[3].parse::<u64>().ok(),
            c["refused"].as_u64(),
            "{name}: refused"
        );
        for (cell, key, z) in [
            (cells[4], "beta_pulls", 1.0),
            (cells[5], "beta_pulls", 1.96),
            (cells[6], "t0_pulls", 1.0),
            (cells[7], "t0_pulls", 1.96),
        ] {
            let n = inside(key, z);
            let (count, percent) = cell
                .split_once(" (")
                .unwrap_or_else(|| panic!("{name}: a cell 'N (P %)': {cell}"));
            assert_eq!(
                count.parse::<u64>().ok(),
                Some(n),
                "{name}: {key} within {z}"
            );
            let percent = percent.trim_end_matches(" %)");
            assert!(
                agrees(percent, 100.0 * n as f64 / runs as f64),
                "{name}: {key} within {z}: {percent} % against {n} of {runs}"
            );
        }
        assert_eq!(
            cells[8].parse::<u64>().ok(),
            c["law_drifts"].as_u64(),
            "{name}: law drifts"
        );
    }
}

#[test]
fn the_model_choice_counts_are_the_stored_ones() {
    let doc = prose("docs/experiment.md");
    let stored: Value = serde_json::from_str(&raw("snapshots/model_choice.json"))
        .expect("snapshots/model_choice.json");
    let outcomes = stored["outcomes"].as_array().expect("the stored outcomes");
    let analysed: Vec<&Value> = outcomes.iter().filter(|o| o["refused"].is_null()).collect();
    let preferred = analysed
        .iter()
        .filter(|o| o["two_over_single"].as_f64().is_some_and(|d| d > 0.0))
        .count();
    let called = analysed
        .iter()
        .filter(|o| o["called_two"].as_bool() == Some(true))
        .count();
    let written = |words: &str| count_before(&doc, words).map(|n| n as usize);
    assert_eq!(
        written(" recordings of one mechanism,"),
        Some(outcomes.len()),
        "recordings"
    );
    assert_eq!(
        written(" are refused as no spin-down"),
        Some(outcomes.len() - analysed.len()),
        "refused"
    );
    assert_eq!(
        written(" of the analysed ones"),
        Some(preferred),
        "preferred by BIC"
    );
    assert_eq!(
        number_after(&doc, "calls two mechanisms on ").and_then(|n| n.parse::<usize>().ok()),
        Some(called),
        "called two mechanisms"
    );
}

#[test]
fn the_limits_written_are_the_tools() {
    let doc = raw("docs/limits.md");
    let nutating = built_in_scene("nutating-coin");
    let disk = row(&doc, "disk");
    for (key, written) in [
        ("radius", "radius: 0.01213"),
        ("mass", "mass: 0.00567"),
        ("g", "g: 9.81"),
        ("k", "k: 0.25"),
    ] {
        let (lo, hi) = range_after(disk, &format!(" {key} "))
            .unwrap_or_else(|| panic!("docs/limits.md: no range for {key}"));
        assert!(nutating.contains(written), "nutating-coin has {written}");
        let beyond = nutating.replace(written, &format!("{key}: {:.1e}", hi * 10.0));
        let err = refusal(key, &beyond);
        assert_eq!(
            range_after(&err, "supported range "),
            Some((lo, hi)),
            "docs/limits.md's range of {key} against the tool's refusal: {err}"
        );
    }
    let mib = count_before(row(&doc, "scene file"), " MiB").expect("the scene file's limit");
    let limit = mib << 20;
    let big = format!("{nutating}{}", "#\n".repeat(limit as usize / 2 + 1));
    let err = refusal("size", &big);
    assert_eq!(
        number_after(&err, "limit of ").map(|n| n.replace(',', "")),
        Some(limit.to_string()),
        "docs/limits.md's scene size against the tool's refusal: {err}"
    );
    let rows = number_after(row(&doc, "recorded rows"), "at most ")
        .expect("the limit on rows")
        .replace(',', "");
    assert!(
        nutating.contains("sample: 0.0005"),
        "nutating-coin's sample"
    );
    let err = refusal(
        "rows",
        &nutating.replace("sample: 0.0005", "sample: 1.0e-10"),
    );
    assert_eq!(
        number_after(&err, "more than the limit of ").map(|n| n.replace(',', "")),
        Some(rows),
        "docs/limits.md's rows against the tool's refusal: {err}"
    );
    let (least, most) =
        range_after(row(&doc, "solver"), "`max_steps` ").expect("max_steps's range");
    let solver = "solver: { method: dop853, rtol: 1.0e-10, atol: 1.0e-12 }";
    assert!(nutating.contains(solver), "nutating-coin's solver");
    let asked = solver.replace(" }", &format!(", max_steps: {:.0} }}", most * 10.0));
    let err = refusal("steps", &nutating.replace(solver, &asked));
    assert_eq!(
        range_after(&err, "max_steps must lie between "),
        Some((least, most)),
        "docs/limits.md's max_steps against the tool's refusal: {err}"
    );
    let rtol = range_after(row(&doc, "solver"), "rtol strictly between ").expect("rtol's bounds");
    let err = refusal("rtol", &nutating.replace("rtol: 1.0e-10", "rtol: 1.0"));
    assert_eq!(
        range_after(&err, "rtol must lie strictly between "),
        Some(rtol),
        "docs/limits.md's rtol bounds against the tool's refusal: {err}"
    );
    let seconds =
        count_before(row(&doc, "wall time"), " s per integration").expect("the wall-time budget");
    let out = tool(&["--help"]);
    let help = String::from_utf8_lossy(&out.stdout);
    let at = help
        .find("--max-seconds")
        .expect("--help names --max-seconds");
    let rest = &help[at..];
    let default = rest
        .find("default")
        .map(|i| {
            rest[i + "default".len()..].trim_start_matches(|c: char| c == ':' || c.is_whitespace())
        })
        .and_then(|d| d.split(|c: char| !c.is_ascii_digit()).next())
        .and_then(|d| d.parse::<u64>().ok());
    assert_eq!(
        default,
        Some(seconds),
        "docs/limits.md's wall time against --help: {help}"
    );
}

#[test]
fn the_scenes_in_the_docs_are_the_built_in_ones() {
    let fence = "```yaml\nname: ";
    let mut shown = 0;
    for file in markdown_files() {
        let doc = raw(&file);
        for (at, _) in doc.match_indices(fence) {
            let start = at + "```yaml\n".len();
            let end = start + doc[start..].find("```").expect("the end of the example");
            let name = doc[start + "name: ".len()..]
                .lines()
                .next()
                .expect("the scene's name")
                .trim();
            assert_eq!(
                &doc[start..end],
                built_in_scene(name),
                "{file}'s scene {name} against scenes --show {name}"
            );
            shown += 1;
        }
    }
    assert!(shown > 0, "no scene shown in docs/");
}

/// The README and every Markdown file of `docs/`.
fn markdown_files() -> Vec<String> {
    let mut files = vec!["README.md".to_string()];
    for entry in std::fs::read_dir(format!("{ROOT}/docs")).expect("docs/") {
        let name = entry
            .expect("an entry of docs/")
            .file_name()
            .into_string()
            .expect("a UTF-8 name");
        if name.ends_with(".md") {
            files.push(format!("docs/{name}"));
        }
    }
    files.sort();
    files
}

#[test]
fn the_links_lead_somewhere_and_no_history_is_written() {
    let files = markdown_files();
    assert!(files.len() > 1, "no docs/*.md");
    for file in &files {
        let text = raw(file);
        let dir = if file.starts_with("docs/") {
            "docs/"
        } else {
            ""
        };
        for (i, _) in text.match_indices("](") {
            let target = &text[i + 2..];
            let target = &target[..target.find(')').expect("a closing parenthesis")];
            if target.starts_with("http") {
                continue;
            }
            let path = target.split('#').next().unwrap_or(target);
            assert!(
                std::path::Path::new(&format!("{ROOT}/{dir}{path}")).exists(),
                "{file} links to {target}, which does not exist"
            );
        }
        let lower = text.to_lowercase();
        for (i, _) in lower.match_indices("issue ") {
            assert!(
                !lower[i + "issue ".len()..].starts_with(|c: char| c.is_ascii_digit()),
                "{file} names an issue number"
            );
        }
        assert!(
            !text.as_bytes().windows(10).any(is_date),
            "{file} holds a date"
        );
    }
}
