//! The temporary directories of a set being written ([`crate::output::SetWriter`]): named so
//! that no user's file is taken for one, marked inside so that the tool can prove a directory is
//! its own, and removed after a run that was killed only when that proof holds.
//!
//! A temporary for the target `NAME` is `.NAME.rolling-disk-PID-N` beside it (`N` the first free
//! number, so that a name already taken, by anything, is never touched); a previous set moved
//! aside during a swap is `.NAME.rolling-disk-old-PID-N`. A directory is this tool's own when it
//! has such a name, is a directory (not a symbolic link), and holds the [`MARKER`] naming that
//! same PID or a set's manifest ([`MANIFEST`]), or holds nothing but the beginning of that
//! marker (a run killed between making the directory and finishing its marker); it is left
//! over when no process of that PID is alive. Anything else, such as a user's
//! `.NAME.tmp-12345/` or a directory of that name holding a file of theirs, is never removed.

use std::path::{Path, PathBuf};

/// The file that marks a directory as a complete report set written by this tool, listing the
/// set's files with their sizes. It is written last, inside the temporary directory, before
/// the swap.
pub const MANIFEST: &str = ".rolling-disk-set";

/// The file inside a temporary directory that marks it as this tool's, naming the process.
pub const MARKER: &str = ".rolling-disk-temporary";

/// The prefix of the temporaries of the target named `name`.
fn prefix(name: &str) -> String {
    format!(".{name}.rolling-disk-")
}

/// The text of the marker of process `pid`.
fn marker_text(pid: u32) -> String {
    format!("a temporary directory of rolling-disk, process {pid}\n")
}

/// Creates a new temporary directory for the target named `name` in `parent`, with its marker.
pub fn create(parent: &Path, name: &str) -> std::io::Result<PathBuf> {
    create_kind(parent, name, "")
}

/// The name a previous set is moved to while a new one takes its place.
pub fn aside(parent: &Path, name: &str) -> PathBuf {
    let pid = std::process::id();
    (0u32..)
        .map(|n| parent.join(format!("{}old-{pid}-{n}", prefix(name))))
        .find(|p| std::fs::symlink_metadata(p).is_err())
        .unwrap_or_else(|| parent.join(format!("{}old-{pid}", prefix(name))))
}

fn create_kind(parent: &Path, name: &str, kind: &str) -> std::io::Result<PathBuf> {
    let pid = std::process::id();
    for n in 0u32.. {
        let dir = parent.join(format!("{}{kind}{pid}-{n}", prefix(name)));
        match std::fs::create_dir(&dir) {
            Ok(()) => {
                let marked = std::fs::OpenOptions::new()
                    .write(true)
                    .create_new(true)
                    .open(dir.join(MARKER))
                    .and_then(|mut f| {
                        std::io::Write::write_all(&mut f, marker_text(pid).as_bytes())
                    });
                if let Err(e) = marked {
                    let _ = std::fs::remove_dir_all(&dir);
                    return Err(e);
                }
                return Ok(dir);
            }
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(e),
        }
    }
    Err(std::io::Error::other("no free temporary name"))
}

/// Removes `dir`, a directory of this tool's, with its proof ([`MANIFEST`], then [`MARKER`])
/// last: a run killed while removing it leaves a directory still provably the tool's, or an
/// empty one, which the next run removes in turn.
pub fn remove(dir: &Path) -> std::io::Result<()> {
    for entry in std::fs::read_dir(dir)? {
        let entry = entry?;
        let name = entry.file_name();
        if name == MARKER || name == MANIFEST {
            continue;
        }
        if entry.file_type()?.is_dir() {
            std::fs::remove_dir_all(entry.path())?;
        } else {
            std::fs::remove_file(entry.path())?;
        }
    }
    for proof in [MANIFEST, MARKER] {
        match std::fs::remove_file(dir.join(proof)) {
            Err(e) if e.kind() != std::io::ErrorKind::NotFound => return Err(e),
            _ => {}
        }
    }
    std::fs::remove_dir(dir)
}

