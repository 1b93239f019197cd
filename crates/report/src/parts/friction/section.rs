//! The "Friction and contact" section as the paper would print it: a paragraph of what was run
//! and found, and the studies' numbers in tables (the full output is [`super::listing`]).

use crate::error::ReportError;
use crate::number::{measured, places as fixed, prose, scientific};
use crate::parts::prose::{paragraph, table};
use crate::study_table::{StudySection, StudyTable};
use studies::sliding::Studies;

/// The section's tables.
pub fn tables(s: &Studies) -> Result<Vec<StudyTable>, ReportError> {
    let templates = &super::ABOUT.templates;
    let none = serde_json::json!({});
    let mut onset = table(
        templates,
        "table-onset",
        &none,
        &[
            "α₀ (rad)",
            "μ",
            "b, eq 42 (mm)",
            "b, integrated (mm)",
            "relative error",
        ],
    )?;
    for r in &s.slip_onset {
        onset.row(vec![
            fixed(r.alpha0, 2),
            fixed(r.mu, 2),
            fixed(r.b_eq42 * 1e3, 4),
            fixed(r.b_integrated * 1e3, 4),
            fixed(r.relative_error, 3),
        ]);
    }
    let mut negative = table(
        templates,
        "table-negative",
        &none,
        &[
            "α₀ (rad)",
            "μ",
            "μ eq 43 needs",
            "b / b_edge held, integrated",
            "held, exact",
        ],
    )?;
    for r in &s.negative_b {
        negative.row(vec![
            fixed(r.alpha0, 2),
            fixed(r.mu, 2),
            fixed(r.mu_eq43, 3),
            fixed(r.beta_integrated, 4),
            fixed(r.beta_exact, 4),
        ]);
    }
    let mut spiral = table(
        templates,
        "table-spiral",
        &serde_json::json!({ "duration": studies::sliding::spiral::DURATION.to_string() }),
        &[
            "α₀ (rad)",
            "b₀ (mm)",
            "μ",
            "|b|, eq 42 (mm)",
            "slid (s)",
            "radius at end (mm)",
            "α at end (rad)",
        ],
    )?;
    for r in &s.spiral {
        spiral.row(vec![
            fixed(r.alpha0, 2),
            fixed(r.b0 * 1e3, 1),
            fixed(r.mu, 2),
            fixed(r.b_eq42 * 1e3, 3),
            fixed(r.slip_time, 3),
            r.radius_end.map_or("halted".into(), |x| fixed(x * 1e3, 3)),
            fixed(r.alpha_end, 3),
        ]);
    }
    Ok(vec![
        onset,
        negative,
        spiral,
        rising(s)?,
        contact(s)?,
        mechanisms(s)?,
    ])
}

/// Sec. 10: the rising of a disk launched nearly upright.
fn rising(s: &Studies) -> Result<StudyTable, ReportError> {
    let ri = &s.rising;
    let values = serde_json::json!({
        "tilt": format!("{:.0}", ri.launch_tilt_deg),
        "rate": format!("{:.1}", ri.launch_rate),
        "slip": format!("{:.3}", ri.launch_slip),
        "duration": studies::sliding::rising::DURATION.to_string(),
    });
    let mut t = table(
        &super::ABOUT.templates,
        "table-rising",
        &values,
        &[
            "contact",
            "μ",
            "gain of tilt (°)",
            "highest tilt (°)",
            "slid (s)",
        ],
    )?;
    for c in &ri.cases {
        t.row(vec![
            c.contact.to_string(),
            fixed(c.mu, 2),
            fixed(c.rise_deg, 3),
            fixed(c.highest_deg, 2),
            if c.mu == 0.0 {
                "–".into()
            } else {
                fixed(c.slip_time.max(0.0), 3)
            },
        ]);
    }
    Ok(t)
}

/// Eqs 80-81's premise: whether the spinning-down disk slips or lifts before its end.
fn contact(s: &Studies) -> Result<StudyTable, ReportError> {
    let mut t = table(
        &super::ABOUT.templates,
        "table-contact",
        &serde_json::json!({}),
        &[
            "μ",
            "first slip, t (s)",
            "α there (°)",
            "Ω there (rad/s)",
            "least F_z / m g",
            "the run ends",
        ],
    )?;
    for c in &s.contact_loss {
        let at = |f: fn(&studies::sliding::contact_loss::Moment) -> String| {
            c.first_slip.as_ref().map_or("–".to_string(), f)
        };
        let ends = match (c.first_slip, c.lift_off) {
            (Some(_), _) => "at the first slip".to_string(),
            (None, Some(m)) => format!("contact lost at {:.3} s", m.t),
            (None, None) => format!("never slips nor lifts; α = 1e-4 rad at {:.3} s", c.end.t),
        };
        t.row(vec![
            fixed(c.mu, 2),
            c.first_slip.map_or("never".into(), |m| fixed(m.t, 3)),
            at(|m| fixed(m.alpha.to_degrees(), 3)),
            at(|m| fixed(m.omega, 1)),
            fixed(c.min_normal_rolling, 3),
            ends,
        ]);
    }
    Ok(t)
}

