//! `rolling-disk check`: every equation and claim against its reference, as a table or JSON.

use crate::cli::paper_input::PaperInput;
use crate::cli::precision::print_preset_accuracy;
use checks::check::{run_checks, Checked, Selection, Tally};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use report::document::PAPER;

/// The arguments of `rolling-disk check`.
#[derive(clap::Args)]
pub struct Args {
    /// Only these: equation numbers, ranges and claim ids, comma-separated, with or without
    /// a prefix (e.g. 23-25,eq50,claim:k-uniform-disk).
    #[arg(long, value_name = "LIST")]
    pub only: Option<String>,
    /// Print the findings as JSON instead of a table.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub(crate) input: PaperInput,
}

impl Args {
    /// Runs the command.
    pub fn run(self) -> anyhow::Result<()> {
        check(self.only.as_deref(), self.json, &self.input)
    }
}

fn check(only: Option<&str>, json: bool, input: &PaperInput) -> anyhow::Result<()> {
    let bench = input.bench()?;
    let accuracy = input.accuracy;
    let started = std::time::Instant::now();
    let selection = match only {
        Some(text) if text.split(',').all(|s| s.trim().is_empty()) => {
            return Err(anyhow::anyhow!(
                "--only was given an empty list; name equations, ranges or claim ids \
                 (for example --only 23-25,50) or leave --only out to run every check"
            ))
        }
        Some(text) => ::checks::select::parse_only(text, bench.paper)?,
        None => Selection::default(),
    };
    let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr());
    bar.set_style(
        ProgressStyle::with_template("{spinner} checking [{bar:30}] {pos}/{len} {elapsed}")
            .expect("a valid template")
            .progress_chars("=> "),
    );
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    let progress = |done: usize, total: usize| {
        bar.set_length(total as u64);
        bar.set_position(done as u64);
    };
    let checked = run_checks(&bench, &selection, threads, &progress)?;
    bar.finish_and_clear();
    crate::cli::within_budget()?;
    let elapsed = started.elapsed().as_secs_f64();
    if json {
        use ::report::json;
        let settings = json::Settings {
            method: "DOP853".into(),
            rtol: bench.rtol,
            command: std::iter::once("rolling-disk".to_string())
                .chain(std::env::args().skip(1))
                .collect::<Vec<_>>()
                .join(" "),
        };
        let document = json::CheckDocument {
            header: json::Header::new(
                json::CHECK_SCHEMA_ID,
                PAPER,
                bench.paper,
                settings,
                &checked,
            ),
            checks: checked.iter().map(json::CheckRecord::of).collect(),
        };
        println!(
            "{}",
            serde_json::to_string_pretty(&document)
                .map_err(|e| anyhow::anyhow!("cannot write JSON: {e}"))?
        );
    } else {
        print_table(&checked);
        println!(
            "integrations: DOP853 at rtol {:e}; {} checks in {elapsed:.2} s on {threads} threads",
            bench.rtol,
            checked.len()
        );
        if let Some(a) = accuracy {
            print_preset_accuracy(a)?;
        }
    }
    let tally = Tally::of(&checked);
    if tally.not_run > 0 {
        return Err(anyhow::anyhow!(
            "{} check(s) could not run (see above)",
            tally.not_run
        ));
    }
    Ok(())
}

pub(crate) fn print_table(checked: &[Checked]) {
    println!(
        "{:<34} {:>3}  {:<17} {:>10} {:>10}  verdict",
        "checked", "sec", "method", "error", "tolerance"
    );
    for c in checked {
        match &c.finding {
            Ok(f) => println!(
                "{:<34} {:>3}  {:<17} {:>10.3e} {:>10.3e}  {}{}",
                c.subject.name(),
                c.section,
                f.method.to_string(),
                f.error,
                f.tolerance.value,
                f.verdict,
                if f.premises_failing.is_empty() {
                    String::new()
                } else {
                    format!(" ({} fails)", f.premises_failing.join(", "))
                }
            ),
            Err(e) => println!("{:<34} {:>3}  {e}", c.subject.name(), c.section),
        }
    }
    for c in checked {
        if let Ok(f) = &c.finding {
            if !f.verdict.passes() {
                let unit = match f.unit.as_str() {
                    "" | "1" => String::new(),
                    u => format!(" {u}"),
                };
                let verdict = match f.verdict {
                    ::checks::finding::Verdict::Fails => "FAILS".to_string(),
                    v => v.to_string().to_uppercase(),
                };
                println!(
                    "\n{} {verdict}: {}\n  claimed {:.9e}{unit}, reference {:.9e}{unit}, error {:.3e} > {:.3e} ({})\n  at {}",
                    c.subject.name(),
                    f.compared,
                    f.claimed,
                    f.reference,
                    f.error,
                    f.tolerance.value,
                    f.tolerance.rule,
                    f.at
                );
                for a in &f.robustness {
                    println!(
                        "  {}: {}: reference {:.6e}{unit}, {}",
                        a.choice, a.alternative, a.reference, a.verdict
                    );
                }
                if !c.dimensions.starts_with("consistent") {
                    println!("  dimensions: {}", c.dimensions);
                }
                if let Some(cause) = &c.cause {
                    println!("  cause: {}", cause.describe());
                }
            }
        }
    }
    print_root_causes(checked);
    let (eqs, claims): (Vec<&Checked>, Vec<&Checked>) = checked
        .iter()
        .partition(|c| matches!(c.subject, ::checks::check::Subject::Equation { .. }));
    println!();
    for (what, subjects) in [("equations", eqs), ("claims", claims)] {
        let t = Tally::of(subjects.iter().copied());
        println!("{} {what}: {}", t.total(), t.sentence());
    }
}

/// The failing equations grouped by root cause: each root cause with the equations that inherit
/// its error, then those whose cause could not be settled.
pub(crate) fn print_root_causes(checked: &[Checked]) {
    use ::checks::cause::{consequences, Cause};
    let causes = ::checks::check::equation_causes(checked);
    if causes.is_empty() {
        return;
    }
    println!("\nroot causes:");
    for (root, inherit) in consequences(&causes) {
        let tail = if inherit.is_empty() {
            String::new()
        } else {
            format!(
                "; inherited by {}",
                inherit
                    .iter()
                    .map(|n| format!("eq {n}"))
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        };
        println!("  eq {root}{tail}");
    }
    for (n, c) in &causes {
        if let Cause::Undetermined { .. } = c {
            println!("  eq {n}: {}", c.describe());
        }
    }
}
