//! Scope CSVs as instruments write them (Tektronix, Rigol, PicoScope, Keysight), the choice of
//! columns (`--time`, `--signal`), and the refusal of a file with several channels and none
//! chosen: the same simulated trace, written in each layout, is analysed to the same beta.

use experiment::scope_layout::{ColumnChoice, ColumnRef};
use experiment::*;
use physics::Disk;
use std::fmt::Write as _;

/// A simulated scope trace of eq 84's law (the paper's beta = 2) at the default scope.
fn simulated() -> Trace {
    let disk = Disk::uniform(0.0375);
    law_trace(&Law { beta: 2.0, c: 7e8 }, &disk, &LightModel::default()).unwrap()
}

/// The trace in a Tektronix spreadsheet file: settings in columns 1-3 of the first rows,
/// time and volts in columns 4 and 5 of every row.
fn tektronix(tr: &Trace) -> String {
    let dt = tr.t[1] - tr.t[0];
    let settings = [
        ("Record Length", format!("{}", tr.t.len())),
        ("Sample Interval", format!("{dt}")),
        ("Trigger Point", "0".into()),
        ("", String::new()),
        ("", String::new()),
        ("Source", "CH1".into()),
        ("Vertical Units", "V".into()),
        ("Vertical Scale", "0.5".into()),
        ("Vertical Offset", "0".into()),
        ("Horizontal Units", "s".into()),
        ("Horizontal Scale", "1".into()),
        ("Pt Fmt", "Y".into()),
        ("Yzero", "0".into()),
        ("Probe Atten", "1".into()),
        ("Model Number", "TDS2012C".into()),
        ("Firmware Version", "FV:v24.26".into()),
    ];
    let mut s = String::new();
    for (j, (t, v)) in tr.t.iter().zip(&tr.v).enumerate() {
        let (k, x) = settings.get(j).map_or(("", ""), |(k, x)| (*k, x.as_str()));
        let _ = write!(s, "{k},{x},,{t},{v}\r\n");
    }
    s
}

/// The trace in a Rigol file: `X,CH1,...,Start,Increment`, `Sequence,Volt,...`, then one row
/// per sample index. `extra` adds a second channel of this constant value.
fn rigol(tr: &Trace, extra: Option<f64>) -> String {
    let dt = (tr.t[tr.t.len() - 1] - tr.t[0]) / (tr.t.len() - 1) as f64;
    let mut s = match extra {
        Some(_) => format!(
            "X,CH1,CH2,Start,Increment,\nSequence,Volt,Volt,{},{dt},\n",
            tr.t[0]
        ),
        None => format!("X,CH1,Start,Increment,\nSequence,Volt,{},{dt},\n", tr.t[0]),
    };
    for (k, v) in tr.v.iter().enumerate() {
        match extra {
            Some(c) => {
                let _ = writeln!(s, "{k},{v},{c},");
            }
            None => {
                let _ = writeln!(s, "{k},{v},");
            }
        }
    }
    s
}

/// The trace with a units row under the header: PicoScope's `(ms),(V),(V)` or Keysight's
/// `second,Volt,Volt`; the second channel is flat.
fn units_row(tr: &Trace, pico: bool) -> String {
    let mut s = if pico {
        "Time,Channel A,Channel B\n(ms),(V),(V)\n".to_string()
    } else {
        "x-axis,1,2\nsecond,Volt,Volt\n".to_string()
    };
    let k = if pico { 1e3 } else { 1.0 };
    for (t, v) in tr.t.iter().zip(&tr.v) {
        let _ = writeln!(s, "{},{v},0.01", t * k);
    }
    s
}

fn beta(tr: &Trace) -> experiment::fit::Eq84Fit {
    analyze(tr, &AnalysisSettings::default()).unwrap().eq84
}

fn choose(signal: &str) -> ColumnChoice {
    ColumnChoice {
        time: None,
        signal: Some(ColumnRef::parse(signal)),
    }
}

