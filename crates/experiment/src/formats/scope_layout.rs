//! The layouts in which oscilloscopes write a CSV, recognised by their first lines, and the
//! choice of the time and signal columns (`--time`, `--signal`, by name or 1-based number).
//!
//! The layouts, as their makers' manuals and the files they write show them:
//!
//! - **Tektronix** (TDS 1000/2000, TBS 1000 "spreadsheet" files): the settings in columns 1-3
//!   of the first rows (`Record Length,2500,`, `Sample Interval,4e-06,`, `Source,CH1,`,
//!   `Vertical Units,V,`, `Horizontal Units,s,` ...), the samples in columns 4 (time, s) and 5
//!   (signal, in the vertical units) of every row, one file per channel.
//! - **Rigol** (DS1000Z and later): the header `X,CH1[,CH2...],Start,Increment`, then
//!   `Sequence,Volt[,Volt...],<start>,<increment>`, then one row per sample whose first cell is
//!   the sample's index $k$: its time is $t = \text{start} + k\,\text{increment}$.
//! - **PicoScope** 6: the header `Time,Channel A,Channel B`, then a row of units in parentheses
//!   `(ms),(V),(V)`, then the samples (PicoScope 6 User's Guide, "Text formats").
//! - **Keysight** InfiniiVision: the header `x-axis,1,2` (channel numbers), then a row of unit
//!   words `second,Volt,Volt`, then the samples (InfiniiVision User's Guide, "CSV and ASCII XY
//!   file structure").
//! - **plain**: a header naming the columns, units in it (`time_s`, `Time (ms)`, `CH1 [mV]`),
//!   or no header at all.
//!
//! A file with more than one signal column is analysed only with `--signal` naming one: the
//! refusal lists the channels, so no channel is taken silently.

use crate::error::ExperimentError;
use crate::formats::cells::{cells, header_unit, signal_factor, time_factor};

/// A column of a scope CSV as the user names it: by its header's name or by its 1-based number
/// (a number that is itself a header's name, as Keysight names channels `1` and `2`, is that
/// column).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ColumnRef {
    /// By name, as the header writes it (case ignored; a unit written in the cell may be left out).
    Name(String),
    /// By number, 1 for the file's first column.
    Number(usize),
}

impl ColumnRef {
    /// A number when `s` is all digits, else a name.
    pub fn parse(s: &str) -> Self {
        let s = s.trim();
        match s.parse::<usize>() {
            Ok(n) if s.bytes().all(|b| b.is_ascii_digit()) => ColumnRef::Number(n),
            _ => ColumnRef::Name(s.to_string()),
        }
    }
}

impl std::fmt::Display for ColumnRef {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ColumnRef::Name(n) => write!(f, "{n}"),
            ColumnRef::Number(k) => write!(f, "{k}"),
        }
    }
}

/// Which columns to read; `None` lets the layout decide (the time's column, and the only signal
/// column when there is one).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct ColumnChoice {
    /// The time column.
    pub time: Option<ColumnRef>,
    /// The signal column.
    pub signal: Option<ColumnRef>,
}

/// Where the time of a row is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum TimeSource {
    /// In this 0-based cell, times this factor to seconds.
    Cell(usize, f64),
    /// Computed from the sample index in this 0-based cell: `start + k * increment` (s).
    Sequence(usize, f64, f64),
}

/// A scope CSV's layout with its columns chosen.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Layout {
    /// The instrument's layout: "Tektronix", "Rigol", "PicoScope", "Keysight" or "plain".
    pub kind: &'static str,
    /// Where the time is.
    pub time: TimeSource,
    /// The 0-based cell of the signal, and its factor to volts.
    pub signal: (usize, f64),
    /// The 0-based index, among the content lines, of the first data row.
    pub data_from: usize,
    /// What was chosen, in words: the signal's name and column, the layout, and the file's
    /// channels.
    pub described: String,
}

/// A content line: its 1-based number in the file and its cells.
pub(crate) type Line<'a> = (usize, Vec<&'a str>);

/// Whether a cell is a number.
fn numeric(c: &str) -> bool {
    c.parse::<f64>().is_ok()
}

