//! One output file written while a long run makes it (the rows of `simulate --csv`), through the
//! same door as every other output ([`crate::output_file::output_target`]): a regular file with
//! one name is written to a new temporary file beside it and renamed over it once the run is
//! done; a regular file with other names (hard links), standard output, a FIFO or a character
//! device get the bytes spooled in an unlinked temporary file and copied there once the run is
//! done. A reader never sees half a file; a failed run writes nothing and leaves an old file as
//! it was; nothing but the tool's own temporary is ever renamed or removed.

use crate::output_file::{output_target, OutputError, OutputTarget};
use std::fs::File;
use std::io::{BufWriter, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};

/// Where spooled bytes go once the run is done.
enum Through {
    /// Standard output.
    Stdout,
    /// A FIFO or a character device, written through.
    Device(PathBuf),
    /// A regular file with other names, written into so that every name keeps naming it.
    Into(PathBuf),
}

/// The destination of the bytes.
enum Target {
    /// Bytes spooled in an unlinked temporary file, copied to `to` by [`Streamed::finish`].
    Spool { file: BufWriter<File>, to: Through },
    /// A new temporary file renamed over `path` by [`Streamed::finish`].
    Replace {
        tmp: PathBuf,
        path: PathBuf,
        file: BufWriter<File>,
    },
}

/// An output file written as it is made.
pub struct Streamed {
    target: Option<Target>,
    error: Option<std::io::Error>,
    shown: String,
}

/// Why a streamed output cannot be opened or finished.
#[derive(Debug, thiserror::Error)]
pub enum StreamedError {
    /// The path is refused by the output door.
    #[error(transparent)]
    Output(#[from] OutputError),
    /// The bytes announced do not fit the disk that takes them.
    #[error(
        "{shown}: the output takes up to {bytes:.3e} bytes, more than the {free:.3e} bytes free \
         on its disk"
    )]
    NoRoom {
        /// The path as given.
        shown: String,
        /// The bytes announced.
        bytes: f64,
        /// The bytes free.
        free: f64,
    },
    /// Writing or putting the file in place failed.
    #[error("cannot write {0} ({1})")]
    Io(String, std::io::Error),
}

impl StreamedError {
    /// Whether the reader of standard output or of a FIFO went away (a closed pipe).
    pub fn is_closed_pipe(&self) -> bool {
        matches!(self, StreamedError::Io(_, e) if e.kind() == std::io::ErrorKind::BrokenPipe)
    }
}

impl Streamed {
    /// Opens the output at `path` (`-` for standard output). `bytes`, when known, is the most the
    /// output will take: it must fit the space free on the disk that takes it.
    pub fn open(path: &Path, bytes: Option<u64>) -> Result<Self, StreamedError> {
        let shown = path.display().to_string();
        let target = if path.as_os_str() == "-" {
            spool(Through::Stdout, &shown, bytes)?
        } else {
            match output_target(path)? {
                OutputTarget::WriteThrough(p) => spool(Through::Device(p), &shown, bytes)?,
                OutputTarget::WriteInto(p) => spool(Through::Into(p), &shown, bytes)?,
                OutputTarget::Replace(p) => replace(p, &shown, bytes)?,
            }
        };
        Ok(Self {
            target: Some(target),
            error: None,
            shown,
        })
    }

    /// Writes `bytes` (the first failure is kept and said by [`Streamed::finish`]).
    pub fn write(&mut self, bytes: &[u8]) {
        if self.error.is_some() {
            return;
        }
        let result = match self.target.as_mut() {
            Some(Target::Spool { file, .. } | Target::Replace { file, .. }) => {
                file.write_all(bytes)
            }
            None => Ok(()),
        };
        if let Err(e) = result {
            self.error = Some(e);
        }
    }

