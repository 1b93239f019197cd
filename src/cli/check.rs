//! `rolling-disk check`: every equation and claim against its reference, as a table or JSON;
//! a snapshot of the results (`--snapshot`), a run compared with one (`--against`, `--bless`),
//! and an exit status for CI (`--fail-on`; the statuses are [`crate::cli::exit`]'s).

use crate::cli::paper_input::PaperInput;
use crate::cli::precision::print_preset_accuracy;
use crate::cli::{exit, stdin, stdout, verdict_snapshot};
use checks::check::{run_checks, Checked, Selection, Tally};
use checks::finding::Verdict;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use report::document::PAPER;
use serde_json::Value;
use std::path::{Path, PathBuf};

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
    /// Also write a snapshot of every check (verdict, cause, and its numbers each with the change
    /// it may take), with the tool's version and the paper's hash, as JSON to FILE; `-` writes it
    /// to standard output in place of the table.
    #[arg(long, value_name = "FILE", conflicts_with = "against")]
    pub snapshot: Option<PathBuf>,
    /// Compare this run with the snapshot in FILE (`-`: standard input): print each verdict or
    /// cause that changed and each number that moved beyond its tolerance, in place of the
    /// table, and exit with status 3 if any did.
    #[arg(long, value_name = "FILE", conflicts_with = "json")]
    pub against: Option<PathBuf>,
    /// With --against: accept this run, rewriting FILE with its snapshot (status 0 whatever
    /// changed).
    #[arg(long, requires = "against")]
    pub bless: bool,
    /// Exit with status 4 when a check's verdict is of this kind: `fails` (fails), `premise`
    /// (fails, or holds only under a premise that fails), `any` (every verdict but holds, holds
    /// approximately, definition and estimate).
    #[arg(long, value_name = "KIND", value_enum)]
    pub fail_on: Option<FailOn>,
    #[command(flatten)]
    pub caching: crate::cli::caching::Caching,
    #[command(flatten)]
    pub(crate) input: PaperInput,
}

/// The verdicts `--fail-on` ends a run with status 4 on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum FailOn {
    /// A check fails (a claim restating a failing equation fails with it).
    Fails,
    /// A check fails, or holds only under a premise that fails.
    Premise,
    /// Any verdict but holds, holds approximately, definition and estimate.
    Any,
}

impl FailOn {
    /// Whether `v` is a verdict of this kind.
    pub fn meets(self, v: &Verdict) -> bool {
        let fails = matches!(v, Verdict::Fails | Verdict::Restates { .. });
        match self {
            FailOn::Fails => fails,
            FailOn::Premise => fails || matches!(v, Verdict::PremiseFails),
            FailOn::Any => !v.passes() || matches!(v, Verdict::PremiseFails),
        }
    }
}

impl Args {
    /// Runs the command.
    pub fn run(self) -> anyhow::Result<()> {
        if self.json && self.snapshot.as_deref().is_some_and(stdin::is_stdin) {
            return Err(anyhow::anyhow!(
                "--snapshot - and --json would both write to standard output: give --snapshot a file"
            ));
        }
        if let Some(path) = &self.snapshot {
            stdout::check_output(path).map_err(|e| anyhow::anyhow!("--snapshot {e}"))?;
        }
        let against = match &self.against {
            Some(path) => Some(Against::read(path, self.bless)?),
            None => None,
        };
        let (checked, snapshot) = check(&self)?;
        finish(&self, &checked, snapshot, against.as_ref())
    }
}

