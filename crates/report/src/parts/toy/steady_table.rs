//! Eq 30 for the toy in the report: the toy's condition on $b$ beside the thin disk's, with the
//! sliding model's checks of it ([`studies::toy_steady`]), and what of eqs 29-30 survives for
//! the toy, as the part's summary template reads it.

use crate::error::ReportError;
use crate::number::{places, scientific};
use crate::parts::prose;
use crate::study_table::StudyTable;
use studies::toy_steady::{ToySteady, HOLD, OFFSET};

/// The table: one row per tilt.
pub fn table(t: &ToySteady) -> Result<StudyTable, ReportError> {
    let values = serde_json::json!({ "offset": OFFSET.to_string(), "hold": HOLD.to_string() });
    let mut s = prose::table(
        &super::ABOUT.templates,
        "table-edge",
        &values,
        &[
            "α₀ (°)",
            "b*/a thin",
            "b*/a toy",
            "toy's side",
            "Ω₀(b = 0) thin (rad/s)",
            "Ω₀(b = 0) toy (rad/s)",
            "steady found",
            "shot / closed form − 1",
            "held (rad)",
            "missed (rad)",
        ],
    )?;
    for r in &t.rows {
        s.row(vec![
            places(r.alpha0_deg, 0),
            format!("{:+.4}", r.thin_edge),
            format!("{:+.4}", r.toy_edge),
            if r.toy_above { "b > b*" } else { "b < b*" }.into(),
            places(r.thin_b0, 2),
            r.toy_b0.map_or("–".into(), |w| places(w, 2)),
            format!("{} / {}", r.roots_allowed, r.roots_forbidden),
            scientific(r.shot_error, 1),
            scientific(r.held, 1),
            scientific(r.missed, 1),
        ]);
    }
    Ok(s)
}

/// What of eqs 29-30 survives for the toy, as its summary's template reads it: the edges at the
/// first tilt, the tilts between which the toy has no steady motion with its centre at rest,
/// whether the sliding model found exactly the closed form's steady motions, and the table's
/// citation `cite`.
pub fn edges(t: &ToySteady, cite: &str) -> serde_json::Value {
    let (lo, hi) = t.no_spin_in_place_deg;
    let first = &t.rows[0];
    serde_json::json!({
        "cite": cite,
        "held": t.rows.iter().all(|r| r.roots_allowed == 1 && r.roots_forbidden == 0),
        "toy": first.toy_edge,
        "at": first.alpha0_deg,
        "thin": first.thin_edge,
        "lo": lo,
        "hi": hi,
    })
}
