//! Where one output file (`--csv FILE`, `--wav FILE`, `--out FILE`) goes, decided from what the
//! path names before anything is written: a new path or a regular file with one name is written
//! atomically ([`crate::atomic::write_atomically`]); a regular file with other names (hard links)
//! is written into, so that every name keeps showing the same file; a symbolic link is followed
//! and its target treated the same way; a FIFO or a character device (`/dev/null`, a terminal) is
//! written through, as a shell's `>` would; one of the command's own inputs
//! ([`crate::inputs`]), a read-only file, a directory and anything else are refused with a
//! sentence. Nothing that is not a regular file is ever replaced by one.
//!
//! This is the one door for a file at a path the user named; the files of a set (a report, a
//! folder of figures) go through [`crate::output::SetWriter`].

use std::io::Write;
use std::path::{Path, PathBuf};

/// What an output path names.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum OutputTarget {
    /// A path where nothing is yet, or a regular file with one name that the user may write:
    /// replaced atomically.
    Replace(PathBuf),
    /// A regular file with other names (hard links): written into, so that all its names keep
    /// naming it.
    WriteInto(PathBuf),
    /// A FIFO or a character device: opened and written through, never replaced.
    WriteThrough(PathBuf),
}

/// Why an output path is refused.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    /// The path is a directory.
    #[error("{0}: is a directory; give the path of a file (or - for standard output)")]
    Directory(String),
    /// The file has no write permission.
    #[error("{0}: is read-only; make it writable (chmod u+w) or give another path")]
    ReadOnly(String),
    /// A symbolic link whose target does not exist or cannot be resolved.
    #[error("{0}: is a symbolic link to nothing ({1}); give the path of a file")]
    DanglingLink(String, std::io::Error),
    /// A block device, a socket or another kind of file that is not written to.
    #[error("{0}: is not a regular file, a FIFO or a character device; give the path of a file")]
    Special(String),
    /// The path names a file this command reads.
    #[error("{0}: is an input of this command (read as {1}); give another path for the output")]
    Input(String, String),
    /// The write itself failed.
    #[error("cannot write {0} ({1})")]
    Io(String, std::io::Error),
}

/// Decides, without writing, where the bytes for `path` go.
pub fn output_target(path: &Path) -> Result<OutputTarget, OutputError> {
    let shown = path.display().to_string();
    let meta = match std::fs::symlink_metadata(path) {
        Err(_) => return Ok(OutputTarget::Replace(path.to_path_buf())),
        Ok(m) => m,
    };
    if meta.file_type().is_symlink() {
        let real = std::fs::canonicalize(path).map_err(|e| OutputError::DanglingLink(shown, e))?;
        return output_target(&real);
    }
    if meta.is_dir() {
        return Err(OutputError::Directory(shown));
    }
    if meta.is_file() {
        if let Some(input) = crate::inputs::input_named(path) {
            return Err(OutputError::Input(shown, input.display().to_string()));
        }
        if meta.permissions().readonly() || !writable(path) {
            return Err(OutputError::ReadOnly(shown));
        }
        if link_count(&meta) > 1 {
            return Ok(OutputTarget::WriteInto(path.to_path_buf()));
        }
        return Ok(OutputTarget::Replace(path.to_path_buf()));
    }
    if is_fifo_or_char_device(&meta) {
        return Ok(OutputTarget::WriteThrough(path.to_path_buf()));
    }
    Err(OutputError::Special(shown))
}

/// Writes `bytes` to `path` as [`output_target`] decides.
pub fn write_output(path: &Path, bytes: &[u8]) -> Result<(), OutputError> {
    let shown = |p: &Path| p.display().to_string();
    match output_target(path)? {
        OutputTarget::Replace(p) => {
            crate::atomic::write_atomically(&p, bytes).map_err(|e| OutputError::Io(shown(&p), e))
        }
        OutputTarget::WriteInto(p) => std::fs::OpenOptions::new()
            .write(true)
            .truncate(true)
            .open(&p)
            .and_then(|mut f| f.write_all(bytes).and_then(|()| f.sync_all()))
            .map_err(|e| OutputError::Io(shown(&p), e)),
        OutputTarget::WriteThrough(p) => std::fs::OpenOptions::new()
            .write(true)
            .open(&p)
            .and_then(|mut f| f.write_all(bytes).and_then(|()| f.flush()))
            .map_err(|e| OutputError::Io(shown(&p), e)),
    }
}

/// How many names (hard links) the file has.
#[cfg(unix)]
fn link_count(meta: &std::fs::Metadata) -> u64 {
    use std::os::unix::fs::MetadataExt;
    meta.nlink()
}

#[cfg(not(unix))]
fn link_count(_meta: &std::fs::Metadata) -> u64 {
    1
}

#[cfg(unix)]
fn is_fifo_or_char_device(meta: &std::fs::Metadata) -> bool {
    use std::os::unix::fs::FileTypeExt;
    meta.file_type().is_fifo() || meta.file_type().is_char_device()
}

