//! The ranges a chart is drawn over: the data's bounds with margins (linear or logarithmic), the
//! check that a fixed range can be drawn, and the grid of a [`super::Style::Cells`] map.

use crate::figures::FigureError;

pub(super) fn bounds(values: impl Iterator<Item = f64>, log: bool) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in values.filter(|v| v.is_finite() && (!log || *v > 0.0)) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if !lo.is_finite() {
        return if log { (0.1, 10.0) } else { (-1.0, 1.0) };
    }
    if log {
        let (l, h) = (lo.log10(), hi.log10());
        let pad = ((h - l) * 0.05).max(0.05);
        (10f64.powf(l - pad), 10f64.powf(h + pad))
    } else {
        let span = hi - lo;
        let pad = if span > 0.0 {
            0.05 * span
        } else {
            0.5 * lo.abs().max(1e-12)
        };
        (lo - pad, hi + pad)
    }
}

/// The smallest positive spacing between distinct sorted values (the size of a grid's cell).
pub(super) fn grid_step(mut v: Vec<f64>) -> f64 {
    v.retain(|x| x.is_finite());
    v.sort_by(f64::total_cmp);
    let span = v.last().copied().unwrap_or(0.0) - v.first().copied().unwrap_or(0.0);
    v.windows(2)
        .map(|w| w[1] - w[0])
        .filter(|d| *d > 1e-12 * span.abs().max(1e-300))
        .fold(f64::INFINITY, f64::min)
}

/// Cells in columns: runs of cells with the same x and consecutive y (spacing `2 hy`) merged
/// into (x, first y, last y), so that a map draws as few rectangles as it has runs.
pub(super) fn merge_cells(mut pts: Vec<(f64, f64)>, hy: f64) -> Vec<(f64, f64, f64)> {
    pts.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    let mut out: Vec<(f64, f64, f64)> = Vec::new();
    for (x, y) in pts {
        match out.last_mut() {
            Some(last) if last.0 == x && (y - last.2) <= 2.0 * hy * 1.001 => last.2 = y,
            _ => out.push((x, y, y)),
        }
    }
    out
}

pub(super) fn checked(r: (f64, f64), log: bool, what: &str) -> Result<(f64, f64), FigureError> {
    let ok = r.0.is_finite() && r.1.is_finite() && r.1 > r.0 && (!log || r.0 > 0.0);
    if ok {
        Ok(r)
    } else {
        Err(format!(
            "the {what} range {:?} cannot be drawn (it must be finite, increasing, and positive on a log axis)",
            r
        ).into())
    }
}
