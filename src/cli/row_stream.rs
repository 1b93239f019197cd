//! Where `simulate --csv` writes its rows while the run makes them, holding none in memory: a
//! regular file is written to a temporary file beside it and renamed over it once the run is
//! done; standard output (`-`), a FIFO or a character device get the rows spooled on the
//! temporary directory's disk and copied there once the run is done. A reader never sees half
//! a table, and a failed run writes nothing and leaves an old file as it was. Before the run
//! starts, the rows' bytes are bounded and compared with the space free on the disk that takes
//! them.

use crate::cli::stdout::CLOSED_PIPE_STATUS;
use files::output_file::{output_target, OutputTarget};
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// The most bytes one number takes in a row: 17 significant digits, a sign, a point and an
/// exponent of up to three digits with its sign (`-1.2345678901234567e-100`), then a comma or
/// the newline.
pub(crate) const CELL_BYTES: u64 = 25;

/// Where spooled rows go once the run is done.
enum Through {
    Stdout,
    File(PathBuf),
}

/// The destination of the rows.
enum Target {
    /// Rows spooled in an unlinked temporary file, copied to `to` by [`RowStream::finish`].
    Spool { file: BufWriter<File>, to: Through },
    /// A temporary file renamed over `path` by [`RowStream::finish`].
    Replace {
        tmp: PathBuf,
        path: PathBuf,
        file: BufWriter<File>,
    },
}

/// Rows written as CSV while a run makes them.
pub(crate) struct RowStream {
    target: Option<Target>,
    line: Vec<u8>,
    error: Option<std::io::Error>,
    shown: String,
}

impl RowStream {
    /// Opens the stream for `path` and writes the header. `rows` is the number of rows the run
    /// samples, when known: their bytes must fit the space free on the file's disk.
    pub(crate) fn open(path: &Path, columns: &[String], rows: Option<u64>) -> anyhow::Result<Self> {
        let shown = path.display().to_string();
        let target = if path.as_os_str() == "-" {
            spool(Through::Stdout, &shown, rows, columns.len())?
        } else {
            match output_target(path)? {
                OutputTarget::WriteThrough(p) => {
                    spool(Through::File(p), &shown, rows, columns.len())?
                }
                OutputTarget::Replace(p) => replace(p, &shown, rows, columns.len())?,
            }
        };
        let mut s = Self {
            target: Some(target),
            line: Vec::with_capacity(32 * columns.len()),
            error: None,
            shown,
        };
        s.line.extend_from_slice(columns.join(",").as_bytes());
        s.line.push(b'\n');
        s.flush_line();
        Ok(s)
    }

    /// Writes one row (the first failure is kept and said by [`RowStream::finish`]).
    pub(crate) fn write(&mut self, row: &[f64]) {
        if self.error.is_some() {
            return;
        }
        self.line.clear();
        physics::run::csv_row(row, &mut self.line);
        self.flush_line();
    }

    fn flush_line(&mut self) {
        let line = &self.line;
        let result = match self.target.as_mut() {
            Some(Target::Spool { file, .. } | Target::Replace { file, .. }) => file.write_all(line),
            None => Ok(()),
        };
        if let Err(e) = result {
            self.error = Some(e);
        }
    }

    /// Ends the stream: flushes it and puts the file in place. An error says which file and
    /// why; the temporary file is then removed and the old file left as it was.
    pub(crate) fn finish(mut self) -> anyhow::Result<()> {
        let target = self.target.take();
        let error = self.error.take();
        let result = match target {
            Some(Target::Spool { file, to }) => {
                let r = error.map_or(Ok(()), Err).and_then(|()| copy_out(file, to));
                if let Err(e) = &r {
                    if e.kind() == std::io::ErrorKind::BrokenPipe {
                        std::process::exit(CLOSED_PIPE_STATUS);
                    }
                }
                r
            }
            Some(Target::Replace { tmp, path, file }) => {
                let r = error.map_or(Ok(()), Err).and_then(|()| {
                    let f = file.into_inner().map_err(|e| e.into_error())?;
                    f.sync_all()?;
                    std::fs::rename(&tmp, &path)
                });
                if r.is_err() {
                    let _ = std::fs::remove_file(&tmp);
                }
                r
            }
            None => Ok(()),
        };
        result.map_err(|e| anyhow::anyhow!("cannot write {} ({e})", self.shown))
    }
}

