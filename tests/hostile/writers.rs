//! Every command that writes a file, against every target issue 48 names, in a recorded
//! sandbox: a character device (made with mknod where this user may, else a symbolic link to
//! /dev/null), a FIFO, a read-only file, a symbolic link, a hard link, the command's own input
//! and a user's `.NAME.tmp-PID` folders beside the output. Each run ends within its limit and
//! without a panic, and afterwards nothing in the sandbox differs from before except the files
//! the named output leads to.

use super::sandbox::{bounded, Ran, Sandbox};
use crate::common::temp_dir;
use std::os::unix::fs::{FileTypeExt, MetadataExt, PermissionsExt};
use std::path::{Path, PathBuf};
use std::time::Duration;

/// A run that writes a file is given this long (the slowest, a WAV of 960 kB, takes about 1 s).
const WRITES: Duration = Duration::from_secs(20);

/// A writing command: its arguments with `OUT` where the output path goes, and its input.
struct Writer {
    args: &'static [&'static str],
    input: Option<&'static str>,
}

const WRITERS: [Writer; 5] = [
    Writer {
        args: &["peer", "export", "scene.yaml", "--out", "OUT"],
        input: Some("scene.yaml"),
    },
    Writer {
        args: &["simulate", "my.yaml", "--csv", "OUT"],
        input: Some("my.yaml"),
    },
    Writer {
        args: &["experiment", "simulate", "exp.yaml", "--csv", "OUT"],
        input: Some("exp.yaml"),
    },
    Writer {
        args: &["experiment", "simulate", "--wav", "OUT"],
        input: None,
    },
    Writer {
        args: &["check", "--only", "1", "--snapshot", "OUT"],
        input: None,
    },
];

/// A sandbox with the writers' inputs.
fn sandbox(tag: &str) -> PathBuf {
    let dir = temp_dir("hostile-writers", tag);
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    std::fs::copy(
        root.join("tests/reference/peer/thick-fall/scene.yaml"),
        dir.join("scene.yaml"),
    )
    .expect("copied");
    std::fs::copy(
        root.join("paper/scenes/spinning-coin.yaml"),
        dir.join("my.yaml"),
    )
    .expect("copied");
    std::fs::copy(
        root.join("paper/scenes/spin-down.yaml"),
        dir.join("exp.yaml"),
    )
    .expect("copied");
    dir
}

fn write_to(dir: &Path, w: &Writer, out: &str, limit: Duration) -> Ran {
    let args: Vec<&str> = w
        .args
        .iter()
        .map(|a| if *a == "OUT" { out } else { a })
        .collect();
    bounded(dir, &args, limit)
}

/// A character device: a node made with mknod (the null device's numbers), or where that is
/// not allowed a symbolic link to /dev/null. Returns the name to write to.
fn device(dir: &Path) -> &'static str {
    let made = std::process::Command::new("mknod")
        .arg(dir.join("dev"))
        .args(["c", "1", "3"])
        .status()
        .is_ok_and(|s| s.success());
    if made {
        std::fs::set_permissions(dir.join("dev"), std::fs::Permissions::from_mode(0o666)).ok();
    } else {
        std::os::unix::fs::symlink("/dev/null", dir.join("dev")).expect("a link");
    }
    "dev"
}

#[test]
fn no_writer_replaces_a_device_a_read_only_file_or_its_input() {
    for (i, w) in WRITERS.iter().enumerate() {
        let dir = sandbox(&format!("dev-{i}"));
        let dev = device(&dir);
        std::fs::write(dir.join("ro.txt"), "mine").ok();
        std::fs::set_permissions(dir.join("ro.txt"), std::fs::Permissions::from_mode(0o444)).ok();
        let null_before = std::fs::symlink_metadata("/dev/null").map(|m| (m.ino(), m.rdev()));
        let sandbox = Sandbox::record(&dir);
        // A device is written into (or refused): it stays the same node.
        let ran = write_to(&dir, w, dev, WRITES);
        assert!(ran.ok || !ran.stderr.is_empty(), "{:?}", w.args);
        let meta = std::fs::symlink_metadata(dir.join(dev)).expect("still there");
        assert!(
            meta.file_type().is_char_device() || meta.file_type().is_symlink(),
            "{:?}: the device became {:?}",
            w.args,
            meta.file_type()
        );
        // A read-only file is refused by its mode, even for root.
        let ran = write_to(&dir, w, "ro.txt", Duration::from_secs(2));
        assert!(
            !ran.ok && ran.stderr.contains("read-only"),
            "{:?}: {}",
            w.args,
            ran.stderr
        );
        // Its own input, by its name and through a link to it.
        if let Some(input) = w.input {
            let ran = write_to(&dir, w, input, Duration::from_secs(2));
            assert!(
                !ran.ok && ran.stderr.contains("is an input"),
                "{}",
                ran.stderr
            );
            let dotted = format!("./{input}");
            let ran = write_to(&dir, w, &dotted, Duration::from_secs(2));
            assert!(
                !ran.ok && ran.stderr.contains("is an input"),
                "{}",
                ran.stderr
            );
        }
        sandbox.assert_kept(&[], &[]);
        assert_eq!(
            std::fs::symlink_metadata("/dev/null")
                .map(|m| (m.ino(), m.rdev()))
                .ok(),
            null_before.ok(),
            "/dev/null changed"
        );
    }
}

