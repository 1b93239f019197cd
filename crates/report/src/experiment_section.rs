//! The section "The experiment, simulated" as the paper would print it: a paragraph of what the
//! analysis found, a table of its fits against the simulated model's truth, and the analysis's
//! full text for the disclosure and the appendix.

use crate::number::prose;
use crate::study_table::StudyTable;
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
pub fn table(e: &Synthetic) -> StudyTable {
    let a = &e.analysis;
    let (beta_sigma, t0_sigma) = a.stated_sigmas();
    let mut t = StudyTable::new(
        format!(
            "The fits of the simulated light signal ({} cycles) against the model that made it; \
             uncertainties as the analysis states them (eq 84's: statistical and the law's).",
            a.window.cycles.len()
        ),
        &["fitted by", "β", "t₀ (s)"],
    );
    t.row(vec![
        "eq 84, on the light signal".into(),
        format!("{:.4} ± {:.4}", a.eq84.beta, beta_sigma),
        format!("{:.4} ± {:.4}", a.eq84.t0, t0_sigma),
    ]);
    t.row(vec![
        "eq 85, on the light signal".into(),
        format!("{:.4} ± {:.4}", a.eq85.beta, a.eq85.beta_sigma),
        "–".into(),
    ]);
    if let Some(law) = &e.motion_law {
        t.row(vec![
            "eq 84, on the model's exact motion".into(),
            format!("{:.4}", law.beta),
            format!("{:.4}", law.t0),
        ]);
    }
    if let Some(truth) = &e.trace.truth {
        t.row(vec![
            "truth: the simulated model".into(),
            format!("{}", crate::number::significant(truth.beta)),
            format!("{:.4}", truth.t0),
        ]);
    }
    t
}

/// What the analysis found, in a paragraph.
pub fn summary(e: &Synthetic) -> String {
    let a = &e.analysis;
    let w = &a.window;
    let mut s = format!(
        "The analysis fits {} cycles between t = {:.2} s and {:.2} s, Ω rising to {:.0} rad/s. \
         Eq 84 gives β = {:.3} and eq 85 β = {:.3}.",
        w.cycles.len(),
        w.t_first,
        w.t_last,
        w.omega_last,
        a.eq84.beta,
        a.eq85.beta
    );
    if let Some(truth) = &e.trace.truth {
        s.push_str(&format!(
            " The model that made the signal has β = {}; eq 84's t₀ falls {:.1} ms before the \
             model's singular time",
            crate::number::significant(truth.beta),
            1e3 * (truth.t0 - a.eq84.t0)
        ));
        match &e.motion_law {
            Some(law) => s.push_str(&format!(
                ", and eq 84 fitted to the model's exact motion (no light, no noise) falls {:.1} \
                 ms before it: that part of the error is the law's (the model is not eq 79 \
                 exactly), the rest, {:.2} ms, the analysis's own.",
                1e3 * (truth.t0 - law.t0),
                1e3 * (law.t0 - a.eq84.t0)
            )),
            None => s.push('.'),
        }
    }
    s
}
