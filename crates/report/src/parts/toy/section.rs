//! The friction part's section on the real toy: the peer program's stored runs against this
//! tool, and what the toy's thickness does to the paper's numbers, as tables and a paragraph
//! that says, number by number, whether the paper's conclusion survives for the toy.

use crate::error::ReportError;
use crate::number::{error, places, scientific};
use crate::parts::prose::{paragraph, table};
use crate::study_table::{StudySection, StudyTable};
use std::fmt::Write;
use studies::peer::stored::{Differences, StoredComparison};
use studies::sliding::swing::Swing;
use studies::thickness::{
    SpinDownLaw, Thickness, DRAG, FALL_LEFT, FALL_TIME, FIT_TILTS, SPIN_DOWN_START, TOY,
};
use studies::toy::Toy;

/// The switches: "peer / here, largest paired time difference", or "none".
fn switches(d: &Differences) -> String {
    if d.switch_counts.0 + d.switch_counts.1 == 0 {
        "none".into()
    } else if d.switch_counts.0.min(d.switch_counts.1) == 0 {
        format!("{} / {}", d.switch_counts.0, d.switch_counts.1)
    } else {
        format!(
            "{} / {}, {} s",
            d.switch_counts.0,
            d.switch_counts.1,
            error(d.switch_time)
        )
    }
}

/// The section's tables: the peer runs, their explanations, the steady motions, the spin-down.
pub fn tables(t: &Toy) -> Result<Vec<StudyTable>, ReportError> {
    let scenes: Vec<String> = t
        .peer
        .iter()
        .map(|c| format!("{}, {}", c.name, c.words))
        .collect();
    let templates = &super::ABOUT.templates;
    let mut peer = table(
        templates,
        "table-peer",
        &serde_json::json!({ "scenes": scenes.join("; ") }),
        &[
            "scene",
            "compared to (s)",
            "Δα (rad)",
            "Δ spin (rad/s)",
            "Δ heading (rad)",
            "Δ centre (m)",
            "switches",
        ],
    )?;
    let meanings: Vec<String> = studies::peer::stored::EXPLANATIONS
        .iter()
        .map(|(phrase, means)| format!("{phrase}: {means}"))
        .collect();
    let mut why = table(
        templates,
        "table-why",
        &serde_json::json!({ "choices": meanings.join("; ") }),
        &[
            "scene",
            "Δα, ε = 1e-3 (rad)",
            "Δα, ε = 1e-7 (rad)",
            "before the slip ends (rad)",
            "after the relock, restarted (rad)",
            "explained by",
        ],
    )?;
    for c in &t.peer {
        let d = &c.regularized;
        peer.row(vec![
            c.name.clone(),
            places(d.until, 3),
            scientific(d.tilt, 2),
            scientific(d.spin, 2),
            scientific(d.heading, 2),
            scientific(d.centre, 2),
            switches(d),
        ]);
        why.row(vec![
            c.name.clone(),
            scientific(d.tilt, 2),
            c.sharp
                .as_ref()
                .map_or("–".into(), |s| scientific(s.tilt, 2)),
            c.relock.map_or("–".into(), |r| scientific(r.before, 2)),
            c.relock.map_or("–".into(), |r| scientific(r.after, 2)),
            explanation(c),
        ]);
    }
    Ok(vec![
        peer,
        why,
        steady(&t.thickness)?,
        spin_down(&t.thickness)?,
        fall(&t.thickness)?,
        super::steady_table::table(&t.steady)?,
    ])
}

/// What explains `c`'s differences, or that none needs explaining.
fn explanation(c: &StoredComparison) -> String {
    if c.regularized.at_printed_digits() {
        return "– (at the printed digits)".into();
    }
    match &c.sharp {
        Some(s) if s.at_printed_digits() => format!("{} (gone at ε = 1e-7)", c.explained_by),
        _ => c.explained_by.clone(),
    }
}

