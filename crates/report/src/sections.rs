//! The studies' sections in the report's order (the experiment, the coverage of its stated
//! uncertainties, friction and contact, speed against accuracy): their tables numbered through
//! the report, their paragraphs citing those numbers and the figures'.

use crate::error::ReportError;
use crate::json::PrecisionRecord;
use crate::results::Results;
use crate::study;
use crate::study_table::{number_tables, StudySection};
use crate::{
    coverage_section, experiment_section, precision_section, sliding_tables, toy_section,
    FigureView,
};
use checks::equations::Bench;

/// The studies' sections.
pub struct Sections {
    /// The experiment, simulated.
    pub experiment: StudySection,
    /// Friction and contact, when the friction studies were computed.
    pub friction: Option<StudySection>,
    /// The real toy and the peer program, when computed.
    pub toy: Option<StudySection>,
    /// The coverage of the experiment's stated uncertainties.
    pub coverage: StudySection,
    /// Speed against accuracy.
    pub precision: StudySection,
    /// Every run of the speed/accuracy study, for `report.json`.
    pub precision_records: Vec<PrecisionRecord>,
}

/// The sections from the pipeline's `results`; `figures` give the figures' numbers.
pub fn sections(
    bench: &Bench,
    results: &Results,
    figures: &[FigureView],
) -> Result<Sections, ReportError> {
    let synthetic = results.required(&study::Experiment, "the report")?;
    let precision = results.required(&study::Precision, "the report")?;
    let stored = studies::coverage_record::stored().map_err(|e| e.to_string())?;
    let friction = results.get(&study::Friction).map(|f| &f.studies);

    let mut experiment_tables = vec![experiment_section::table(synthetic)];
    let mut friction_tables = friction.map_or(Vec::new(), sliding_tables::tables);
    let toy = results.get(&study::Toy);
    let mut toy_tables = toy.map_or(Vec::new(), toy_section::tables);
    let mut coverage_tables = coverage_section::tables(&stored);
    let mut precision_tables = precision_section::tables(precision);
    number_tables([
        &mut experiment_tables,
        &mut coverage_tables,
        &mut friction_tables,
        &mut toy_tables,
        &mut precision_tables,
    ]);
    let figure = |name: &str| figures.iter().find(|f| f.name == name).map(|f| f.number);
    let slip_stick: Vec<usize> = ["slip-stick", "slip-stick-path"]
        .iter()
        .filter_map(|n| figure(n))
        .collect();
    let mut experiment = experiment_section::section(synthetic, experiment_tables);
    if let Some(sound) = results.get(&study::Sound) {
        experiment.summary.push_str("\n\n");
        experiment
            .summary
            .push_str(&crate::sound_section::paragraph(
                sound,
                figure("sound-spectrogram"),
                figure("sound-residuals"),
            ));
        experiment
            .output
            .push_str(&format!("\n\n{}", sound.analysis));
    }
    Ok(Sections {
        experiment,
        friction: friction
            .map(|s| sliding_tables::section(s, bench.paper, friction_tables, &slip_stick)),
        coverage: coverage_section::section(&stored, coverage_tables, figure("coverage")),
        toy: toy.map(|t| {
            let agreement: Vec<usize> = ["peer-tilt", "peer-difference"]
                .iter()
                .filter_map(|n| figure(n))
                .collect();
            toy_section::section(t, toy_tables, &agreement)
        }),
        precision: precision_section::section(
            precision,
            precision_tables,
            figure("work-precision"),
        ),
        precision_records: precision_section::records(precision),
    })
}