/// The unit a cell of a units row names: in parentheses or brackets (`(ms)`, `[V]`) or a unit
/// word alone (`second`, `Volt`, `ms`).
fn unit_cell(c: &str) -> Option<&str> {
    let c = c.trim();
    for (open, close) in [('(', ')'), ('[', ']')] {
        if let Some(inner) = c.strip_prefix(open).and_then(|r| r.strip_suffix(close)) {
            return Some(inner.trim());
        }
    }
    let words = [
        "s", "ms", "us", "µs", "μs", "ns", "second", "seconds", "sec", "V", "mV", "uV", "µV", "μV",
        "Volt", "Volts", "volt", "volts", "A", "mA",
    ];
    words.contains(&c).then_some(c)
}

/// Whether the line is a row of units (every cell names a unit).
fn units_row(line: &Line<'_>) -> bool {
    !line.1.is_empty() && line.1.iter().all(|c| unit_cell(c).is_some())
}

/// The time factor of a unit, or the located refusal.
fn time_unit(unit: &str, file: &str, line: usize, col: usize) -> Result<f64, ExperimentError> {
    let unit = match unit {
        "second" | "seconds" | "Second" | "Seconds" => "s",
        u => u,
    };
    time_factor(unit).ok_or_else(|| ExperimentError::UnknownUnit {
        file: file.into(),
        line,
        column: col,
        unit: physics::scene::message::cut(unit),
    })
}

