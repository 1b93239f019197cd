//! The report's tables as a reader meets them: in the HTML each sits in a box of its own that
//! scrolls sideways when the window is narrower than the table; in the LaTeX every table has its
//! own number and link target (numbered as in the HTML, never reset); and the unit misprints are
//! listed apart from the prose claims that fail.

use super::built;

/// The claim ids of `report.json` whose verdict is `verdict`.
fn claims_with(json: &str, verdict: &str) -> Vec<String> {
    let doc: serde_json::Value = serde_json::from_str(json).expect("report.json parses");
    doc["claims"]
        .as_array()
        .expect("report.json has its claims")
        .iter()
        .filter(|c| c["outcome"]["verdict"] == verdict)
        .map(|c| c["id"].as_str().expect("a claim has an id").to_string())
        .collect()
}

/// The text of `doc` from `start` to the next `end` (or to its end), `start` required.
fn between<'a>(doc: &'a str, start: &str, end: &str) -> &'a str {
    let from = doc.find(start).unwrap_or_else(|| panic!("{start} missing"));
    let rest = &doc[from + start.len()..];
    &rest[..rest.find(end).unwrap_or(rest.len())]
}

#[test]
fn every_html_table_scrolls_in_its_own_box() {
    let html = &built().0;
    let mut tables = 0;
    for (at, _) in html.match_indices("<table") {
        tables += 1;
        let tag = &html[at..at + html[at..].find('>').expect("a closed tag")];
        // A finding's small table of numbers is its own scrolling box (display: block).
        let own_box = tag.contains("class=\"numbers\"");
        let wrapped = html[..at].trim_end().ends_with("<div class=\"scroll\">");
        assert!(
            own_box || wrapped,
            "a table outside a scrolling box: {}",
            &html[at.saturating_sub(120)..at + tag.len() + 1]
        );
    }
    assert!(tables > 10, "only {tables} tables");
    let css = between(html, "<style>", "</style>");
    assert!(css.contains(".scroll { overflow-x: auto;"));
    assert!(css.contains("table.numbers { display: block; overflow-x: auto;"));
}

#[test]
fn unit_misprints_are_listed_apart_from_the_failing_claims() {
    let (html, latex, _, json) = built();
    let misprints = claims_with(json, "unit_misprint");
    let fails = claims_with(json, "fails");
    assert!(
        !misprints.is_empty() && !fails.is_empty(),
        "the built-in paper has both: {misprints:?}, {fails:?}"
    );
    let html_fails = between(html, "<h3>Prose claims that fail</h3>", "<h3>");
    let html_misprints = between(html, "<h3>Unit misprints</h3>", "<h");
    let tex_fails = between(latex, "\\subsection*{Prose claims that fail}", "subsection");
    let tex_misprints = between(latex, "\\subsection*{Unit misprints}", "subsection");
    let in_html = |table: &str, id: &str| table.contains(&format!("href=\"#claim-{id}\""));
    // The LaTeX escapes `-` pairs only; an id's row starts the line.
    let in_tex = |table: &str, id: &str| {
        let id = report::tex::escape(id);
        table.lines().any(|l| l.starts_with(&format!("{id} &")))
    };
    for id in &misprints {
        assert!(
            in_html(html_misprints, id),
            "{id} not among the HTML's unit misprints"
        );
        assert!(
            !in_html(html_fails, id),
            "{id} among the HTML's failing claims"
        );
        assert!(
            in_tex(tex_misprints, id),
            "{id} not among the LaTeX's unit misprints"
        );
        assert!(
            !in_tex(tex_fails, id),
            "{id} among the LaTeX's failing claims"
        );
    }
    for id in &fails {
        assert!(
            in_html(html_fails, id),
            "{id} not among the HTML's failing claims"
        );
        assert!(
            !in_html(html_misprints, id),
            "{id} among the HTML's unit misprints"
        );
        assert!(
            in_tex(tex_fails, id),
            "{id} not among the LaTeX's failing claims"
        );
        assert!(
            !in_tex(tex_misprints, id),
            "{id} among the LaTeX's unit misprints"
        );
    }
}

/// The numbers LaTeX gives the captioned longtables of `latex`, in order: longtable steps the
/// table counter at every table, captioned or not, `\addtocounter{table}{-1}` gives a step back.
/// Panics on a `\setcounter{table}` (a reset numbers two tables alike, and hyperref then names
/// two link targets alike) and on a table with two captions.
fn latex_table_numbers(latex: &str) -> Vec<i64> {
    assert!(
        !latex.contains("\\setcounter{table}"),
        "the LaTeX resets the table counter"
    );
    let mut counter = 0i64;
    let mut numbers = Vec::new();
    let mut rest = latex;
    loop {
        let table = rest.find("\\begin{longtable}");
        let back = rest.find("\\addtocounter{table}{-1}");
        let Some(at) = table.into_iter().chain(back).min() else {
            return numbers;
        };
        if Some(at) == table {
            counter += 1;
            let body = between(&rest[at..], "\\begin{longtable}", "\\end{longtable}");
            let captions = body.matches("\\caption{").count();
            assert!(captions <= 1, "a table with {captions} captions");
            if captions == 1 {
                numbers.push(counter);
            }
        } else {
            counter -= 1;
        }
        rest = &rest[at + 1..];
    }
}

#[test]
fn latex_numbers_its_tables_once_as_the_html_does() {
    let (html, latex, _, _) = built();
    let html_numbers: Vec<i64> = html
        .match_indices("<figure class=\"study\" id=\"table-")
        .map(|(at, m)| {
            let n = &html[at + m.len()..];
            n[..n.find('"').expect("a closed id")]
                .parse()
                .expect("a number")
        })
        .collect();
    assert!(html_numbers.len() > 5, "{html_numbers:?}");
    assert_eq!(latex_table_numbers(latex), html_numbers);
    // Link targets follow longtable's own count of its tables, which nothing resets.
    assert!(latex.contains("\\renewcommand{\\theHtable}{\\arabic{LT@tables}}"));
}

#[test]
fn the_table_count_sees_a_reset_and_a_missing_step_back() {
    let good = "\\begin{longtable}h\\end{longtable}\\addtocounter{table}{-1}\
                \\begin{longtable}\\caption{a}\\end{longtable}\
                \\begin{longtable}\\caption{b}\\end{longtable}";
    assert_eq!(latex_table_numbers(good), vec![1, 2]);
    let unreturned = good.replacen("\\addtocounter{table}{-1}", "", 1);
    assert_eq!(latex_table_numbers(&unreturned), vec![2, 3]);
    let reset = std::panic::catch_unwind(|| {
        latex_table_numbers("\\begin{longtable}\\end{longtable}\\setcounter{table}{0}")
    });
    assert!(reset.is_err(), "a reset must be refused");
}
