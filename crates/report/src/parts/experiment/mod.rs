//! The part "The experiment, simulated": the analysis of section 11 run on a simulated light
//! signal ([`section`]), the phone's sound of the same spin-down ([`sound`]), and the paper's
//! own numbers recomputed from its fitted constants.

pub mod record;
pub mod section;
pub mod sound;

use super::{About, Draft, Drafted, Part, Written};
use crate::error::ReportError;
use crate::results::Results;
use crate::study;
use checks::equations::Bench;
use schemars::{Schema, SchemaGenerator};

/// The experiment, simulated.
pub struct Experiment;

const ABOUT: About = About {
    name: "experiment",
    contents: Some("The experiment, simulated"),
    studies: &[&study::Experiment, &study::Sound],
    templates: part_templates!("experiment", ["summary", "sound", "table-fits"]),
};

impl Part for Experiment {
    fn about(&self) -> &'static About {
        &ABOUT
    }

    fn draft<'r>(&self, bench: &'r Bench, results: &'r Results) -> Drafted<'r> {
        let synthetic = results.required(&study::Experiment, "the report")?;
        let sound = results.get(&study::Sound);
        let fit = bench.paper.fit;
        let paper_numbers =
            experiment::numbers::numbers(fit.beta, fit.c_inv_root, physics::Disk::uniform(1.0).k)
                .to_string();
        Ok(Some(Draft {
            tables: vec![section::table(synthetic)?],
            finish: Box::new(move |tables, figures| {
                let mut s = section::section(synthetic, tables)?;
                if let Some(sound) = sound {
                    s.summary.push_str("\n\n");
                    s.summary.push_str(&sound::paragraph_of(
                        sound,
                        figures.number("sound-spectrogram"),
                        figures.number("sound-residuals"),
                    )?);
                    s.output.push_str(&format!("\n\n{}", sound.analysis));
                }
                let mut written = Written::from(s);
                written.values.insert("paper_numbers", paper_numbers);
                Ok(written)
            }),
        }))
    }

    /// The fits on the light signal and on the sound, beside the truth.
    fn record(&self, results: &Results) -> Result<Option<super::record::Record>, ReportError> {
        let record = results
            .get(&study::Experiment)
            .map(|e| record::record(e, results.get(&study::Sound)));
        super::record::record_of(record.as_ref())
    }

    fn record_schema(&self, generator: &mut SchemaGenerator) -> Schema {
        generator.subschema_for::<record::ExperimentRecord>()
    }
}
