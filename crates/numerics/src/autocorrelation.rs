//! The sample lag-one autocorrelation of a series, shared by the fits' covariance (the error
//! inflation of correlated residuals), the phase fit's structure test and the residuals' figure.

/// $\hat\rho = \sum_{k=1}^{n-1} (r_k - \bar r)(r_{k+1} - \bar r) / \sum_{k=1}^{n} (r_k - \bar r)^2$;
/// 0 below three values or where they do not vary.
pub fn lag_one(r: &[f64]) -> f64 {
    let n = r.len();
    if n < 3 {
        return 0.0;
    }
    let m = r.iter().sum::<f64>() / n as f64;
    let c0: f64 = r.iter().map(|x| (x - m).powi(2)).sum();
    let c1: f64 = r.windows(2).map(|w| (w[0] - m) * (w[1] - m)).sum();
    if c0 > 0.0 {
        c1 / c0
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::lag_one;

    #[test]
    fn alternation_is_anticorrelated_and_a_ramp_correlated() {
        let alternating: Vec<f64> = (0..100)
            .map(|k| if k % 2 == 0 { 1.0 } else { -1.0 })
            .collect();
        assert!((lag_one(&alternating) + 0.99).abs() < 1e-12);
        let ramp: Vec<f64> = (0..100).map(f64::from).collect();
        assert!(lag_one(&ramp) > 0.95);
        assert_eq!(lag_one(&[1.0, 1.0, 1.0]), 0.0);
        assert_eq!(lag_one(&[1.0, 2.0]), 0.0);
    }
}