/// Eqs 29 and 54-55: the steady motion spinning in place and its small oscillations.
fn steady(t: &Thickness) -> Result<StudyTable, ReportError> {
    let values = serde_json::json!({
        "a_mm": (TOY.0 * 1e3).to_string(),
        "thickness_mm": (TOY.1 * 1e3).to_string(),
        "fillet_mm": (TOY.2 * 1e3).to_string(),
    });
    let mut s = table(
        &super::ABOUT.templates,
        "table-steady",
        &values,
        &[
            "α₀ (rad)",
            "Ω₀ thin, eq 29 (rad/s)",
            "Ω₀ toy (rad/s)",
            "change",
            "ω₁ toy (rad/s)",
            "ϖ thin (rad/s)",
            "ϖ toy (rad/s)",
            "change",
        ],
    )?;
    let tau = 2.0 * std::f64::consts::PI;
    for r in &t.steady {
        s.row(vec![
            places(r.alpha0, 1),
            places(r.eq29, 3),
            places(r.toy, 3),
            format!("{:+.1} %", 100.0 * (r.toy / r.eq29 - 1.0)),
            places(r.toy_spin, 3),
            places(tau / r.thin_period, 2),
            places(tau / r.toy_period, 2),
            format!("{:+.1} %", 100.0 * (r.thin_period / r.toy_period - 1.0)),
        ]);
    }
    Ok(s)
}

/// Eqs 79-81: the spin-down law's constant and where contact would be lost.
fn spin_down(t: &Thickness) -> Result<StudyTable, ReportError> {
    let (epsilon, beta) = DRAG;
    let values = serde_json::json!({
        "start": SPIN_DOWN_START.to_string(),
        "beta": beta.to_string(),
        "epsilon": scientific(epsilon, 2),
        "fit_from": FIT_TILTS.0.to_string(),
        "fit_to": FIT_TILTS.1.to_string(),
    });
    let mut s = table(
        &super::ABOUT.templates,
        "table-spin-down",
        &values,
        &[
            "quantity",
            "eq 79-80 printed, thin",
            "thin",
            "toy",
            "toy / thin",
        ],
    )?;
    let [thin, toy] = [&t.spin_down[0], &t.spin_down[1]];
    let ratio = |f: fn(&SpinDownLaw) -> f64| places(f(toy) / f(thin), 3);
    s.row(vec![
        "C of eq 79 (1/s³)".into(),
        scientific(t.eq79_c, 3),
        scientific(thin.c, 3),
        scientific(toy.c, 3),
        ratio(|l| l.c),
    ]);
    // A quantity of both disks' laws, scaled, with the toy's over the thin disk's when asked.
    let mut law_row =
        |what: &str, paper: String, of: fn(&SpinDownLaw) -> f64, scale: f64, with_ratio: bool| {
            s.row(vec![
                what.into(),
                paper,
                places(of(thin) * scale, 3),
                places(of(toy) * scale, 3),
                if with_ratio { ratio(of) } else { "–".into() },
            ]);
        };
    law_row(
        "eq 85's exponent β + 3",
        places(beta + 3.0, 0),
        |l| l.exponent,
        1.0,
        false,
    );
    let eq80 = format!("{} (eq 80, fitted C)", places(t.eq80_thin.1 * 1e3, 3));
    law_row(
        "tilt of lost contact (mrad)",
        eq80,
        |l| l.loss_tilt,
        1e3,
        true,
    );
    law_row(
        "t₀ − t there (ms)",
        "–".into(),
        |l| l.loss_before_t0,
        1e3,
        true,
    );
    let least = |l: &SpinDownLaw| l.least_normal.0;
    law_row(
        "least F_z / m g in the run",
        "0 (eq 80)".into(),
        least,
        1.0,
        false,
    );
    Ok(s)
}

