//! The part "Coverage of the stated uncertainties": whether the experiment's intervals mean what
//! they say, from the stored Monte Carlo studies ([`section`]).

pub mod section;

use super::{About, Draft, Drafted, Part};
use crate::error::ReportError;
use crate::results::Results;
use checks::equations::Bench;
use schemars::{Schema, SchemaGenerator};

/// The coverage of the stated uncertainties.
pub struct Coverage;

const ABOUT: About = About {
    name: "coverage",
    contents: Some("Coverage of the stated uncertainties"),
    studies: &[],
    templates: part_templates!("coverage", ["summary", "table-coverage"]),
};

impl Part for Coverage {
    fn about(&self) -> &'static About {
        &ABOUT
    }

    /// None: it reads the stored studies (`snapshots/coverage.json`), too slow for a report.
    fn draft<'r>(&self, _: &'r Bench, _: &'r Results) -> Drafted<'r> {
        let stored = studies::coverage_record::stored().map_err(|e| e.to_string())?;
        Ok(Some(Draft {
            tables: section::tables(&stored)?,
            finish: Box::new(move |tables, figures| {
                Ok(section::section(&stored, tables, figures.number("coverage"))?.into())
            }),
        }))
    }

    /// The stored coverage studies as they are.
    fn record(&self, _: &Results) -> Result<Option<super::record::Record>, ReportError> {
        let stored = studies::coverage_record::stored().map_err(|e| e.to_string())?;
        super::record::record_of(Some(&stored))
    }

    fn record_schema(&self, generator: &mut SchemaGenerator) -> Schema {
        generator.subschema_for::<Vec<studies::coverage_record::StoredCoverage>>()
    }
}
