//! `rolling-disk report`: the reproduction report, written as one set of files.

use crate::cli::paper_input::PaperInput;
use std::path::{Path, PathBuf};

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum ReportFormat {
    Html,
    Latex,
    Json,
    All,
}

/// The arguments of `rolling-disk report`.
#[derive(clap::Args)]
pub struct Args {
    /// Which formats to write.
    #[arg(long, value_enum, default_value = "all")]
    pub format: ReportFormat,
    /// The directory to write to.
    #[arg(long, value_name = "DIR", default_value = "report")]
    pub out: PathBuf,
    /// Prints where the time goes, on standard error: the wall and CPU seconds of each study
    /// (computed one after another, so that each one's CPU time is its own) and of each stage
    /// after them. The report's files are the same to the byte.
    #[arg(long, short)]
    pub verbose: bool,
    #[command(flatten)]
    pub caching: crate::cli::caching::Caching,
    #[command(flatten)]
    pub(crate) input: PaperInput,
}

impl Args {
    /// Runs the command.
    pub fn run(self) -> anyhow::Result<()> {
        let cache = self.caching.cache();
        report(self.format, &self.out, &self.input, self.verbose, cache)
    }
}

fn report(
    format: ReportFormat,
    out: &Path,
    input: &PaperInput,
    verbose: bool,
    cache: Option<::report::cache::Cache>,
) -> anyhow::Result<()> {
    use ::report::{build, pipeline::RunConfig, render, timing::Timings};
    // Check --out and make room beside it before computing anything.
    let set = crate::cli::stdout::begin_set(out)?;
    let bench = input.bench()?;
    let status = |s: &str| crate::cli::stdout::progress(&format!("report: {s}"));
    let timings = Timings::new();
    let config = RunConfig::report(bench).with_cache(cache);
    let (report, figures) = build::build_from(&config, &status, verbose.then_some(&timings))?;
    crate::cli::within_budget()?;
    let formats = match format {
        ReportFormat::Html => vec![render::Format::Html],
        ReportFormat::Latex => vec![render::Format::Latex],
        ReportFormat::Json => vec![render::Format::Json],
        ReportFormat::All => vec![
            render::Format::Html,
            render::Format::Latex,
            render::Format::Json,
        ],
    };
    status("writing");
    let written = timings.time("writing", || {
        render::write(&report, &figures, set.dir(), &formats)
    })?;
    if verbose {
        eprint!(
            "where the time went (CPU: every thread of the process):\n{}",
            timings.table()
        );
    }
    let shown: Vec<PathBuf> = written.iter().map(|p| set.final_path(p)).collect();
    set.commit(&written)?;
    let written = shown;
    // The same counts in the same words as `check`'s closing lines.
    let (t, c) = (&report.summary.equations, &report.summary.claims);
    println!(
        "{} equations checked: {}; {} claims: {}",
        t.total(),
        t.sentence(),
        c.total(),
        c.sentence()
    );
    for p in written
        .iter()
        .filter(|p| p.extension().is_some_and(|e| e != "png"))
    {
        crate::cli::stdout::note(format_args!("wrote {}", p.display()));
    }
    let pngs = written
        .iter()
        .filter(|p| p.extension().is_some_and(|e| e == "png"))
        .count();
    if pngs > 0 {
        crate::cli::stdout::note(format_args!(
            "wrote {pngs} figures under {}",
            out.join("figures").display()
        ));
    }
    Ok(())
}
