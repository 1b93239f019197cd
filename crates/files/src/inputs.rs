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
            // Kept under every path it was read by: an entry of a file removed since may hold
            // the same identity (the system gives a freed inode to a new file), and must not
            // hide this one.
            if !read.iter().any(|(i, p)| *i == id && p == path) {
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

    /// An entry left by a file since removed holds the identity the system may give to a new
    /// file; the new file, read under its own name, is still known as an input.
    #[cfg(unix)]
    #[test]
    fn a_removed_input_does_not_hide_a_new_one_with_its_identity() {
        let dir = std::env::temp_dir().join(format!("rolling-disk-reused-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).ok();
        let file = dir.join("new.yaml");
        std::fs::write(&file, "name: x\n").ok();
        // The removed file's entry: the same identity, under a name that no longer exists.
        let gone = dir.join("gone.yaml");
        std::fs::hard_link(&file, &gone).ok();
        let meta = std::fs::metadata(&file).unwrap();
        record(&gone, &meta);
        std::fs::remove_file(&gone).ok();
        assert_eq!(input_named(&file), None);
        record(&file, &meta);
        assert_eq!(input_named(&file), Some(file.clone()));
        let _ = std::fs::remove_dir_all(&dir);
    }
}