/// Removes the marker from a temporary about to become the set (its manifest already written).
pub fn unmark(dir: &Path) -> std::io::Result<()> {
    std::fs::remove_file(dir.join(MARKER))
}

/// A left-over of this tool found beside a target.
#[derive(Debug, PartialEq, Eq)]
pub enum LeftOver {
    /// A temporary of a run that did not finish: to remove.
    Temporary(PathBuf),
    /// A complete previous set moved aside by a run killed in the middle of a swap.
    Aside(PathBuf),
}

/// The left-overs of dead runs of this tool beside the target named `name` in `parent`: only
/// directories it can prove are its own (see the module's documentation).
pub fn left_overs(parent: &Path, name: &str) -> std::io::Result<Vec<LeftOver>> {
    let prefix = prefix(name);
    let mut out = Vec::new();
    let mut entries: Vec<_> = std::fs::read_dir(parent)?.flatten().collect();
    entries.sort_by_key(|e| e.file_name());
    for entry in entries {
        let file_name = entry.file_name().to_string_lossy().into_owned();
        let Some(rest) = file_name.strip_prefix(&prefix) else {
            continue;
        };
        let (aside, rest) = match rest.strip_prefix("old-") {
            Some(r) => (true, r),
            None => (false, rest),
        };
        let Some(pid) = rest
            .split_once('-')
            .filter(|(_, n)| n.parse::<u32>().is_ok())
            .and_then(|(p, _)| p.parse::<u32>().ok())
        else {
            continue;
        };
        let path = entry.path();
        let is_dir = std::fs::symlink_metadata(&path).is_ok_and(|m| m.is_dir());
        if !is_dir || !process_is_gone(pid) {
            continue;
        }
        let marked =
            std::fs::read_to_string(path.join(MARKER)).is_ok_and(|t| t == marker_text(pid));
        let a_set = std::fs::symlink_metadata(path.join(MANIFEST)).is_ok_and(|m| m.is_file());
        // Empty, or holding only a marker's first bytes: a run killed while it made the
        // directory, or while it removed one (its proof goes last, see [`remove`]).
        let unfinished = !marked && !a_set && holds_at_most_a_partial_marker(&path, pid);
        match (aside, marked || unfinished, a_set) {
            (false, true, _) | (false, false, true) | (true, true, false) => {
                out.push(LeftOver::Temporary(path))
            }
            (true, _, true) => out.push(LeftOver::Aside(path)),
            _ => {}
        }
    }
    Ok(out)
}

/// Whether `dir` holds nothing, or only a regular file named [`MARKER`] whose text is the
/// beginning of process `pid`'s marker: a temporary of that process killed after it made the
/// directory and before its marker was whole, which holds nothing of anyone's to lose.
fn holds_at_most_a_partial_marker(dir: &Path, pid: u32) -> bool {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return false;
    };
    let entries: Vec<_> = entries.flatten().take(2).collect();
    match entries.as_slice() {
        [] => true,
        [only] => {
            only.file_name() == MARKER
                && std::fs::symlink_metadata(only.path()).is_ok_and(|m| m.is_file())
                && std::fs::read(only.path())
                    .is_ok_and(|t| marker_text(pid).as_bytes().starts_with(&t))
        }
        _ => false,
    }
}

