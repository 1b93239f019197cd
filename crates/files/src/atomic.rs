//! Writing one file so that a reader never sees half of it: write a temporary file beside the
//! target, then rename it over the target. The temporary's name is one that nothing has yet
//! (created with `O_EXCL`), so that no file of the user's is ever truncated or renamed away.

use std::io::Write;
use std::path::{Path, PathBuf};

/// Creates a new file beside `name` in `dir`, at the first free name `.NAME.PID-N.tmp`, open
/// for reading and writing.
pub(crate) fn new_temporary(dir: &Path, name: &str) -> std::io::Result<(PathBuf, std::fs::File)> {
    let pid = std::process::id();
    for n in 0u32.. {
        let tmp = dir.join(format!(".{name}.{pid}-{n}.tmp"));
        match std::fs::OpenOptions::new()
            .read(true)
            .write(true)
            .create_new(true)
            .open(&tmp)
        {
            Ok(f) => return Ok((tmp, f)),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(e),
        }
    }
    Err(std::io::Error::other("no free temporary name"))
}

/// Writes `bytes` to `path` atomically (a new temporary file in the same directory, then a
/// rename).
pub fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let dir = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let name = path
        .file_name()
        .ok_or_else(|| std::io::Error::new(std::io::ErrorKind::InvalidInput, "not a file name"))?;
    let (tmp, mut f) = new_temporary(dir, &name.to_string_lossy())?;
    let result = f
        .write_all(bytes)
        .and_then(|()| f.sync_all())
        .and_then(|()| std::fs::rename(&tmp, path));
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}
