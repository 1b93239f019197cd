//! The physical ranges of the command line's numeric options: each option's value parser
//! refuses a value outside its range with the range, so that a number without meaning (a hum
//! of 1e300 V, mains at 1 GHz) never reaches a computation.

/// Where a range's end lies: on it (the end accepted) or beyond it (only values past it).
#[derive(Clone, Copy)]
enum End {
    On(f64),
    Past(f64),
}

/// A number between `lo` and `hi`, or a sentence naming the range (in the user's own digits).
fn within(s: &str, lo: End, hi: End, what: &str) -> Result<f64, String> {
    let range = match (lo, hi) {
        (End::On(a), End::On(b)) => format!("from {a} to {b}"),
        (End::Past(a), End::On(b)) => format!("above {a}, at most {b}"),
        (End::On(a), End::Past(b)) => format!("from {a} to below {b}"),
        (End::Past(a), End::Past(b)) => format!("above {a} and below {b}"),
    };
    let x: f64 = s
        .trim()
        .parse()
        .map_err(|_| format!("{s} is not a number; give {what} {range}"))?;
    let above = match lo {
        End::On(a) => x >= a,
        End::Past(a) => x > a,
    };
    let below = match hi {
        End::On(b) => x <= b,
        End::Past(b) => x < b,
    };
    if x.is_finite() && above && below {
        Ok(x)
    } else {
        Err(format!("{s} is outside the range; give {what} {range}"))
    }
}

/// A fraction of the signal's span, 0 to 1 (`--drift`, `--hum`).
pub(crate) fn fraction(s: &str) -> Result<f64, String> {
    within(
        s,
        End::On(0.0),
        End::On(1.0),
        "a fraction of the signal's span",
    )
}

/// A mains frequency, 10 to 1000 Hz: the grids run at 50 or 60 Hz, railways at 16.7, aircraft
/// at 400.
pub(crate) fn mains_hz(s: &str) -> Result<f64, String> {
    within(s, End::On(10.0), End::On(1000.0), "a mains frequency in Hz")
}

/// The fraction of the signal's range kept below the clipping, above 0 and at most 1 (1 clips
/// nothing) (`--clip`).
pub(crate) fn clip(s: &str) -> Result<f64, String> {
    within(
        s,
        End::Past(0.0),
        End::On(1.0),
        "the fraction of the range kept",
    )
}

/// Isolated glitches per second, 0 to [`experiment::synthetic::artifacts::MAX_GLITCHES_PER_S`]:
/// more is noise, not glitches (`--glitches`).
pub(crate) fn glitches(s: &str) -> Result<f64, String> {
    use experiment::synthetic::artifacts::MAX_GLITCHES_PER_S;
    within(
        s,
        End::On(0.0),
        End::On(MAX_GLITCHES_PER_S),
        "isolated glitches per second",
    )
}

/// The fraction of samples dropped, 0 to below a half (`--dropped`).
pub(crate) fn dropped(s: &str) -> Result<f64, String> {
    within(
        s,
        End::On(0.0),
        End::Past(0.5),
        "the fraction of samples dropped",
    )
}

/// A wall-time budget in seconds, above 0 and at most a day, 86400 s (`--max-seconds`; the
/// range `physics::budget::set_wall_seconds` takes).
pub(crate) fn seconds(s: &str) -> Result<f64, String> {
    within(s, End::Past(0.0), End::On(86_400.0), "a number of seconds")
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
        // Open ends: the end itself refused, a value just inside accepted.
        assert!(clip("0").unwrap_err().contains("above 0, at most 1"));
        assert_eq!(clip("1"), Ok(1.0));
        assert!(dropped("0.5").unwrap_err().contains("from 0 to below 0.5"));
        assert_eq!(dropped("0.499"), Ok(0.499));
        assert!(glitches("-1").unwrap_err().contains("from 0 to 1000"));
        assert!(seconds("0").is_err() && seconds("1e300").unwrap_err().contains("1e300 is"));
        assert_eq!(seconds("86400"), Ok(86400.0));
    }
}
