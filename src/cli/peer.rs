//! `peer export` and `peer compare`: the independent program's input and its comparison.

use super::*;
use std::io::Write;

/// Writes `text` to standard output; a reader that closes the pipe early is not an error.
fn print_text(text: &str) -> anyhow::Result<()> {
    match std::io::stdout().lock().write_all(text.as_bytes()) {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => Err(e.into()),
        _ => Ok(()),
    }
}

pub(crate) fn peer_export(name: &str, out: Option<&Path>) -> anyhow::Result<()> {
    let scene = Scene::load(name)?;
    let text = ::studies::peer::response::response(&scene)?;
    match out {
        Some(path) => write_atomically(path, text.as_bytes())
            .map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?,
        None => print_text(&text)?,
    }
    Ok(())
}

pub(crate) fn peer_compare(name: &str, result: &Path, json: bool) -> anyhow::Result<()> {
    let scene = Scene::load(name)?;
    let c = ::studies::peer::compare_file(&scene, result)?;
    if json {
        print_text(&format!("{}\n", serde_json::to_string_pretty(&c)?))
    } else {
        print_text(&c.to_string())
    }
}
