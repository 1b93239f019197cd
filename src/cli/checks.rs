//! `check` and `mutants`: the paper to check, the accuracy, the table and the JSON they print.

use super::*;

pub(crate) fn mutants(only: Option<&str>, json: bool, paper: Option<&Path>) -> anyhow::Result<()> {
    let bench = bench_for(None, load_paper(paper)?);
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
            println!("         survives: {change}");
        }
    }
    println!("{killed}/{made} mutants killed");
    Ok(())
}

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

pub(crate) fn check(
    only: Option<&str>,
    json: bool,
    accuracy: Option<Accuracy>,
    paper: Option<&Path>,
) -> anyhow::Result<()> {
    let bench = bench_for(accuracy, load_paper(paper)?);
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
    let elapsed = started.elapsed().as_secs_f64();
    if json {
        use ::report::json;
        let document = json::CheckDocument {
            schema: json::CHECK_SCHEMA_ID.into(),
            schema_version: json::SCHEMA_VERSION,
            tool: json::Tool {
                name: env!("CARGO_PKG_NAME").into(),
                version: env!("CARGO_PKG_VERSION").into(),
            },
            paper: json::PaperSource::of(PAPER_TITLE, bench.paper),
            settings: json::Settings {
                method: "DOP853".into(),
                rtol: bench.rtol,
                command: std::iter::once("rolling-disk".to_string())
                    .chain(std::env::args().skip(1))
                    .collect::<Vec<_>>()
                    .join(" "),
            },
            summary: json::SummaryCounts::of(&checked),
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

/// The paper, as the JSON documents name it.
pub(crate) const PAPER_TITLE: &str =
    "A. J. McDonald and K. T. McDonald, The Rolling Motion of a Disk on a Horizontal Plane (2001)";

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
                println!(
                    "\n{} FAILS: {}\n  claimed {:.9e}{unit}, reference {:.9e}{unit}, error {:.3e} > {:.3e} ({})\n  at {}",
                    c.subject.name(),
                    f.compared,
                    f.claimed,
                    f.reference,
                    f.error,
                    f.tolerance.value,
                    f.tolerance.rule,
                    f.at
                );
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
    let line = |what: &str, t: Tally, n: usize| {
        format!(
            "{n} {what}: {} hold, {} hold approximately, {} definitions, {} estimates (scaling \
             confirmed), {} hold only under a premise that fails, {} fail, {} could not run",
            t.holds,
            t.approximately,
            t.definitions,
            t.estimates,
            t.premise_fails,
            t.fails,
            t.not_run
        )
    };
    println!();
    println!(
        "{}",
        line("equations", Tally::of(eqs.iter().copied()), eqs.len())
    );
    println!(
        "{}",
        line("claims", Tally::of(claims.iter().copied()), claims.len())
    );
}

/// The failing equations grouped by root cause: each root cause with the equations that inherit
/// its error, then those whose cause could not be settled.
pub(crate) fn print_root_causes(checked: &[Checked]) {
    use ::checks::cause::{consequences, Cause};
    let causes: std::collections::BTreeMap<u32, Cause> = checked
        .iter()
        .filter_map(|c| match (&c.subject, &c.cause) {
            (::checks::check::Subject::Equation { number, .. }, Some(cause)) => {
                Some((*number, cause.clone()))
            }
            _ => None,
        })
        .collect();
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