/// Sec. 7's fall "to about 60°": thin and toy from the thin disk's unstable band, each by what
/// its tilt does over the run.
fn fall(t: &Thickness) -> Result<StudyTable, ReportError> {
    let values = serde_json::json!({
        "time": FALL_TIME.to_string(),
        "left": FALL_LEFT.to_string(),
    });
    let mut s = table(
        &super::ABOUT.templates,
        "table-fall",
        &values,
        &[
            "α₀ (°)",
            "b / a",
            "Ω₀ thin (rad/s)",
            "Ω₀ toy (rad/s)",
            "thin: tilt (°), mean",
            "toy: tilt (°), mean",
        ],
    )?;
    let cell = |x: Option<&Swing>| {
        x.map_or("–".into(), |w| {
            format!(
                "{}–{}, {}; {}",
                places(w.min_deg, 1),
                places(w.max_deg, 1),
                places(w.mean_deg, 1),
                if w.settles { "settles" } else { "nutates" }
            )
        })
    };
    for f in &t.falls {
        s.row(vec![
            places(f.alpha0_deg, 0),
            places(f.b_over_a, 3),
            places(f.precession.0, 3),
            f.precession.1.map_or("–".into(), |v| places(v, 3)),
            cell(Some(&f.swing.0)),
            cell(f.swing.1.as_ref()),
        ]);
    }
    Ok(s)
}

/// The section, its tables ([`tables`]) numbered already; `figures` are the numbers of the
/// agreement figures.
pub fn section(
    t: &Toy,
    tables: Vec<StudyTable>,
    figures: &[usize],
) -> Result<StudySection, ReportError> {
    Ok(StudySection {
        title: "The real toy, and an independent program".into(),
        summary: summary(t, &tables, figures)?,
        output: output(&tables),
        output_title: "The toy's tables as text".into(),
        tables,
    })
}

/// " (Table N)" for the `i`th of `tables`.
fn cite(tables: &[StudyTable], i: usize) -> String {
    tables
        .get(i)
        .map_or(String::new(), |t| format!(" (Table {})", t.number))
}

/// The runs that end a slip, split at the peer's relock ([`studies::peer::relock`]): their
/// names, and how closely they agree before and after the split and over the whole run.
fn relocked(t: &Toy) -> serde_json::Value {
    let slip_ends: Vec<(&str, studies::peer::relock::RelockSplit)> = t
        .peer
        .iter()
        .filter(|c| c.explained_by.contains("relock at a print step"))
        .filter_map(|c| c.relock.map(|r| (c.name.as_str(), r)))
        .collect();
    let largest = |f: fn(&studies::peer::relock::RelockSplit) -> f64| {
        scientific(slip_ends.iter().map(|(_, r)| f(r)).fold(0.0, f64::max), 1)
    };
    serde_json::json!({
        "names": slip_ends.iter().map(|(n, _)| *n).collect::<Vec<_>>(),
        "before": largest(|r| r.before),
        "after": largest(|r| r.after),
        "whole": scientific(
            slip_ends.iter().map(|(_, r)| r.whole).fold(f64::INFINITY, f64::min),
            1
        ),
    })
}

