//! Standard input as the file named `-`: a scene (`simulate -`), a recording (`experiment
//! analyze -`), a snapshot or a recorded run (`--against -`). It is read whole, at most a
//! bound of bytes, once per command: a second `-` in the same command is refused, and so is a
//! terminal (nothing was piped in, and reading would wait for typing).

use physics::scene::Scene;
use std::io::{IsTerminal, Read};
use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};

/// How standard input is named in messages.
pub(crate) const NAME: &str = "stdin";

/// Whether standard input was read already by this command.
static TAKEN: AtomicBool = AtomicBool::new(false);

/// Whether the path of an argument is `-`, standard input.
pub(crate) fn is_stdin(path: &Path) -> bool {
    path.as_os_str() == "-"
}

/// Reads standard input whole, for the argument `what` (named in messages), refusing more than
/// `limit` bytes, a terminal, and a second reader.
pub(crate) fn read(what: &str, limit: u64) -> anyhow::Result<Vec<u8>> {
    if TAKEN.swap(true, Ordering::SeqCst) {
        return Err(anyhow::anyhow!(
            "{what}: - (standard input) is already read by another argument of this command; \
             give a file for one of them"
        ));
    }
    let stdin = std::io::stdin();
    if stdin.is_terminal() {
        return Err(anyhow::anyhow!(
            "{what}: - reads standard input, which is a terminal: pipe or redirect a file into it \
             (for example `rolling-disk simulate - < my-scene.yaml`)"
        ));
    }
    let mut bytes = Vec::new();
    stdin
        .lock()
        .take(limit.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(|e| anyhow::anyhow!("{what}: cannot read standard input ({e})"))?;
    if bytes.len() as u64 > limit {
        return Err(anyhow::anyhow!(
            "{what}: standard input holds more than the limit of {limit} bytes for this kind of \
             file: give a smaller file"
        ));
    }
    Ok(bytes)
}

/// Reads standard input as UTF-8 text (a byte-order mark dropped, line ends made LF).
pub(crate) fn read_text(what: &str, limit: u64) -> anyhow::Result<String> {
    let bytes = read(what, limit)?;
    match String::from_utf8(bytes) {
        Ok(text) => Ok(files::input::normalize(&text).into_owned()),
        Err(e) => {
            let upto = &e.as_bytes()[..e.utf8_error().valid_up_to()];
            let line = 1 + upto.iter().filter(|&&b| b == b'\n').count();
            Err(anyhow::anyhow!(
                "{NAME}:{line}: {what} is not UTF-8 text: save it as UTF-8"
            ))
        }
    }
}

/// The scene of a SCENE argument: a file, a built-in scene's name, or `-` for a scene's YAML on
/// standard input.
pub(crate) fn scene(name: &str) -> anyhow::Result<Scene> {
    if name != "-" {
        return Ok(Scene::load(name)?);
    }
    let text = read_text("the scene", files::input::MAX_SCENE_BYTES)?;
    Ok(Scene::parse(&text, NAME)?)
}