#[cfg(not(unix))]
fn is_fifo_or_char_device(_meta: &std::fs::Metadata) -> bool {
    false
}

/// Whether the calling user may write `path` (the kernel's answer, which for root ignores the
/// mode; the mode's own write bits are checked beside it).
#[cfg(target_os = "linux")]
pub(crate) fn writable(path: &Path) -> bool {
    rustix::fs::access(path, rustix::fs::Access::WRITE_OK).is_ok()
}

#[cfg(not(target_os = "linux"))]
pub(crate) fn writable(_path: &Path) -> bool {
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let d =
            std::env::temp_dir().join(format!("rolling-disk-out-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).ok();
        d
    }

    #[test]
    fn a_new_path_and_a_writable_file_are_replaced_and_a_directory_is_refused() {
        let root = scratch("kinds");
        let new = root.join("a.csv");
        assert_eq!(
            output_target(&new).ok(),
            Some(OutputTarget::Replace(new.clone()))
        );
        assert!(write_output(&new, b"one").is_ok());
        assert!(write_output(&new, b"two").is_ok());
        assert_eq!(std::fs::read(&new).ok().as_deref(), Some(&b"two"[..]));
        assert!(matches!(
            output_target(&root),
            Err(OutputError::Directory(_))
        ));
        let _ = std::fs::remove_dir_all(&root);
    }

    #[cfg(unix)]
    #[test]
    fn a_symlink_is_written_through_and_a_read_only_file_is_refused() {
        use std::os::unix::fs::PermissionsExt;
        let root = scratch("links");
        let real = root.join("real.csv");
        std::fs::write(&real, "old").ok();
        let link = root.join("link.csv");
        std::os::unix::fs::symlink(&real, &link).ok();
        assert!(write_output(&link, b"new").is_ok());
        assert!(std::fs::symlink_metadata(&link).is_ok_and(|m| m.file_type().is_symlink()));
        assert_eq!(std::fs::read(&real).ok().as_deref(), Some(&b"new"[..]));
        let dangling = root.join("dangling.csv");
        std::os::unix::fs::symlink(root.join("nothing"), &dangling).ok();
        assert!(matches!(
            write_output(&dangling, b"x"),
            Err(OutputError::DanglingLink(..))
        ));
        std::fs::set_permissions(&real, std::fs::Permissions::from_mode(0o444)).ok();
        assert!(matches!(
            write_output(&real, b"x"),
            Err(OutputError::ReadOnly(_))
        ));
        assert!(matches!(
            write_output(&link, b"x"),
            Err(OutputError::ReadOnly(_))
        ));
        assert_eq!(std::fs::read(&real).ok().as_deref(), Some(&b"new"[..]));
        let _ = std::fs::remove_dir_all(&root);
    }

    #[cfg(unix)]
    #[test]
    fn a_hard_link_is_written_into_and_an_input_is_refused() {
        let root = scratch("hard");
        let one = root.join("one.csv");
        let two = root.join("two.csv");
        std::fs::write(&one, "old").ok();
        std::fs::hard_link(&one, &two).ok();
        assert_eq!(
            output_target(&two).map_err(|e| e.to_string()),
            Ok(OutputTarget::WriteInto(two.clone()))
        );
        assert!(write_output(&two, b"new").is_ok());
        assert_eq!(std::fs::read(&one).ok().as_deref(), Some(&b"new"[..]));
        let scene = root.join("my.yaml");
        std::fs::write(&scene, "name: x\n").ok();
        assert!(crate::input::read_text(&scene, 100).is_ok());
        assert!(matches!(
            write_output(&scene, b"t,alpha\n"),
            Err(OutputError::Input(..))
        ));
        let link = root.join("link.yaml");
        std::os::unix::fs::symlink(&scene, &link).ok();
        assert!(matches!(
            write_output(&link, b"t,alpha\n"),
            Err(OutputError::Input(..))
        ));
        assert_eq!(
            std::fs::read(&scene).ok().as_deref(),
            Some(&b"name: x\n"[..])
        );
        let _ = std::fs::remove_dir_all(&root);
    }

    #[cfg(unix)]
    #[test]
    fn a_character_device_is_written_through_not_replaced() {
        use std::os::unix::fs::FileTypeExt;
        // Only where the machine's /dev/null is the character device it should be (a sandbox may
        // have a regular file there).
        let null = Path::new("/dev/null");
        if std::fs::symlink_metadata(null).is_ok_and(|m| m.file_type().is_char_device()) {
            assert_eq!(
                output_target(null).ok(),
                Some(OutputTarget::WriteThrough(null.to_path_buf()))
            );
            assert!(write_output(null, b"bytes").is_ok());
            assert!(std::fs::metadata(null).is_ok_and(|m| !m.is_file()));
        }
    }
}
