//! The tool used as a hostile user would (issue 48): every command that writes a file goes
//! through one door that never replaces a device, a FIFO, a symbolic link, a hard link's other
//! names or one of its own inputs; no budget or scene value makes it panic; every value out of
//! its range is refused with the range, and each piece of advice works when applied. Every run
//! here must end without a panic, and the ones that refuse at once within 2 s.

use crate::common::{cli_timed, temp_dir};
use std::path::{Path, PathBuf};
use std::time::Duration;

/// Runs the binary in `dir` and asserts it did not panic: (success, stdout, stderr, time).
fn run(dir: &Path, args: &[&str]) -> (bool, String, String, Duration) {
    let (ok, out, err, took) = cli_timed(dir, args);
    assert!(
        !err.contains("panicked") && !err.contains("RUST_BACKTRACE"),
        "{args:?} panicked: {err}"
    );
    (ok, out, err, took)
}

/// Asserts that `args` is refused at once (under 2 s) with a message holding every one of `says`.
fn refused(dir: &Path, args: &[&str], says: &[&str]) {
    let (ok, _, err, took) = run(dir, args);
    assert!(!ok, "{args:?} was accepted");
    assert!(took < Duration::from_secs(2), "{args:?} took {took:?}");
    for s in says {
        assert!(err.contains(s), "{args:?}: {err} lacks {s}");
    }
}

/// A sliding scene with a thickness, the peer's kind, copied into `dir`.
fn peer_scene(dir: &Path) -> PathBuf {
    let src =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reference/peer/thick-fall/scene.yaml");
    let scene = dir.join("scene.yaml");
    std::fs::copy(src, &scene).expect("copied");
    scene
}

#[cfg(unix)]
#[test]
fn peer_export_goes_through_the_door() {
    use std::os::unix::fs::{FileTypeExt, MetadataExt, PermissionsExt};
    let dir = temp_dir("hostile", "peer-out");
    let scene = peer_scene(&dir);
    let before = std::fs::read(&scene).unwrap_or_default();
    // Its own input, under its name and through a link, is refused and kept.
    refused(
        &dir,
        &["peer", "export", "scene.yaml", "--out", "scene.yaml"],
        &["is an input of this command"],
    );
    std::os::unix::fs::symlink("scene.yaml", dir.join("link.yaml")).ok();
    refused(
        &dir,
        &["peer", "export", "scene.yaml", "--out", "link.yaml"],
        &["is an input"],
    );
    assert_eq!(std::fs::read(&scene).unwrap_or_default(), before);
    // A character device stays one (where this machine's /dev/null is one).
    let null_device =
        || std::fs::symlink_metadata("/dev/null").is_ok_and(|m| m.file_type().is_char_device());
    if null_device() {
        let (ok, _, err, _) = run(
            &dir,
            &["peer", "export", "scene.yaml", "--out", "/dev/null"],
        );
        assert!(ok, "{err}");
        assert!(null_device());
    }
    // A read-only file is refused untouched.
    let ro = dir.join("ro.txt");
    std::fs::write(&ro, "mine").ok();
    std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o444)).ok();
    // Refused by its mode, even for root.
    refused(
        &dir,
        &["peer", "export", "scene.yaml", "--out", "ro.txt"],
        &["read-only"],
    );
    assert_eq!(std::fs::read_to_string(&ro).unwrap_or_default(), "mine");
    // A symbolic link is kept and its file written; a hard link's names stay one file.
    std::fs::write(dir.join("real.txt"), "old").ok();
    std::os::unix::fs::symlink("real.txt", dir.join("sym.txt")).ok();
    let (ok, _, err, _) = run(&dir, &["peer", "export", "scene.yaml", "--out", "sym.txt"]);
    assert!(ok, "{err}");
    assert!(
        std::fs::symlink_metadata(dir.join("sym.txt")).is_ok_and(|m| m.file_type().is_symlink())
    );
    let real = std::fs::read_to_string(dir.join("real.txt")).unwrap_or_default();
    assert!(real.len() > 100, "{real}");
    std::fs::write(dir.join("one.txt"), "old").ok();
    std::fs::hard_link(dir.join("one.txt"), dir.join("two.txt")).ok();
    let (ok, _, err, _) = run(&dir, &["peer", "export", "scene.yaml", "--out", "two.txt"]);
    assert!(ok, "{err}");
    let one = std::fs::metadata(dir.join("one.txt")).map(|m| m.ino()).ok();
    assert_eq!(
        one,
        std::fs::metadata(dir.join("two.txt")).map(|m| m.ino()).ok()
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("one.txt")).unwrap_or_default(),
        real
    );
    // A FIFO is written through: its reader gets the whole export.
    let fifo = dir.join("pipe.txt");
    if std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .is_ok_and(|s| s.success())
    {
        let reader = {
            let fifo = fifo.clone();
            std::thread::spawn(move || std::fs::read_to_string(fifo).unwrap_or_default())
        };
        let (ok, _, err, _) = run(&dir, &["peer", "export", "scene.yaml", "--out", "pipe.txt"]);
        assert!(ok, "{err}");
        assert_eq!(reader.join().unwrap_or_default(), real);
        assert!(std::fs::symlink_metadata(&fifo).is_ok_and(|m| m.file_type().is_fifo()));
    }
}

