//! A part's paragraphs and table captions: text templates (`templates/parts/NAME/PARAGRAPH.txt.tera`,
//! a table's `table-TABLE.txt.tera`) that write the prose around the numbers the part computes, and
//! the columns of its listings (with the
//! filters of [`crate::text_cells`]). A paragraph is rendered once, as text, and each format
//! then escapes it like any other text of the section.

use super::Templates;
use crate::error::ReportError;
use crate::study_table::StudyTable;
use serde::Serialize;

/// The paragraph `name` of a part's `templates`, rendered from `values` (its numbers, already
/// written by [`crate::number`]).
pub fn paragraph(
    templates: &Templates,
    name: &str,
    values: &impl Serialize,
) -> Result<String, ReportError> {
    text(
        &format!("the paragraph {name:?}"),
        source(templates, name)?,
        values,
    )
}

/// The source of the text template `name` of `templates`.
fn source(templates: &Templates, name: &str) -> Result<&'static str, ReportError> {
    templates
        .text
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, s)| *s)
        .ok_or_else(|| format!("the report has no text template {name:?}").into())
}

/// The text of the template `source` (named `name` in messages) rendered from `values`, without
/// its final newline.
pub fn text(name: &str, source: &str, values: &impl Serialize) -> Result<String, ReportError> {
    let context = tera::Context::from_serialize(values)
        .map_err(|e| ReportError::Template(format!("{name}: {e}")))?;
    let failed = |e: tera::Error| {
        let cause = std::error::Error::source(&e).map_or(String::new(), |s| format!(": {s}"));
        ReportError::Template(format!("cannot render {name}: {e}{cause}"))
    };
    let mut tera = tera::Tera::default();
    crate::text_cells::register(&mut tera);
    tera.add_raw_template(name, source).map_err(failed)?;
    let text = tera.render(name, &context).map_err(failed)?;
    Ok(text.strip_suffix('\n').unwrap_or(&text).to_string())
}

/// A part's table with no rows yet: its caption the text template `name` of `templates` (one
/// paragraph, so each line break is read as a space) rendered from `values`, its `columns`.
pub fn table(
    templates: &Templates,
    name: &str,
    values: &impl Serialize,
    columns: &[&str],
) -> Result<StudyTable, ReportError> {
    let source = source(templates, name)?.trim_end().replace('\n', " ");
    let caption = text(&format!("the caption {name:?}"), &source, values)?;
    Ok(StudyTable::new(caption, columns))
}
