//! The paper a command reads (the built-in copy or `--paper DIR`) and the accuracy it checks at.

use checks::equations::{built_in_paper, Bench};
use paper::Paper;
use std::path::{Path, PathBuf};
use studies::precision::Accuracy;

/// The paper a command checks and the accuracy of its checks, as options.
#[derive(clap::Args)]
pub(crate) struct PaperInput {
    /// Integration accuracy of the checks (fast: DOPRI5 at rtol 1e-6; standard and high:
    /// DOP853 at 1e-10 and 1e-13; each prints what it reaches on the benchmark scene);
    /// without it, DOP853 at rtol 1e-12, the accuracy the tolerances were designed at.
    #[arg(long, value_enum)]
    pub accuracy: Option<Accuracy>,
    #[command(flatten)]
    pub dir: PaperDir,
}

/// The paper's directory, as an option.
#[derive(clap::Args)]
pub(crate) struct PaperDir {
    /// Read the paper's equations from DIR/equations.yaml (and DIR/symbols.yaml, DIR/claims.yaml
    /// when present) instead of the built-in copy: an edited equation is re-checked without
    /// rebuilding.
    #[arg(long, value_name = "DIR")]
    pub paper: Option<PathBuf>,
}

impl PaperInput {
    /// The bench of these options, the paper read once.
    pub(crate) fn bench(&self) -> anyhow::Result<Bench<'static>> {
        Ok(bench_for(self.accuracy, self.dir.load()?))
    }
}

impl PaperDir {
    /// The paper of this option, read once.
    pub(crate) fn load(&self) -> anyhow::Result<&'static Paper> {
        load_paper(self.paper.as_deref())
    }
}

/// The paper to check: the built-in copy, or the one in `dir` (read once for the whole run).
fn load_paper(dir: Option<&Path>) -> anyhow::Result<&'static Paper> {
    match dir {
        None => Ok(built_in_paper()),
        Some(d) => match refuse_unreadable(d).and_then(|()| Ok(Paper::from_dir(d)?)) {
            Ok(p) => Ok(Box::leak(Box::new(p))),
            Err(e) => Err(anyhow::anyhow!("--paper {}: {e}", d.display())),
        },
    }
}

/// The paper's files in `dir` that are there, looked at through the files crate's reading door
/// before the paper's reader opens them: a FIFO, a device (a link to `/dev/zero`), a directory
/// or a file over the reader's limit is refused at once instead of blocking or reading forever.
fn refuse_unreadable(dir: &Path) -> anyhow::Result<()> {
    for name in [
        "equations.yaml",
        "symbols.yaml",
        "claims.yaml",
        "corrections.yaml",
    ] {
        let path = dir.join(name);
        if std::fs::symlink_metadata(&path).is_ok() {
            files::input::read_bytes(&path, paper::MAX_FILE_BYTES as u64)?;
        }
    }
    Ok(())
}

pub(crate) fn bench_for(accuracy: Option<Accuracy>, paper: &'static Paper) -> Bench<'static> {
    let bench = Bench::with_paper(paper);
    match accuracy {
        Some(a) => Bench {
            rtol: a.settings().rtol,
            method: a.settings().method,
            ..bench
        },
        None => bench,
    }
}
