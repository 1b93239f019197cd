//! `rolling-disk report`: the reproduction report, written as one set of files.

use crate::cli::paper_input::{bench_for, load_paper};
use files::output::SetWriter;
use std::path::{Path, PathBuf};
use studies::precision::Accuracy;

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
    /// Integration accuracy of the checks (default: rtol 1e-12).
    #[arg(long, value_enum)]
    pub accuracy: Option<Accuracy>,
    /// Read the paper's equations from DIR/equations.yaml (and DIR/symbols.yaml,
    /// DIR/claims.yaml when present) instead of the built-in copy.
    #[arg(long, value_name = "DIR")]
    pub paper: Option<PathBuf>,
}

impl Args {
    /// Runs the command.
    pub fn run(self) -> anyhow::Result<()> {
        report(self.format, &self.out, self.accuracy, self.paper.as_deref())
    }
}

fn report(
    format: ReportFormat,
    out: &Path,
    accuracy: Option<Accuracy>,
    paper: Option<&Path>,
) -> anyhow::Result<()> {
    use ::report::{build::build, render};
    // Check --out and make room beside it before computing anything.
    let set = SetWriter::begin(out)?;
    let bench = bench_for(accuracy, load_paper(paper)?);
    let status = |s: &str| eprintln!("report: {s}");
    let (report, figures) = build(&bench, &status)?;
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
    let written = render::write(&report, &figures, set.dir(), &formats)?;
    let shown: Vec<PathBuf> = written.iter().map(|p| set.final_path(p)).collect();
    set.commit(&written)?;
    let written = shown;
    let t = &report.summary.equations;
    println!(
        "{} equations checked: {} hold, {} hold approximately, {} definitions, {} estimates \
         (scaling confirmed), {} hold only under a premise that fails, {} fail; {} claims fail \
         (and {} more as the equation they restate, counted there), {} unit misprints",
        t.holds
            + t.approximately
            + t.definitions
            + t.estimates
            + t.premise_fails
            + t.fails
            + t.not_run,
        t.holds,
        t.approximately,
        t.definitions,
        t.estimates,
        t.premise_fails,
        t.fails,
        report.summary.claims.fails,
        report.summary.claims.restated,
        report.summary.claims.unit_misprints
    );
    for p in written
        .iter()
        .filter(|p| p.extension().is_some_and(|e| e != "png"))
    {
        println!("wrote {}", p.display());
    }
    let pngs = written
        .iter()
        .filter(|p| p.extension().is_some_and(|e| e == "png"))
        .count();
    if pngs > 0 {
        println!(
            "wrote {pngs} figures under {}",
            out.join("figures").display()
        );
    }
    Ok(())
}
