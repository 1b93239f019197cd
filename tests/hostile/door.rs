//! Paths and values as a hostile user gives them (issue 48): `--out` through a link to a
//! folder, a file that shadows a built-in scene's name, a `--paper` folder whose equations are
//! a FIFO or endless, and numeric options and `max_steps` outside their physical range, each
//! refused with the range within 2 s, and each piece of advice applied and working.

use super::sandbox::{cli_timed, refused_at_once};
use crate::common::temp_dir;
use std::path::Path;

#[cfg(unix)]
#[test]
fn out_through_a_link_to_a_folder_writes_the_folder_and_keeps_the_link() {
    let dir = temp_dir("hostile", "out-link");
    let (ok, _, err, _) = cli_timed(&dir, &["experiment", "simulate", "--csv", "trace.csv"]);
    assert!(ok, "{err}");
    std::fs::create_dir_all(dir.join("real")).ok();
    std::os::unix::fs::symlink("real", dir.join("link")).ok();
    let (ok, _, err, _) = cli_timed(
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
    refused_at_once(
        &dir,
        &["simulate", "spinning-coin"],
        &["./spinning-coin", "builtin:spinning-coin"],
    );
    // Both pieces of advice work.
    for arg in ["./spinning-coin", "builtin:spinning-coin"] {
        let (ok, _, err, _) = cli_timed(&dir, &["simulate", arg]);
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
        refused_at_once(
            &dir,
            &["check", "--only", "1", "--paper", "fifo"],
            &["FIFO", "equations.yaml"],
        );
    }
    let zero = dir.join("zero");
    std::fs::create_dir_all(&zero).ok();
    std::os::unix::fs::symlink("/dev/zero", zero.join("equations.yaml")).ok();
    refused_at_once(
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
        refused_at_once(&dir, args, &[says]);
    }
    assert!(!dir.join("a.csv").exists() && !dir.join("a.wav").exists());
    // The ranges' ends are accepted.
    let (ok, _, err, _) = cli_timed(
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
    refused_at_once(
        &dir,
        &["simulate", "big.yaml"],
        &["max_steps", "between 1 and 5e7"],
    );
    std::fs::write(dir.join("zero.yaml"), with("0")).ok();
    refused_at_once(&dir, &["simulate", "zero.yaml"], &["between 1 and 5e7"]);
    // The range's end is within the range; a memory budget may still lower it for this scene,
    // and then the number that message gives is applied and works.
    std::fs::write(dir.join("at.yaml"), with("5e7")).ok();
    let (ok, _, err, _) = cli_timed(&dir, &["simulate", "at.yaml"]);
    if !ok {
        let fits = err
            .split("lower max_steps to ")
            .nth(1)
            .and_then(|r| r.split_whitespace().next())
            .unwrap_or_default();
        assert!(!fits.is_empty(), "{err}");
        std::fs::write(dir.join("fits.yaml"), with(fits)).ok();
        let (ok, _, err, _) = cli_timed(&dir, &["simulate", "fits.yaml"]);
        assert!(ok, "{err}");
    }
}