/// Beyond the paper: each dissipation mechanism alone, fitted by the experiment's eq 84.
fn mechanisms(s: &Studies) -> Result<StudyTable, ReportError> {
    let m = &s.mechanisms;
    let mut t = table(
        &super::ABOUT.templates,
        "table-mechanisms",
        &serde_json::json!({ "omega": format!("{:.0}", m.omega_cal) }),
        &[
            "mechanism",
            "coefficient",
            "its β",
            "β fitted",
            "turns",
            "Ω (rad/s)",
        ],
    )?;
    for r in &m.spin_downs {
        let unit = if r.unit == "1" {
            String::new()
        } else {
            format!(" {}", r.unit)
        };
        t.row(vec![
            r.mechanism.clone(),
            format!("{}{unit}", scientific(r.coefficient, 3)),
            fixed(r.exponent, 1),
            match (r.beta, &r.refused) {
                (Some((b, e)), None) => measured(b, e),
                (_, Some(_)) => "refused".into(),
                (None, None) => "–".into(),
            },
            r.fitted.to_string(),
            format!("{:.0}–{:.0}", r.omega_range.0, r.omega_range.1),
        ]);
    }
    Ok(t)
}

/// The section, its tables ([`tables`]) numbered already; `figures` are the numbers of the
/// slip-stick figures. Its paragraph is `templates/parts/friction/summary.txt.tera`.
pub fn section(
    s: &Studies,
    paper: &paper::Paper,
    tables: Vec<StudyTable>,
    figures: &[usize],
) -> Result<StudySection, ReportError> {
    Ok(StudySection {
        title: "Friction and contact".into(),
        summary: summary(s, paper, &tables, figures)?,
        tables,
        output: prose(&super::listing::listing(s, paper)?),
        output_title: "The studies' full output: every run, the fall study run by run, the notes"
            .into(),
    })
}

/// " (Table N)", the number of the `i`th of `tables`.
fn cite(tables: &[StudyTable], i: usize) -> String {
    tables
        .get(i)
        .map_or(String::new(), |t| format!(" (Table {})", t.number))
}

/// What was run and what was found, in a paragraph citing `tables` (as [`tables`] orders them)
/// and the slip-stick `figures`.
pub fn summary(
    s: &Studies,
    paper: &paper::Paper,
    tables: &[StudyTable],
    figures: &[usize],
) -> Result<String, ReportError> {
    let (lo, hi) = s
        .slip_onset
        .iter()
        .map(|r| r.relative_error.abs() * 100.0)
        .fold((f64::INFINITY, 0.0_f64), |(lo, hi), e| {
            (lo.min(e), hi.max(e))
        });
    let below: Vec<_> = s.negative_b.iter().filter(|r| r.mu < r.mu_eq43).collect();
    let held_below = below.iter().filter(|r| r.beta_integrated > 0.0).count();
    let never = s
        .contact_loss
        .iter()
        .filter(|c| c.first_slip.is_none() && c.lift_off.is_none())
        .map(|c| fixed(c.mu, 2))
        .collect::<Vec<_>>();
    let two: Vec<&str> = s
        .mechanisms
        .spin_downs
        .iter()
        .filter(|r| r.gives(2.0))
        .map(|r| r.mechanism.as_str())
        .collect();
    let values = serde_json::json!({
        "lo": format!("{lo:.1}"),
        "hi": format!("{hi:.0}"),
        "held_below": held_below,
        "below": below.len(),
        "cite": (0..6).map(|i| cite(tables, i)).collect::<Vec<_>>(),
        "never": never,
        "two": two,
        "fall": fall(&s.fall, paper),
        "slip_stick": figures,
    });
    paragraph(&super::ABOUT.templates, "summary", &values)
}

/// The fall study's numbers: how fast the disk falls, how often it settles into a lower steady
/// rolling, and how often there at the claimed tilt (judged on the motion over the run).
fn fall(f: &studies::sliding::fall::Fall, paper: &paper::Paper) -> Option<serde_json::Value> {
    let (claimed, within) = super::listing::fall_claim(paper)?;
    let (lo, hi) = (claimed * (1.0 - within), claimed * (1.0 + within));
    let slowest = f
        .cases
        .iter()
        .filter_map(|c| c.fall_periods)
        .fold(0.0, f64::max);
    let held = f
        .cases
        .iter()
        .filter(|c| super::listing::bears_out(&c.swing, lo, hi))
        .count();
    let settled: Vec<f64> = f
        .cases
        .iter()
        .filter(|c| c.swing.settles)
        .filter_map(|c| c.swing.late_mean_deg)
        .collect();
    let nutating = f.cases.iter().filter(|c| !c.swing.settles);
    Some(serde_json::json!({
        "slowest": format!("{slowest:.2}"),
        "claimed": format!("{claimed:.0}"),
        "lo": format!("{lo:.0}"),
        "hi": format!("{hi:.0}"),
        "held": held,
        "below": f.cases.iter().filter(|c| super::listing::settles_at_most(c, hi)).count(),
        "runs": f.cases.len(),
        "settled": settled.len(),
        "settled_lo": format!("{:.1}", settled.iter().copied().fold(f64::INFINITY, f64::min)),
        "settled_hi": format!("{:.1}", settled.iter().copied().fold(f64::NEG_INFINITY, f64::max)),
        "settled_slid": f.cases.iter().filter(|c| c.swing.settles).all(|c| c.slipped),
        "nutating_mean_lo": format!("{:.1}", nutating.clone().map(|c| c.swing.mean_deg).fold(f64::INFINITY, f64::min)),
        "nutating_mean_hi": format!("{:.1}", nutating.map(|c| c.swing.mean_deg).fold(f64::NEG_INFINITY, f64::max)),
    }))
}
