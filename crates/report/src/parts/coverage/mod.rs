//! The part "Coverage of the stated uncertainties": whether the experiment's intervals mean what
//! they say, from the stored Monte Carlo studies ([`section`]).

pub mod section;

use super::{Draft, Part, Templates};
use crate::error::ReportError;
use crate::results::Results;
use crate::study::Run;
use checks::equations::Bench;

/// The coverage of the stated uncertainties.
pub struct Coverage;

const TEMPLATES: Templates = part_templates!("coverage", ["summary"]);

impl Part for Coverage {
    fn name(&self) -> &'static str {
        "coverage"
    }

    fn contents(&self) -> Option<&'static str> {
        Some("Coverage of the stated uncertainties")
    }

    /// None: it reads the stored studies (`snapshots/coverage.json`), too slow for a report.
    fn studies(&self) -> &'static [&'static dyn Run] {
        &[]
    }

    fn templates(&self) -> &'static Templates {
        &TEMPLATES
    }

    fn draft<'r>(&self, _: &'r Bench, _: &'r Results) -> Result<Option<Draft<'r>>, ReportError> {
        let stored = studies::coverage_record::stored().map_err(|e| e.to_string())?;
        Ok(Some(Draft {
            tables: section::tables(&stored),
            finish: Box::new(move |tables, figures| {
                Ok(section::section(&stored, tables, figures.number("coverage"))?.into())
            }),
        }))
    }
}
