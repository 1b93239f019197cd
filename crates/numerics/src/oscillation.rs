//! Frequencies measured on sampled signals, and thresholds located by bisection.

/// The angular frequency of an oscillating signal `x(t)` sampled at times `t`: the mean period
/// between successive upward crossings of its mean level, each crossing located by cubic
/// interpolation through the four samples around it. `None` with fewer than two crossings.
pub fn angular_frequency(t: &[f64], x: &[f64]) -> Option<f64> {
    let n = t.len().min(x.len());
    if n < 4 {
        return None;
    }
    let mean = x[..n].iter().sum::<f64>() / n as f64;
    let mut crossings = Vec::new();
    for i in 1..n - 2 {
        let (a, b) = (x[i] - mean, x[i + 1] - mean);
        if a < 0.0 && b >= 0.0 {
            crossings.push(cubic_root(&t[i - 1..i + 3], &x[i - 1..i + 3], mean));
        }
    }
    if crossings.len() < 2 {
        return None;
    }
    let periods = (crossings.len() - 1) as f64;
    let period = (crossings[crossings.len() - 1] - crossings[0]) / periods;
    Some(2.0 * std::f64::consts::PI / period)
}

/// Where the cubic through four points `(t, x)` crosses `level` upward between the middle two
/// (`x[1] <= level <= x[2]`), by bisection on the Lagrange interpolant.
pub fn cubic_root(t: &[f64], x: &[f64], level: f64) -> f64 {
    let p = |s: f64| {
        let mut sum = 0.0;
        for i in 0..4 {
            let mut l = 1.0;
            for j in 0..4 {
                if i != j {
                    l *= (s - t[j]) / (t[i] - t[j]);
                }
            }
            sum += x[i] * l;
        }
        sum - level
    };
    let (mut lo, mut hi) = (t[1], t[2]);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if p(mid) < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// Bisection on a predicate that is false at `lo` and true at `hi` (or the reverse): returns the
/// final bracket, narrowed until its width is below `rel_width` times its upper end.
///
/// A predicate that answers the same at both ends (an integration cut short by the wall-time
/// budget, a user's equation with no edge in the bracket) has no edge to locate: the bracket
/// returned is then `(NaN, NaN)`, so that every number computed from it is not a number and the
/// caller reports a reference that could not be located, never a value and never a panic.
pub fn bisect(lo: f64, hi: f64, rel_width: f64, holds: impl Fn(f64) -> bool) -> (f64, f64) {
    let at_lo = holds(lo);
    if at_lo == holds(hi) {
        return (f64::NAN, f64::NAN);
    }
    let narrow = |lo: f64, hi: f64| (hi - lo).abs() <= rel_width * hi.abs().max(lo.abs());
    try_bisect(lo, hi, narrow, |x| Some(holds(x) != at_lo)).unwrap_or((lo, hi))
}

/// The boundary between `lo` (predicate false) and `hi` (true), by bisection to an absolute
/// `width`; `None` when a run of the predicate fails.
pub fn bisect_to_width(
    lo: f64,
    hi: f64,
    width: f64,
    pred: impl Fn(f64) -> Option<bool>,
) -> Option<f64> {
    let narrow = |lo: f64, hi: f64| (hi - lo).abs() <= width;
    try_bisect(lo, hi, narrow, pred).map(|(lo, hi)| 0.5 * (lo + hi))
}

/// Bisection on a predicate that may fail to answer (`None`, e.g. an integration that could
/// not run): `holds` is taken false at `lo` and true at `hi`, the bracket is halved until
/// `narrow(lo, hi)` or until the midpoint is one of the ends (the last bit), and the first
/// `None` ends it with `None`. The one bisection loop of the crate: [`bisect`] is this with a
/// predicate that always answers. Written here rather than taken from a root-finding crate
/// (`roots`, `argmin`) because what the crate locates are the edges of predicates (a run slips
/// or does not, a Jacobian has a growing mode or not, a printed relation's two sides change
/// order), which those crates, built for real-valued functions, do not take.
pub fn try_bisect(
    mut lo: f64,
    mut hi: f64,
    narrow: impl Fn(f64, f64) -> bool,
    holds: impl Fn(f64) -> Option<bool>,
) -> Option<(f64, f64)> {
    while !narrow(lo, hi) {
        let mid = 0.5 * (lo + hi);
        if mid == lo || mid == hi {
            break;
        }
        if holds(mid)? {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Some((lo, hi))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_predicate_without_an_edge_gives_a_bracket_of_nans() {
        let (lo, hi) = bisect(0.0, 1.0, 1e-10, |_| true);
        assert!(lo.is_nan() && hi.is_nan());
        let (lo, hi) = bisect(0.0, 1.0, 1e-10, |x| x > 0.25);
        assert!((0.5 * (lo + hi) - 0.25).abs() < 1e-9, "{lo} {hi}");
    }

    #[test]
    fn a_cubic_crossing_is_found_exactly() {
        let f = |t: f64| 3.0 + 40.0 * t + 7.0 * t * t + 2.0 * t * t * t;
        let x = [0.0, 0.1, 0.2, 0.3];
        let s = cubic_root(&x, &x.map(f), f(0.137));
        assert!((s - 0.137).abs() < 1e-13, "{s}");
    }

    #[test]
    fn measures_the_frequency_of_a_sine() {
        let w = 7.3;
        let t: Vec<f64> = (0..4000).map(|i| i as f64 * 1e-3).collect();
        let x: Vec<f64> = t.iter().map(|t| 2.0 + 0.1 * (w * t + 0.4).sin()).collect();
        let m = angular_frequency(&t, &x).unwrap();
        assert!((m - w).abs() / w < 1e-9, "{m}");
    }

    #[test]
    fn bisects_to_the_width_asked() {
        let (lo, hi) = bisect(0.0, 10.0, 1e-10, |x| x * x > 2.0);
        assert!(lo < 2f64.sqrt() && hi >= 2f64.sqrt() && hi - lo < 1e-9);
    }
}
