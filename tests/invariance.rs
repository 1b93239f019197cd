//! Metamorphic tests of the experiment's analysis: the same recording with its clock started
//! elsewhere (epoch seconds), written in another unit, with its polarity reversed or with
//! silence added gives the same answer: the same model choice, and beta and t0 (from the
//! record's start) within their stated uncertainties. A clock so large that a second is below
//! its resolution is refused or analysed within seconds, never hangs.

use crate::common::{cli_in, temp_dir};
use std::path::Path;
use std::time::{Duration, Instant};

/// The samples `(t, v)` of a CSV written by `experiment simulate`.
fn samples(text: &str) -> Vec<(f64, f64)> {
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("time"))
        .filter_map(|l| {
            let (t, v) = l.split_once(',')?;
            Some((t.parse().ok()?, v.parse().ok()?))
        })
        .collect()
}

fn write_csv(path: &Path, header: &str, rows: &[(f64, f64)]) {
    let mut s = format!("{header}\n");
    for (t, v) in rows {
        s.push_str(&format!("{t:?},{v:?}\n"));
    }
    std::fs::write(path, s).expect("written");
}

/// What an analysis answers: the chosen law, beta and its sigma, t0 from the record's start
/// and its sigma, in seconds of the recording's own clock divided by `unit`.
#[derive(Debug)]
struct Answer {
    choice: String,
    laws: Vec<String>,
    beta: (f64, f64),
    t0: (f64, f64),
}

fn answer(dir: &Path, file: &str, origin: f64, unit: f64) -> Answer {
    let (ok, out, err) = cli_in(dir, &["experiment", "analyze", file, "--json"]);
    assert!(ok, "{file}: {err}");
    let j: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let num = |p: &str| {
        j.pointer(p)
            .and_then(serde_json::Value::as_f64)
            .unwrap_or(f64::NAN)
    };
    let laws: Vec<String> = j
        .pointer("/models/candidates")
        .and_then(|c| c.as_array())
        .map(|c| {
            c.iter()
                .filter_map(|x| x.get("name").and_then(|n| n.as_str()).map(String::from))
                .collect()
        })
        .unwrap_or_default();
    Answer {
        choice: laws.first().cloned().unwrap_or_default(),
        laws,
        beta: (num("/eq84/beta"), num("/eq84/beta_sigma")),
        t0: (
            (num("/eq84/t0") - origin) / unit,
            num("/eq84/t0_sigma") / unit,
        ),
    }
}

#[test]
fn the_analysis_does_not_depend_on_the_clock_its_unit_polarity_or_trailing_silence() {
    let dir = temp_dir("invariance", "metamorphic");
    let (ok, _, err) = cli_in(&dir, &["experiment", "simulate", "--csv", "base.csv"]);
    assert!(ok, "{err}");
    let rows = samples(&std::fs::read_to_string(dir.join("base.csv")).unwrap_or_default());
    assert!(rows.len() > 1000);
    let map = |f: &dyn Fn(f64, f64) -> (f64, f64)| -> Vec<(f64, f64)> {
        rows.iter().map(|&(t, v)| f(t, v)).collect()
    };
    write_csv(&dir.join("plain.csv"), "time_s,signal_V", &rows);
    let epoch = 1.764e9;
    write_csv(
        &dir.join("epoch.csv"),
        "time_s,signal_V",
        &map(&|t, v| (t + epoch, v)),
    );
    write_csv(
        &dir.join("ms.csv"),
        "time (ms),signal_V",
        &map(&|t, v| (t * 1e3, v)),
    );
    write_csv(
        &dir.join("us.csv"),
        "time (us),signal_V",
        &map(&|t, v| (t * 1e6, v)),
    );
    write_csv(
        &dir.join("reversed.csv"),
        "time_s,signal_V",
        &map(&|t, v| (t, -v)),
    );
    let (dt, (t_end, v_end)) = (rows[1].0 - rows[0].0, rows[rows.len() - 1]);
    let mut quiet = rows.clone();
    quiet.extend((1..=5000).map(|k| (t_end + dt * f64::from(k), v_end)));
    write_csv(&dir.join("silence.csv"), "time_s,signal_V", &quiet);

    let base = answer(&dir, "plain.csv", 0.0, 1.0);
    assert!(base.laws.iter().any(|l| l == "two mechanisms"), "{base:?}");
    for (file, origin) in [
        ("epoch.csv", epoch),
        ("ms.csv", 0.0),
        ("us.csv", 0.0),
        ("reversed.csv", 0.0),
        ("silence.csv", 0.0),
    ] {
        let a = answer(&dir, file, origin, 1.0);
        assert_eq!(a.choice, base.choice, "{file}: {a:?} against {base:?}");
        assert_eq!(
            a.laws.len(),
            base.laws.len(),
            "{file}: {a:?} against {base:?}"
        );
        let sigma = |x: (f64, f64), y: (f64, f64)| (x.0 - y.0).abs() / x.1.hypot(y.1);
        assert!(
            sigma(a.beta, base.beta) < 1.0,
            "{file}: beta {a:?} against {base:?}"
        );
        assert!(
            sigma(a.t0, base.t0) < 1.0,
            "{file}: t0 {a:?} against {base:?}"
        );
    }
}

#[test]
fn a_recording_in_another_time_scale_keeps_its_laws() {
    // The same recording on a clock a million times faster (times x 1e-6, still "seconds"):
    // eq 79 has no time scale of its own, so beta and the ranking of the laws are the same.
    let dir = temp_dir("invariance", "scale");
    let (ok, _, err) = cli_in(&dir, &["experiment", "simulate", "--csv", "base.csv"]);
    assert!(ok, "{err}");
    let rows = samples(&std::fs::read_to_string(dir.join("base.csv")).unwrap_or_default());
    write_csv(&dir.join("plain.csv"), "time_s,signal_V", &rows);
    let fast: Vec<(f64, f64)> = rows.iter().map(|&(t, v)| (t * 1e-6, v)).collect();
    write_csv(&dir.join("fast.csv"), "time_s,signal_V", &fast);
    let base = answer(&dir, "plain.csv", 0.0, 1.0);
    let a = answer(&dir, "fast.csv", 0.0, 1e-6);
    assert_eq!(a.laws, base.laws, "{a:?} against {base:?}");
    assert!(
        (a.beta.0 - base.beta.0).abs() < base.beta.1,
        "{a:?} against {base:?}"
    );
    assert!(
        (a.t0.0 - base.t0.0).abs() < base.t0.1,
        "{a:?} against {base:?}"
    );
}

#[test]
fn a_clock_beyond_double_precision_ends_within_seconds() {
    let dir = temp_dir("invariance", "huge-clock");
    let (ok, _, err) = cli_in(&dir, &["experiment", "simulate", "--csv", "base.csv"]);
    assert!(ok, "{err}");
    let rows = samples(&std::fs::read_to_string(dir.join("base.csv")).unwrap_or_default());
    for scale in [1e14, 1e16, 1e18] {
        let scaled: Vec<(f64, f64)> = rows.iter().map(|&(t, v)| (t * scale, v)).collect();
        write_csv(&dir.join("scaled.csv"), "time_s,signal_V", &scaled);
        let start = Instant::now();
        let (_, _, err) = cli_in(&dir, &["experiment", "analyze", "scaled.csv"]);
        let took = start.elapsed();
        assert!(took < Duration::from_secs(2), "x{scale:e}: {took:?}");
        assert!(!err.contains("panicked"), "x{scale:e}: {err}");
    }
}