/// Finds the layout of a scope CSV from its first content lines (`head`, comments and blank
/// lines left out) and chooses its columns.
pub(crate) fn layout(
    head: &[Line<'_>],
    file: &str,
    choice: &ColumnChoice,
) -> Result<Layout, ExperimentError> {
    let first = &head[0];
    if first
        .1
        .first()
        .is_some_and(|c| c.eq_ignore_ascii_case("Record Length"))
    {
        return tektronix(head, file, choice);
    }
    let lower: Vec<String> = first.1.iter().map(|c| c.to_ascii_lowercase()).collect();
    if lower.first().is_some_and(|c| c == "x")
        && lower.iter().any(|c| c == "start")
        && lower.iter().any(|c| c == "increment")
    {
        return rigol(head, file, choice, &lower);
    }
    if first.1.first().is_some_and(|c| numeric(c)) {
        let names: Vec<String> = (1..=first.1.len()).map(|k| format!("column {k}")).collect();
        let units = vec![None; names.len()];
        return columns("plain", head, 0, &names, &units, file, choice);
    }
    if first.1.len() < 2 || first.1[1].is_empty() {
        return Err(ExperimentError::MissingColumn {
            file: file.into(),
            line: first.0,
            found: first.1.iter().filter(|c| !c.is_empty()).count(),
        });
    }
    let names: Vec<String> = first.1.iter().map(|c| c.to_string()).collect();
    match head.get(1) {
        Some(u) if units_row(u) => {
            let kind = if u.1.iter().all(|c| c.starts_with('(')) {
                "PicoScope"
            } else {
                "Keysight"
            };
            let units: Vec<Option<(usize, String)>> = (0..names.len())
                .map(|k| {
                    u.1.get(k)
                        .and_then(|c| unit_cell(c))
                        .map(|x| (u.0, x.into()))
                })
                .collect();
            columns(kind, head, 2, &names, &units, file, choice)
        }
        _ => {
            let units: Vec<Option<(usize, String)>> = first
                .1
                .iter()
                .map(|c| header_unit(c).map(|x| (first.0, x.to_string())))
                .collect();
            columns("plain", head, 1, &names, &units, file, choice)
        }
    }
}

/// The name of a header cell without its unit: `CH1 [mV]` is `CH1`, `time_s` is `time`.
fn bare(name: &str) -> &str {
    let n = name.trim();
    match n.find(['(', '[']) {
        Some(k) if k > 0 => n[..k].trim(),
        _ => match n.rfind(['_', '/']) {
            Some(k) if k > 0 => &n[..k],
            _ => n,
        },
    }
}

/// The 0-based column `r` names among `names` (time excluded from the signal's choice by the
/// caller), or the refusal that lists them.
fn find(
    r: &ColumnRef,
    names: &[String],
    what: &str,
    file: &str,
    line: usize,
) -> Result<usize, ExperimentError> {
    // A header cell that is itself a number (Keysight's channels `1`, `2`) is taken by name.
    let by_name = |n: &str| names.iter().position(|c| c.eq_ignore_ascii_case(n));
    let found = match r {
        ColumnRef::Number(k) => {
            by_name(&k.to_string()).or_else(|| (*k >= 1 && *k <= names.len()).then(|| k - 1))
        }
        ColumnRef::Name(n) => names
            .iter()
            .position(|c| c.eq_ignore_ascii_case(n))
            .or_else(|| names.iter().position(|c| bare(c).eq_ignore_ascii_case(n))),
    };
    found.ok_or_else(|| ExperimentError::Columns {
        file: file.into(),
        line,
        message: format!(
            "--{what} {r}: the file has no such column; its columns are {}: give one of these names or numbers",
            listed(names, 0..names.len())
        ),
    })
}

/// Columns in words: `"CH1" (column 2), "CH2" (column 3)`.
fn listed(names: &[String], ks: impl IntoIterator<Item = usize>) -> String {
    ks.into_iter()
        .map(|k| format!("\"{}\" (column {})", names[k], k + 1))
        .collect::<Vec<_>>()
        .join(", ")
}

/// A layout whose header names every column (plain, PicoScope, Keysight): the time in the
/// first column unless `--time` says otherwise, the signal the only other column unless
/// `--signal` names one. `units` holds each column's unit with the line that writes it.
fn columns(
    kind: &'static str,
    head: &[Line<'_>],
    data_from: usize,
    names: &[String],
    units: &[Option<(usize, String)>],
    file: &str,
    choice: &ColumnChoice,
) -> Result<Layout, ExperimentError> {
    let line = head[0].0;
    let t = match &choice.time {
        Some(r) => find(r, names, "time", file, line)?,
        None => 0,
    };
    let others: Vec<usize> = (0..names.len())
        .filter(|&k| k != t && !names[k].is_empty())
        .collect();
    let s = match &choice.signal {
        Some(r) => {
            let s = find(r, names, "signal", file, line)?;
            if s == t {
                return Err(ExperimentError::Columns {
                    file: file.into(),
                    line,
                    message: format!(
                        "--signal {r} is the time column: choose the signal among {}",
                        listed(names, others.iter().copied())
                    ),
                });
            }
            s
        }
        None => match others.as_slice() {
            [s] => *s,
            [] => {
                return Err(ExperimentError::MissingColumn {
                    file: file.into(),
                    line,
                    found: 1,
                })
            }
            _ => {
                return Err(ExperimentError::Columns {
                    file: file.into(),
                    line,
                    message: format!(
                        "{} signal columns, {}: choose the photodiode's with --signal NAME or --signal NUMBER (e.g. --signal {})",
                        others.len(),
                        listed(names, others.iter().copied()),
                        bare(&names[others[0]])
                    ),
                })
            }
        },
    };
    let kt = match &units[t] {
        Some((l, u)) => time_unit(u, file, *l, t + 1)?,
        None => 1.0,
    };
    let kv = units[s].as_ref().map_or(1.0, |(_, u)| signal_factor(u));
    Ok(Layout {
        kind,
        time: TimeSource::Cell(t, kt),
        signal: (s, kv),
        data_from,
        described: format!(
            "\"{}\" (column {} of a {kind} file; its signal columns: {})",
            names[s],
            s + 1,
            listed(names, others.iter().copied())
        ),
    })
}

/// The Tektronix spreadsheet layout: settings in columns 1-3, time and signal in 4 and 5.
fn tektronix(
    head: &[Line<'_>],
    file: &str,
    choice: &ColumnChoice,
) -> Result<Layout, ExperimentError> {
    let setting = |key: &str| {
        head.iter()
            .find(|l| l.1.first().is_some_and(|c| c.eq_ignore_ascii_case(key)))
            .and_then(|l| l.1.get(1).map(|v| (l.0, v.to_string())))
    };
    let source = setting("Source").map_or("CH1".to_string(), |(_, s)| s);
    let names = vec![
        "Record Length".to_string(),
        String::new(),
        String::new(),
        "time".to_string(),
        source.clone(),
    ];
    refuse_other_than(choice, &names, &[3, 4], "Tektronix", file, head[0].0)?;
    let kt = match setting("Horizontal Units") {
        Some((l, u)) => time_unit(&u, file, l, 2)?,
        None => 1.0,
    };
    let kv = setting("Vertical Units").map_or(1.0, |(_, u)| signal_factor(&u));
    Ok(Layout {
        kind: "Tektronix",
        time: TimeSource::Cell(3, kt),
        signal: (4, kv),
        data_from: 0,
        described: format!("\"{source}\" (column 5 of a Tektronix file, one channel per file)"),
    })
}

/// Refuses a `--time` or `--signal` other than the layout's own columns `fixed` (time, signal).
fn refuse_other_than(
    choice: &ColumnChoice,
    names: &[String],
    fixed: &[usize; 2],
    kind: &str,
    file: &str,
    line: usize,
) -> Result<(), ExperimentError> {
    for (what, r, k) in [
        ("time", &choice.time, fixed[0]),
        ("signal", &choice.signal, fixed[1]),
    ] {
        if let Some(r) = r {
            if find(r, names, what, file, line).ok() != Some(k) {
                return Err(ExperimentError::Columns {
                    file: file.into(),
                    line,
                    message: format!(
                        "--{what} {r}: a {kind} file holds its {what} in column {} (\"{}\"): leave --{what} out",
                        k + 1,
                        names[k]
                    ),
                });
            }
        }
    }
    Ok(())
}

/// The Rigol layout: `X,CH1[,CH2...],Start,Increment`, then `Sequence,Volt...,start,increment`.
fn rigol(
    head: &[Line<'_>],
    file: &str,
    choice: &ColumnChoice,
    lower: &[String],
) -> Result<Layout, ExperimentError> {
    let first = &head[0];
    let at = |key: &str| lower.iter().position(|c| c == key).unwrap_or(0);
    let (start_k, inc_k) = (at("start"), at("increment"));
    let last_channel = start_k.min(inc_k);
    let bad = |line: usize, what: String| {
        ExperimentError::Columns {
        file: file.into(),
        line,
        message: format!(
            "a Rigol header (X,CH1,...,Start,Increment) must be followed by a row \"Sequence,Volt,...,START,INCREMENT\" with the start and the increment as numbers: {what}; export the file again from the scope"
        ),
    }
    };
    let Some(second) = head.get(1) else {
        return Err(bad(first.0, "the file ends after the header".into()));
    };
    let num = |k: usize| second.1.get(k).and_then(|c| c.parse::<f64>().ok());
    let (Some(start), Some(inc)) = (num(start_k), num(inc_k)) else {
        return Err(bad(
            second.0,
            format!("line {} reads \"{}\"", second.0, second.1.join(",")),
        ));
    };
    if !(start.is_finite() && inc.is_finite() && inc > 0.0) {
        return Err(bad(
            second.0,
            format!("the increment {inc} s is not a positive number"),
        ));
    }
    let names: Vec<String> = first.1[..last_channel]
        .iter()
        .map(|c| c.to_string())
        .collect();
    let channels: Vec<usize> = (1..names.len()).collect();
    let s = match (&choice.signal, channels.as_slice()) {
        (Some(r), _) => {
            let s = find(r, &names, "signal", file, first.0)?;
            if s == 0 {
                return Err(bad(first.0, format!("--signal {r} is the sample index X")));
            }
            s
        }
        (None, [s]) => *s,
        (None, _) => {
            return Err(ExperimentError::Columns {
                file: file.into(),
                line: first.0,
                message: format!(
                    "{} channels, {}: choose the photodiode's with --signal NAME or --signal NUMBER (e.g. --signal {})",
                    channels.len(),
                    listed(&names, channels.iter().copied()),
                    names.get(1).map_or("CH1", |n| n.as_str())
                ),
            })
        }
    };
    if let Some(r) = &choice.time {
        if find(r, &names, "time", file, first.0).ok() != Some(0) {
            return Err(ExperimentError::Columns {
                file: file.into(),
                line: first.0,
                message: format!(
                    "--time {r}: a Rigol file's time is START + X * INCREMENT from its second line: leave --time out"
                ),
            });
        }
    }
    let kv = second.1.get(s).map_or(1.0, |u| signal_factor(u));
    Ok(Layout {
        kind: "Rigol",
        time: TimeSource::Sequence(0, start, inc),
        signal: (s, kv),
        data_from: 2,
        described: format!(
            "\"{}\" (column {} of a Rigol file; its channels: {})",
            names[s],
            s + 1,
            listed(&names, channels.iter().copied())
        ),
    })
}

/// The cells of the file's content lines, as [`layout`] reads them.
pub(crate) fn line_cells(number: usize, s: &str) -> Line<'_> {
    (number, cells(s))
}
