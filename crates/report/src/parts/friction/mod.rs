//! The part "Friction and contact": the sections that argue from slipping and from losing
//! contact, run on the sliding model ([`section`] in tables and a paragraph, [`listing`] in full).

pub mod listing;
pub mod section;

use super::{Draft, Part, Templates};
use crate::error::ReportError;
use crate::results::Results;
use crate::study::{self, Run};
use checks::equations::Bench;

/// Friction and contact.
pub struct Friction;

const TEMPLATES: Templates = part_templates!("friction", ["summary", "listing"]);

impl Part for Friction {
    fn name(&self) -> &'static str {
        "friction"
    }

    fn contents(&self) -> Option<&'static str> {
        Some("Friction and contact")
    }

    fn studies(&self) -> &'static [&'static dyn Run] {
        &[&study::Friction]
    }

    fn templates(&self) -> &'static Templates {
        &TEMPLATES
    }

    fn draft<'r>(
        &self,
        bench: &'r Bench,
        results: &'r Results,
    ) -> Result<Option<Draft<'r>>, ReportError> {
        let Some(friction) = results.get(&study::Friction) else {
            return Ok(None);
        };
        let studies = &friction.studies;
        Ok(Some(Draft {
            tables: section::tables(studies),
            finish: Box::new(move |tables, figures| {
                let slip_stick = figures.numbers(&["slip-stick", "slip-stick-path"]);
                Ok(section::section(studies, bench.paper, tables, &slip_stick)?.into())
            }),
        }))
    }
}
