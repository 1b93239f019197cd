//! Building the report from the pipeline's results ([`super::pipeline`]): every equation's
//! MathML, the findings, the figures (pure functions of the results), the speed/accuracy table
//! and the experiment's analysis. Nothing here computes a study. Everything here is
//! deterministic: seeded randomness, no clocks, no wall times.

use super::json;
use super::mathml::display_math;
use super::{
    fmt_num, EquationView, FailureView, FigureView, Report, RootCauseView, RunSettings, SceneView,
    SectionView, Summary,
};
use crate::document::equation_checked;
use crate::error::ReportError;
use crate::figures::{self, Drawing, Figure, FigureError};
use crate::finding_view::{
    claim_views, finding_of, headline_text, printed_and_true, relative_error, values,
};
use crate::pipeline::{compute, compute_timed, RunConfig};
use crate::results::Results;
use crate::study;
use crate::timing::Timings;
use checks::check::{Checked, Subject, Tally};
use checks::equations::{Bench, UNCHECKABLE_EQUATIONS};
use checks::finding::Verdict;
use checks::mutation::StoredScores;
use physics::scene::{builtin::BUILTIN, Scene};
use rayon::prelude::*;

/// The subject of each section of the paper, in our words.
const SECTIONS: [(u32, &str); 10] = [
    (
        3,
        "The equations of motion of a disk rolling without slipping",
    ),
    (4, "Steady motion"),
    (
        5,
        "Steady motion with the centre of mass at rest, derived directly",
    ),
    (6, "Friction needed in steady motion, and radial slip"),
    (7, "Small oscillations about steady motion"),
    (
        8,
        "A disk spinning about a vertical diameter, without friction",
    ),
    (9, "Small oscillations about steady motion without friction"),
    (10, "Rising of a nearly upright disk"),
    (11, "Dissipation at small tilt, and the experiment"),
    (12, "Summary of the motion"),
];

/// A failing check as one row of the summary; `None` when it does not fail.
fn failure_view(c: &Checked) -> Option<FailureView> {
    let f = c.finding.as_ref().ok()?;
    let (claimed, reference) = values(f);
    matches!(
        f.verdict,
        Verdict::Fails
            | Verdict::UnitMisprint
            | Verdict::DependsOn { .. }
            | Verdict::DimensionalSlip
    )
    .then(|| FailureView {
        name: c.subject.name(),
        at: crate::number::prose(&f.at),
        anchor: match &c.subject {
            Subject::Equation { number, .. } => format!("eq-{number}"),
            Subject::Claim { id } => format!("claim-{id}"),
        },
        compared: crate::number::prose(&f.compared),
        claimed: claimed.clone(),
        reference: reference.clone(),
        error: crate::number::error(f.error),
        relative_error: printed_and_true(f)
            .map_or_else(|| "-".into(), |(p, t, _)| relative_error(p, t)),
        headline: f
            .headline
            .as_ref()
            .map(|h| headline_text(h, &format!("paper {{}} ({})", h.paper_is))),
        headline_at: f.headline.as_ref().map(|h| crate::number::prose(&h.at)),
        row: match &f.headline {
            Some(h) => {
                let unit = if h.unit == "1" {
                    String::new()
                } else {
                    format!(" {}", paper::unit_tex::unit_prose(&h.unit))
                };
                [
                    h.quantity.clone(),
                    format!("{}{unit} ({})", fmt_num(h.paper), h.paper_is),
                    format!("{}{unit}", fmt_num(h.reference)),
                ]
            }
            None => [f.compared.clone(), claimed.clone(), reference.clone()],
        },
    })
}

