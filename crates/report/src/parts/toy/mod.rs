//! The part on the real toy, a subsection of "Friction and contact": the peer program's stored
//! runs against this tool, and what the toy's thickness does to the paper's numbers
//! ([`section`], with eq 30 for the toy in [`steady_table`]).

pub mod section;
pub mod steady_table;

use super::{Draft, Part, Templates};
use crate::error::ReportError;
use crate::results::Results;
use crate::study::{self, Run};
use checks::equations::Bench;

/// The real toy.
pub struct Toy;

const TEMPLATES: Templates = part_templates!("toy", ["summary"]);

impl Part for Toy {
    fn name(&self) -> &'static str {
        "toy"
    }

    /// None: it is a subsection of friction and contact.
    fn contents(&self) -> Option<&'static str> {
        None
    }

    fn studies(&self) -> &'static [&'static dyn Run] {
        &[&study::Toy, &study::Friction]
    }

    fn templates(&self) -> &'static Templates {
        &TEMPLATES
    }

    /// `None` without the friction studies too, whose subsection it is.
    fn draft<'r>(
        &self,
        _: &'r Bench,
        results: &'r Results,
    ) -> Result<Option<Draft<'r>>, ReportError> {
        let (Some(toy), Some(_)) = (results.get(&study::Toy), results.get(&study::Friction)) else {
            return Ok(None);
        };
        Ok(Some(Draft {
            tables: section::tables(toy),
            finish: Box::new(move |tables, figures| {
                let agreement = figures.numbers(&["peer-tilt", "peer-difference"]);
                Ok(section::section(toy, tables, &agreement)?.into())
            }),
        }))
    }
}
