//! Where `simulate --csv` writes its rows while the run makes them, holding none in memory: the
//! CSV text of each row handed to the files crate's streamed output
//! ([`files::streamed::Streamed`]), which puts the whole file in place once the run is done and
//! writes nothing when it fails. Before the run starts, the rows' bytes are bounded and compared
//! with the space free on the disk that takes them.

use crate::cli::stdout::CLOSED_PIPE_STATUS;
use files::streamed::Streamed;
use std::path::Path;

/// The most bytes one number takes in a row ([`physics::run::csv_row`], the shortest decimal
/// that reads back): at most 17 significant digits, a sign, a point and an exponent of up to
/// three digits with its sign (`-1.2345678901234567e-308`, 24 bytes), then a comma or the
/// newline.
pub(crate) const CELL_BYTES: u64 = 25;

/// Rows written as CSV while a run makes them.
pub(crate) struct RowStream {
    out: Streamed,
    line: Vec<u8>,
}

impl RowStream {
    /// Opens the stream for `path` (`-` for standard output) and writes the header. `rows` is
    /// the number of rows the run samples, when known: their bytes must fit the space free on
    /// the file's disk.
    pub(crate) fn open(path: &Path, columns: &[String], rows: Option<u64>) -> anyhow::Result<Self> {
        let bytes = rows.map(|r| {
            r.saturating_add(1)
                .saturating_mul(columns.len() as u64)
                .saturating_mul(CELL_BYTES)
        });
        let out = Streamed::open(path, bytes).map_err(|e| match e {
            files::streamed::StreamedError::NoRoom { .. } => anyhow::anyhow!(
                "{e}: raise the scene's sample, lower stop.time, or write to a disk with more room"
            ),
            e => anyhow::anyhow!("--csv {e}"),
        })?;
        let mut s = Self {
            out,
            line: Vec::with_capacity(32 * columns.len()),
        };
        s.line.extend_from_slice(columns.join(",").as_bytes());
        s.line.push(b'\n');
        s.out.write(&s.line);
        Ok(s)
    }

    /// Writes one row (the first failure is kept and said by [`RowStream::finish`]).
    pub(crate) fn write(&mut self, row: &[f64]) {
        self.line.clear();
        physics::run::csv_row(row, &mut self.line);
        self.out.write(&self.line);
    }

    /// Ends the stream: puts the file in place. A reader that closed standard output ends the
    /// program quietly, as `| head` expects.
    pub(crate) fn finish(self) -> anyhow::Result<()> {
        match self.out.finish() {
            Err(e) if e.is_closed_pipe() => std::process::exit(CLOSED_PIPE_STATUS),
            r => r.map_err(anyhow::Error::from),
        }
    }
}
