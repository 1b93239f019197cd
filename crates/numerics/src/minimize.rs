//! The minimum of a unimodal function of one variable by golden-section search. Hand-written:
//! ten lines, and the stability checks and studies need nothing a crate's minimiser adds.

/// The abscissa and value of the minimum of `f`, unimodal on `[lo, hi]`, bracketed to a width
/// of `tol` relative to $1 + |hi|$.
pub fn golden_min(mut lo: f64, mut hi: f64, tol: f64, f: impl Fn(f64) -> f64) -> (f64, f64) {
    let r = (5f64.sqrt() - 1.0) / 2.0;
    let (mut x1, mut x2) = (hi - r * (hi - lo), lo + r * (hi - lo));
    let (mut f1, mut f2) = (f(x1), f(x2));
    while hi - lo > tol * (1.0 + hi.abs()) {
        if f1 < f2 {
            (hi, x2, f2) = (x2, x1, f1);
            x1 = hi - r * (hi - lo);
            f1 = f(x1);
        } else {
            (lo, x1, f1) = (x1, x2, f2);
            x2 = lo + r * (hi - lo);
            f2 = f(x2);
        }
    }
    let x = 0.5 * (lo + hi);
    (x, f(x))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_the_vertex_of_a_parabola() {
        let (x, v) = golden_min(-3.0, 5.0, 1e-10, |x| (x - 1.25).powi(2) + 0.5);
        assert!((x - 1.25).abs() < 1e-8 && (v - 0.5).abs() < 1e-15);
    }
}
