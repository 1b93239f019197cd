//! Scope CSV: a header (time in s, signal in V) and one row per sample, as a scope exports it.
//!
//! Reading validates every row and names the file and the 1-based line of the first problem:
//! a missing column, a cell that is not a number, NaN or infinity, a time that does not
//! increase. Lines starting with `#` are comments; a synthetic trace writes its truth there
//! (`# truth.beta: 2`), and reading it back restores it.

use crate::experiment::error::ExperimentError;
use crate::experiment::trace::{Trace, Truth};
use std::fmt::Write as _;
use std::path::Path;

impl Trace {
    /// The trace as CSV: comments (source, truth), the header `time_s,signal_V`, the samples.
    /// Numbers are written in their shortest exact form, so they read back bit for bit.
    pub fn to_csv(&self) -> String {
        let mut s = String::with_capacity(self.t.len() * 32 + 256);
        let _ = writeln!(s, "# rolling-disk scope trace");
        let _ = writeln!(s, "# source: {}", self.source);
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

/// Reads and validates a scope CSV file.
pub fn read_trace(path: impl AsRef<Path>) -> Result<Trace, ExperimentError> {
    let path = path.as_ref();
    let file = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| ExperimentError::Io {
        file: file.clone(),
        message: format!("cannot read this CSV ({e})"),
    })?;
    parse_trace(&text, &file)
}

/// Parses and validates CSV text; `file` names it in errors.
pub fn parse_trace(text: &str, file: &str) -> Result<Trace, ExperimentError> {
    let mut t = Vec::new();
    let mut v = Vec::new();
    let mut header_line = None;
    let mut truth = TruthFields::default();
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let s = raw.trim();
        if s.is_empty() {
            continue;
        }
        if let Some(c) = s.strip_prefix('#') {
            truth.read(c.trim());
            continue;
        }
        let cells: Vec<&str> = s.split(',').map(str::trim).collect();
        let numeric = cells[0].parse::<f64>().is_ok();
        if header_line.is_none() && t.is_empty() && !numeric {
            if cells.len() < 2 || cells[1].is_empty() {
                return Err(ExperimentError::MissingColumn {
                    file: file.into(),
                    line,
                    found: cells.iter().filter(|c| !c.is_empty()).count(),
                });
            }
            header_line = Some(line);
            continue;
        }
        if cells.len() < 2 || cells[1].is_empty() {
            return Err(ExperimentError::MissingColumn {
                file: file.into(),
                line,
                found: cells.iter().filter(|c| !c.is_empty()).count(),
            });
        }
        let num = |k: usize, name: &str| -> Result<f64, ExperimentError> {
            let x = cells[k]
                .parse::<f64>()
                .map_err(|_| ExperimentError::NotANumber {
                    file: file.into(),
                    line,
                    column: name.into(),
                    cell: cells[k].into(),
                })?;
            if x.is_finite() {
                Ok(x)
            } else {
                Err(ExperimentError::NonFinite {
                    file: file.into(),
                    line,
                    column: name.into(),
                    value: x,
                })
            }
        };
        let ti = num(0, "time")?;
        let vi = num(1, "signal")?;
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
    Ok(Trace {
        source: file.into(),
        t,
        v,
        truth: truth.finish(),
    })
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