/// The root causes among the failing equations, each with its consequences, and the failing
/// equations whose cause is undetermined.
fn causes_view(checked: &[Checked]) -> (Vec<RootCauseView>, Vec<FailureView>) {
    use checks::cause::Cause;
    let causes: std::collections::BTreeMap<u32, Cause> = checks::check::equation_causes(checked);
    let row = |n: u32| equation_checked(checked, n).and_then(failure_view);
    let roots = checks::cause::consequences(&causes)
        .into_iter()
        .filter_map(|(root, inherit)| {
            Some(RootCauseView {
                failure: row(root)?,
                cause: causes.get(&root).map(Cause::describe).unwrap_or_default(),
                consequences: inherit.into_iter().filter_map(row).collect(),
            })
        })
        .collect();
    let undetermined = causes
        .iter()
        .filter(|(_, c)| matches!(c, Cause::Undetermined { .. }))
        .filter_map(|(n, _)| row(*n))
        .collect();
    (roots, undetermined)
}

/// The premises graph of the report: every equation, coloured by its verdict.
fn premises_figure(bench: &Bench, checked: &[Checked]) -> Result<Figure, FigureError> {
    use checks::cause::graph::{PremisesGraph, Status};
    let premises = (1..=85u32)
        .map(|n| (n, bench.paper.equation(n).entry.premises.clone()))
        .collect();
    let status = |n: u32| match equation_checked(checked, n).map(|c| &c.finding) {
        Some(Ok(f)) => Status::of(f.verdict),
        _ => Status::Unchecked,
    };
    let causes = checks::check::equation_causes(checked);
    Ok(Figure {
        name: "premises",
        title: "Which equation follows from which, and where the errors start".into(),
        caption: crate::figures::captions::caption("premises", &serde_json::json!({}))?,
        drawing: Drawing::Premises(PremisesGraph::new(&premises, &status, &causes)),
    })
}

