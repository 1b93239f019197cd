//! What the integration tests share: the binary run in a directory, and fresh scratch
//! directories.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

/// Runs the binary in `dir`: (success, stdout, stderr, wall time).
pub fn cli_timed(dir: &Path, args: &[&str]) -> (bool, String, String, Duration) {
    let start = Instant::now();
    let out = Command::new(env!("CARGO_BIN_EXE_rolling-disk"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("the binary runs");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
        start.elapsed(),
    )
}

/// Runs the binary in `dir`: (success, stdout, stderr).
pub fn cli_in(dir: &Path, args: &[&str]) -> (bool, String, String) {
    let (ok, out, err, _) = cli_timed(dir, args);
    (ok, out, err)
}

/// An empty scratch directory `rolling-disk-{family}-{tag}-{pid}` under the system's temp dir.
pub fn temp_dir(family: &str, tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!(
        "rolling-disk-{family}-{tag}-{}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("a scratch directory");
    d
}

/// Asserts that `results` hold exactly the studies `expected` (in any order), each computed once.
pub fn assert_computed_once(results: &report::results::Results, mut expected: Vec<&str>) {
    let studies: Vec<&str> = results.computed.keys().copied().collect();
    expected.sort_unstable();
    assert_eq!(studies, expected);
    assert!(
        results.computed.values().all(|&n| n == 1),
        "{:?}",
        results.computed
    );
}

/// The 16-bit samples (interleaved) and the rate of a WAV file.
pub fn read_wav_i16(path: &Path) -> (Vec<i16>, u32) {
    let mut r = hound::WavReader::open(path).expect("a WAV file");
    let rate = r.spec().sample_rate;
    let v = r.samples::<i16>().map(|s| s.expect("a sample")).collect();
    (v, rate)
}

/// Writes interleaved 16-bit samples of `channels` channels as a WAV file.
pub fn write_wav_i16(path: &Path, v: &[i16], rate: u32, channels: u16) {
    let spec = hound::WavSpec {
        channels,
        sample_rate: rate,
        bits_per_sample: 16,
        sample_format: hound::SampleFormat::Int,
    };
    let mut w = hound::WavWriter::create(path, spec).expect("a WAV file");
    for &x in v {
        w.write_sample(x).expect("a sample");
    }
    w.finalize().expect("the WAV written");
}

/// Fails unless docs/experiment.md says each of `written` (any run of white space read as one
/// space).
pub fn experiment_docs_say(written: &[String]) {
    let doc = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/experiment.md"))
        .expect("docs/experiment.md")
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ");
    for w in written {
        assert!(doc.contains(w), "docs/experiment.md should say: {w}");
    }
}

/// Runs the binary in `dir` with `input` on its standard input (none: an empty one):
/// (exit status, stdout, stderr).
pub fn cli_piped(dir: &Path, args: &[&str], input: &[u8]) -> (i32, String, String) {
    use std::io::Write;
    use std::process::Stdio;
    let mut child = Command::new(env!("CARGO_BIN_EXE_rolling-disk"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    let mut stdin = child.stdin.take().expect("a standard input");
    let input = input.to_vec();
    // Written from a thread: a command that does not read it must not block the test.
    let writer = std::thread::spawn(move || {
        let _ = stdin.write_all(&input);
    });
    let out = child.wait_with_output().expect("the binary ends");
    let _ = writer.join();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Runs the binary in `dir` with an empty standard input: (exit status, stdout, stderr).
pub fn cli_status(dir: &Path, args: &[&str]) -> (i32, String, String) {
    cli_piped(dir, args, b"")
}

/// The numbers of the last line of a CSV text (its last row).
pub fn last_row(csv: &str) -> Vec<f64> {
    let line = csv.lines().last().expect("a CSV with a row");
    line.split(',')
        .map(|c| {
            c.parse()
                .unwrap_or_else(|e| panic!("cell {c:?} of {line:?}: {e}"))
        })
        .collect()
}

/// The output of `command`, run to its end; the test fails with its standard error unless it
/// succeeds.
pub fn succeeds(command: &mut Command) -> std::process::Output {
    let out = command.output().expect("the command runs");
    assert!(
        out.status.success(),
        "{:?}: {}",
        command,
        String::from_utf8_lossy(&out.stderr)
    );
    out
}
