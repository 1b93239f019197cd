//! Least-squares fits.

/// The slope of $\log y$ against $\log x$ by least squares: the order $n$ of $y \propto x^n$.
/// NaN when fewer than two points are usable (positive and finite).
pub fn log_log_slope(x: &[f64], y: &[f64]) -> f64 {
    let pts: Vec<(f64, f64)> = x
        .iter()
        .zip(y)
        .filter(|(a, b)| a.is_finite() && b.is_finite() && **a > 0.0 && **b > 0.0)
        .map(|(a, b)| (a.ln(), b.ln()))
        .collect();
    if pts.len() < 2 {
        return f64::NAN;
    }
    let n = pts.len() as f64;
    let (mx, my) = pts
        .iter()
        .fold((0.0, 0.0), |(sx, sy), (a, b)| (sx + a / n, sy + b / n));
    let (sxy, sxx) = pts.iter().fold((0.0, 0.0), |(sxy, sxx), (a, b)| {
        (sxy + (a - mx) * (b - my), sxx + (a - mx) * (a - mx))
    });
    sxy / sxx
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn recovers_a_power_law() {
        let x: Vec<f64> = (1..10).map(|i| 0.5f64.powi(i)).collect();
        let y: Vec<f64> = x.iter().map(|v| 3.0 * v.powf(2.5)).collect();
        assert!((log_log_slope(&x, &y) - 2.5).abs() < 1e-12);
        assert!(log_log_slope(&[1.0], &[1.0]).is_nan());
    }
}
