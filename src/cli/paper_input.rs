//! The paper a command reads (the built-in copy or `--paper DIR`) and the accuracy it checks at.

use checks::equations::{built_in_paper, Bench};
use paper::Paper;
use std::path::Path;
use studies::precision::Accuracy;

/// The paper to check: the built-in copy, or the one in `dir` (read once for the whole run).
pub(crate) fn load_paper(dir: Option<&Path>) -> anyhow::Result<&'static Paper> {
    match dir {
        None => Ok(built_in_paper()),
        Some(d) => match Paper::from_dir(d) {
            Ok(p) => Ok(Box::leak(Box::new(p))),
            Err(e) => Err(anyhow::anyhow!("--paper {}: {e}", d.display())),
        },
    }
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
