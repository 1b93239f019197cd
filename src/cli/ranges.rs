//! The physical ranges of the command line's numeric options: each option's value parser
//! refuses a value outside its range with the range, so that a number without meaning (a hum
//! of 1e300 V, mains at 1 GHz) never reaches a computation.

/// A number in `lo..=hi`, or a sentence naming the range.
fn within(s: &str, lo: f64, hi: f64, what: &str) -> Result<f64, String> {
    let x: f64 = s
        .trim()
        .parse()
        .map_err(|_| format!("{s} is not a number; give {what} from {lo} to {hi}"))?;
    if x.is_finite() && (lo..=hi).contains(&x) {
        Ok(x)
    } else {
        Err(format!(
            "{s} is outside {lo} to {hi}; give {what} in that range"
        ))
    }
}

/// A fraction of the signal's span, 0 to 1 (`--drift`, `--hum`).
pub(crate) fn fraction(s: &str) -> Result<f64, String> {
    within(s, 0.0, 1.0, "a fraction of the signal's span")
}

/// A mains frequency, 10 to 1000 Hz: the grids run at 50 or 60 Hz, railways at 16.7, aircraft
/// at 400.
pub(crate) fn mains_hz(s: &str) -> Result<f64, String> {
    within(s, 10.0, 1000.0, "a mains frequency in Hz")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_outside_a_range_are_refused_with_the_range_and_its_ends_accepted() {
        assert_eq!(fraction("1"), Ok(1.0));
        assert_eq!(fraction("0"), Ok(0.0));
        let e = fraction("1e300").unwrap_err();
        assert!(e.contains("0 to 1"), "{e}");
        assert!(fraction("NaN").is_err() && fraction("inf").is_err() && fraction("-0.1").is_err());
        assert_eq!(mains_hz("60"), Ok(60.0));
        assert!(mains_hz("1e9").unwrap_err().contains("10 to 1000"));
        assert!(mains_hz("abc").unwrap_err().contains("not a number"));
    }
}