/// The done-when of issue 50 item 4: a Tektronix-style and a Rigol-style CSV of a simulated
/// trace are analysed to the same beta as the plain CSV; PicoScope's and Keysight's layouts
/// with their channel chosen too.
#[test]
fn every_layout_gives_the_plain_csvs_beta() {
    let tr = simulated();
    let plain = parse_trace(&tr.to_csv(), "plain.csv").unwrap();
    let base = beta(&plain);
    println!("plain: beta = {} +- {}", base.beta, base.beta_sigma);
    let (tek, said) =
        parse_trace_columns(&tektronix(&tr), "tek.csv", &ColumnChoice::default()).unwrap();
    assert!(said.contains("of a Tektronix file"), "{said}");
    assert_eq!(tek.t, plain.t);
    assert_eq!(tek.v, plain.v);
    assert_eq!(beta(&tek).beta, base.beta);
    let (rig, said) =
        parse_trace_columns(&rigol(&tr, None), "rigol.csv", &ColumnChoice::default()).unwrap();
    assert!(said.contains("of a Rigol file"), "{said}");
    let worst = rig
        .t
        .iter()
        .zip(&plain.t)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    assert!(worst < 1e-12, "Rigol times off by {worst:e} s");
    let b = beta(&rig);
    println!("Rigol: beta = {} +- {}", b.beta, b.beta_sigma);
    assert!(
        (b.beta - base.beta).abs() < 1e-3 * base.beta_sigma,
        "{} against {}",
        b.beta,
        base.beta
    );
    for pico in [true, false] {
        let text = units_row(&tr, pico);
        let e = parse_trace(&text, "two.csv").unwrap_err().to_string();
        assert!(
            e.contains("2 signal columns") && e.contains("--signal"),
            "{e}"
        );
        let name = if pico { "Channel A" } else { "1" };
        let (two, said) = parse_trace_columns(&text, "two.csv", &choose(name)).unwrap();
        assert!(
            said.contains(if pico {
                "of a PicoScope file"
            } else {
                "of a Keysight file"
            }),
            "{said}"
        );
        // By number: the second column of the file; Keysight's header names its channels by
        // number, and its "2" is its second channel, the flat one.
        let (by_number, _) = parse_trace_columns(&text, "two.csv", &choose("2")).unwrap();
        if pico {
            assert_eq!(by_number.v, two.v);
        } else {
            assert!(by_number.v.iter().all(|&v| v == 0.01));
        }
        let b = beta(&two);
        assert!(
            (b.beta - base.beta).abs() < 1e-3 * base.beta_sigma,
            "{said}: {} against {}",
            b.beta,
            base.beta
        );
    }
}

