//! The part "Speed against accuracy": the benchmark scene integrated by each method over a range
//! of steps or tolerances ([`section`]).

pub mod section;

use super::{Draft, Part, Templates};
use crate::error::ReportError;
use crate::results::Results;
use crate::study::{self, Run};
use checks::equations::Bench;

/// Speed against accuracy.
pub struct Precision;

const TEMPLATES: Templates = part_templates!("precision", ["summary"]);

impl Part for Precision {
    fn name(&self) -> &'static str {
        "precision"
    }

    fn contents(&self) -> Option<&'static str> {
        Some("Speed against accuracy")
    }

    fn studies(&self) -> &'static [&'static dyn Run] {
        &[&study::Precision]
    }

    fn templates(&self) -> &'static Templates {
        &TEMPLATES
    }

    fn draft<'r>(
        &self,
        _: &'r Bench,
        results: &'r Results,
    ) -> Result<Option<Draft<'r>>, ReportError> {
        let precision = results.required(&study::Precision, "the report")?;
        Ok(Some(Draft {
            tables: section::tables(precision),
            finish: Box::new(move |tables, figures| {
                Ok(section::section(precision, tables, figures.number("work-precision"))?.into())
            }),
        }))
    }
}
