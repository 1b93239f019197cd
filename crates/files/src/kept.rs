//! The tool's own folder of kept results (a cache): files it writes there under names it makes,
//! reads back on a later run, and removes when it keeps too many. Nothing else in the folder is
//! touched: a file is replaced only where it is a regular file (never through a link, never a
//! device or a folder), and removed only where the caller recognises its name as its own.

use std::path::Path;

/// Stores `bytes` as `dir/name` (creating `dir`), atomically: a reader sees the old file or the
/// new one, never half of one. Refused where `dir/name` exists and is not a regular file.
pub fn store(dir: &Path, name: &str, bytes: &[u8]) -> std::io::Result<()> {
    std::fs::create_dir_all(dir)?;
    let path = dir.join(name);
    if let Ok(meta) = std::fs::symlink_metadata(&path) {
        if !meta.file_type().is_file() {
            return Err(std::io::Error::other(format!(
                "{} is not a regular file: the cache leaves it as it is",
                path.display()
            )));
        }
    }
    crate::atomic::write_atomically(&path, bytes)
}

/// Removes the oldest regular files of `dir` whose names `own` recognises, so that at most
/// `keep` of them are left besides `spare` (which is never removed). Errors are ignored: a file
/// that cannot be removed stays.
pub fn prune(dir: &Path, own: impl Fn(&str) -> bool, keep: usize, spare: &Path) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let mut owned: Vec<(std::time::SystemTime, std::path::PathBuf)> = entries
        .filter_map(Result::ok)
        .filter(|e| e.file_type().is_ok_and(|t| t.is_file()))
        .map(|e| e.path())
        .filter(|p| p != spare && p.file_name().and_then(|n| n.to_str()).is_some_and(&own))
        .filter_map(|p| Some((std::fs::metadata(&p).ok()?.modified().ok()?, p)))
        .collect();
    owned.sort();
    let excess = owned.len().saturating_sub(keep);
    for (_, p) in owned.into_iter().take(excess) {
        let _ = std::fs::remove_file(p);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_link_is_not_written_through_and_only_owned_files_are_pruned() {
        let dir = std::env::temp_dir().join(format!("rolling-disk-kept-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let target = dir.join("user.txt");
        std::fs::write(&target, "mine").unwrap();
        std::os::unix::fs::symlink(&target, dir.join("a-1.kept")).unwrap();
        assert!(store(&dir, "a-1.kept", b"new").is_err());
        assert_eq!(std::fs::read_to_string(&target).unwrap(), "mine");
        for n in 2..6 {
            store(&dir, &format!("a-{n}.kept"), b"x").unwrap();
        }
        let own = |n: &str| n.starts_with("a-") && n.ends_with(".kept");
        prune(&dir, own, 1, &dir.join("a-5.kept"));
        let mut left: Vec<String> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        left.sort();
        // The link is not a regular file: not pruned; one owned file besides the spared one.
        assert_eq!(left.len(), 4, "{left:?}");
        assert!(left.contains(&"user.txt".to_string()) && left.contains(&"a-1.kept".to_string()));
        assert!(left.contains(&"a-5.kept".to_string()));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
