//! The report's parts: one per topic that a study's results make (the experiment, the coverage
//! of its stated uncertainties, friction and contact, the real toy, speed against accuracy),
//! each in its own folder with the studies it reads, its tables and its prose, and its
//! templates in `templates/parts/NAME/` (its section in HTML and in LaTeX, and the paragraphs it
//! writes as text). Every part is a row of [`PARTS`], in the report's order; the HTML and LaTeX
//! templates loop over the parts drawn, and their tables are numbered through the report in that
//! order; each writes its record in `report.json` ([`record`]). Adding a topic is one folder
//! here, one in `templates/parts/`, and its row.

use crate::error::ReportError;
use crate::results::Results;
use crate::study::Run;
use crate::study_table::{number_tables, StudySection, StudyTable};
use crate::FigureView;
use checks::equations::Bench;
use serde::Serialize;
use std::collections::BTreeMap;

/// The [`Templates`] of the part whose templates are in `templates/parts/NAME/`: its section in
/// each format and its text paragraphs, each `PARAGRAPH.txt.tera`.
macro_rules! part_templates {
    ($name:literal, [$($paragraph:literal),* $(,)?]) => {
        $crate::parts::Templates {
            html: include_str!(concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/../../templates/parts/",
                $name,
                "/section.html.tera"
            )),
            tex: include_str!(concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/../../templates/parts/",
                $name,
                "/section.tex.tera"
            )),
            text: &[$((
                $paragraph,
                include_str!(concat!(
                    env!("CARGO_MANIFEST_DIR"),
                    "/../../templates/parts/",
                    $name,
                    "/",
                    $paragraph,
                    ".txt.tera"
                )),
            )),*],
        }
    };
}

pub mod coverage;
pub mod experiment;
pub mod friction;
pub mod precision;
pub mod prose;
pub mod record;
pub mod toy;

/// A part's templates, compiled into the binary: its section in each format, and the
/// paragraphs it writes as text (rendered once, then escaped by each format like any text).
pub struct Templates {
    /// Its section in HTML (`templates/parts/NAME/section.html.tera`).
    pub html: &'static str,
    /// Its section in LaTeX (`templates/parts/NAME/section.tex.tera`).
    pub tex: &'static str,
    /// Its paragraphs as text, by name (`templates/parts/NAME/PARAGRAPH.txt.tera`).
    pub text: &'static [(&'static str, &'static str)],
}

/// A part drafted from the results: its tables, not yet numbered, and how it writes its section
/// once they are.
pub struct Draft<'r> {
    /// Its tables, in its order.
    pub tables: Vec<StudyTable>,
    /// Its section from its numbered tables and the figures' numbers.
    #[allow(clippy::type_complexity)]
    pub finish: Box<dyn FnOnce(Vec<StudyTable>, &Figures) -> Result<Written, ReportError> + 'r>,
}

/// A part's section and the values its templates read beside it.
pub struct Written {
    /// Its section.
    pub section: StudySection,
    /// Values its section's templates print beside the section, by name.
    pub values: BTreeMap<&'static str, String>,
}

impl From<StudySection> for Written {
    fn from(section: StudySection) -> Self {
        Self {
            section,
            values: BTreeMap::new(),
        }
    }
}

/// A part's draft, `None` when what it shows was not computed.
pub type Drafted<'r> = Result<Option<Draft<'r>>, ReportError>;

/// What a part is: its name, its title, the studies it reads and its templates.
pub struct About {
    /// Its name: its anchor in the HTML and its folders (`parts/NAME`, `templates/parts/NAME`).
    pub name: &'static str,
    /// Its title in the HTML's contents; `None` for a part that is a subsection of the one
    /// before it.
    pub contents: Option<&'static str>,
    /// The studies it reads.
    pub studies: &'static [&'static dyn Run],
    /// Its templates.
    pub templates: Templates,
}

/// A topic of the report.
pub trait Part: Sync {
    /// What it is.
    fn about(&self) -> &'static About;
    /// Its draft from `results`, or `None` when what it shows was not computed.
    fn draft<'r>(&self, bench: &'r Bench, results: &'r Results) -> Drafted<'r>;
    /// Its record in `report.json` from `results` (made with [`record::record_of`]), `None`
    /// when what it records was not computed.
    fn record(&self, results: &Results) -> Result<Option<record::Record>, ReportError>;
    /// The JSON schema of its record.
    fn record_schema(&self, generator: &mut schemars::SchemaGenerator) -> schemars::Schema;
    /// Its name ([`About::name`]).
    fn name(&self) -> &'static str {
        self.about().name
    }
    /// Its title in the contents ([`About::contents`]).
    fn contents(&self) -> Option<&'static str> {
        self.about().contents
    }
    /// The studies it reads ([`About::studies`]).
    fn studies(&self) -> &'static [&'static dyn Run] {
        self.about().studies
    }
    /// Its templates ([`About::templates`]).
    fn templates(&self) -> &'static Templates {
        &self.about().templates
    }
}

/// Every part, in the report's order.
pub const PARTS: &[&dyn Part] = &[
    &experiment::Experiment,
    &coverage::Coverage,
    &friction::Friction,
    &toy::Toy,
    &precision::Precision,
];

/// The numbers of the report's figures, by name.
pub struct Figures<'f>(&'f [FigureView]);

impl Figures<'_> {
    /// The number of the figure `name`, if it is drawn.
    pub fn number(&self, name: &str) -> Option<usize> {
        self.0.iter().find(|f| f.name == name).map(|f| f.number)
    }

    /// The numbers of those of `names` that are drawn, in order.
    pub fn numbers(&self, names: &[&str]) -> Vec<usize> {
        names.iter().filter_map(|n| self.number(n)).collect()
    }
}

/// A part as the templates read it.
#[derive(Debug, Clone, Serialize)]
pub struct PartView {
    /// Its name ([`Part::name`]).
    pub name: String,
    /// Its title in the contents, if it has one there.
    pub contents: Option<String>,
    /// Its section.
    pub section: StudySection,
    /// The values its templates print beside the section.
    pub values: BTreeMap<&'static str, String>,
}

/// The parts whose studies were computed, in the report's order, their tables numbered through
/// the report; `figures` give the figures' numbers.
pub fn parts(
    bench: &Bench,
    results: &Results,
    figures: &[FigureView],
) -> Result<Vec<PartView>, ReportError> {
    let mut drafts = Vec::new();
    for p in PARTS {
        if let Some(d) = p.draft(bench, results)? {
            drafts.push((*p, d));
        }
    }
    let mut tables: Vec<Vec<StudyTable>> = drafts
        .iter_mut()
        .map(|(_, d)| std::mem::take(&mut d.tables))
        .collect();
    number_tables(tables.iter_mut());
    let figures = Figures(figures);
    drafts
        .into_iter()
        .zip(tables)
        .map(|((p, d), t)| {
            let written = (d.finish)(t, &figures)?;
            Ok(PartView {
                name: p.name().into(),
                contents: p.contents().map(String::from),
                section: written.section,
                values: written.values,
            })
        })
        .collect()
}

/// The part named `name`.
pub fn part(name: &str) -> Option<&'static dyn Part> {
    PARTS.iter().copied().find(|p| p.name() == name)
}

#[cfg(test)]
mod tests;
