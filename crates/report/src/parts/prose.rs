//! A part's paragraphs: text templates (`templates/parts/NAME/PARAGRAPH.txt.tera`) that write
//! the prose around the numbers the part computes and formats. A paragraph is rendered once,
//! as text, and each format then escapes it like any other text of the section.

use super::Templates;
use crate::error::ReportError;
use serde::Serialize;

/// The paragraph `name` of a part's `templates`, rendered from `values` (its numbers, already
/// written by [`crate::number`]).
pub fn paragraph(
    templates: &Templates,
    name: &str,
    values: &impl Serialize,
) -> Result<String, ReportError> {
    let source = templates
        .text
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, s)| *s)
        .ok_or_else(|| format!("the report has no paragraph template {name:?}"))?;
    let context = tera::Context::from_serialize(values)
        .map_err(|e| ReportError::Template(format!("the paragraph {name:?}: {e}")))?;
    let text = tera::Tera::one_off(source, &context, false).map_err(|e| {
        let cause = std::error::Error::source(&e).map_or(String::new(), |s| format!(": {s}"));
        ReportError::Template(format!("cannot render the paragraph {name:?}: {e}{cause}"))
    })?;
    Ok(text.strip_suffix('\n').unwrap_or(&text).to_string())
}
