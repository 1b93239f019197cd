//! Bounded reading of the files a user hands the tool.
//!
//! A path may name anything: a FIFO that blocks forever, `/dev/zero` that never ends, a file of
//! gigabytes. [`read_text`] refuses what is not a regular file before opening it, reads at most
//! a limit of bytes (so a file that grows, or lies about its size, still cannot exhaust memory),
//! and normalises the text as people write it: a UTF-8 byte-order mark is dropped and CRLF and
//! lone CR line ends become LF, so that line numbers in messages match what an editor shows.

use std::borrow::Cow;
use std::io::Read;
use std::path::Path;
use thiserror::Error;

/// Largest scene file read, in bytes (1 MiB; a scene is about 1 KB).
pub const MAX_SCENE_BYTES: u64 = 1 << 20;

/// A user's file that cannot be read: each variant names the file and what to do.
#[derive(Debug, Error)]
pub enum InputError {
    /// The file could not be opened or inspected.
    #[error("{path}: cannot read this file ({source})")]
    Open {
        /// The file.
        path: String,
        /// Why.
        source: std::io::Error,
    },
    /// The path names a directory, a FIFO, a socket or a device.
    #[error("{path}: is a {kind}, not a regular file: give the path of a file")]
    NotRegular {
        /// The file.
        path: String,
        /// What it is.
        kind: &'static str,
    },
    /// The file is larger than the limit.
    #[error(
        "{path}: larger than the limit of {limit} bytes for this kind of file: give a smaller file"
    )]
    TooLarge {
        /// The file.
        path: String,
        /// The limit.
        limit: u64,
    },
    /// The file is not UTF-8 text.
    #[error("{path}:{line}: not UTF-8 text: save the file as UTF-8")]
    NotText {
        /// The file.
        path: String,
        /// The 1-based line of the first invalid byte.
        line: usize,
    },
}

impl InputError {
    /// The message without the file's name, for callers that name the file themselves.
    pub fn reason(&self) -> String {
        match self {
            InputError::Open { source, .. } => format!("cannot read this file ({source})"),
            InputError::NotRegular { kind, .. } => {
                format!("is a {kind}, not a regular file: give the path of a file")
            }
            InputError::TooLarge { limit, .. } => format!(
                "larger than the limit of {limit} bytes for this kind of file: give a smaller file"
            ),
            InputError::NotText { .. } => "not UTF-8 text: save the file as UTF-8".to_string(),
        }
    }
}

/// What a non-regular file is, for messages.
fn kind_of(meta: &std::fs::Metadata) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        let t = meta.file_type();
        if t.is_fifo() {
            return "FIFO (named pipe)";
        }
        if t.is_char_device() || t.is_block_device() {
            return "device";
        }
        if t.is_socket() {
            return "socket";
        }
    }
    if meta.is_dir() {
        "directory"
    } else {
        "special file"
    }
}

/// Reads at most `limit` bytes of the regular file at `path`, refusing anything else at once.
pub fn read_bytes(path: &Path, limit: u64) -> Result<Vec<u8>, InputError> {
    read_bounded(path, limit, true)
}

/// Reads a text file as [`read_text`] does, for a command that replaces that very file on
/// purpose (a snapshot that `check --against FILE --bless` rewrites): it is not recorded as an
/// input ([`crate::inputs`]), so the output door lets the command write it.
pub fn read_text_to_replace(path: &Path, limit: u64) -> Result<String, InputError> {
    text_of(path, read_bounded(path, limit, false)?)
}

