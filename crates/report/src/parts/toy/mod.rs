//! The part on the real toy, a subsection of "Friction and contact": the peer program's stored
//! runs against this tool, and what the toy's thickness does to the paper's numbers
//! ([`section`], with eq 30 for the toy in [`steady_table`]).

pub mod section;
pub mod steady_table;

use super::{About, Draft, Drafted, Part};
use crate::error::ReportError;
use crate::results::Results;
use crate::study;
use checks::equations::Bench;
use schemars::{Schema, SchemaGenerator};

/// The real toy.
pub struct Toy;

const ABOUT: About = About {
    name: "toy",
    contents: None, // a subsection of friction and contact
    studies: &[&study::Toy, &study::Friction],
    templates: part_templates!(
        "toy",
        [
            "summary",
            "table-peer",
            "table-why",
            "table-steady",
            "table-spin-down",
            "table-fall",
            "table-edge",
        ]
    ),
};

impl Part for Toy {
    fn about(&self) -> &'static About {
        &ABOUT
    }

    /// `None` without the friction studies too, whose subsection it is.
    fn draft<'r>(&self, _: &'r Bench, results: &'r Results) -> Drafted<'r> {
        let (Some(toy), Some(_)) = (results.get(&study::Toy), results.get(&study::Friction)) else {
            return Ok(None);
        };
        Ok(Some(Draft {
            tables: section::tables(toy)?,
            finish: Box::new(move |tables, figures| {
                let agreement = figures.numbers(&["peer-tilt", "peer-difference"]);
                Ok(section::section(toy, tables, &agreement)?.into())
            }),
        }))
    }

    /// The peer program's stored runs compared, and the toy's thickness against the thin disk.
    fn record(&self, results: &Results) -> Result<Option<super::record::Record>, ReportError> {
        super::record::record_of(results.get(&study::Toy))
    }

    fn record_schema(&self, generator: &mut SchemaGenerator) -> Schema {
        generator.subschema_for::<studies::toy::Toy>()
    }
}