    /// Ends the output: flushes it and puts it in place. On an error the temporary file is
    /// removed and an old file left as it was.
    pub fn finish(mut self) -> Result<(), StreamedError> {
        let target = self.target.take();
        let error = self.error.take();
        let result = match target {
            Some(Target::Spool { file, to }) => {
                error.map_or(Ok(()), Err).and_then(|()| copy_out(file, to))
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
        result.map_err(|e| StreamedError::Io(self.shown.clone(), e))
    }
}

impl Drop for Streamed {
    /// An output dropped before [`Streamed::finish`] (the run failed) leaves no temporary file.
    fn drop(&mut self) {
        if let Some(Target::Replace { tmp, .. }) = self.target.take() {
            let _ = std::fs::remove_file(tmp);
        }
    }
}

/// Bytes spooled on the temporary directory's disk for `to`.
fn spool(to: Through, shown: &str, bytes: Option<u64>) -> Result<Target, StreamedError> {
    let dir = std::env::temp_dir();
    check_space(&dir, shown, bytes)?;
    let (tmp, f) = crate::atomic::new_temporary(&dir, "rolling-disk-spool")
        .map_err(|e| StreamedError::Io(shown.to_string(), e))?;
    // Unlinked at once: the file lives as long as it is open, whatever happens to the run.
    let _ = std::fs::remove_file(&tmp);
    Ok(Target::Spool {
        file: BufWriter::with_capacity(1 << 16, f),
        to,
    })
}

/// Bytes written to a new temporary file beside `path`, renamed over it at the end.
fn replace(path: PathBuf, shown: &str, bytes: Option<u64>) -> Result<Target, StreamedError> {
    let dir = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."))
        .to_path_buf();
    check_space(&dir, shown, bytes)?;
    let name = path.file_name().map_or_else(
        || "output".to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    let (tmp, f) = crate::atomic::new_temporary(&dir, &name)
        .map_err(|e| StreamedError::Io(shown.to_string(), e))?;
    Ok(Target::Replace {
        tmp,
        path,
        file: BufWriter::with_capacity(1 << 16, f),
    })
}

/// Copies the spooled bytes in `file` to `to`.
fn copy_out(file: BufWriter<File>, to: Through) -> std::io::Result<()> {
    let mut f = file.into_inner().map_err(|e| e.into_error())?;
    f.seek(SeekFrom::Start(0))?;
    let mut out: Box<dyn Write> = match to {
        Through::Stdout => Box::new(std::io::stdout().lock()),
        Through::Device(p) => Box::new(std::fs::OpenOptions::new().write(true).open(p)?),
        Through::Into(p) => Box::new(
            std::fs::OpenOptions::new()
                .write(true)
                .truncate(true)
                .open(p)?,
        ),
    };
    std::io::copy(&mut f, &mut out)?;
    out.flush()
}

/// Refuses an output of `bytes` larger than the space free on the disk of `dir`.
fn check_space(dir: &Path, shown: &str, bytes: Option<u64>) -> Result<(), StreamedError> {
    let (Some(bytes), Some(free)) = (bytes, free_bytes(dir)) else {
        return Ok(());
    };
    if bytes > free {
        return Err(StreamedError::NoRoom {
            shown: shown.to_string(),
            bytes: bytes as f64,
            free: free as f64,
        });
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_streamed_file_appears_whole_at_the_end_and_a_failed_one_not_at_all() {
        let dir = std::env::temp_dir().join(format!("streamed-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("rows.csv");
        std::fs::write(&path, "old\n").unwrap();
        let mut s = Streamed::open(&path, Some(10)).unwrap();
        s.write(b"new\n");
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "old\n");
        s.finish().unwrap();
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "new\n");
        let mut s = Streamed::open(&path, None).unwrap();
        s.write(b"half");
        drop(s);
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "new\n");
        let left: Vec<_> = std::fs::read_dir(&dir).unwrap().collect();
        assert_eq!(left.len(), 1, "no temporary file is left");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_hard_linked_file_is_written_into() {
        let dir = std::env::temp_dir().join(format!("streamed-link-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("a.csv");
        std::fs::write(&path, "old\n").unwrap();
        std::fs::hard_link(&path, dir.join("b.csv")).unwrap();
        let mut s = Streamed::open(&path, None).unwrap();
        s.write(b"new\n");
        s.finish().unwrap();
        assert_eq!(std::fs::read_to_string(dir.join("b.csv")).unwrap(), "new\n");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn more_bytes_than_the_disk_holds_are_refused_before_anything_is_written() {
        let dir = std::env::temp_dir();
        let path = dir.join(format!("streamed-huge-{}.csv", std::process::id()));
        match Streamed::open(&path, Some(u64::MAX)) {
            Err(StreamedError::NoRoom { .. }) => {}
            Err(e) => panic!("refused for another reason: {e}"),
            Ok(_) => panic!("u64::MAX bytes were accepted"),
        }
        assert!(!path.exists());
    }
}
