//! Writing sets of files ([`SetWriter`]) so that a reader never sees a mix of two runs: the set
//! is written into a temporary directory, then swapped in whole.

use crate::atomic::write_atomically;
use std::path::{Path, PathBuf};

pub use crate::temporary::MANIFEST;

/// Why a set of files could not be written.
#[derive(Debug, thiserror::Error)]
pub enum SetError {
    /// The target exists and holds files this tool did not write.
    #[error("--out {0}: exists and is not a set of outputs written by this tool (it has no {MANIFEST}); give a new or empty directory so that nothing of yours is replaced")]
    Foreign(String),
    /// The target is a set written by this tool that now also holds a file the set does not list.
    #[error("--out {path}: holds {file}, which this tool did not write (its {MANIFEST} does not list it); move that file elsewhere or give another directory, since the whole set is replaced")]
    Unlisted {
        /// The target.
        path: String,
        /// The file not in the manifest, relative to the target.
        file: String,
    },
    /// The target directory cannot be written by the user (its mode or its owner says so).
    #[error("--out {0}: is a directory you cannot write to (read-only or another user's); give a directory of your own")]
    ReadOnly(String),
    /// The target has no name of its own (`.`, `..`, `/`).
    #[error("--out {0}: name a directory of its own (for example --out report), not . or .. or /, since the whole set is replaced")]
    NoName(String),
    /// The target exists and is not a directory (nor a symbolic link to one).
    #[error("--out {0}: exists and is not a directory (nor a link to one); give the path of a directory")]
    NotDirectory(String),
    /// The directory beside the target cannot be written.
    #[error("--out {path}: cannot write beside it in {parent} ({source}); give a directory you can write to")]
    Unwritable {
        /// The target.
        path: String,
        /// Its parent.
        parent: String,
        /// Why.
        source: std::io::Error,
    },
    /// A step of writing or swapping failed.
    #[error("--out {path}: {what} failed ({source}); the previous set, if any, is unchanged")]
    Io {
        /// The target.
        path: String,
        /// What was being done.
        what: &'static str,
        /// Why.
        source: std::io::Error,
    },
}

/// A set of files (a report: HTML, LaTeX, JSON, figures) written as one: everything goes into
/// a temporary directory beside the target, a manifest is written last, and the directory is
/// then swapped with the target in one rename. A reader, or a run killed at any moment, sees
/// the previous complete set or the new complete set, never a mix.
///
/// Temporaries are named and marked by [`crate::temporary`]: unique names beside the target,
/// never a name already taken; those of runs no longer alive that the tool can prove its own are
/// removed by the next [`SetWriter::begin`] (a killed run cannot clean up after itself), and
/// nothing else. On Linux the swap is `renameat2(RENAME_EXCHANGE)`, atomic even when the target
/// exists; elsewhere the old set is first moved aside, and a run killed between the two renames
/// leaves it aside, which the next run puts back.
#[derive(Debug)]
pub struct SetWriter {
    target: PathBuf,
    tmp: PathBuf,
    committed: bool,
}

fn io_err(target: &Path, what: &'static str) -> impl FnOnce(std::io::Error) -> SetError {
    let path = target.display().to_string();
    move |source| SetError::Io { path, what, source }
}

/// Writes one file of a set under construction, at `path` inside [`SetWriter::dir`] (or inside
/// a directory of the caller's own making): atomically, and only where nothing is or a regular
/// file is; a symbolic link or anything else there is refused, never replaced.
pub fn write_set_file(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    match std::fs::symlink_metadata(path) {
        Ok(m) if !m.is_file() => Err(std::io::Error::new(
            std::io::ErrorKind::AlreadyExists,
            "something that is not a regular file is in the way",
        )),
        _ => write_atomically(path, bytes),
    }
}

/// The files a set's manifest lists, relative to the set's directory; `None` without a manifest.
fn read_manifest(target: &Path) -> Option<std::collections::BTreeSet<PathBuf>> {
    let text = std::fs::read_to_string(target.join(MANIFEST)).ok()?;
    let mut files: std::collections::BTreeSet<PathBuf> = text
        .lines()
        .filter(|l| !l.starts_with('#'))
        .filter_map(|l| l.split_once(' ').map(|(_, rel)| PathBuf::from(rel)))
        .collect();
    files.insert(PathBuf::from(MANIFEST));
    Some(files)
}

