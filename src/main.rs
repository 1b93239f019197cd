//! The `rolling-disk` command line: parse, call the library, print. No physics here.

use clap::{Parser, Subcommand};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rolling_disk::check::{run_checks, Checked, Selection, Tally};
use rolling_disk::equations::Bench;
use rolling_disk::output::write_atomically;
use rolling_disk::run::{run, Run};
use rolling_disk::scene::{builtin::BUILTIN, Scene};
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "rolling-disk",
    version,
    about = "Reproduces and checks McDonald & McDonald (2001), The Rolling Motion of a Disk on a Horizontal Plane"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Integrates a scene (a YAML file, or a built-in scene by name) and prints a summary.
    Simulate {
        /// A scene file, or the name of a built-in scene (see `rolling-disk scenes`).
        scene: String,
        /// Also write the recorded trajectory as CSV to this file.
        #[arg(long, value_name = "FILE")]
        csv: Option<PathBuf>,
    },
    /// Lists the built-in scenes.
    Scenes,
    /// Checks the paper's equations and prose claims, each against an independent reference.
    Check {
        /// Only these: equation numbers, ranges and claim ids, comma-separated (e.g. 23-25,50).
        #[arg(long, value_name = "LIST")]
        only: Option<String>,
        /// Print the findings as JSON instead of a table.
        #[arg(long)]
        json: bool,
    },
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Simulate { scene, csv } => simulate(&scene, csv),
        Command::Scenes => scenes(),
        Command::Check { only, json } => check(only.as_deref(), json),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::FAILURE
        }
    }
}

fn scenes() -> Result<(), String> {
    for (name, src) in BUILTIN {
        let scene = Scene::parse(src, &format!("builtin:{name}")).map_err(|e| e.to_string())?;
        let first_sentence = scene.description.split(". ").next().unwrap_or("");
        println!("{name:28} {:13} {first_sentence}", scene.model.to_string());
    }
    Ok(())
}

fn progress_bar(t_end: f64) -> ProgressBar {
    let bar = ProgressBar::with_draw_target(Some(1000), ProgressDrawTarget::stderr());
    bar.set_style(
        ProgressStyle::with_template("{spinner} simulated {msg} [{bar:30}] {elapsed}")
            .expect("a valid template")
            .progress_chars("=> "),
    );
    bar.set_message(format!("0 of {t_end} s"));
    bar
}

fn simulate(name: &str, csv: Option<PathBuf>) -> Result<(), String> {
    let scene = Scene::load(name).map_err(|e| e.to_string())?;
    let bar = progress_bar(scene.stop.time);
    let t_end = scene.stop.time;
    let report = |t: f64| {
        bar.set_position((1000.0 * t / t_end) as u64);
        bar.set_message(format!("{t:.3} of {t_end} s"));
    };
    let result = run(&scene, Some(&report)).map_err(|e| format!("{}: {e}", scene.source));
    bar.finish_and_clear();
    let result = result?;
    print_summary(&scene, &result);
    if let Some(path) = csv {
        write_atomically(&path, result.to_csv().as_bytes())
            .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        println!(
            "trajectory: {} rows written to {}",
            result.rows.len(),
            path.display()
        );
    }
    if result.ending.is_complete() {
        Ok(())
    } else {
        Err(format!("the run did not finish: {}", result.ending))
    }
}

fn print_summary(scene: &Scene, r: &Run) {
    let (t_end, _) = (r.rows.last().map_or(0.0, |row| row[0]), ());
    let m = &r.last;
    println!("scene       {} ({})", scene.name, scene.source);
    println!("model       {}, {} states integrated", r.model, r.states);
    println!(
        "solver      {} rtol {:e} atol {:e}",
        scene.settings.method, scene.settings.rtol, scene.settings.atol
    );
    println!("ended       {} (t = {t_end:.6} s)", r.ending);
    println!(
        "final       alpha = {:.12} rad, alpha_dot = {:.12e} rad/s, Omega = {:.12} rad/s, omega_1 = {:.12} rad/s",
        m.alpha, m.alpha_dot, m.precession, m.spin
    );
    let label = if scene.dissipation.is_some() {
        "energy lost"
    } else {
        "energy drift"
    };
    println!(
        "{label:11} {:.3e} relative (E0 = {:.9e} J, E_end = {:.9e} J)",
        r.energy_change, r.energy.0, r.energy.1
    );
    println!(
        "work        {} right-hand-side evaluations ({} more to locate events and sample), {} accepted and {} rejected steps",
        r.stats.evaluations, r.stats.extra_evaluations, r.stats.accepted, r.stats.rejected
    );
}

fn check(only: Option<&str>, json: bool) -> Result<(), String> {
    let selection = match only {
        Some(text) => Selection::parse(text)?,
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
    let checked = run_checks(&Bench::default(), &selection, threads, &progress)?;
    bar.finish_and_clear();
    if json {
        println!(
            "{}",
            serde_json::to_string_pretty(&checked)
                .map_err(|e| format!("cannot write JSON: {e}"))?
        );
    } else {
        print_table(&checked);
    }
    let tally = Tally::of(&checked);
    if tally.not_run > 0 {
        return Err(format!(
            "{} check(s) could not run (see above)",
            tally.not_run
        ));
    }
    Ok(())
}

fn print_table(checked: &[Checked]) {
    println!(
        "{:<34} {:>3}  {:<17} {:>10} {:>10}  verdict",
        "checked", "sec", "method", "error", "tolerance"
    );
    for c in checked {
        match &c.finding {
            Ok(f) => println!(
                "{:<34} {:>3}  {:<17} {:>10.3e} {:>10.3e}  {}",
                c.subject.name(),
                c.section,
                f.method.to_string(),
                f.error,
                f.tolerance.value,
                f.verdict
            ),
            Err(e) => println!("{:<34} {:>3}  {e}", c.subject.name(), c.section),
        }
    }
    for c in checked {
        if let Ok(f) = &c.finding {
            if !f.verdict.passes() {
                println!(
                    "\n{} FAILS: {}\n  claimed {:.9e}, reference {:.9e}, error {:.3e} > {:.3e} ({})\n  at {}",
                    c.subject.name(),
                    f.compared,
                    f.claimed,
                    f.reference,
                    f.error,
                    f.tolerance.value,
                    f.tolerance.rule,
                    f.at
                );
            }
        }
    }
    let (eqs, claims): (Vec<&Checked>, Vec<&Checked>) = checked
        .iter()
        .partition(|c| matches!(c.subject, rolling_disk::check::Subject::Equation { .. }));
    let line = |what: &str, t: Tally, n: usize| {
        format!(
            "{n} {what}: {} hold, {} hold approximately, {} definitions, {} fail, {} could not run",
            t.holds, t.approximately, t.definitions, t.fails, t.not_run
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
