//! The section "The experiment, simulated" as the paper would print it: a paragraph of what the
//! analysis found, a table of its fits against the simulated model's truth, and the analysis's
//! full text for the disclosure and the appendix.

use crate::error::ReportError;
use crate::number::{measured, prose, significant, to_place_of};
use crate::parts::prose::paragraph;
use crate::study_table::{cite, StudySection, StudyTable};
use studies::synthetic::Synthetic;

/// The analysis's full text, with the error split when the model's truth is known.
pub fn text(e: &Synthetic) -> String {
    let mut text = e.analysis.to_string();
    if let (Some(law), Some(truth)) = (&e.motion_law, &e.trace.truth) {
        text.push_str(&experiment::motion_law::split(&e.analysis, law, truth));
    }
    prose(&text)
}

/// The fits of β and t₀ against the model's truth.
pub fn table(e: &Synthetic) -> Result<StudyTable, ReportError> {
    let a = &e.analysis;
    let (beta_sigma, t0_sigma) = a.stated_sigmas();
    let mut t = crate::parts::prose::table(
        &super::ABOUT.templates,
        "table-fits",
        &serde_json::json!({ "cycles": a.window.cycles.len() }),
        &["fitted by", "β", "t₀ (s)"],
    )?;
    t.row(vec![
        "eq 84, on the light signal".into(),
        measured(a.eq84.beta, beta_sigma),
        measured(a.eq84.t0, t0_sigma),
    ]);
    t.row(vec![
        "eq 85, on the light signal".into(),
        measured(a.eq85.beta, a.eq85.beta_sigma),
        "–".into(),
    ]);
    // The fit to the exact motion and the truth have no noise: written to the place of the
    // light signal's uncertainties, against which they are read.
    if let Some(law) = &e.motion_law {
        t.row(vec![
            "eq 84, on the model's exact motion".into(),
            to_place_of(law.beta, beta_sigma),
            to_place_of(law.t0, t0_sigma),
        ]);
    }
    if let Some(truth) = &e.trace.truth {
        t.row(vec![
            "truth: the simulated model".into(),
            significant(truth.beta),
            to_place_of(truth.t0, t0_sigma),
        ]);
    }
    Ok(t)
}

/// What the analysis found, in a paragraph citing `tables`
/// (`templates/parts/experiment/summary.txt.tera`).
pub fn summary(e: &Synthetic, tables: &[StudyTable]) -> Result<String, ReportError> {
    let a = &e.analysis;
    let w = &a.window;
    let (beta_sigma, t0_sigma) = a.stated_sigmas();
    let ms = 1e3 * t0_sigma;
    let truth = e.trace.truth.as_ref();
    let values = serde_json::json!({
        "cycles": w.cycles.len(),
        "t_first": format!("{:.2}", w.t_first),
        "t_last": format!("{:.2}", w.t_last),
        "omega_last": format!("{:.0}", w.omega_last),
        "beta_84": measured(a.eq84.beta, beta_sigma),
        "beta_85": measured(a.eq85.beta, a.eq85.beta_sigma),
        "tables": cite(tables),
        "truth": truth.map(|t| serde_json::json!({
            "beta": significant(t.beta),
            "t0_before": measured(1e3 * (t.t0 - a.eq84.t0), ms),
        })),
        "law": truth.zip(e.motion_law.as_ref()).map(|(t, law)| serde_json::json!({
            "t0_before": to_place_of(1e3 * (t.t0 - law.t0), ms),
            "analysis": measured(1e3 * (law.t0 - a.eq84.t0), ms),
        })),
    });
    paragraph(&super::ABOUT.templates, "summary", &values)
}

/// The section, its tables numbered already.
pub fn section(e: &Synthetic, tables: Vec<StudyTable>) -> Result<StudySection, ReportError> {
    Ok(StudySection {
        title: "The experiment, simulated".into(),
        summary: summary(e, &tables)?,
        tables,
        output: text(e),
        output_title: "The analysis's full output: the window, the fits of eqs 84 and 85, the \
                       model choice, the checks of a spin-down, and the error split"
            .into(),
    })
}
