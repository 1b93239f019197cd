//! `simulate --against FILE.csv`: a run compared, row by row as it is made, with a run recorded
//! by `simulate --csv`. A cell of the recorded value $x$ may differ by the scene's own
//! solver tolerances, $\mathrm{atol} + \mathrm{rtol}\,|x|$ (the error the solver is asked to
//! keep each step within); the first row and column beyond it are said, with how many cells
//! are. The recorded numbers are read back to the same doubles as were written, so a run of
//! an unchanged scene differs from its recording in no cell.

use crate::cli::stdin;
use std::fmt::Write as _;
use std::path::Path;

/// The largest recorded run read, in bytes.
const MAX_RECORDED_BYTES: u64 = 1 << 30;

/// A run recorded by `simulate --csv`.
pub(crate) struct Recorded {
    /// How the file is named in messages.
    name: String,
    /// Its header's column names.
    columns: Vec<String>,
    /// Its rows.
    rows: Vec<Vec<f64>>,
}

impl Recorded {
    /// Reads the recorded run at `path` (`-`: standard input).
    pub(crate) fn read(path: &Path) -> anyhow::Result<Self> {
        let (name, text) = if stdin::is_stdin(path) {
            let text = stdin::read_text("--against", MAX_RECORDED_BYTES)?;
            (stdin::NAME.to_string(), text)
        } else {
            let text = files::input::read_text(path, MAX_RECORDED_BYTES)
                .map_err(|e| anyhow::anyhow!("--against {e}"))?;
            (path.display().to_string(), text)
        };
        let mut lines = text.lines().enumerate();
        let redo = "give a CSV written by `rolling-disk simulate SCENE --csv FILE`";
        let Some((_, header)) = lines.find(|(_, l)| !l.trim().is_empty()) else {
            return Err(anyhow::anyhow!("{name}: is empty; {redo}"));
        };
        let columns: Vec<String> = header.split(',').map(|c| c.trim().to_string()).collect();
        let mut rows = Vec::new();
        for (i, line) in lines {
            if line.trim().is_empty() {
                continue;
            }
            let row = line
                .split(',')
                .enumerate()
                .map(|(k, cell)| {
                    cell.trim().parse::<f64>().map_err(|_| {
                        anyhow::anyhow!(
                            "{name}:{}: column {} (`{}`) is not a number; {redo}",
                            i + 1,
                            columns.get(k).map_or(format!("{}", k + 1), Clone::clone),
                            cell.trim()
                        )
                    })
                })
                .collect::<anyhow::Result<Vec<f64>>>()?;
            if row.len() != columns.len() {
                return Err(anyhow::anyhow!(
                    "{name}:{}: {} cells where the header names {} columns; {redo}",
                    i + 1,
                    row.len(),
                    columns.len()
                ));
            }
            rows.push(row);
        }
        Ok(Self {
            name,
            columns,
            rows,
        })
    }
}

/// The first cell beyond its tolerance.
#[derive(Debug, Clone, Copy)]
struct Cell {
    /// The row, from 1 (the header not counted).
    row: usize,
    /// The column's index.
    column: usize,
    /// The recorded value.
    before: f64,
    /// This run's.
    after: f64,
    /// The difference allowed.
    tolerance: f64,
}

/// A run compared with a recording as its rows come.
pub(crate) struct TraceAgainst<'a> {
    recorded: &'a Recorded,
    rtol: f64,
    atol: f64,
    /// Rows of this run so far.
    rows: usize,
    /// The first cell beyond its tolerance.
    first: Option<Cell>,
    /// Cells beyond their tolerance.
    cells: u64,
    /// Whether the run's columns are the recording's.
    same_columns: bool,
}

impl<'a> TraceAgainst<'a> {
    /// A comparison with `recorded` of a run with `columns`, at the scene's `rtol` and `atol`.
    pub(crate) fn new(recorded: &'a Recorded, columns: &[String], rtol: f64, atol: f64) -> Self {
        Self {
            recorded,
            rtol,
            atol,
            rows: 0,
            first: None,
            cells: 0,
            same_columns: recorded.columns == columns,
        }
    }

    /// Compares the run's next row.
    pub(crate) fn push(&mut self, row: &[f64]) {
        self.rows += 1;
        if !self.same_columns {
            return;
        }
        let Some(before) = self.recorded.rows.get(self.rows - 1) else {
            return;
        };
        for (column, (&b, &a)) in before.iter().zip(row).enumerate() {
            let tolerance = self.atol + self.rtol * b.abs();
            let beyond = (a - b).abs() > tolerance || (a.is_nan() != b.is_nan());
            if beyond {
                self.cells += 1;
                if self.first.is_none() {
                    self.first = Some(Cell {
                        row: self.rows,
                        column,
                        before: b,
                        after: a,
                        tolerance,
                    });
                }
            }
        }
    }

    /// What differs, one line each (none when the run matches its recording), and one line of
    /// totals; the second item is true when anything differs.
    pub(crate) fn finish(&self, run_columns: &[String]) -> (String, bool) {
        let mut s = String::new();
        let name = &self.recorded.name;
        let mut changed = false;
        if !self.same_columns {
            changed = true;
            let _ = writeln!(
                s,
                "columns: recorded {}; this run {}",
                self.recorded.columns.join(","),
                run_columns.join(",")
            );
        }
        if self.rows != self.recorded.rows.len() {
            changed = true;
            let _ = writeln!(
                s,
                "rows: recorded {}; this run {}",
                self.recorded.rows.len(),
                self.rows
            );
        }
        if let Some(c) = self.first {
            changed = true;
            let _ = writeln!(
                s,
                "first difference: row {} column {}: recorded {:.16e}, this run {:.16e}, \
                 difference {:.3e} > tolerance {:.3e} (atol {:e} + rtol {:e} x |recorded|); \
                 {} cell(s) beyond their tolerance",
                c.row,
                self.recorded.columns[c.column],
                c.before,
                c.after,
                (c.after - c.before).abs(),
                c.tolerance,
                self.atol,
                self.rtol,
                self.cells
            );
        }
        if changed {
            let _ = writeln!(s, "against {name}: the run differs from its recording");
        } else {
            let _ = writeln!(
                s,
                "against {name}: {} rows, every cell within atol {:e} + rtol {:e} x |recorded|",
                self.rows, self.atol, self.rtol
            );
        }
        (s, changed)
    }
}
