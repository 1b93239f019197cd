//! The files this process has read, by identity (device and inode), so that no output is ever
//! written over one of its own inputs (`simulate my.yaml --csv my.yaml`), under whatever name
//! (a symbolic link, a hard link, `./my.yaml`) the output path reaches it.
//!
//! Every reader of a user's file goes through [`crate::input::read_bytes`], which records here
//! what it read; the output door ([`crate::output_file::write_output`]) asks [`input_named`]
//! before it writes.

use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// A file's identity: the device it is on and its inode there.
type Identity = (u64, u64);

/// The inputs read so far, with the path each was read under.
static READ: Mutex<Vec<(Identity, PathBuf)>> = Mutex::new(Vec::new());

#[cfg(unix)]
fn identity(meta: &std::fs::Metadata) -> Option<Identity> {
    use std::os::unix::fs::MetadataExt;
    Some((meta.dev(), meta.ino()))
}

#[cfg(not(unix))]
fn identity(_meta: &std::fs::Metadata) -> Option<Identity> {
    None
}

/// Records that the file `path`, whose metadata (taken from the opened file) is `meta`, is an
/// input of this process.
pub fn record(path: &Path, meta: &std::fs::Metadata) {
    if let Some(id) = identity(meta) {
        if let Ok(mut read) = READ.lock() {
            if !read.iter().any(|(i, _)| *i == id) {
                read.push((id, path.to_path_buf()));
            }
        }
    }
}

/// The path under which the file that `path` names (following symbolic links) was read as an
/// input, if it was.
pub fn input_named(path: &Path) -> Option<PathBuf> {
    let id = identity(&std::fs::metadata(path).ok()?)?;
    let read = READ.lock().ok()?;
    // The input's own path must still name it: an input removed since, whose inode the system
    // has given to a new file, is not that new file.
    read.iter()
        .find(|(i, p)| *i == id && std::fs::metadata(p).ok().and_then(|m| identity(&m)) == Some(id))
        .map(|(_, p)| p.clone())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[cfg(unix)]
    #[test]
    fn an_input_is_known_under_another_name() {
        let dir = std::env::temp_dir().join(format!("rolling-disk-inputs-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).ok();
        let scene = dir.join("my.yaml");
        std::fs::write(&scene, "name: x\n").ok();
        let link = dir.join("link.yaml");
        std::os::unix::fs::symlink(&scene, &link).ok();
        let other = dir.join("other.yaml");
        std::fs::write(&other, "name: y\n").ok();
        assert_eq!(input_named(&link), None);
        assert!(crate::input::read_text(&scene, 100).is_ok());
        assert_eq!(input_named(&link), Some(scene.clone()));
        assert_eq!(input_named(&dir.join("./my.yaml")), Some(scene.clone()));
        assert_eq!(input_named(&other), None);
        assert_eq!(input_named(&dir.join("absent.yaml")), None);
        let _ = std::fs::remove_dir_all(&dir);
    }
}