/// The first file under `dir` (`rel` inside the set) that `listed` does not hold, or a
/// subdirectory that holds none of the listed files; walked in name order.
fn first_unlisted(
    dir: &Path,
    rel: &Path,
    listed: &std::collections::BTreeSet<PathBuf>,
) -> Option<String> {
    let Ok(entries) = std::fs::read_dir(dir.join(rel)) else {
        return Some(rel.display().to_string());
    };
    let mut names: Vec<_> = entries.flatten().map(|e| e.file_name()).collect();
    names.sort();
    for name in names {
        let path = rel.join(&name);
        let is_dir = std::fs::symlink_metadata(dir.join(&path)).is_ok_and(|m| m.is_dir());
        if is_dir && listed.iter().any(|f| f.starts_with(&path)) {
            if let Some(found) = first_unlisted(dir, &path, listed) {
                return Some(found);
            }
        } else if is_dir || !listed.contains(&path) {
            return Some(path.display().to_string());
        }
    }
    None
}

impl SetWriter {
    /// Checks the target, cleans the temporaries of dead runs, and creates the temporary
    /// directory to write into: all before any computing, so that a target that cannot be
    /// written is reported at once.
    ///
    /// A symbolic link to a directory is followed: the set goes to the directory it names, and
    /// the link is kept.
    pub fn begin(target: &Path) -> Result<SetWriter, SetError> {
        let shown = target.display().to_string();
        if std::fs::symlink_metadata(target).is_ok_and(|m| m.file_type().is_symlink()) {
            return match std::fs::canonicalize(target) {
                Ok(real) if real.is_dir() => Self::begin(&real),
                _ => Err(SetError::NotDirectory(shown)),
            };
        }
        let name = target
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .ok_or_else(|| SetError::NoName(shown.clone()))?;
        let parent = target
            .parent()
            .filter(|p| !p.as_os_str().is_empty())
            .unwrap_or(Path::new("."))
            .to_path_buf();
        std::fs::create_dir_all(&parent).map_err(|source| SetError::Unwritable {
            path: shown.clone(),
            parent: parent.display().to_string(),
            source,
        })?;
        Self::clean_stale(target, &parent, &name)?;
        match std::fs::symlink_metadata(target) {
            Ok(m) if !m.is_dir() => return Err(SetError::NotDirectory(shown)),
            Ok(m) => {
                if m.permissions().readonly() || !crate::output_file::writable(target) {
                    return Err(SetError::ReadOnly(shown));
                }
                let empty = std::fs::read_dir(target)
                    .map_err(io_err(target, "reading the target"))?
                    .next()
                    .is_none();
                if !empty {
                    let listed = read_manifest(target).ok_or(SetError::Foreign(shown.clone()))?;
                    if let Some(file) = first_unlisted(target, Path::new(""), &listed) {
                        return Err(SetError::Unlisted { path: shown, file });
                    }
                }
            }
            Err(_) => {}
        }
        let tmp =
            crate::temporary::create(&parent, &name).map_err(|source| SetError::Unwritable {
                path: shown,
                parent: parent.display().to_string(),
                source,
            })?;
        Ok(SetWriter {
            target: target.to_path_buf(),
            tmp,
            committed: false,
        })
    }

    /// Removes the temporaries of runs no longer alive that are provably this tool's; puts back
    /// a previous set left aside by a run killed in the middle of a non-atomic swap.
    fn clean_stale(target: &Path, parent: &Path, name: &str) -> Result<(), SetError> {
        use crate::temporary::LeftOver;
        let found = crate::temporary::left_overs(parent, name)
            .map_err(io_err(target, "listing the parent"))?;
        for left in found {
            match left {
                LeftOver::Temporary(path) => crate::temporary::remove(&path)
                    .map_err(io_err(target, "removing a temporary"))?,
                LeftOver::Aside(path) if std::fs::symlink_metadata(target).is_ok() => {
                    crate::temporary::remove(&path)
                        .map_err(io_err(target, "removing a previous set"))?
                }
                LeftOver::Aside(path) => std::fs::rename(&path, target)
                    .map_err(io_err(target, "restoring the previous set"))?,
            }
        }
        Ok(())
    }

