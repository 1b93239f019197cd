//! Standard output as a careful tool writes it: a reader that stops reading (`| head`, a closed
//! pipe) ends the program quietly with the conventional status 141 (128 + SIGPIPE) instead of a
//! panic. The binary's `print!` and `println!` (defined in `main.rs`, before every module) come
//! here, so that every line of every command is covered by this one place.

use std::io::Write;
use std::sync::atomic::{AtomicBool, Ordering};

/// Whether `--quiet` was given: the notes of [`note`] are then not printed.
static QUIET: AtomicBool = AtomicBool::new(false);

/// Sets `--quiet` for the whole process.
pub(crate) fn set_quiet(quiet: bool) {
    QUIET.store(quiet, Ordering::Relaxed);
}

/// Whether `--quiet` was given.
pub(crate) fn quiet() -> bool {
    QUIET.load(Ordering::Relaxed)
}

/// Writes a line of progress on standard error, only where a person watches it (standard error
/// is a terminal) and `--quiet` was not given: a log or a pipe gets the results alone.
pub(crate) fn progress(line: &str) {
    use std::io::IsTerminal;
    if !quiet() && std::io::stderr().is_terminal() {
        eprintln!("{line}");
    }
}

/// Writes a note about what the command did (a file it wrote) as a line on standard output,
/// unless `--quiet` was given.
pub(crate) fn note(args: std::fmt::Arguments<'_>) {
    if !quiet() {
        write(format_args!("{args}\n"));
    }
}

/// The exit status of a program whose reader closed the pipe: 128 + SIGPIPE (13).
pub(crate) const CLOSED_PIPE_STATUS: i32 = 141;

/// Writes `args` to standard output. A closed pipe exits quietly with
/// [`CLOSED_PIPE_STATUS`]; any other failure to write (a full disk behind a redirection) is
/// said in one sentence on standard error, with a non-zero exit.
pub(crate) fn write(args: std::fmt::Arguments<'_>) {
    let mut out = std::io::stdout().lock();
    if let Err(e) = out.write_fmt(args) {
        exit_on(e);
    }
}

/// Flushes standard output; the same endings as [`write`].
pub(crate) fn flush() {
    if let Err(e) = std::io::stdout().lock().flush() {
        exit_on(e);
    }
}

fn exit_on(e: std::io::Error) -> ! {
    if e.kind() == std::io::ErrorKind::BrokenPipe {
        std::process::exit(CLOSED_PIPE_STATUS);
    }
    eprintln!("error: cannot write to standard output ({e})");
    std::process::exit(1);
}

/// Checks, before anything is computed, that the output file `path` of an option can be
/// written (`-`, standard output, always can): the same refusals as [`write_to`], at once.
pub(crate) fn check_output(path: &std::path::Path) -> anyhow::Result<()> {
    if path.as_os_str() != "-" {
        files::output_file::output_target(path)?;
    }
    Ok(())
}

/// Writes `bytes` to the output file `path` of an option such as `--csv` or `--wav`: `-` is
/// standard output, any other path goes through [`files::output_file::write_output`].
/// Returns whether standard output was used, so that the caller says what it did on standard
/// error instead.
pub(crate) fn write_to(path: &std::path::Path, bytes: &[u8]) -> anyhow::Result<bool> {
    if path.as_os_str() == "-" {
        let mut out = std::io::stdout().lock();
        if let Err(e) = out.write_all(bytes).and_then(|()| out.flush()) {
            exit_on(e);
        }
        return Ok(true);
    }
    files::output_file::write_output(path, bytes)?;
    Ok(false)
}

/// Begins the set of files of `--out DIR` ([`files::output::SetWriter`]); `-` is refused, as a
/// directory of files has no place on standard output.
pub(crate) fn begin_set(path: &std::path::Path) -> anyhow::Result<files::output::SetWriter> {
    if path.as_os_str() == "-" {
        return Err(anyhow::anyhow!(
            "--out -: this writes a set of files (a directory), which standard output cannot \
             hold; name a directory (for example --out results)"
        ));
    }
    Ok(files::output::SetWriter::begin(path)?)
}
