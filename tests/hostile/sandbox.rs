//! The hostile suite's two guards: a run of the binary that is killed and failed when it
//! outlives its limit, and a sandbox folder whose every entry (kind, inode, permissions, link
//! target and, for a regular file, its bytes) is recorded before a run and compared after it.

use std::collections::BTreeMap;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// What one run did: its exit, its output and its wall time.
pub struct Ran {
    pub ok: bool,
    pub stdout: String,
    pub stderr: String,
    pub took: Duration,
    /// Its processor time, user and system, all its threads (read from `/proc`).
    pub cpu: Duration,
}

/// The processor time of process `pid` so far, from `/proc/PID/stat` (its fields 14 and 15, in
/// clock ticks of 1/100 s); zero where that cannot be read.
fn cpu_of(pid: u32) -> Duration {
    let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).unwrap_or_default();
    // The command's name, in parentheses, may hold spaces: count fields after its end.
    let after = stat.rsplit_once(')').map_or("", |(_, rest)| rest);
    let field = |n: usize| {
        after
            .split_whitespace()
            .nth(n - 3)
            .and_then(|v| v.parse::<u64>().ok())
            .unwrap_or(0)
    };
    Duration::from_millis(10 * (field(14) + field(15)))
}

/// Runs the binary in `dir` with `args`, kills it and fails the test if it runs over `limit`,
/// and fails it on a panic.
pub fn bounded(dir: &Path, args: &[&str], limit: Duration) -> Ran {
    let start = Instant::now();
    let mut child = Command::new(env!("CARGO_BIN_EXE_rolling-disk"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary starts");
    // Read both pipes aside so a full pipe never stalls the child.
    let drain = |mut r: Box<dyn Read + Send>| {
        std::thread::spawn(move || {
            let mut s = Vec::new();
            r.read_to_end(&mut s).ok();
            String::from_utf8_lossy(&s).into_owned()
        })
    };
    let out = drain(Box::new(child.stdout.take().expect("a stdout pipe")));
    let err = drain(Box::new(child.stderr.take().expect("a stderr pipe")));
    let mut cpu = Duration::ZERO;
    let status = loop {
        // Read before waiting: an exited child not yet waited for still shows its final times.
        cpu = cpu.max(cpu_of(child.id()));
        if let Some(status) = child.try_wait().expect("waits") {
            break status;
        }
        if start.elapsed() > limit {
            child.kill().ok();
            child.wait().ok();
            panic!("{args:?} ran over {limit:?} and was killed");
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let took = start.elapsed();
    let ran = Ran {
        ok: status.success(),
        stdout: out.join().unwrap_or_default(),
        stderr: err.join().unwrap_or_default(),
        took,
        cpu,
    };
    assert!(
        !ran.stderr.contains("panicked") && !ran.stderr.contains("RUST_BACKTRACE"),
        "{args:?} panicked: {}",
        ran.stderr
    );
    ran
}

/// How long a run that computes may take before it is killed as a hang: far beyond any run of
/// this suite on a loaded machine (each refusal is held to 2 s on its own).
pub const COMPUTES: Duration = Duration::from_secs(60);

/// [`bounded`] within [`COMPUTES`]: (success, stdout, stderr, wall time).
pub fn cli_timed(dir: &Path, args: &[&str]) -> (bool, String, String, Duration) {
    let ran = bounded(dir, args, COMPUTES);
    (ran.ok, ran.stdout, ran.stderr, ran.took)
}

/// A refusal: `args` fails within 2 s with every one of `says` in its message.
pub fn refused_at_once(dir: &Path, args: &[&str], says: &[&str]) -> Ran {
    let ran = bounded(dir, args, Duration::from_secs(2));
    assert!(!ran.ok, "{args:?} was accepted");
    for s in says {
        assert!(ran.stderr.contains(s), "{args:?}: {} lacks {s}", ran.stderr);
    }
    ran
}

/// One entry of a folder as it stands, links not followed.
#[derive(Debug, Clone, PartialEq)]
enum Entry {
    File { ino: u64, mode: u32, bytes: Vec<u8> },
    Folder { ino: u64, mode: u32 },
    Link { target: PathBuf },
    Other { ino: u64, mode: u32, rdev: u64 },
}

/// A folder's entries, recorded.
pub struct Sandbox {
    pub dir: PathBuf,
    before: BTreeMap<PathBuf, Entry>,
}

fn walk(dir: &Path, under: &Path, into: &mut BTreeMap<PathBuf, Entry>) {
    use std::os::unix::fs::{MetadataExt, PermissionsExt};
    let Ok(read) = std::fs::read_dir(dir) else {
        return;
    };
    for e in read.flatten() {
        let path = e.path();
        let Ok(meta) = std::fs::symlink_metadata(&path) else {
            continue;
        };
        let rel = path.strip_prefix(under).unwrap_or(&path).to_path_buf();
        let (ino, mode) = (meta.ino(), meta.permissions().mode());
        let t = meta.file_type();
        let entry = if t.is_symlink() {
            Entry::Link {
                target: std::fs::read_link(&path).unwrap_or_default(),
            }
        } else if t.is_dir() {
            walk(&path, under, into);
            Entry::Folder { ino, mode }
        } else if t.is_file() {
            Entry::File {
                ino,
                mode,
                bytes: std::fs::read(&path).unwrap_or_default(),
            }
        } else {
            Entry::Other {
                ino,
                mode,
                rdev: meta.rdev(),
            }
        };
        into.insert(rel, entry);
    }
}

impl Sandbox {
    /// Records `dir` as it stands now.
    pub fn record(dir: &Path) -> Self {
        let mut before = BTreeMap::new();
        walk(dir, dir, &mut before);
        Sandbox {
            dir: dir.to_path_buf(),
            before,
        }
    }

    /// Every entry recorded is there as it was, except the `written` ones (relative paths: the
    /// outputs the user named, and the files they lead to); every new entry is one of
    /// `created` or lies inside one of them, and none is a hidden temporary.
    pub fn assert_kept(&self, written: &[&str], created: &[&str]) {
        let mut now = BTreeMap::new();
        walk(&self.dir, &self.dir, &mut now);
        let named = |p: &Path, list: &[&str]| list.iter().any(|w| p.starts_with(w));
        for (p, was) in &self.before {
            if named(p, written) {
                continue;
            }
            assert_eq!(
                now.get(p),
                Some(was),
                "{} was changed or removed",
                p.display()
            );
        }
        for p in now.keys() {
            if self.before.contains_key(p) {
                continue;
            }
            assert!(
                named(p, created) || named(p, written),
                "{} appeared unasked",
                p.display()
            );
        }
    }
}
