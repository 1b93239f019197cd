//! Tick positions: at least three labelled ticks on every axis, whatever its range.
//!
//! plotters labels a logarithmic axis only at the powers of ten it spans (one label, or none,
//! on an axis shorter than a decade: the paper's tek728 had a single tick), and a narrow linear
//! axis at as few as one value. Log axes therefore get their ticks from here, bound to the axis
//! with plotters' `with_key_points`; linear axes keep plotters' nice numbers, with the density
//! hint raised until three of them fall inside the range.

use plotters::coord::ranged1d::{BoldPoints, Ranged};
use plotters::coord::types::RangedCoordf64;

/// Labelled and unlabelled ticks of a logarithmic axis over `lo..hi` (both > 0): the coarsest of
/// the mantissa sets {1}, {1, 3}, {1, 2, 5}, {1, 2, 3, 5}, {1, ..., 9} times the powers of ten
/// that puts three to ten ticks in range, every second or third power of ten on a long axis,
/// and evenly spaced values on an axis shorter than a factor of about 1.3. The unlabelled ticks
/// (grid lines) are every digit times the powers of ten when there are not too many.
pub fn log_ticks(lo: f64, hi: f64) -> (Vec<f64>, Vec<f64>) {
    if !(lo > 0.0 && hi > lo && lo.is_finite() && hi.is_finite()) {
        return (vec![], vec![]);
    }
    let (k0, k1) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
    let within = |v: f64| v >= lo * (1.0 - 1e-9) && v <= hi * (1.0 + 1e-9);
    let with = |mantissas: &[f64]| -> Vec<f64> {
        (k0..=k1)
            .flat_map(|k| mantissas.iter().map(move |m| m * 10f64.powi(k)))
            .filter(|v| within(*v))
            .collect()
    };
    let light: Vec<f64> = {
        let all = with(&[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0]);
        if all.len() <= 60 {
            all
        } else {
            with(&[1.0])
        }
    };
    let decades = with(&[1.0]);
    if decades.len() > 10 {
        let step = decades.len().div_ceil(8);
        return (decades.into_iter().step_by(step).collect(), light);
    }
    for set in [
        &[1.0][..],
        &[1.0, 3.0],
        &[1.0, 2.0, 5.0],
        &[1.0, 2.0, 3.0, 5.0],
        &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0],
    ] {
        let t = with(set);
        if (3..=10).contains(&t.len()) {
            return (t, light);
        }
    }
    // Shorter than a factor of about 1.3: four evenly spaced values at nice numbers.
    let step = nice_step((hi - lo) / 3.0);
    let first = (lo / step).ceil() * step;
    let t: Vec<f64> = (0..6)
        .map(|i| first + i as f64 * step)
        .filter(|v| within(*v))
        .collect();
    (t, light)
}

/// The nice number (1, 2 or 5 times a power of ten) nearest above `raw`.
fn nice_step(raw: f64) -> f64 {
    let p = 10f64.powf(raw.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * p)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * p)
}

/// The density hint, from `want` up, for which plotters puts at least three labelled ticks on a
/// linear axis over `lo..hi`.
pub fn linear_hint(lo: f64, hi: f64, want: usize) -> usize {
    let axis = RangedCoordf64::from(lo..hi);
    (want..=want.max(3) + 12)
        .find(|n| axis.key_points(BoldPoints(*n)).len() >= 3)
        .unwrap_or(want)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_log_axis_shorter_than_a_decade_has_three_ticks() {
        let (t, light) = log_ticks(0.0025, 0.012);
        assert!(t.len() >= 3, "{t:?}");
        assert!(light.len() >= t.len());
        let (t, _) = log_ticks(0.06, 7.0);
        assert!(t.len() >= 3, "{t:?}");
        let (t, _) = log_ticks(1e-16, 1e-2);
        assert!((3..=10).contains(&t.len()), "{t:?}");
        let (t, _) = log_ticks(100.0, 110.0);
        assert!(t.len() >= 3, "{t:?}");
    }

    #[test]
    fn a_narrow_linear_axis_gets_a_denser_hint() {
        let n = linear_hint(-0.4, 0.4, 4);
        let axis = RangedCoordf64::from(-0.4..0.4);
        assert!(axis.key_points(BoldPoints(n)).len() >= 3);
    }
}

/// A logarithmic axis with the ticks of [`log_ticks`]: maps a value by its base-10 logarithm
/// between the ends of `lo..hi`. It stands in for plotters' `LogCoord` wrapped in
/// `WithKeyPoints`, which rustc 1.95 instantiated twice in this crate (a duplicate-symbol link
/// error); the mapping is the one line of a log axis, the ticks are this module's.
#[derive(Debug, Clone)]
pub struct LogAxis {
    lo: f64,
    hi: f64,
    bold: Vec<f64>,
    light: Vec<f64>,
}

impl LogAxis {
    /// The axis over `lo..hi` (both > 0).
    pub fn new(lo: f64, hi: f64) -> Self {
        let (bold, light) = log_ticks(lo, hi);
        Self {
            lo,
            hi,
            bold,
            light,
        }
    }
}

impl Ranged for LogAxis {
    type FormatOption = plotters::coord::ranged1d::DefaultFormatting;
    type ValueType = f64;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        let (a, b) = (self.lo.log10(), self.hi.log10());
        let t = if b > a && *value > 0.0 {
            (value.log10() - a) / (b - a)
        } else {
            0.0
        };
        let px = limit.0 as f64 + t * (limit.1 - limit.0) as f64;
        px.clamp(-1e7, 1e7).round() as i32
    }

    fn key_points<Hint: plotters::coord::ranged1d::KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            self.light.clone()
        } else {
            self.bold.clone()
        }
    }

    fn range(&self) -> std::ops::Range<f64> {
        self.lo..self.hi
    }
}