/// Rows spooled on the temporary directory's disk for `to`.
fn spool(to: Through, shown: &str, rows: Option<u64>, columns: usize) -> anyhow::Result<Target> {
    let dir = std::env::temp_dir();
    if let Some(rows) = rows {
        check_space(&dir, shown, rows, columns)?;
    }
    let tmp = dir.join(format!("rolling-disk-rows.{}.tmp", std::process::id()));
    let _ = std::fs::remove_file(&tmp);
    let f = std::fs::OpenOptions::new()
        .read(true)
        .write(true)
        .create_new(true)
        .open(&tmp)
        .map_err(|e| anyhow::anyhow!("cannot spool the rows for {shown} ({e})"))?;
    // Unlinked at once: the file lives as long as it is open, whatever happens to the run.
    let _ = std::fs::remove_file(&tmp);
    Ok(Target::Spool {
        file: BufWriter::with_capacity(1 << 16, f),
        to,
    })
}

/// Rows written to a temporary file beside `path`, renamed over it at the end.
fn replace(
    path: PathBuf,
    shown: &str,
    rows: Option<u64>,
    columns: usize,
) -> anyhow::Result<Target> {
    let dir = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."))
        .to_path_buf();
    if let Some(rows) = rows {
        check_space(&dir, shown, rows, columns)?;
    }
    let name = path
        .file_name()
        .map_or_else(|| "rows".to_string(), |n| n.to_string_lossy().into_owned());
    let tmp = dir.join(format!(".{name}.{}.tmp", std::process::id()));
    let f = File::create(&tmp).map_err(|e| anyhow::anyhow!("cannot write {shown} ({e})"))?;
    Ok(Target::Replace {
        tmp,
        path,
        file: BufWriter::with_capacity(1 << 16, f),
    })
}

/// Copies the spooled rows in `file` to `to`.
fn copy_out(file: BufWriter<File>, to: Through) -> std::io::Result<()> {
    use std::io::{Seek, SeekFrom};
    let mut f = file.into_inner().map_err(|e| e.into_error())?;
    f.seek(SeekFrom::Start(0))?;
    match to {
        Through::Stdout => {
            let mut out = std::io::stdout().lock();
            std::io::copy(&mut f, &mut out)?;
            out.flush()
        }
        Through::File(p) => {
            let mut out = std::fs::OpenOptions::new().write(true).open(p)?;
            std::io::copy(&mut f, &mut out)?;
            out.flush()
        }
    }
}

impl Drop for RowStream {
    /// A stream dropped before [`RowStream::finish`] (the run failed) leaves no temporary file.
    fn drop(&mut self) {
        if let Some(Target::Replace { tmp, .. }) = self.target.take() {
            let _ = std::fs::remove_file(tmp);
        }
    }
}

/// Refuses rows whose bytes exceed the space free on the disk of `dir`.
fn check_space(dir: &Path, shown: &str, rows: u64, columns: usize) -> anyhow::Result<()> {
    let bytes = rows
        .saturating_mul(columns as u64)
        .saturating_mul(CELL_BYTES);
    let Some(free) = free_bytes(dir) else {
        return Ok(());
    };
    if bytes > free {
        return Err(anyhow::anyhow!(
            "{shown}: the run samples {rows} rows, up to {:.3e} bytes as CSV, more than the \
             {:.3e} bytes free on its disk: raise the scene's sample, lower stop.time, or write \
             to a disk with more room",
            bytes as f64,
            free as f64
        ));
    }
    Ok(())
}

#[cfg(target_os = "linux")]
fn free_bytes(dir: &Path) -> Option<u64> {
    let s = rustix::fs::statvfs(dir).ok()?;
    Some(s.f_bavail.saturating_mul(s.f_frsize))
}

#[cfg(not(target_os = "linux"))]
fn free_bytes(_dir: &Path) -> Option<u64> {
    None
}
