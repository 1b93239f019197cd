//! Scope CSV: a header (time in s, signal in V) and one row per sample, as a scope exports it.
//!
//! Reading validates every row and names the file, the 1-based line and column of the first
//! problem: a missing column, a cell that is not a number, NaN or infinity, a time that does not
//! increase, an unknown time unit, too many rows. Files are opened only through
//! [`read_bounded`](crate::formats::input::read_bounded). Lines starting with `#` are comments; a synthetic trace writes its truth there
//! (`# truth.beta: 2`), and reading it back restores it.

use crate::error::ExperimentError;
use crate::formats::cells::cells;
use crate::formats::input::{
    first_bytes, is_binary, read_bounded, FORMATS_READ, MAX_BYTES, MAX_SAMPLES,
};
use crate::formats::scope_layout::{layout, line_cells, ColumnChoice, TimeSource};
use crate::trace::{Trace, Truth};
use std::fmt::Write as _;
use std::path::Path;

impl Trace {
    /// The trace as CSV: comments (source, truth), the header `time_s,signal_V`, the samples.
    /// Numbers are written in their shortest exact form, so they read back bit for bit.
    pub fn to_csv(&self) -> String {
        self.to_csv_noting(&[])
    }

    /// The trace as CSV, as [`Trace::to_csv`], with `notes` as comment lines after the source
    /// (how it was made: the scope, the artifacts and their seeds).
    pub fn to_csv_noting(&self, notes: &[String]) -> String {
        let mut s = String::with_capacity(self.t.len() * 32 + 256);
        let _ = writeln!(s, "# rolling-disk scope trace");
        let _ = writeln!(s, "# source: {}", self.source);
        for n in notes {
            let _ = writeln!(s, "# {n}");
        }
        if let Some(tr) = &self.truth {
            let _ = writeln!(s, "# truth.beta: {}", tr.beta);
            let _ = writeln!(s, "# truth.t0: {}", tr.t0);
            let _ = writeln!(s, "# truth.t_stop: {}", tr.t_stop);
            let _ = writeln!(s, "# truth.tau_rem: {}", tr.tau_rem);
            if let Some(c) = tr.c {
                let _ = writeln!(s, "# truth.c: {c}");
            }
            let _ = writeln!(s, "# truth.origin: {}", tr.origin);
        }
        s.push_str("time_s,signal_V\n");
        for (t, v) in self.t.iter().zip(&self.v) {
            let _ = writeln!(s, "{t},{v}");
        }
        s
    }
}

/// Reads and validates a scope CSV file (at most [`MAX_BYTES`] bytes, [`MAX_SAMPLES`] rows).
pub fn read_trace(path: impl AsRef<Path>) -> Result<Trace, ExperimentError> {
    read_trace_columns(path, &ColumnChoice::default()).map(|(t, _)| t)
}

/// Reads and validates a scope CSV file with the columns `choice` names; returns the trace and
/// the layout and column read, in words. A binary file (not a recording this tool knows) is
/// refused naming its first bytes and the formats read; a text in another encoding than UTF-8
/// names the line of its first invalid byte.
pub fn read_trace_columns(
    path: impl AsRef<Path>,
    choice: &ColumnChoice,
) -> Result<(Trace, String), ExperimentError> {
    let path = path.as_ref();
    let file = path.display().to_string();
    let bytes = read_bounded(path, MAX_BYTES)?;
    if is_binary(&bytes) {
        return Err(ExperimentError::Io {
            file,
            message: format!(
                "its content is neither text nor a recording this tool reads: the first bytes are \
                 {}; the formats read are {FORMATS_READ}: export the recording in one of them",
                first_bytes(&bytes)
            ),
        });
    }
    let text = String::from_utf8(bytes).map_err(|e| {
        let at = e.utf8_error().valid_up_to();
        let bytes = e.as_bytes();
        let line = 1 + bytes[..at].iter().filter(|&&b| b == b'\n').count();
        ExperimentError::Io {
            file: file.clone(),
            message: format!(
                "line {line}: byte {} (0x{:02x}) is not UTF-8: the text is in another encoding; \
                 save the CSV as UTF-8 or ASCII text",
                at + 1,
                bytes[at]
            ),
        }
    })?;
    parse_trace_columns(&text, &file, choice)
}

/// The lines of `text` whatever their ends: LF, CRLF or CR alone.
fn lines_any(text: &str) -> impl Iterator<Item = &str> {
    let mut rest = Some(text);
    std::iter::from_fn(move || {
        let r = rest?;
        match r.find(['\n', '\r']) {
            Some(k) => {
                let skip = if r[k..].starts_with("\r\n") { 2 } else { 1 };
                rest = Some(&r[k + skip..]);
                Some(&r[..k])
            }
            None => {
                rest = None;
                (!r.is_empty()).then_some(r)
            }
        }
    })
}

/// Parses and validates CSV text; `file` names it in errors. The file's layout decides the
/// columns ([`parse_trace_columns`] with no choice).
pub fn parse_trace(text: &str, file: &str) -> Result<Trace, ExperimentError> {
    parse_trace_columns(text, file, &ColumnChoice::default()).map(|(t, _)| t)
}

/// The content lines read to recognise a layout (a Tektronix file's settings fill its first 16).
const HEAD_LINES: usize = 24;

