//! `rolling-disk figures`: the figures alone, by the paper's names.

use files::output::write_set_file;
use std::path::{Path, PathBuf};

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum FigureFormat {
    Svg,
    Png,
}

/// The arguments of `rolling-disk figures`.
#[derive(clap::Args)]
pub struct Args {
    /// Only these figures, comma-separated (default: all).
    #[arg(long, value_name = "NAMES")]
    pub only: Option<String>,
    /// The directory to write to.
    #[arg(long, value_name = "DIR", default_value = "figures")]
    pub out: PathBuf,
    /// File format.
    #[arg(long, value_enum, default_value = "svg")]
    pub format: FigureFormat,
    /// Lists the figures' names, one a line, and draws nothing.
    #[arg(long, conflicts_with = "only")]
    pub list: bool,
}

impl Args {
    /// Runs the command.
    pub fn run(self) -> anyhow::Result<()> {
        if self.list {
            for name in ::report::figures::names() {
                println!("{name}");
            }
            return Ok(());
        }
        figures(self.only.as_deref(), &self.out, self.format)
    }
}

fn figures(only: Option<&str>, out: &Path, format: FigureFormat) -> anyhow::Result<()> {
    use ::report::pipeline::{compute, RunConfig};
    let names: Vec<&str> = ::report::figures::names();
    let wanted: Vec<&str> = match only {
        Some(list) => list
            .split(',')
            .map(str::trim)
            .filter(|s| !s.is_empty())
            .collect(),
        None => names.clone(),
    };
    if wanted.is_empty() {
        return Err(anyhow::anyhow!(
            "--only was given no figure name; name some (the figures are: {}) or leave --only out \
             to draw them all",
            names.join(", ")
        ));
    }
    for w in &wanted {
        if !names.contains(w) {
            return Err(anyhow::anyhow!(
                "--only: no figure is called {w}{}; the figures are: {} (`figures --list`)",
                physics::nearest::nearest(w, names.iter().copied())
                    .map_or(String::new(), |n| format!(" (did you mean {n}?)")),
                names.join(", ")
            ));
        }
    }
    // The folder is a set: checked before any computing, replaced whole at the end.
    let set = crate::cli::stdout::begin_set(out)?;
    // Only the studies the wanted figures are drawn from, each once.
    let config = RunConfig::figures(::checks::equations::Bench::default(), &wanted)?;
    let results = compute(&config, &|s: &str| {
        crate::cli::stdout::progress(&format!("figures: {s}"))
    })?;
    crate::cli::within_budget()?;
    let all = ::report::figures::some(&wanted, &results)?;
    let mut written = Vec::new();
    for f in &all {
        let path = match format {
            FigureFormat::Svg => {
                let path = set.dir().join(format!("{}.svg", f.name));
                let svg = f.drawing.to_svg(760, 480)?;
                write_set_file(&path, svg.as_bytes()).map_err(|e| {
                    anyhow::anyhow!("cannot write {}: {e}", set.final_path(&path).display())
                })?;
                path
            }
            FigureFormat::Png => {
                let path = set.dir().join(format!("{}.png", f.name));
                f.drawing.to_png(&path)?;
                path
            }
        };
        written.push(path);
    }
    let shown: Vec<PathBuf> = written.iter().map(|p| set.final_path(p)).collect();
    set.commit(&written)?;
    for path in shown {
        crate::cli::stdout::note(format_args!("wrote {}", path.display()));
    }
    Ok(())
}
