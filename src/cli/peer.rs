//! `rolling-disk peer export` and `peer compare`: an independent program as a reference.

use physics::scene::Scene;
use std::io::Write;
use std::path::{Path, PathBuf};

/// The commands of `rolling-disk peer`.
#[derive(clap::Subcommand)]
pub enum Command {
    /// Writes the peer's response file for a sliding scene with a thickness (a built-in one
    /// mapped to the peer's gravity and a nominal thickness, as stated on standard error).
    Export {
        /// A scene file, or the name of a built-in scene.
        #[arg(value_parser = crate::cli::utf8::scene())]
        scene: String,
        /// Write to this file instead of standard output.
        #[arg(long, value_name = "FILE")]
        out: Option<PathBuf>,
    },
    /// Reads the peer's result.txt, runs the scene here, prints the largest differences.
    Compare {
        /// The scene the peer ran (as exported; a built-in one mapped the same way).
        #[arg(value_parser = crate::cli::utf8::scene())]
        scene: String,
        /// The peer's result.txt.
        result: PathBuf,
        /// Print the comparison as JSON.
        #[arg(long)]
        json: bool,
    },
}

impl Command {
    /// Runs the command.
    pub fn run(self) -> anyhow::Result<()> {
        match self {
            Command::Export { scene, out } => peer_export(&scene, out.as_deref()),
            Command::Compare {
                scene,
                result,
                json,
            } => peer_compare(&scene, &result, json),
        }
    }
}

/// Writes `text` to standard output; a reader that closes the pipe early is not an error.
fn print_text(text: &str) -> anyhow::Result<()> {
    match std::io::stdout().lock().write_all(text.as_bytes()) {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => Err(e.into()),
        _ => Ok(()),
    }
}

/// The scene `name` (or standard input's, `-`) as the peer runs it: a built-in scene mapped to
/// the peer's gravity and a nominal thickness (`studies::peer::builtin`), with a note for each
/// change.
fn peer_scene(name: &str) -> anyhow::Result<(Scene, Vec<String>)> {
    let scene = crate::cli::stdin::scene(name)?;
    let (mapped, notes) = ::studies::peer::builtin::for_peer(&scene)?;
    let source = scene.source;
    Ok((
        mapped,
        notes
            .into_iter()
            .map(|n| format!("{source}: mapped for the peer: {n}"))
            .collect(),
    ))
}

fn peer_export(name: &str, out: Option<&Path>) -> anyhow::Result<()> {
    let (scene, notes) = peer_scene(name)?;
    if let Some(path) = out {
        crate::cli::stdout::check_output(path).map_err(|e| anyhow::anyhow!("--out {e}"))?;
    }
    let mut text = ::studies::peer::response::response(&scene)?;
    for n in &notes {
        eprintln!("note: {n}");
    }
    if !notes.is_empty() {
        let mapping: String = notes.iter().map(|n| format!("# {n}\n")).collect();
        // After the two header lines, before the answers.
        let at = text.match_indices('\n').nth(1).map_or(0, |(i, _)| i + 1);
        text.insert_str(at, &mapping);
    }
    for w in ::studies::peer::floors::floors(&scene)? {
        eprintln!("warning: {}: {w}", scene.source);
    }
    match out {
        Some(path) => {
            crate::cli::stdout::write_to(path, text.as_bytes())
                .map_err(|e| anyhow::anyhow!("--out {e}"))?;
        }
        None => print_text(&text)?,
    }
    Ok(())
}

fn peer_compare(name: &str, result: &Path, json: bool) -> anyhow::Result<()> {
    let (scene, notes) = peer_scene(name)?;
    for n in &notes {
        eprintln!("note: {n}");
    }
    let c = ::studies::peer::compare_file(&scene, result)?;
    if json {
        print_text(&format!("{}\n", serde_json::to_string_pretty(&c)?))
    } else {
        print_text(&c.to_string())
    }
}