#[test]
fn no_command_writes_over_the_scene_it_reads() {
    let dir = temp_dir("hostile", "over-input");
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("paper/scenes/spinning-coin.yaml");
    std::fs::copy(src, dir.join("my.yaml")).expect("copied");
    let before = std::fs::read(dir.join("my.yaml")).unwrap_or_default();
    refused(
        &dir,
        &["simulate", "my.yaml", "--csv", "my.yaml"],
        &["--csv", "my.yaml", "is an input"],
    );
    refused(
        &dir,
        &["simulate", "my.yaml", "--csv", "./my.yaml"],
        &["is an input"],
    );
    let spin_down = Path::new(env!("CARGO_MANIFEST_DIR")).join("paper/scenes/spin-down.yaml");
    std::fs::copy(spin_down, dir.join("exp.yaml")).expect("copied");
    let exp = std::fs::read(dir.join("exp.yaml")).unwrap_or_default();
    refused(
        &dir,
        &["experiment", "simulate", "exp.yaml", "--csv", "exp.yaml"],
        &["--csv exp.yaml", "is an input"],
    );
    assert_eq!(std::fs::read(dir.join("exp.yaml")).unwrap_or_default(), exp);
    assert_eq!(
        std::fs::read(dir.join("my.yaml")).unwrap_or_default(),
        before
    );
    // The advice: another path for the output.
    let (ok, _, err, _) = run(&dir, &["simulate", "my.yaml", "--csv", "my.csv"]);
    assert!(ok, "{err}");
}