/// [`read_bytes`], recording the file as an input when `record` is true.
fn read_bounded(path: &Path, limit: u64, record: bool) -> Result<Vec<u8>, InputError> {
    let name = path.display().to_string();
    let open_err = |source| InputError::Open {
        path: name.clone(),
        source,
    };
    // Inspect before opening: opening a FIFO for reading blocks until a writer appears.
    let meta = std::fs::metadata(path).map_err(open_err)?;
    if !meta.is_file() {
        return Err(InputError::NotRegular {
            path: name,
            kind: kind_of(&meta),
        });
    }
    if meta.len() > limit {
        return Err(InputError::TooLarge { path: name, limit });
    }
    let file = std::fs::File::open(path).map_err(open_err)?;
    // The path may have been swapped between the two looks: check what was opened.
    let opened = file.metadata().map_err(open_err)?;
    if !opened.is_file() {
        return Err(InputError::NotRegular {
            path: name,
            kind: kind_of(&opened),
        });
    }
    if record {
        crate::inputs::record(path, &opened);
    }
    let mut bytes = Vec::new();
    file.take(limit.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(open_err)?;
    if bytes.len() as u64 > limit {
        return Err(InputError::TooLarge { path: name, limit });
    }
    Ok(bytes)
}

/// Reads a text file of at most `limit` bytes (see [`read_bytes`]) and normalises it with
/// [`normalize`].
pub fn read_text(path: &Path, limit: u64) -> Result<String, InputError> {
    text_of(path, read_bytes(path, limit)?)
}

/// The bytes read from `path` as normalised text.
fn text_of(path: &Path, bytes: Vec<u8>) -> Result<String, InputError> {
    let text = String::from_utf8(bytes).map_err(|e| {
        let upto = &e.as_bytes()[..e.utf8_error().valid_up_to()];
        InputError::NotText {
            path: path.display().to_string(),
            line: 1 + upto.iter().filter(|&&b| b == b'\n').count(),
        }
    })?;
    Ok(normalize(&text).into_owned())
}

/// The text without a leading byte-order mark, with CRLF and lone CR line ends turned into LF.
pub fn normalize(text: &str) -> Cow<'_, str> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    if !text.contains('\r') {
        return Cow::Borrowed(text);
    }
    Cow::Owned(text.replace("\r\n", "\n").replace('\r', "\n"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalize_drops_the_bom_and_unifies_line_ends() {
        assert_eq!(
            normalize("\u{feff}a: 1\r\nb: 2\rc: 3\n"),
            "a: 1\nb: 2\nc: 3\n"
        );
        assert!(matches!(normalize("a: 1\n"), Cow::Borrowed(_)));
    }

    #[test]
    fn directories_and_devices_are_refused_at_once() {
        let dir = std::env::temp_dir();
        assert!(matches!(
            read_bytes(&dir, 10),
            Err(InputError::NotRegular {
                kind: "directory",
                ..
            })
        ));
        #[cfg(unix)]
        assert!(matches!(
            read_bytes(Path::new("/dev/zero"), 10),
            Err(InputError::NotRegular { kind: "device", .. })
        ));
    }

    #[test]
    fn a_file_over_the_limit_is_refused_and_one_at_it_is_read() {
        let path = std::env::temp_dir().join(format!("rolling-disk-input-{}", std::process::id()));
        std::fs::write(&path, b"0123456789").ok();
        assert!(matches!(
            read_bytes(&path, 9),
            Err(InputError::TooLarge { limit: 9, .. })
        ));
        assert_eq!(read_bytes(&path, 10).ok(), Some(b"0123456789".to_vec()));
        std::fs::write(&path, b"ok\n\xff").ok();
        assert!(matches!(
            read_text(&path, 10),
            Err(InputError::NotText { line: 2, .. })
        ));
        std::fs::remove_file(&path).ok();
    }

    #[test]
    fn a_file_read_to_be_replaced_is_not_an_input_and_one_read_is() {
        let dir = std::env::temp_dir().join(format!("rolling-disk-replace-{}", std::process::id()));
        std::fs::create_dir_all(&dir).ok();
        let kept = dir.join("snapshot.json");
        std::fs::write(&kept, "{}\r\n").ok();
        assert_eq!(
            read_text_to_replace(&kept, 10).ok(),
            Some("{}\n".to_string())
        );
        assert_eq!(crate::inputs::input_named(&kept), None);
        assert!(crate::output_file::write_output(&kept, b"[]\n").is_ok());
        assert!(read_text(&kept, 10).is_ok());
        assert_eq!(crate::inputs::input_named(&kept), Some(kept.clone()));
        assert!(crate::output_file::write_output(&kept, b"{}\n").is_err());
        std::fs::remove_dir_all(&dir).ok();
    }
}