/// Whether no process `pid` is alive. Without `/proc` nothing can be proved, so nothing is
/// called gone.
fn process_is_gone(pid: u32) -> bool {
    if pid == std::process::id() {
        return false;
    }
    Path::new("/proc/self").exists() && !Path::new(&format!("/proc/{pid}")).exists()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A new empty folder for the test `name`.
    fn scratch(name: &str) -> PathBuf {
        let root = std::env::temp_dir().join(format!("rolling-disk-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&root);
        std::fs::create_dir_all(&root).ok();
        root
    }

    /// A pid that no process has: above the kernel's largest (2^22).
    const DEAD: u32 = 4_194_304 + 17;

    #[test]
    fn only_marked_directories_of_dead_runs_are_left_overs() {
        let root = scratch("tmpnames");
        let dead = DEAD;
        let ours = root.join(format!(".r1.rolling-disk-{dead}-0"));
        std::fs::create_dir_all(&ours).ok();
        std::fs::write(ours.join(MARKER), marker_text(dead)).ok();
        // The user's: the old naming, an unmarked directory of the new naming, a file.
        let users = [
            root.join(format!(".r1.tmp-{dead}")),
            root.join(format!(".r1.rolling-disk-{dead}-1")),
        ];
        for u in &users {
            std::fs::create_dir_all(u).ok();
            std::fs::write(u.join("notes.txt"), "mine").ok();
        }
        std::fs::write(root.join(format!(".r1.rolling-disk-{dead}-2")), "mine").ok();
        let found = left_overs(&root, "r1").unwrap_or_default();
        assert_eq!(found, vec![LeftOver::Temporary(ours.clone())]);
        // A run killed after it made its directory and before its marker was whole: the
        // directory empty, or holding only the marker's first bytes; beside the same with a
        // user's file too, and a marker of another text.
        let empty = root.join(format!(".r1.rolling-disk-{dead}-3"));
        let partial = root.join(format!(".r1.rolling-disk-{dead}-4"));
        let crowded = root.join(format!(".r1.rolling-disk-{dead}-5"));
        let other = root.join(format!(".r1.rolling-disk-{dead}-6"));
        for d in [&empty, &partial, &crowded, &other] {
            std::fs::create_dir_all(d).ok();
        }
        for d in [&partial, &crowded] {
            std::fs::write(d.join(MARKER), &marker_text(dead)[..10]).ok();
        }
        std::fs::write(crowded.join("notes.txt"), "mine").ok();
        std::fs::write(other.join(MARKER), "my own notes").ok();
        let found = left_overs(&root, "r1").unwrap_or_default();
        assert_eq!(
            found,
            vec![
                LeftOver::Temporary(ours.clone()),
                LeftOver::Temporary(empty.clone()),
                LeftOver::Temporary(partial.clone())
            ]
        );
        for d in [&empty, &partial] {
            std::fs::remove_dir_all(d).ok();
        }
        // An aside left empty by a run killed while it removed it.
        let aside_empty = root.join(format!(".r1.rolling-disk-old-{dead}-0"));
        std::fs::create_dir_all(&aside_empty).ok();
        assert_eq!(
            left_overs(&root, "r1").unwrap_or_default(),
            vec![
                LeftOver::Temporary(ours.clone()),
                LeftOver::Temporary(aside_empty.clone())
            ]
        );
        std::fs::remove_dir_all(&aside_empty).ok();
        let new = create(&root, "r1").ok();
        assert!(new.as_ref().is_some_and(|d| d.join(MARKER).is_file()));
        // A live process's temporary (this one's) is not a left-over.
        assert_eq!(left_overs(&root, "r1").map(|l| l.len()).ok(), Some(1));
        let _ = std::fs::remove_dir_all(&root);
    }

    /// [`remove`] takes a temporary's files and folders, then its proof, then itself; a
    /// directory whose other files are gone but whose proof is still there is still the tool's.
    #[test]
    fn a_temporary_is_removed_with_its_proof_last() {
        let root = scratch("tmpremove");
        let dead = DEAD;
        let dir = root.join(format!(".r2.rolling-disk-{dead}-0"));
        std::fs::create_dir_all(dir.join("figures")).ok();
        std::fs::write(dir.join("figures/a.png"), "png").ok();
        std::fs::write(dir.join("report.html"), "html").ok();
        std::fs::write(dir.join(MARKER), marker_text(dead)).ok();
        std::fs::write(dir.join(MANIFEST), "list").ok();
        assert!(remove(&dir).is_ok());
        assert!(!dir.exists());
        // What a removal killed after the files and the manifest leaves: still a left-over.
        std::fs::create_dir_all(&dir).ok();
        std::fs::write(dir.join(MARKER), marker_text(dead)).ok();
        assert_eq!(
            left_overs(&root, "r2").unwrap_or_default(),
            vec![LeftOver::Temporary(dir.clone())]
        );
        let _ = std::fs::remove_dir_all(&root);
    }
}