#[test]
fn a_users_temporary_looking_folder_is_never_removed() {
    let dir = temp_dir("hostile", "user-tmp");
    let (ok, _, err, _) = run(&dir, &["experiment", "simulate", "--csv", "trace.csv"]);
    assert!(ok, "{err}");
    // Names the old tool took for its own, with a pid no process has, and a file in the way.
    let dead = 4_194_304 + 4242;
    for name in [
        format!(".od.tmp-{dead}"),
        ".od.tmp-4242".to_string(),
        format!(".od.rolling-disk-{dead}-0"),
    ] {
        std::fs::create_dir_all(dir.join(&name)).ok();
        std::fs::write(dir.join(&name).join("mine.txt"), "mine").ok();
    }
    std::fs::write(
        dir.join(format!(".od.rolling-disk-{}-0", std::process::id())),
        "mine",
    )
    .ok();
    let (ok, _, err, _) = run(&dir, &["experiment", "analyze", "trace.csv", "--out", "od"]);
    assert!(ok, "{err}");
    for name in [
        format!(".od.tmp-{dead}"),
        ".od.tmp-4242".to_string(),
        format!(".od.rolling-disk-{dead}-0"),
    ] {
        assert_eq!(
            std::fs::read_to_string(dir.join(&name).join("mine.txt")).unwrap_or_default(),
            "mine",
            "{name} was touched"
        );
    }
    // The tool's own temporaries are gone: only the set and the user's things are left.
    let left: Vec<String> = std::fs::read_dir(&dir)
        .map(|d| {
            d.flatten()
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    assert_eq!(left.len(), 6, "{left:?}");
}

#[cfg(unix)]
#[test]
fn out_through_a_link_to_a_folder_writes_the_folder_and_keeps_the_link() {
    let dir = temp_dir("hostile", "out-link");
    let (ok, _, err, _) = run(&dir, &["experiment", "simulate", "--csv", "trace.csv"]);
    assert!(ok, "{err}");
    std::fs::create_dir_all(dir.join("real")).ok();
    std::os::unix::fs::symlink("real", dir.join("link")).ok();
    let (ok, _, err, _) = run(
        &dir,
        &["experiment", "analyze", "trace.csv", "--out", "link"],
    );
    assert!(ok, "{err}");
    assert!(std::fs::symlink_metadata(dir.join("link")).is_ok_and(|m| m.file_type().is_symlink()));
    assert!(dir.join("real/analysis.json").is_file());
}

#[test]
fn a_file_with_a_built_in_scenes_name_is_named_not_silently_taken() {
    let dir = temp_dir("hostile", "shadow");
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("paper/scenes/spinning-coin.yaml");
    std::fs::copy(&src, dir.join("spinning-coin")).expect("copied");
    refused(
        &dir,
        &["simulate", "spinning-coin"],
        &["./spinning-coin", "builtin:spinning-coin"],
    );
    // Both pieces of advice work.
    for arg in ["./spinning-coin", "builtin:spinning-coin"] {
        let (ok, _, err, _) = run(&dir, &["simulate", arg]);
        assert!(ok, "{arg}: {err}");
    }
}

#[cfg(unix)]
#[test]
fn a_paper_dir_whose_equations_are_a_fifo_or_endless_is_refused_at_once() {
    let dir = temp_dir("hostile", "paper-fifo");
    let fifo = dir.join("fifo");
    std::fs::create_dir_all(&fifo).ok();
    if std::process::Command::new("mkfifo")
        .arg(fifo.join("equations.yaml"))
        .status()
        .is_ok_and(|s| s.success())
    {
        refused(
            &dir,
            &["check", "--only", "1", "--paper", "fifo"],
            &["FIFO", "equations.yaml"],
        );
    }
    let zero = dir.join("zero");
    std::fs::create_dir_all(&zero).ok();
    std::os::unix::fs::symlink("/dev/zero", zero.join("equations.yaml")).ok();
    refused(
        &dir,
        &["check", "--only", "1", "--paper", "zero"],
        &["device", "equations.yaml"],
    );
}

#[test]
fn numeric_options_out_of_their_physical_range_are_refused_with_it() {
    let dir = temp_dir("hostile", "ranges");
    for (args, says) in [
        (
            &["experiment", "simulate", "--wav", "a.wav", "--rate", "0"][..],
            "1000..=384000",
        ),
        (
            &[
                "experiment",
                "simulate",
                "--wav",
                "a.wav",
                "--rate",
                "384001",
            ][..],
            "1000..=384000",
        ),
        (
            &["experiment", "simulate", "--csv", "a.csv", "--hum", "1e300"][..],
            "0 to 1",
        ),
        (
            &[
                "experiment",
                "simulate",
                "--csv",
                "a.csv",
                "--drift",
                "1e300",
            ][..],
            "0 to 1",
        ),
        (
            &["experiment", "simulate", "--csv", "a.csv", "--mains", "1e9"][..],
            "10 to 1000",
        ),
    ] {
        refused(&dir, args, &[says]);
    }
    assert!(!dir.join("a.csv").exists() && !dir.join("a.wav").exists());
    // The ranges' ends are accepted.
    let (ok, _, err, _) = run(
        &dir,
        &[
            "experiment",
            "simulate",
            "--csv",
            "a.csv",
            "--hum",
            "1",
            "--mains",
            "10",
        ],
    );
    assert!(ok, "{err}");
}

#[test]
fn max_steps_out_of_range_names_its_range_and_the_range_works() {
    let dir = temp_dir("hostile", "max-steps");
    let src = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("paper/scenes/spinning-coin.yaml"),
    )
    .unwrap_or_default();
    let with = |steps: &str| src.replace("solver: {", &format!("solver: {{ max_steps: {steps},"));
    assert!(src.contains("solver: {"), "{src}");
    std::fs::write(dir.join("big.yaml"), with("1e12")).ok();
    refused(
        &dir,
        &["simulate", "big.yaml"],
        &["max_steps", "between 1 and 5e7"],
    );
    std::fs::write(dir.join("zero.yaml"), with("0")).ok();
    refused(&dir, &["simulate", "zero.yaml"], &["between 1 and 5e7"]);
    // The range's end is within the range; a memory budget may still lower it for this scene,
    // and then the number that message gives is applied and works.
    std::fs::write(dir.join("at.yaml"), with("5e7")).ok();
    let (ok, _, err, _) = run(&dir, &["simulate", "at.yaml"]);
    if !ok {
        let fits = err
            .split("lower max_steps to ")
            .nth(1)
            .and_then(|r| r.split_whitespace().next())
            .unwrap_or_default();
        assert!(!fits.is_empty(), "{err}");
        std::fs::write(dir.join("fits.yaml"), with(fits)).ok();
        let (ok, _, err, _) = run(&dir, &["simulate", "fits.yaml"]);
        assert!(ok, "{err}");
    }
}
