//! A fitted end that the record contradicts: eq 79's $t_0$ is where the rate diverges and the
//! disk stops turning, so every pulse the disk makes comes before it. A fitted $t_0$ before the
//! last pulse the analysis detected is physically impossible: the law the fit found ends too
//! early (over the fitting window it follows a law that does not hold up to the end).
//!
//! The last detected pulse is the last peak spanning at least the analysis's `min_snr` noise
//! deviations, the criterion that tells the disk's pulses from noise and hum.

use crate::light_analysis::peak::Peak;
use serde::Serialize;

/// The fitted $t_0$ lies before the last detected pulse.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct EarlyEnd {
    /// The fitted $t_0$ (s).
    pub t0: f64,
    /// The last detected pulse's time (s).
    pub last_peak: f64,
    /// How far $t_0$ lies before it (s, positive).
    pub before: f64,
    /// That distance in $t_0$'s stated uncertainty.
    pub sigmas: f64,
    /// The finding in words.
    pub message: String,
}

/// The finding when `t0` (stated uncertainty `t0_sigma`) lies before the last of `peaks`
/// spanning at least `min_span` volts; `None` otherwise.
pub fn early_end(t0: f64, t0_sigma: f64, peaks: &[Peak], min_span: f64) -> Option<EarlyEnd> {
    let last = peaks.iter().rev().find(|p| p.span >= min_span)?.t;
    if t0 >= last {
        return None;
    }
    let before = last - t0;
    let sigmas = before / t0_sigma;
    Some(EarlyEnd {
        t0,
        last_peak: last,
        before,
        sigmas,
        message: format!(
            "the fitted t0 lies {:.1} ms ({sigmas:.1} stated sigmas) before the last detected \
             peak at {last:.4} s: the law ends too early",
            1e3 * before
        ),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn peak(t: f64, span: f64) -> Peak {
        Peak {
            t,
            sigma: 1e-5,
            rise: t - 1e-4,
            fall: t + 1e-4,
            span,
            height: span / 2.0,
            slope: 1.0,
        }
    }

    #[test]
    fn an_end_before_the_last_pulse_is_flagged_and_noise_is_not_a_pulse() {
        let peaks = [peak(7.20, 1.0), peak(7.265, 0.5), peak(7.30, 0.01)];
        let e = early_end(7.2541, 0.0016, &peaks, 0.1).unwrap();
        assert!((e.before - 0.0109).abs() < 1e-9, "{e:?}");
        assert!((e.sigmas - 0.0109 / 0.0016).abs() < 1e-9, "{e:?}");
        assert!(
            e.message.contains("10.9 ms") && e.message.contains("7.2650 s"),
            "{e:?}"
        );
        assert_eq!(early_end(7.27, 0.0016, &peaks, 0.1), None);
        assert_eq!(early_end(7.0, 0.0016, &peaks, 2.0), None);
    }
}