/// What was compared and found, and for each of the paper's numbers whether its conclusion
/// survives for the toy.
fn summary(t: &Toy, tables: &[StudyTable], figures: &[usize]) -> Result<String, ReportError> {
    let at = t
        .peer
        .iter()
        .filter(|c| c.regularized.at_printed_digits())
        .count();
    let sharp = t
        .peer
        .iter()
        .filter(|c| c.sharp.as_ref().is_some_and(Differences::at_printed_digits))
        .count();
    let worst = t
        .peer
        .iter()
        .map(|c| c.regularized.tilt)
        .fold(0.0, f64::max);
    let th = &t.thickness;
    let change = |f: &dyn Fn(&studies::thickness::SteadyPair) -> f64| {
        th.steady
            .iter()
            .map(|r| serde_json::json!({ "change": f(r), "alpha0": r.alpha0 }))
            .collect::<Vec<_>>()
    };
    let [thin, toy] = [&th.spin_down[0], &th.spin_down[1]];
    let values = serde_json::json!({
        "n": t.peer.len(),
        "t0": cite(tables, 0),
        "t1": cite(tables, 1),
        "t2": tables
            .get(2..4)
            .map_or(String::new(), |t| format!(" ({})", crate::study_table::cite(t))),
        "closest": t
            .peer
            .iter()
            .map(|c| c.closest_to_upright)
            .fold(f64::INFINITY, f64::min),
        "early": t
            .peer
            .iter()
            .filter(|c| c.regularized.peer_end < c.regularized.tool_end - 2e-3)
            .map(|c| c.name.as_str())
            .collect::<Vec<_>>(),
        "ns": t.peer.iter().filter(|c| c.sharp.is_some()).count(),
        "relock": relocked(t),
        "restarted": t
            .peer
            .iter()
            .filter(|c| c.restarted)
            .map(|c| c.name.as_str())
            .collect::<Vec<_>>()
            .join(", "),
        "rest": scientific(
            t.peer
                .iter()
                .filter(|c| c.restarted)
                .filter_map(|c| c.sharp.as_ref().map(|d| d.tilt))
                .fold(0.0, f64::max),
            2
        ),
        "worst": scientific(worst, 2),
        "om": change(&|r| r.toy / r.eq29 - 1.0),
        "w": change(&|r| r.thin_period / r.toy_period - 1.0),
        "te": places(toy.exponent, 2),
        "ti": places(thin.exponent, 2),
        "cr": places(toy.c / thin.c, 2),
        "pc": places(th.eq79_c / thin.c, 2),
        "lt": places(toy.loss_tilt * 1e3, 2),
        "li": places(thin.loss_tilt * 1e3, 2),
        "nt": places(toy.least_normal.0, 2),
        "t4": cite(tables, 4),
        "falls": th
            .falls
            .iter()
            .map(|f| {
                serde_json::json!({
                    "alpha0_deg": f.alpha0_deg,
                    "toy": f.swing.1,
                    "thin": f.swing.0,
                })
            })
            .collect::<Vec<_>>(),
        "falls_settle": th
            .falls
            .iter()
            .any(|f| f.swing.0.settles || f.swing.1.is_some_and(|w| w.settles)),
        "toy_swings_lower": th.falls.iter().all(|f| {
            f.swing
                .1
                .is_none_or(|w| w.mean_deg < f.swing.0.mean_deg && w.min_deg < f.swing.0.min_deg)
        }),
        "ni": places(thin.least_normal.0, 2),
        "eq30": super::steady_table::edges(&t.steady, &cite(tables, 5)),
        "at": at,
        "sharp": sharp,
        "figures": figures,
    });
    paragraph(&super::ABOUT.templates, "summary", &values)
}

/// `text` in ASCII, for the LaTeX appendix's listing: the Greek letters and sub- and
/// superscripts of the tables spelled out.
fn ascii(text: &str) -> String {
    let mut o = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            'α' => o.push_str("alpha"),
            'β' => o.push_str("beta"),
            'ε' => o.push_str("eps"),
            'ϖ' => o.push_str("varpi"),
            'ω' => o.push_str("omega"),
            'Ω' => o.push_str("Omega"),
            'Δ' => o.push('d'),
            'π' => o.push_str("pi"),
            'μ' => o.push_str("mu"),
            '₀' => o.push('0'),
            '₁' => o.push('1'),
            '²' => o.push_str("^2"),
            '³' => o.push_str("^3"),
            '°' => o.push_str(" deg"),
            '−' | '–' => o.push('-'),
            c if c.is_ascii() => o.push(c),
            _ => o.push('?'),
        }
    }
    o
}

/// The tables as text, for the disclosure and the appendix: a caption's formulas written plain
/// ([`crate::inline_math::plain`]), then in ASCII.
fn output(tables: &[StudyTable]) -> String {
    let mut o = String::new();
    for t in tables {
        let caption = crate::inline_math::plain(&t.caption);
        let _ = writeln!(o, "Table {}: {caption}", t.number);
        let _ = writeln!(o, "  {}", t.columns.join(" | "));
        for r in &t.rows {
            let _ = writeln!(o, "  {}", r.join(" | "));
        }
        o.push('\n');
    }
    ascii(&o)
}