/// Computes every study once ([`compute`]) and builds the report from the results, at the
/// bench's accuracy. `progress` receives short status lines.
pub fn build(
    bench: &Bench,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<(Report, Vec<Figure>), ReportError> {
    build_from(&RunConfig::report(*bench), progress, None)
}

/// Builds the report for `config` (a [`RunConfig::report`], with or without a cache): every
/// study side by side ([`compute`]), or, with `timings`, one after another, each one's and each
/// later stage's wall and CPU time recorded there. The same report, to the byte, either way,
/// and from a cold cache, a warm one or none.
pub fn build_from(
    config: &RunConfig,
    progress: &(dyn Fn(&str) + Sync),
    timings: Option<&Timings>,
) -> Result<(Report, Vec<Figure>), ReportError> {
    match timings {
        None => {
            let results = compute(config, progress)?;
            from_results(&config.bench, &results, progress)
        }
        Some(timings) => {
            let results = compute_timed(config, progress, timings)?;
            assemble(&config.bench, &results, progress, timings)
        }
    }
}

/// [`build`] with the studies one after another, each study's and each later stage's wall and
/// CPU time recorded in `timings` (`report -v`); the same report, to the byte.
pub fn build_timed(
    bench: &Bench,
    progress: &(dyn Fn(&str) + Sync),
    timings: &Timings,
) -> Result<(Report, Vec<Figure>), ReportError> {
    build_from(&RunConfig::report(*bench), progress, Some(timings))
}

/// Builds the report from results computed before (a full [`RunConfig::report`]); computes
/// nothing.
pub fn from_results(
    bench: &Bench,
    results: &Results,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<(Report, Vec<Figure>), ReportError> {
    assemble(bench, results, progress, &Timings::new())
}

/// [`from_results`], each stage timed in `timings`.
fn assemble(
    bench: &Bench,
    results: &Results,
    progress: &(dyn Fn(&str) + Sync),
    timings: &Timings,
) -> Result<(Report, Vec<Figure>), ReportError> {
    let checked: &[Checked] = results.required(&study::Checks, "the report")?;
    let (stored, mutation) = super::mutation::scores_for(bench.paper);
    let (sections, unchecked) = section_views(bench, checked, stored.as_ref())?;
    let (claims, unchecked_claims) = claim_views(bench, checked);
    let failures: Vec<FailureView> = checked.iter().filter_map(failure_view).collect();
    let (root_causes, undetermined) = causes_view(checked);
    let failing_claims = checked
        .iter()
        .filter(|c| matches!(c.subject, Subject::Claim { .. }))
        .filter_map(failure_view)
        .collect();
    let (corrections, downstream, correction_records) =
        corrections_view(bench, checked, results.get(&study::Corrections))?;
    let (eqs, cls): (Vec<&Checked>, Vec<&Checked>) = checked
        .iter()
        .partition(|c| matches!(c.subject, Subject::Equation { .. }));

    progress("drawing the figures");
    let (figures, figure_views) = timings.time("figures", || {
        let mut figures = figures::all(results)?;
        figures.push(premises_figure(bench, checked)?);
        let views = figure_views(&figures)?;
        Ok::<_, ReportError>((figures, views))
    })?;
    let parts = timings.time("parts", || {
        crate::parts::parts(bench, results, &figure_views)
    })?;

    let scenes = BUILTIN
        .iter()
        .filter_map(|(name, src)| Scene::parse(src, name).ok())
        .map(|s| SceneView {
            name: s.name,
            model: s.model.to_string(),
            description: s.description,
        })
        .collect();

    let settings = RunSettings {
        method: "DOP853".into(),
        rtol: bench.rtol,
        command: "rolling-disk report".into(),
    };
    let part_records = crate::parts::record::PartRecords::of(results)?;
    let document = timings.time("document", || {
        super::document::document(
            bench,
            checked,
            stored.as_ref(),
            &settings,
            &figure_views,
            super::document::Records {
                corrections: correction_records,
                parts: part_records,
            },
        )
    });

    let report = Report {
        paper: super::document::PAPER.into(),
        version: crate::TOOL_VERSION.into(),
        settings,
        summary: Summary {
            equations: Tally::of(eqs.iter().copied()),
            claims: Tally::of(cls.iter().copied()),
            unchecked,
            unchecked_claims,
            failures,
            root_causes,
            undetermined,
            failing_claims,
            corrections,
            downstream,
            mutation,
        },
        sections,
        claims,
        figures: figure_views,
        parts,
        scenes,
        document,
    };
    Ok((report, figures))
}

/// What has no check (an equation's number or a claim's id), each with why.
type Unchecked<K> = Vec<(K, String)>;

/// Every equation's view, in the report's sections, and the equations with no check and why.
fn section_views(
    bench: &Bench,
    checked: &[Checked],
    stored: Option<&StoredScores>,
) -> Result<(Vec<SectionView>, Unchecked<u32>), ReportError> {
    let cat: Vec<&paper::EquationEntry> = bench.paper.equations.iter().map(|e| &e.entry).collect();
    let mut sections: Vec<SectionView> = SECTIONS
        .iter()
        .map(|(n, t)| SectionView {
            number: *n,
            title: (*t).to_string(),
            equations: Vec::new(),
        })
        .collect();
    let mut unchecked = Vec::new();
    for e in &cat {
        let found = checked
            .iter()
            .find(|c| matches!(c.subject, Subject::Equation { number, .. } if number == e.number));
        let why = UNCHECKABLE_EQUATIONS
            .iter()
            .find(|(n, _)| *n == e.number)
            .map(|(_, why)| why.to_string());
        if found.is_none() {
            unchecked.push((
                e.number,
                why.clone().unwrap_or_else(|| "no check yet".into()),
            ));
        }
        let v = EquationView {
            number: e.number,
            label: e.label.clone(),
            anchor: format!("eq-{}", e.number),
            latex: e.latex.clone(),
            mathml: display_math(&e.latex),
            says: e.says.clone(),
            kind: e.kind.clone(),
            premises: e.premises.clone(),
            finding: found.map(finding_of),
            uncheckable: why,
            mutants: stored
                .and_then(|st| st.of(e.number))
                .map(|m| crate::number::prose(&m.describe())),
        };
        match sections.iter_mut().find(|s| s.number == e.section) {
            Some(s) => s.equations.push(v),
            None => {
                return Err(format!(
                    "eq {} is in section {}, which the report does not know",
                    e.number, e.section
                )
                .into())
            }
        }
    }
    sections.retain(|s| !s.equations.is_empty());

    Ok((sections, unchecked))
}

/// The figures as the HTML and LaTeX reports show them: inline SVG (the premises graph with
/// links to its findings), the PNG's file, and the paper-size version of the paper's figures.
fn figure_views(figures: &[Figure]) -> Result<Vec<FigureView>, ReportError> {
    figures
        .par_iter()
        .enumerate()
        .map(|(i, f)| {
            Ok(FigureView {
                number: i + 1,
                name: f.name.to_string(),
                title: f.title.clone(),
                caption: crate::number::prose(&f.caption),
                svg: match &f.drawing {
                    Drawing::Premises(g) => crate::figures::premises::linked_svg(g, 760, 560),
                    d => d.to_svg(760, 480)?,
                },
                file: format!("figures/{}.png", f.name),
                paper: match crate::figures::paper_scale::paper_figure(f.name) {
                    Some((label, says)) => Some(super::PaperScaleView {
                        label: label.to_string(),
                        says,
                        svg: f.paper_svg()?,
                        file: format!("figures/paper/{}.png", f.name),
                    }),
                    None => None,
                },
            })
        })
        .collect::<Result<Vec<_>, ReportError>>()
}

/// The corrections of the summary: each corrected form with the verdicts of the printed form
/// (from the report's checks) and of the corrected one, and the downstream sentence.
fn corrections_view(
    bench: &Bench,
    checked: &[Checked],
    study: Option<&crate::study::CorrectionsStudy>,
) -> Result<
    (
        Vec<super::CorrectionView>,
        String,
        Vec<json::CorrectionRecord>,
    ),
    ReportError,
> {
    let Some(study) = study else {
        return Ok((Vec::new(), String::new(), Vec::new()));
    };
    if let Some(e) = &study.error {
        let note = format!(
            "The corrections of paper/corrections.yaml could not be checked on this paper: {e}"
        );
        return Ok((Vec::new(), note, Vec::new()));
    }
    let verified =
        checks::corrections::assemble(bench.paper, &study.corrections, checked, &study.corrected);
    let records = verified
        .iter()
        .map(|v| json::CorrectionRecord {
            number: v.number,
            printed_latex: v.printed_latex.clone(),
            corrected_latex: v.corrected_latex.clone(),
            why: v.why.clone(),
            printed_verdict: v.printed.verdict.clone(),
            corrected_verdict: v.corrected.verdict.clone(),
            corrected_holds: v.corrected.holds,
        })
        .collect();
    let views = verified
        .into_iter()
        .map(|v| super::CorrectionView {
            number: v.number,
            anchor: format!("eq-{}", v.number),
            mathml: display_math(&v.corrected_latex),
            latex: v.corrected_latex,
            why: v.why,
            printed: v.printed.verdict,
            corrected: v.corrected.verdict,
            holds: v.corrected.holds,
            detail: crate::number::prose(&match v.corrected.headline {
                Some(h) => format!("{} ({})", headline_text(&h, "corrected {}"), h.at),
                None => v.corrected.detail,
            }),
        })
        .collect();
    let downstream = match &study.downstream {
        None => Ok(String::new()),
        Some(d) => crate::parts::prose::text(
            "the corrections' downstream sentence",
            include_str!("../../../templates/partials/downstream.txt.tera"),
            &serde_json::json!({
                "beta": d.beta,
                "c_inv_root": d.c_inv_root,
                "epsilon_printed": fmt_num(d.epsilon_printed),
                "epsilon_corrected": fmt_num(d.epsilon_corrected),
                "ratio": d.epsilon_corrected / d.epsilon_printed,
                "a": d.a,
                "k": d.k,
                "g": d.g,
            }),
        ),
    };
    Ok((views, downstream?, records))
}