    /// The directory to write the set's files into.
    pub fn dir(&self) -> &Path {
        &self.tmp
    }

    /// `path` (inside [`SetWriter::dir`]) as it will be named once the set is in place.
    pub fn final_path(&self, path: &Path) -> PathBuf {
        path.strip_prefix(&self.tmp)
            .map_or_else(|_| path.to_path_buf(), |rel| self.target.join(rel))
    }

    /// Writes the manifest of `files` (paths inside [`SetWriter::dir`]) and swaps the set in.
    pub fn commit(mut self, files: &[PathBuf]) -> Result<(), SetError> {
        let target = self.target.clone();
        let mut manifest = String::from("# a complete report set written by rolling-disk\n");
        for f in files {
            let rel = f.strip_prefix(&self.tmp).unwrap_or(f);
            let len = std::fs::metadata(f)
                .map_err(io_err(&target, "reading a written file"))?
                .len();
            manifest.push_str(&format!("{len} {}\n", rel.display()));
        }
        write_atomically(&self.tmp.join(MANIFEST), manifest.as_bytes())
            .map_err(io_err(&target, "writing the manifest"))?;
        crate::temporary::unmark(&self.tmp).map_err(io_err(&target, "writing the manifest"))?;
        if let Ok(d) = std::fs::File::open(&self.tmp) {
            let _ = d.sync_all();
        }
        self.swap()
            .map_err(io_err(&target, "swapping the new set in"))?;
        self.committed = true;
        Ok(())
    }

    #[cfg(target_os = "linux")]
    fn swap(&self) -> std::io::Result<()> {
        use rustix::fs::{renameat_with, RenameFlags, CWD};
        if self.target.exists() {
            match renameat_with(
                CWD,
                self.tmp.as_path(),
                CWD,
                self.target.as_path(),
                RenameFlags::EXCHANGE,
            ) {
                // The old set now sits at the temporary's name.
                Ok(()) => return crate::temporary::remove(&self.tmp),
                // A filesystem without the exchange: fall back to two renames.
                Err(e) if e == rustix::io::Errno::INVAL || e == rustix::io::Errno::NOSYS => {}
                Err(e) => return Err(e.into()),
            }
        }
        self.swap_by_two_renames()
    }

    #[cfg(not(target_os = "linux"))]
    fn swap(&self) -> std::io::Result<()> {
        self.swap_by_two_renames()
    }

    fn swap_by_two_renames(&self) -> std::io::Result<()> {
        if !self.target.exists() {
            return std::fs::rename(&self.tmp, &self.target);
        }
        let name = self
            .target
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let parent = self.tmp.parent().unwrap_or(Path::new("."));
        let old = crate::temporary::aside(parent, &name);
        std::fs::rename(&self.target, &old)?;
        std::fs::rename(&self.tmp, &self.target)?;
        crate::temporary::remove(&old)
    }
}