/// Runs the checks that `args` select and prints them (the table or the JSON, unless the
/// snapshot or the diff takes standard output); returns them with their snapshot.
fn check(args: &Args) -> anyhow::Result<(Vec<Checked>, Value)> {
    let input = &args.input;
    let bench = input.bench()?;
    let accuracy = input.accuracy;
    let started = std::time::Instant::now();
    let selection = match args.only.as_deref() {
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
    let cache = args.caching.cache();
    let warn = |w: &str| {
        bar.suspend(|| eprintln!("warning: {w}"));
    };
    let checked = report::kept_film::around(cache.as_ref(), &warn, || {
        run_checks(&bench, &selection, threads, &progress)
    })?;
    bar.finish_and_clear();
    crate::cli::within_budget()?;
    let elapsed = started.elapsed().as_secs_f64();
    let snapshot = verdict_snapshot::snapshot(&checked, bench.paper, "DOP853", bench.rtol);
    let stdout_taken =
        args.against.is_some() || args.snapshot.as_deref().is_some_and(stdin::is_stdin);
    if args.json {
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
    } else if !stdout_taken {
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
    Ok((checked, snapshot))
}

/// The largest snapshot read, in bytes (one of the whole paper is about 60 KB).
const MAX_SNAPSHOT_BYTES: u64 = 16 << 20;

/// The snapshot of `--against`, read before any check runs.
struct Against {
    /// Its path.
    path: PathBuf,
    /// Its contents; none when `--bless` creates it.
    before: Option<Value>,
}

impl Against {
    /// Reads the snapshot at `path` (`-`: standard input); with `bless`, one that is not there
    /// yet is created by the run.
    fn read(path: &Path, bless: bool) -> anyhow::Result<Self> {
        let shown = path.display().to_string();
        let text = if stdin::is_stdin(path) {
            if bless {
                return Err(anyhow::anyhow!(
                    "--bless rewrites the snapshot of --against, and - is standard input: give \
                     --against the snapshot's path"
                ));
            }
            stdin::read_text("--against", MAX_SNAPSHOT_BYTES)?
        } else if bless && std::fs::symlink_metadata(path).is_err() {
            stdout::check_output(path).map_err(|e| anyhow::anyhow!("--against {e}"))?;
            return Ok(Self {
                path: path.to_path_buf(),
                before: None,
            });
        } else {
            let read = if bless {
                files::input::read_text_to_replace(path, MAX_SNAPSHOT_BYTES)
            } else {
                files::input::read_text(path, MAX_SNAPSHOT_BYTES)
            };
            read.map_err(|e| match e {
                files::input::InputError::Open { .. } => anyhow::anyhow!(
                    "--against {e}; write a snapshot first with --snapshot {shown}, or add \
                     --bless to create it"
                ),
                e => anyhow::anyhow!("--against {e}"),
            })?
        };
        let shown = if stdin::is_stdin(path) {
            stdin::NAME.to_string()
        } else {
            shown
        };
        Ok(Self {
            path: path.to_path_buf(),
            before: Some(verdict_snapshot::parse(&text, &shown)?),
        })
    }
}

/// After the run: the diff against the snapshot, the snapshot written or blessed, and the exit
/// status (1 when a check could not run, 3 on a change, 4 on a verdict `--fail-on` names).
fn finish(
    args: &Args,
    checked: &[Checked],
    snapshot: Value,
    against: Option<&Against>,
) -> anyhow::Result<()> {
    let mut changed = None;
    if let Some(a) = against {
        let shown = a.path.display().to_string();
        match &a.before {
            Some(before) => {
                let d = verdict_snapshot::diff(before, &snapshot);
                print!("{}", verdict_snapshot::render(&d, &shown));
                let names = d.changed_checks();
                if !names.is_empty() {
                    changed = Some(format!(
                        "{} of {} checks changed against {shown} (a verdict, a cause, or a number \
                         beyond its tolerance: see above); if the change is meant, accept it with \
                         --bless",
                        names.len(),
                        d.checks
                    ));
                }
            }
            None => println!("against {shown}: no snapshot yet; --bless creates it"),
        }
    }
    let tally = Tally::of(checked);
    if tally.not_run > 0 {
        return Err(anyhow::anyhow!(
            "{} check(s) could not run (see above); no snapshot written",
            tally.not_run
        ));
    }
    let bytes = verdict_snapshot::to_bytes(&snapshot);
    if let Some(path) = &args.snapshot {
        let to_stdout =
            stdout::write_to(path, &bytes).map_err(|e| anyhow::anyhow!("--snapshot {e}"))?;
        if !to_stdout {
            stdout::note(format_args!("wrote snapshot {}", path.display()));
        }
    }
    if let (Some(a), true) = (against, args.bless) {
        stdout::write_to(&a.path, &bytes).map_err(|e| anyhow::anyhow!("--against {e}"))?;
        stdout::note(format_args!(
            "blessed: {} now holds this run's {} checks",
            a.path.display(),
            checked.len()
        ));
        changed = None;
    }
    let found: Vec<String> = match args.fail_on {
        Some(kind) => checked
            .iter()
            .filter(|c| c.finding.as_ref().is_ok_and(|f| kind.meets(&f.verdict)))
            .map(|c| c.subject.name())
            .collect(),
        None => Vec::new(),
    };
    let found = (!found.is_empty()).then(|| {
        let kind = match args.fail_on {
            Some(FailOn::Fails) => "fails",
            Some(FailOn::Premise) => "premise",
            Some(FailOn::Any) | None => "any",
        };
        format!(
            "--fail-on {kind}: {} check(s) met it: {}",
            found.len(),
            found.join(", ")
        )
    });
    match (changed, found) {
        (Some(c), f) => {
            if let Some(f) = f {
                eprintln!("error: {f}");
            }
            Err(exit::Status {
                code: exit::CHANGED,
                message: c,
            }
            .into())
        }
        (None, Some(f)) => Err(exit::Status {
            code: exit::FOUND,
            message: f,
        }
        .into()),
        (None, None) => Ok(()),
    }
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
                ::report::inline_math::plain(&f.verdict.to_string()),
                if f.premises_failing.is_empty() {
                    String::new()
                } else {
                    format!(" ({} fails)", f.premises_failing.join(", "))
                }
            ),
            Err(e) => println!("{:<34} {:>3}  {e}", c.subject.name(), c.section),
        }
    }
    // A formula between dollar signs in a card's text, in Unicode for the terminal.
    let plain = ::report::inline_math::plain;
    for c in checked {
        if let Ok(f) = &c.finding {
            if !f.verdict.passes() {
                let unit = match f.unit.as_str() {
                    "" | "1" => String::new(),
                    u => format!(" {}", plain(&::paper::unit_tex::unit_prose(u))),
                };
                let verdict = match f.verdict {
                    ::checks::finding::Verdict::Fails => "FAILS".to_string(),
                    v => v.to_string().to_uppercase(),
                };
                println!(
                    "\n{} {verdict}: {}\n  claimed {:.9e}{unit}, reference {:.9e}{unit}, error {:.3e} > {:.3e} ({})\n  at {}",
                    c.subject.name(),
                    plain(&f.compared),
                    f.claimed,
                    f.reference,
                    f.error,
                    f.tolerance.value,
                    plain(&f.tolerance.rule),
                    plain(&f.at)
                );
                for a in &f.robustness {
                    println!(
                        "  {}: {}: reference {:.6e}{unit}, {}",
                        a.choice,
                        plain(&a.alternative),
                        a.reference,
                        a.verdict
                    );
                }
                if !c.dimensions.starts_with("consistent") {
                    println!("  dimensions: {}", plain(&c.dimensions));
                }
                if let Some(cause) = &c.cause {
                    println!("  cause: {}", plain(&cause.describe()));
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
            println!("  eq {n}: {}", ::report::inline_math::plain(&c.describe()));
        }
    }
}
