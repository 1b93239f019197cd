//! The part "Speed against accuracy": the benchmark scene integrated by each method over a range
//! of steps or tolerances ([`section`]).

pub mod section;

use super::{About, Draft, Drafted, Part};
use crate::error::ReportError;
use crate::results::Results;
use crate::study;
use checks::equations::Bench;
use schemars::{Schema, SchemaGenerator};

/// Speed against accuracy.
pub struct Precision;

const ABOUT: About = About {
    name: "precision",
    contents: Some("Speed against accuracy"),
    studies: &[&study::Precision],
    templates: part_templates!("precision", ["summary", "table-cost"]),
};

impl Part for Precision {
    fn about(&self) -> &'static About {
        &ABOUT
    }

    fn draft<'r>(&self, _: &'r Bench, results: &'r Results) -> Drafted<'r> {
        let precision = results.required(&study::Precision, "the report")?;
        Ok(Some(Draft {
            tables: section::tables(precision)?,
            finish: Box::new(move |tables, figures| {
                Ok(section::section(precision, tables, figures.number("work-precision"))?.into())
            }),
        }))
    }

    /// One record per run of the speed/accuracy study.
    fn record(&self, results: &Results) -> Result<Option<super::record::Record>, ReportError> {
        let records = results.get(&study::Precision).map(section::records);
        super::record::record_of(records.as_ref())
    }

    fn record_schema(&self, generator: &mut SchemaGenerator) -> Schema {
        generator.subschema_for::<Vec<section::PrecisionRecord>>()
    }
}