impl Drop for SetWriter {
    fn drop(&mut self) {
        if !self.committed {
            let _ = crate::temporary::remove(&self.tmp);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("rolling-disk-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).ok();
        d
    }

    fn write_set(target: &Path, text: &str) -> Result<(), SetError> {
        let set = SetWriter::begin(target)?;
        let a = set.dir().join("a.txt");
        let sub = set.dir().join("figures");
        std::fs::create_dir_all(&sub).ok();
        let b = sub.join("b.txt");
        std::fs::write(&a, text).ok();
        std::fs::write(&b, text).ok();
        set.commit(&[a, b])
    }

    /// The names in `dir`.
    fn entries(dir: &Path) -> Vec<String> {
        std::fs::read_dir(dir)
            .map(|d| {
                d.flatten()
                    .map(|e| e.file_name().to_string_lossy().into_owned())
                    .collect()
            })
            .unwrap_or_default()
    }

    #[test]
    fn a_set_replaces_the_previous_one_whole_and_leaves_no_temporary() {
        let root = scratch("set");
        let target = root.join("report");
        write_set(&target, "one").ok();
        write_set(&target, "two").ok();
        assert_eq!(
            std::fs::read_to_string(target.join("a.txt"))
                .ok()
                .as_deref(),
            Some("two")
        );
        assert_eq!(
            std::fs::read_to_string(target.join("figures/b.txt"))
                .ok()
                .as_deref(),
            Some("two")
        );
        let manifest = std::fs::read_to_string(target.join(MANIFEST)).unwrap_or_default();
        assert!(
            manifest.contains("3 a.txt") && manifest.contains("3 figures/b.txt"),
            "{manifest}"
        );
        assert_eq!(entries(&root), vec!["report".to_string()]);
        let _ = std::fs::remove_dir_all(&root);
    }

    #[test]
    fn a_directory_of_someone_elses_files_is_refused_and_kept() {
        let root = scratch("foreign");
        std::fs::write(root.join("thesis.tex"), "mine").ok();
        assert!(matches!(write_set(&root, "x"), Err(SetError::Foreign(_))));
        assert!(root.join("thesis.tex").is_file());
        let file = root.join("thesis.tex");
        assert!(matches!(
            write_set(&file, "x"),
            Err(SetError::NotDirectory(_))
        ));
        assert!(matches!(
            write_set(Path::new("."), "x"),
            Err(SetError::NoName(_))
        ));
        assert!(matches!(
            write_set(Path::new("/"), "x"),
            Err(SetError::NoName(_))
        ));
        let _ = std::fs::remove_dir_all(&root);
    }

    #[test]
    fn temporaries_of_dead_runs_are_removed_and_a_set_left_aside_is_put_back() {
        let root = scratch("stale");
        let target = root.join("report");
        write_set(&target, "old").ok();
        // A pid that no process has: above the kernel's largest (2^22).
        let dead = 4_194_304 + 17;
        let tmp = root.join(format!(".report.rolling-disk-{dead}-0"));
        std::fs::create_dir_all(&tmp).ok();
        std::fs::write(
            tmp.join(crate::temporary::MARKER),
            format!("a temporary directory of rolling-disk, process {dead}\n"),
        )
        .ok();
        std::fs::rename(
            &target,
            root.join(format!(".report.rolling-disk-old-{dead}-0")),
        )
        .ok();
        let users = root.join(format!(".report.tmp-{dead}"));
        std::fs::create_dir_all(&users).ok();
        let set = SetWriter::begin(&target);
        assert!(set.is_ok());
        assert_eq!(
            std::fs::read_to_string(target.join("a.txt"))
                .ok()
                .as_deref(),
            Some("old")
        );
        assert!(!tmp.exists());
        assert!(users.is_dir());
        drop(set);
        let mut left = entries(&root);
        left.sort();
        assert_eq!(
            left,
            vec![format!(".report.tmp-{dead}"), "report".to_string()]
        );
        let _ = std::fs::remove_dir_all(&root);
    }

    #[test]
    fn a_set_holding_a_file_it_does_not_list_is_refused_and_the_file_kept() {
        let root = scratch("unlisted");
        let target = root.join("report");
        assert!(write_set(&target, "one").is_ok());
        assert!(write_set(&target, "two").is_ok());
        std::fs::write(target.join("figures/mine.svg"), "mine").ok();
        assert!(matches!(
            write_set(&target, "three"),
            Err(SetError::Unlisted { ref file, .. }) if file == "figures/mine.svg"
        ));
        assert!(target.join("figures/mine.svg").is_file());
        std::fs::remove_file(target.join("figures/mine.svg")).ok();
        std::fs::create_dir_all(target.join("drafts")).ok();
        assert!(matches!(
            write_set(&target, "three"),
            Err(SetError::Unlisted { ref file, .. }) if file == "drafts"
        ));
        let _ = std::fs::remove_dir_all(&root);
    }
}
