//! `rolling-disk mutants`: the mutation suite's scores and survivors.

use crate::cli::paper_input::{bench_for, PaperDir};
use indicatif::{ProgressBar, ProgressDrawTarget};

/// The arguments of `rolling-disk mutants`.
#[derive(clap::Args)]
pub struct Args {
    /// Only these equations: numbers and ranges, comma-separated (e.g. 23-25,50).
    #[arg(long, value_name = "LIST")]
    pub only: Option<String>,
    /// Print the scores as JSON.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub(crate) dir: PaperDir,
}

impl Args {
    /// Runs the command.
    pub fn run(self) -> anyhow::Result<()> {
        mutants(self.only.as_deref(), self.json, &self.dir)
    }
}

fn mutants(only: Option<&str>, json: bool, dir: &PaperDir) -> anyhow::Result<()> {
    let bench = bench_for(None, dir.load()?);
    let numbers: Vec<u32> = match only {
        None => ::checks::equations::equations()
            .iter()
            .map(|e| e.number)
            .collect(),
        Some(text) => {
            let selection = ::checks::select::parse_only(text, bench.paper)?;
            match selection.numbers {
                Some(n) if !n.is_empty() => n,
                _ => {
                    return Err(anyhow::anyhow!(
                        "--only {text}: name equation numbers or ranges (claims have no mutants)"
                    ))
                }
            }
        }
    };
    let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr());
    let progress = |done: usize, total: usize| {
        bar.set_length(total as u64);
        bar.set_position(done as u64);
    };
    let scores = ::checks::mutation::mutation_scores(&bench, &numbers, &progress);
    bar.finish_and_clear();
    if json {
        println!(
            "{}",
            serde_json::to_string_pretty(&scores)
                .map_err(|e| anyhow::anyhow!("cannot write JSON: {e}"))?
        );
        return Ok(());
    }
    let (mut made, mut killed) = (0, 0);
    for s in &scores {
        if s.printed_fails {
            println!(
                "eq {:2}  the printed form fails its check: no score",
                s.equation
            );
            continue;
        }
        made += s.mutants;
        killed += s.killed;
        println!(
            "eq {:2}  {:3}/{:<3} killed{}",
            s.equation,
            s.killed,
            s.mutants,
            if s.judged_by == "derivation" {
                " (judged by its derivation from its printed premises: the printed form fails its own check)"
            } else {
                ""
            }
        );
        for change in &s.survivors {
            println!(
                "         survives: {}",
                ::report::inline_math::plain(change)
            );
        }
    }
    println!("{killed}/{made} mutants killed");
    Ok(())
}