#[test]
fn every_writer_writes_through_links_and_fifos_and_keeps_them() {
    for (i, w) in WRITERS.iter().enumerate() {
        let dir = sandbox(&format!("links-{i}"));
        std::fs::write(dir.join("real.txt"), "old").ok();
        std::os::unix::fs::symlink("real.txt", dir.join("sym.txt")).expect("a link");
        std::fs::write(dir.join("one.txt"), "old").ok();
        std::fs::hard_link(dir.join("one.txt"), dir.join("two.txt")).expect("a hard link");
        let ino = std::fs::metadata(dir.join("one.txt")).map(|m| m.ino()).ok();
        let status = std::process::Command::new("mkfifo")
            .arg(dir.join("pipe"))
            .status();
        assert!(status.is_ok_and(|s| s.success()), "mkfifo");
        let sandbox = Sandbox::record(&dir);
        // Through a symbolic link: the link stays, its file holds the output.
        let ran = write_to(&dir, w, "sym.txt", WRITES);
        assert!(ran.ok, "{:?}: {}", w.args, ran.stderr);
        let real = std::fs::read(dir.join("real.txt")).unwrap_or_default();
        assert!(real.len() > 100, "{:?}: {} bytes", w.args, real.len());
        // A hard link: both names stay one file, holding the output.
        let ran = write_to(&dir, w, "two.txt", WRITES);
        assert!(ran.ok, "{:?}: {}", w.args, ran.stderr);
        for name in ["one.txt", "two.txt"] {
            assert_eq!(
                std::fs::metadata(dir.join(name)).map(|m| m.ino()).ok(),
                ino,
                "{:?}: {name} is another file",
                w.args
            );
        }
        assert!(std::fs::read(dir.join("one.txt")).unwrap_or_default().len() > 100);
        // A FIFO: its reader gets the output, and it stays a FIFO.
        let reader = {
            let fifo = dir.join("pipe");
            std::thread::spawn(move || std::fs::read(fifo).unwrap_or_default())
        };
        let ran = write_to(&dir, w, "pipe", WRITES);
        if !ran.ok {
            // Refused: free the reader before failing.
            std::fs::write(dir.join("pipe"), b"").ok();
        }
        let got = reader.join().unwrap_or_default();
        assert!(ran.ok, "{:?}: {}", w.args, ran.stderr);
        assert!(
            got.len() > 100,
            "{:?}: the reader got {} bytes",
            w.args,
            got.len()
        );
        assert!(std::fs::symlink_metadata(dir.join("pipe")).is_ok_and(|m| m.file_type().is_fifo()));
        sandbox.assert_kept(&["real.txt", "one.txt", "two.txt"], &[]);
    }
}

/// The name of a process that cannot exist (above the largest PID Linux gives).
const DEAD: u32 = 4_194_304 + 4242;

#[test]
fn a_users_temporary_looking_folders_beside_an_output_are_kept() {
    for (i, w) in WRITERS.iter().enumerate() {
        let dir = sandbox(&format!("tmp-{i}"));
        for name in [
            format!(".out.txt.tmp-{DEAD}"),
            ".out.txt.tmp-4242".to_string(),
            format!(".out.txt.rolling-disk-{DEAD}-0"),
        ] {
            std::fs::create_dir_all(dir.join(&name)).ok();
            std::fs::write(dir.join(&name).join("mine.txt"), "mine").ok();
        }
        std::fs::write(dir.join(".out.txt.tmp-1"), "a file of that name").ok();
        let sandbox = Sandbox::record(&dir);
        let ran = write_to(&dir, w, "out.txt", WRITES);
        assert!(ran.ok, "{:?}: {}", w.args, ran.stderr);
        sandbox.assert_kept(&[], &["out.txt"]);
    }
}

/// A folder output: the user's look-alike folders and files stay; a folder left by a killed
/// run of this tool (its name, its marker, a process that is gone) is removed; one whose marker
/// names a live process is kept.
#[test]
fn a_folder_writer_removes_only_what_it_proves_its_own() {
    let dir = sandbox("folder");
    let ran = bounded(
        &dir,
        &["experiment", "simulate", "--csv", "trace.csv"],
        WRITES,
    );
    assert!(ran.ok, "{}", ran.stderr);
    for name in [
        format!(".od.tmp-{DEAD}"),
        ".od.tmp-4242".to_string(),
        format!(".od.rolling-disk-{DEAD}-1"),
    ] {
        std::fs::create_dir_all(dir.join(&name)).ok();
        std::fs::write(dir.join(&name).join("mine.txt"), "mine").ok();
    }
    // A live process's temporary (this test's own PID) and a dead one's, both marked.
    let marked = |pid: u32, n: u32| {
        let d = dir.join(format!(".od.rolling-disk-{pid}-{n}"));
        std::fs::create_dir_all(&d).ok();
        std::fs::write(
            d.join(".rolling-disk-temporary"),
            format!("a temporary directory of rolling-disk, process {pid}\n"),
        )
        .ok();
        d.file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default()
    };
    let live = marked(std::process::id(), 0);
    let dead = marked(DEAD, 0);
    let sandbox = Sandbox::record(&dir);
    let ran = bounded(
        &dir,
        &["experiment", "analyze", "trace.csv", "--out", "od"],
        WRITES,
    );
    assert!(ran.ok, "{}", ran.stderr);
    assert!(dir.join("od/analysis.json").is_file());
    assert!(
        !dir.join(&dead).exists(),
        "the dead run's temporary is left"
    );
    assert!(
        dir.join(&live).exists(),
        "a live process's temporary was removed"
    );
    sandbox.assert_kept(&[dead.as_str()], &["od"]);
}
