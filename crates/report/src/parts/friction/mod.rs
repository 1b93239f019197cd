//! The part "Friction and contact": the sections that argue from slipping and from losing
//! contact, run on the sliding model ([`section`] in tables and a paragraph, [`listing`] in full).

pub mod listing;
pub mod section;

use super::{About, Draft, Drafted, Part};
use crate::error::ReportError;
use crate::results::Results;
use crate::study;
use checks::equations::Bench;
use schemars::{Schema, SchemaGenerator};

/// Friction and contact.
pub struct Friction;

const ABOUT: About = About {
    name: "friction",
    contents: Some("Friction and contact"),
    studies: &[&study::Friction],
    templates: part_templates!(
        "friction",
        [
            "summary",
            "listing",
            "table-onset",
            "table-negative",
            "table-spiral",
            "table-rising",
            "table-contact",
            "table-mechanisms",
        ]
    ),
};

impl Part for Friction {
    fn about(&self) -> &'static About {
        &ABOUT
    }

    fn draft<'r>(&self, bench: &'r Bench, results: &'r Results) -> Drafted<'r> {
        let Some(friction) = results.get(&study::Friction) else {
            return Ok(None);
        };
        let studies = &friction.studies;
        Ok(Some(Draft {
            tables: section::tables(studies)?,
            finish: Box::new(move |tables, figures| {
                let slip_stick = figures.numbers(&["slip-stick", "slip-stick-path"]);
                Ok(section::section(studies, bench.paper, tables, &slip_stick)?.into())
            }),
        }))
    }

    /// The friction studies as they are.
    fn record(&self, results: &Results) -> Result<Option<super::record::Record>, ReportError> {
        super::record::record_of(results.get(&study::Friction).map(|f| &f.studies))
    }

    fn record_schema(&self, generator: &mut SchemaGenerator) -> Schema {
        generator.subschema_for::<studies::sliding::Studies>()
    }
}
