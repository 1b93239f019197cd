//! `peer export` and `peer compare`: the independent program's input and its comparison.

use super::*;

pub(crate) fn peer_export(name: &str, out: Option<&Path>) -> anyhow::Result<()> {
    let scene = Scene::load(name)?;
    let text = rolling_disk::peer::response::response(&scene)?;
    match out {
        Some(path) => write_atomically(path, text.as_bytes())
            .map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?,
        None => print!("{text}"),
    }
    Ok(())
}

pub(crate) fn peer_compare(name: &str, result: &Path, json: bool) -> anyhow::Result<()> {
    let scene = Scene::load(name)?;
    let c = rolling_disk::peer::compare_file(&scene, result)?;
    if json {
        println!("{}", serde_json::to_string_pretty(&c)?);
    } else {
        print!("{c}");
    }
    Ok(())
}