/// Parses and validates CSV text with the columns `choice` names; returns the trace and, in
/// words, the layout and the column read. `file` names the text in errors.
///
/// Accepted: a UTF-8 byte-order mark; LF, CRLF or CR line ends; cells separated by semicolons,
/// commas, tabs or spaces, each in double quotes or not (a decimal comma refused, naming it);
/// trailing separators; `#` comment lines; the instrument layouts
/// of [`scope_layout`](crate::formats::scope_layout) (Tektronix, Rigol, PicoScope, Keysight);
/// a header whose cells (or the units row under it) name units (time in s, ms, us or ns,
/// converted to s; signal in V, mV or uV, converted to V, or any other unit, kept). At most
/// [`MAX_SAMPLES`] rows.
pub fn parse_trace_columns(
    text: &str,
    file: &str,
    choice: &ColumnChoice,
) -> Result<(Trace, String), ExperimentError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let head: Vec<_> = lines_any(text)
        .enumerate()
        .filter_map(|(i, raw)| {
            let s = raw.trim();
            (!s.is_empty() && !s.starts_with('#')).then_some((i + 1, s))
        })
        .take(HEAD_LINES)
        .map(|(n, s)| line_cells(n, s))
        .collect();
    if head.is_empty() {
        return Err(ExperimentError::Empty { file: file.into() });
    }
    let layout = layout(&head, file, choice)?;
    let header_line = (layout.data_from > 0).then(|| head[layout.data_from - 1].0);
    let mut t = Vec::new();
    let mut v = Vec::new();
    let mut truth = TruthFields::default();
    let mut seen = 0usize;
    let (sk, kv) = layout.signal;
    let tk = match layout.time {
        TimeSource::Cell(k, _) | TimeSource::Sequence(k, _, _) => k,
    };
    let needed = sk.max(tk) + 1;
    for (i, raw) in lines_any(text).enumerate() {
        let line = i + 1;
        let s = raw.trim();
        if s.is_empty() {
            continue;
        }
        if let Some(c) = s.strip_prefix('#') {
            truth.read(c.trim());
            continue;
        }
        seen += 1;
        if seen <= layout.data_from {
            continue;
        }
        let cells = cells(s);
        if cells.len() < needed || cells[tk].is_empty() || cells[sk].is_empty() {
            return Err(ExperimentError::MissingColumn {
                file: file.into(),
                line,
                found: cells.iter().filter(|c| !c.is_empty()).count(),
            });
        }
        if t.len() >= MAX_SAMPLES {
            return Err(ExperimentError::TooManySamples {
                file: file.into(),
                line,
                limit: MAX_SAMPLES,
            });
        }
        let num = |k: usize, name: &str| -> Result<f64, ExperimentError> {
            let x = cells[k].parse::<f64>().map_err(|_| {
                // Quoted cut to a few dozen characters, control characters escaped: one line.
                let cell = physics::scene::message::cut(cells[k]);
                let (file, column, col) = (file.into(), name.into(), k + 1);
                if cells[k].replace(',', ".").parse::<f64>().is_ok() {
                    ExperimentError::DecimalComma {
                        file,
                        line,
                        column,
                        col,
                        cell,
                    }
                } else {
                    ExperimentError::NotANumber {
                        file,
                        line,
                        column,
                        col,
                        cell,
                    }
                }
            })?;
            if x.is_finite() {
                Ok(x)
            } else {
                Err(ExperimentError::NonFinite {
                    file: file.into(),
                    line,
                    column: name.into(),
                    col: k + 1,
                    value: x,
                })
            }
        };
        let ti = match layout.time {
            TimeSource::Cell(k, kt) => num(k, "time")? * kt,
            TimeSource::Sequence(k, start, inc) => start + num(k, "sample index")? * inc,
        };
        let vi = num(sk, "signal")? * kv;
        if let Some(&prev) = t.last() {
            if ti <= prev {
                return Err(ExperimentError::NotIncreasing {
                    file: file.into(),
                    line,
                    previous: prev,
                    t: ti,
                });
            }
        }
        t.push(ti);
        v.push(vi);
    }
    if t.is_empty() {
        return Err(match header_line {
            Some(line) => ExperimentError::HeaderOnly {
                file: file.into(),
                line,
            },
            None => ExperimentError::Empty { file: file.into() },
        });
    }
    let trace = Trace {
        source: file.into(),
        t,
        v,
        truth: truth.finish(),
    };
    Ok((trace, layout.described))
}

/// The truth as read from `# truth.KEY: VALUE` comments.
#[derive(Default)]
struct TruthFields {
    beta: Option<f64>,
    t0: Option<f64>,
    t_stop: Option<f64>,
    tau_rem: Option<f64>,
    c: Option<f64>,
    origin: Option<String>,
}

impl TruthFields {
    fn read(&mut self, comment: &str) {
        let Some(rest) = comment.strip_prefix("truth.") else {
            return;
        };
        let Some((key, value)) = rest.split_once(':') else {
            return;
        };
        let value = value.trim();
        let x = value.parse::<f64>().ok().filter(|x| x.is_finite());
        match key.trim() {
            "beta" => self.beta = x,
            "t0" => self.t0 = x,
            "t_stop" => self.t_stop = x,
            "tau_rem" => self.tau_rem = x,
            "c" => self.c = x,
            "origin" => self.origin = Some(value.to_string()),
            _ => {}
        }
    }

    fn finish(self) -> Option<Truth> {
        let (beta, t0) = (self.beta?, self.t0?);
        Some(Truth {
            beta,
            t0,
            t_stop: self.t_stop.unwrap_or(t0),
            tau_rem: self.tau_rem.unwrap_or(0.0),
            c: self.c,
            origin: self.origin.unwrap_or_default(),
        })
    }
}