/// A file with two channels and none chosen is refused naming both; the advice (`--signal`
/// with a name or a number) reads the channel named; a chosen flat channel is the one analysed.
#[test]
fn several_channels_are_refused_naming_them_and_the_advice_works() {
    let tr = simulated();
    let text = rigol(&tr, Some(0.25));
    let e = parse_trace(&text, "two.csv").unwrap_err().to_string();
    assert!(
        e.starts_with("two.csv:1:")
            && e.contains("\"CH1\" (column 2), \"CH2\" (column 3)")
            && e.contains("--signal CH1"),
        "{e}"
    );
    let (ch1, said) = parse_trace_columns(&text, "two.csv", &choose("CH1")).unwrap();
    assert!(said.contains("\"CH1\" (column 2)"), "{said}");
    assert_eq!(ch1.v, tr.v);
    let (ch2, said) = parse_trace_columns(&text, "two.csv", &choose("3")).unwrap();
    assert!(said.contains("\"CH2\" (column 3)"), "{said}");
    assert!(ch2.v.iter().all(|&v| v == 0.25));
    let e = parse_trace_columns(&text, "two.csv", &choose("CH4"))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("--signal CH4: the file has no such column") && e.contains("\"CH2\""),
        "{e}"
    );
    // A plain header with a column of another quantity: chosen by name, the time by name too.
    let plain = "t_ms,signal_V,temperature\n0,1,20\n1,2,20\n2,3,20\n";
    let e = parse_trace(plain, "p.csv").unwrap_err().to_string();
    assert!(
        e.contains("\"signal_V\" (column 2), \"temperature\" (column 3)"),
        "{e}"
    );
    let c = ColumnChoice {
        time: Some(ColumnRef::parse("t")),
        signal: Some(ColumnRef::parse("signal")),
    };
    let (p, said) = parse_trace_columns(plain, "p.csv", &c).unwrap();
    assert_eq!(p.t, vec![0.0, 1e-3, 2e-3]);
    assert_eq!(p.v, vec![1.0, 2.0, 3.0]);
    assert!(said.contains("\"signal_V\" (column 2)"), "{said}");
    let e = parse_trace_columns(plain, "p.csv", &choose("1"))
        .unwrap_err()
        .to_string();
    assert!(e.contains("is the time column"), "{e}");
    // A Tektronix file holds one channel: a --signal other than its own is refused.
    let e = parse_trace_columns(&tektronix(&tr), "tek.csv", &choose("CH2"))
        .unwrap_err()
        .to_string();
    assert!(e.contains("leave --signal out"), "{e}");
    let (same, _) = parse_trace_columns(&tektronix(&tr), "tek.csv", &choose("CH1")).unwrap();
    assert_eq!(same.v, tr.v);
    // A Rigol header without its Start and Increment row says what the row must be.
    let e = parse_trace("X,CH1,Start,Increment,\n0,1,\n", "r.csv")
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("r.csv:2:") && e.contains("Sequence,Volt"),
        "{e}"
    );
}

/// On the command line: a simulated CSV records its scope, artifacts and seeds in its header;
/// written as a two-channel Rigol file it is refused naming both channels, and analysed with
/// the advice's `--signal`; a flat chosen channel is named in the refusal.
#[test]
fn the_command_line_chooses_columns_and_names_a_flat_one() {
    let dir = crate::common::temp_dir("scope-csv", "cli");
    let (ok, out, err) = crate::common::cli_in(
        &dir,
        &[
            "experiment",
            "simulate",
            "--csv",
            "sim.csv",
            "--hum",
            "0.02",
            "--seed",
            "5",
        ],
    );
    assert!(ok, "{out}{err}");
    let text = std::fs::read_to_string(dir.join("sim.csv")).unwrap();
    let head: Vec<&str> = text.lines().take_while(|l| l.starts_with('#')).collect();
    println!("{}", head.join("\n"));
    assert!(
        head.iter()
            .any(|l| l.starts_with("# scope: 5000 S/s") && l.ends_with("seed 5")),
        "{head:?}"
    );
    assert!(
        head.iter()
            .any(|l| l.starts_with("# artifacts: drift 0 V rms, hum ") && l.ends_with("seed 5")),
        "{head:?}"
    );
    let tr = parse_trace(&text, "sim.csv").unwrap();
    std::fs::write(dir.join("two.csv"), rigol(&tr, Some(0.25))).unwrap();
    let (ok, _, err) = crate::common::cli_in(&dir, &["experiment", "analyze", "two.csv"]);
    assert!(
        !ok && err.contains("2 channels") && err.contains("--signal CH1"),
        "{err}"
    );
    let (ok, out, err) = crate::common::cli_in(
        &dir,
        &["experiment", "analyze", "two.csv", "--signal", "CH1"],
    );
    assert!(ok && out.contains("beta"), "{out}{err}");
    let (ok, _, err) = crate::common::cli_in(
        &dir,
        &["experiment", "analyze", "two.csv", "--signal", "CH2"],
    );
    let _ = std::fs::remove_dir_all(&dir);
    assert!(
        !ok && err.contains("flat") && err.contains("\"CH2\" (column 3 of a Rigol file"),
        "{err}"
    );
}
