//! The `rolling-disk` command line: parse, call the library, print. No physics here.

use clap::{Parser, Subcommand};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rolling_disk::check::{run_checks, Checked, Selection, Tally};
use rolling_disk::equations::{built_in_paper, Bench};
use rolling_disk::experiment;
use rolling_disk::output::{write_atomically, SetWriter};
use rolling_disk::paper::Paper;
use rolling_disk::precision::{self, Accuracy};
use rolling_disk::run::{run, Run};
use rolling_disk::scene::{builtin::BUILTIN, Scene};
use rolling_disk::solve::Ending;
use std::path::Path;
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
    /// Wall-time budget of each integration, in seconds (default 600): a run that takes longer
    /// ends and says so instead of running on.
    #[arg(long, global = true, value_name = "SECONDS")]
    max_seconds: Option<f64>,
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
        /// Also run the scene in another model and print the largest differences
        /// (`lab-frame`: the independent Newton-Euler model).
        #[arg(long, value_name = "MODEL")]
        compare: Option<String>,
    },
    /// Writes the reproduction report (HTML, LaTeX and/or JSON) from the built-in scenes.
    Report {
        /// Which formats to write.
        #[arg(long, value_enum, default_value = "all")]
        format: ReportFormat,
        /// The directory to write to.
        #[arg(long, value_name = "DIR", default_value = "report")]
        out: PathBuf,
        /// Integration accuracy of the checks (default: rtol 1e-12).
        #[arg(long, value_enum)]
        accuracy: Option<Accuracy>,
        /// Read the paper's equations from DIR/equations.yaml (and DIR/symbols.yaml,
        /// DIR/claims.yaml when present) instead of the built-in copy.
        #[arg(long, value_name = "DIR")]
        paper: Option<PathBuf>,
    },
    /// Regenerates figures alone, by the paper's names (see `--only`).
    Figures {
        /// Only these figures, comma-separated (default: all).
        #[arg(long, value_name = "NAMES")]
        only: Option<String>,
        /// The directory to write to.
        #[arg(long, value_name = "DIR", default_value = "figures")]
        out: PathBuf,
        /// File format.
        #[arg(long, value_enum, default_value = "svg")]
        format: FigureFormat,
    },
    /// Lists the built-in scenes, or prints one as a YAML template to edit.
    Scenes {
        /// Print this built-in scene as a ready-to-edit YAML template.
        #[arg(long, value_name = "NAME")]
        show: Option<String>,
    },
    /// The mutation suite: mutants of each printed equation (constants nudged, signs flipped, sin
    /// for cos, terms and factors dropped, powers raised, inequalities reversed) run through the
    /// equation's own check; prints how many each check kills and every survivor.
    Mutants {
        /// Only these equations: numbers and ranges, comma-separated (e.g. 23-25,50).
        #[arg(long, value_name = "LIST")]
        only: Option<String>,
        /// Print the scores as JSON.
        #[arg(long)]
        json: bool,
        /// Mutate the equations of DIR/equations.yaml instead of the built-in paper.
        #[arg(long, value_name = "DIR")]
        paper: Option<PathBuf>,
    },
    /// Checks the paper's equations and prose claims, each against an independent reference.
    Check {
        /// Only these: equation numbers, ranges and claim ids, comma-separated, with or without
        /// a prefix (e.g. 23-25,eq50,claim:k-uniform-disk).
        #[arg(long, value_name = "LIST")]
        only: Option<String>,
        /// Print the findings as JSON instead of a table.
        #[arg(long)]
        json: bool,
        /// Integration accuracy of the checks (fast: DOPRI5 at rtol 1e-6; standard and high:
        /// DOP853 at 1e-10 and 1e-13; each prints what it reaches on the benchmark scene);
        /// without it, DOP853 at rtol 1e-12, the accuracy the tolerances were designed at.
        #[arg(long, value_enum)]
        accuracy: Option<Accuracy>,
        /// Check the equations of DIR/equations.yaml (and DIR/symbols.yaml, DIR/claims.yaml
        /// when present) instead of the built-in copy of the paper: an edited equation is
        /// re-checked without rebuilding.
        #[arg(long, value_name = "DIR")]
        paper: Option<PathBuf>,
    },
    /// Measures speed against accuracy for a scene (default: the benchmark scene): error
    /// against a validated reference, right-hand-side evaluations and wall time, per method.
    Precision {
        /// A scene file or built-in scene name.
        #[arg(default_value = "benchmark")]
        scene: String,
        /// Print the study as JSON.
        #[arg(long)]
        json: bool,
        /// A coarse sweep timed once (seconds instead of a minute).
        #[arg(long)]
        quick: bool,
        /// Also name the cheapest method and tolerance reaching this accuracy (e.g. 1e-8).
        #[arg(long, value_name = "ERROR")]
        target: Option<f64>,
    },
    /// The paper's experiment (section 11): a simulated light signal, and the analysis of a
    /// scope CSV (synthetic or real).
    #[command(subcommand)]
    Experiment(ExperimentCommand),
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum ReportFormat {
    Html,
    Latex,
    Json,
    All,
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum FigureFormat {
    Svg,
    Png,
}

#[derive(Subcommand)]
enum ExperimentCommand {
    /// Simulates a recording of a spin-down scene: the scope's light signal as CSV (time in s,
    /// signal in V), or the disk's sound as WAV, with optional bench artifacts.
    Simulate {
        /// A dissipative scene (file or built-in name), e.g. spin-down.
        #[arg(default_value = "spin-down")]
        scene: String,
        /// Write the scope's light signal to this CSV.
        #[arg(long, value_name = "FILE", required_unless_present = "wav")]
        csv: Option<PathBuf>,
        /// Write the disk's sound (16-bit mono, 8 kHz) to this WAV.
        #[arg(long, value_name = "FILE", conflicts_with = "csv")]
        wav: Option<PathBuf>,
        #[command(flatten)]
        artifacts: ArtifactArgs,
    },
    /// Analyses a recording: a scope CSV (peak times, eqs 84-85) or a WAV (frequency track,
    /// eq 79); fits beta, t0 and C with uncertainties, compares laws, and refuses with a reason
    /// (non-zero exit) what is not a spin-down.
    Analyze {
        /// The recording: a CSV (time and signal columns) or a .wav file.
        #[arg(value_name = "FILE")]
        csv: PathBuf,
        /// Also write analysis.json, peaks.csv, omega.csv and omega_dot.csv here (CSV input).
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
        /// Print the analysis as JSON.
        #[arg(long)]
        json: bool,
    },
}

/// What a bench recording adds (all off by default).
#[derive(clap::Args)]
struct ArtifactArgs {
    /// All of a realistic bench's artifacts: drift 5 %, 50 Hz hum 2 %, clipping of the top
    /// 15 %, 2 glitches/s, 1 % dropped samples (of the signal's span).
    #[arg(long)]
    realistic: bool,
    /// Baseline drift, rms, as a fraction of the signal's span.
    #[arg(long, value_name = "FRACTION")]
    drift: Option<f64>,
    /// Mains hum amplitude as a fraction of the signal's span.
    #[arg(long, value_name = "FRACTION")]
    hum: Option<f64>,
    /// Mains frequency (Hz).
    #[arg(long, value_name = "HZ", default_value_t = 50.0)]
    mains: f64,
    /// Clip above this fraction of the signal's range.
    #[arg(long, value_name = "FRACTION")]
    clip: Option<f64>,
    /// Isolated glitches per second.
    #[arg(long, value_name = "RATE")]
    glitches: Option<f64>,
    /// Fraction of samples dropped.
    #[arg(long, value_name = "FRACTION")]
    dropped: Option<f64>,
    /// Noise seed of the scope or microphone, and of the artifacts.
    #[arg(long, default_value_t = 1)]
    seed: u64,
}

impl ArtifactArgs {
    /// The artifacts for a signal of peak-to-peak `span`.
    fn artifacts(&self, span: f64) -> experiment::Artifacts {
        let mut a = if self.realistic {
            experiment::Artifacts::realistic(span, self.seed)
        } else {
            experiment::Artifacts {
                seed: self.seed,
                ..experiment::Artifacts::none()
            }
        };
        a.mains = self.mains;
        if let Some(x) = self.drift {
            a.drift = x * span;
        }
        if let Some(x) = self.hum {
            a.hum = x * span;
        }
        if let Some(x) = self.clip {
            a.clip = x;
        }
        if let Some(x) = self.glitches {
            a.glitches_per_s = x;
            if a.glitch == 0.0 {
                a.glitch = 0.5 * span;
            }
        }
        if let Some(x) = self.dropped {
            a.dropped = x;
        }
        a
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    if let Some(seconds) = cli.max_seconds {
        if let Err(message) = rolling_disk::budget::set_wall_seconds(seconds) {
            eprintln!("error: {message}");
            return ExitCode::FAILURE;
        }
    }
    let result = match cli.command {
        Command::Simulate {
            scene,
            csv,
            compare,
        } => simulate(&scene, csv, compare.as_deref()),
        Command::Scenes { show: Some(name) } => rolling_disk::select::scene_template(&name)
            .map(|t| print!("{t}"))
            .map_err(anyhow::Error::from),
        Command::Scenes { show: None } => scenes(),
        Command::Mutants { only, json, paper } => mutants(only.as_deref(), json, paper.as_deref()),
        Command::Report {
            format,
            out,
            accuracy,
            paper,
        } => report(format, &out, accuracy, paper.as_deref()),
        Command::Figures { only, out, format } => figures(only.as_deref(), &out, format),
        Command::Check {
            only,
            json,
            accuracy,
            paper,
        } => check(only.as_deref(), json, accuracy, paper.as_deref()),
        Command::Precision {
            scene,
            json,
            quick,
            target,
        } => precision(&scene, json, quick, target),
        Command::Experiment(ExperimentCommand::Simulate {
            scene,
            csv,
            wav,
            artifacts,
        }) => experiment_simulate(&scene, csv.as_deref(), wav.as_deref(), &artifacts),
        Command::Experiment(ExperimentCommand::Analyze { csv, out, json }) => {
            experiment_analyze(&csv, out.as_deref(), json)
        }
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::FAILURE
        }
    }
}

fn mutants(only: Option<&str>, json: bool, paper: Option<&Path>) -> anyhow::Result<()> {
    let bench = bench_for(None, load_paper(paper)?);
    let numbers: Vec<u32> = match only {
        None => rolling_disk::equations::equations()
            .iter()
            .map(|e| e.number)
            .collect(),
        Some(text) => {
            let selection = rolling_disk::select::parse_only(text)?;
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
    let scores = rolling_disk::mutation::mutation_scores(&bench, &numbers, &progress);
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

fn scenes() -> anyhow::Result<()> {
    for (name, src) in BUILTIN {
        let scene = Scene::parse(src, &format!("builtin:{name}"))?;
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

fn simulate(name: &str, csv: Option<PathBuf>, compare: Option<&str>) -> anyhow::Result<()> {
    let scene = Scene::load(name)?;
    if let Some(other) = compare {
        let other = match other {
            "lab-frame" => rolling_disk::compare::lab_frame_for(scene.model)?,
            _ => {
                return Err(anyhow::anyhow!(
                    "--compare: {other} is not a model to compare with; use lab-frame"
                ))
            }
        };
        let c = rolling_disk::compare::compare(&scene, other)?;
        println!("scene {}: {} against {}", c.scene, c.model, c.other);
        println!(
            "{:<24} {:>14} {:>14} {:>10}",
            "quantity", "largest diff", "of its range", "at t (s)"
        );
        for d in &c.differences {
            let relative = d
                .relative
                .map_or("- (zero)".to_string(), |r| format!("{r:.3e}"));
            println!(
                "{:<24} {:>14.3e} {:>14} {:>10.4}",
                d.column, d.largest, relative, d.at_time
            );
        }
        return Ok(());
    }
    let bar = progress_bar(scene.stop.time);
    let t_end = scene.stop.time;
    let report = |t: f64| {
        bar.set_position((1000.0 * t / t_end) as u64);
        bar.set_message(format!("{t:.3} of {t_end} s"));
    };
    let result = run(&scene, Some(&report)).map_err(|e| anyhow::anyhow!("{}: {e}", scene.source));
    bar.finish_and_clear();
    let result = result?;
    if matches!(
        result.ending,
        Ending::Unstable { .. } | Ending::NonFinite { .. }
    ) {
        // No number of such a run means anything: say why, print none.
        return Err(anyhow::anyhow!("{}: {}", scene.source, result.ending));
    }
    print_summary(&scene, &result);
    if let Some(path) = csv {
        write_atomically(&path, result.to_csv().as_bytes())
            .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", path.display()))?;
        println!(
            "trajectory: {} rows written to {}",
            result.rows.len(),
            path.display()
        );
    }
    if result.ending.is_complete() {
        Ok(())
    } else {
        Err(anyhow::anyhow!("the run did not finish: {}", result.ending))
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
    let label = if scene.dissipation.is_some() || scene.friction.is_some() {
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
    if scene.model == rolling_disk::scene::ModelKind::Sliding {
        println!(
            "contact     {} switches and impacts",
            r.contact_events.len()
        );
        for e in &r.contact_events {
            println!("  t = {:.9} s  {} -> {}: {}", e.t, e.from, e.to, e.what);
        }
    }
}

/// The paper to check: the built-in copy, or the one in `dir` (read once for the whole run).
fn load_paper(dir: Option<&Path>) -> anyhow::Result<&'static Paper> {
    match dir {
        None => Ok(built_in_paper()),
        Some(d) => match Paper::from_dir(d) {
            Ok(p) => Ok(Box::leak(Box::new(p))),
            Err(e) => Err(anyhow::anyhow!("--paper {}: {e}", d.display())),
        },
    }
}

fn bench_for(accuracy: Option<Accuracy>, paper: &'static Paper) -> Bench<'static> {
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

fn report(
    format: ReportFormat,
    out: &Path,
    accuracy: Option<Accuracy>,
    paper: Option<&Path>,
) -> anyhow::Result<()> {
    use rolling_disk::report::{build::build, render};
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
        "{} equations checked: {} hold, {} hold approximately, {} definitions, {} fail; {} claims fail",
        t.holds + t.approximately + t.definitions + t.fails + t.not_run,
        t.holds,
        t.approximately,
        t.definitions,
        t.fails,
        report.summary.claims.fails
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

fn figures(only: Option<&str>, out: &Path, format: FigureFormat) -> anyhow::Result<()> {
    use rolling_disk::report::pipeline::{compute, RunConfig};
    let names: Vec<&str> = rolling_disk::figures::NAMES.to_vec();
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
                "--only: no figure is called {w}; the figures are: {}",
                names.join(", ")
            ));
        }
    }
    std::fs::create_dir_all(out)
        .map_err(|e| anyhow::anyhow!("cannot create {}: {e}", out.display()))?;
    // Only the studies the wanted figures are drawn from, each once.
    let config = RunConfig::figures(rolling_disk::equations::Bench::default(), &wanted)?;
    let results = compute(&config, &|s: &str| eprintln!("figures: {s}"))?;
    let all = rolling_disk::figures::some(&wanted, &results)?;
    for f in &all {
        let path = match format {
            FigureFormat::Svg => {
                let path = out.join(format!("{}.svg", f.name));
                let svg = f.drawing.to_svg(760, 480)?;
                write_atomically(&path, svg.as_bytes())
                    .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", path.display()))?;
                path
            }
            FigureFormat::Png => {
                let path = out.join(format!("{}.png", f.name));
                let tmp = out.join(format!(".{}.{}.png", f.name, std::process::id()));
                f.drawing.to_png(&tmp)?;
                std::fs::rename(&tmp, &path)
                    .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", path.display()))?;
                path
            }
        };
        println!("wrote {}", path.display());
    }
    Ok(())
}

fn check(
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
        Some(text) => rolling_disk::select::parse_only(text)?,
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
        use rolling_disk::report::json;
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
const PAPER_TITLE: &str =
    "A. J. McDonald and K. T. McDonald, The Rolling Motion of a Disk on a Horizontal Plane (2001)";

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
                if let Some(cause) = &c.cause {
                    println!("  cause: {}", cause.describe());
                }
            }
        }
    }
    print_root_causes(checked);
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

/// The failing equations grouped by root cause: each root cause with the equations that inherit
/// its error, then those whose cause could not be settled.
fn print_root_causes(checked: &[Checked]) {
    use rolling_disk::cause::{consequences, Cause};
    let causes: std::collections::BTreeMap<u32, Cause> = checked
        .iter()
        .filter_map(|c| match (&c.subject, &c.cause) {
            (rolling_disk::check::Subject::Equation { number, .. }, Some(cause)) => {
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

/// States what a preset actually reaches, measured on the benchmark scene against the validated
/// reference, and what it costs.
fn print_preset_accuracy(a: Accuracy) -> anyhow::Result<()> {
    let scene = Scene::load("benchmark")?;
    let reference = precision::Reference::compute(&scene, &precision::ReferenceOptions::default())?;
    let m = precision::measure_preset(&scene, a, &reference, &precision::Timing::default())?;
    println!(
        "accuracy {a}: on the benchmark scene this preset reaches {:.1e} over the trajectory \
         ({:.1e} at the end; reference uncertainty {:.1e}) in {:.2e} s and {} evaluations",
        m.trajectory_error, m.final_error, m.reference_uncertainty, m.wall_seconds, m.evaluations
    );
    Ok(())
}

fn precision(name: &str, json: bool, quick: bool, target: Option<f64>) -> anyhow::Result<()> {
    let scene = Scene::load(name)?;
    let opts = if quick {
        precision::StudyOptions::quick()
    } else {
        precision::StudyOptions::default()
    };
    eprintln!(
        "measuring {} (this takes {})...",
        scene.name,
        if quick { "seconds" } else { "about a minute" }
    );
    let progress = |done: usize, total: usize, what: &str| {
        eprintln!("  [{done:>2}/{total}] {what}");
    };
    let study = precision::study_with_progress(&scene, &opts, &progress)
        .map_err(|e| anyhow::anyhow!("{}: {e}", scene.source))?;
    if json {
        println!("{}", serde_json::to_string_pretty(&study)?);
        return Ok(());
    }
    let r = &study.reference;
    println!(
        "scene {}: reference {} (uncertainty {:.1e})",
        study.scene,
        precision::reference::label(&r.trace.settings),
        r.uncertainty
    );
    println!(
        "{:<22} {:>11} {:>11} {:>12} {:>12}  ending",
        "method", "evaluations", "wall (s)", "final error", "trajectory"
    );
    for s in &study.series {
        for p in &s.points {
            println!(
                "{:<22} {:>11} {:>11.3e} {:>12.2e} {:>12.2e}  {}",
                p.label, p.evaluations, p.wall_seconds, p.final_error, p.trajectory_error, p.ending
            );
        }
        match s.observed_order {
            Some(o) => println!(
                "  {}: observed order {o:.2} (nominal {})",
                s.method, s.nominal_order
            ),
            None => println!("  {}: too few resolved points to fit an order", s.method),
        }
    }
    if let Some(target) = target {
        match precision::cheapest(&study, target, precision::Cost::Evaluations) {
            Some(p) => println!(
                "cheapest to reach {target:e}: {} ({} evaluations, {:.2e} s)",
                p.label, p.evaluations, p.wall_seconds
            ),
            None => println!(
                "no setting reaches {target:e} resolvably (the reference's own uncertainty is {:.1e})",
                r.uncertainty
            ),
        }
    }
    Ok(())
}

fn experiment_simulate(
    name: &str,
    csv: Option<&Path>,
    wav: Option<&Path>,
    args: &ArtifactArgs,
) -> anyhow::Result<()> {
    let scene = Scene::load(name)?;
    eprintln!("simulating the recording of {}...", scene.name);
    let (path, bytes, trace) = if let Some(path) = wav {
        let mic = experiment::Microphone {
            seed: args.seed,
            ..experiment::Microphone::default()
        };
        let a = args.artifacts(2.0 * mic.amplitude);
        let trace = experiment::simulate_sound(&scene, &mic, &a)?;
        let bytes = experiment::wav_bytes(&trace.v, mic.sample_rate)
            .map_err(|e| anyhow::anyhow!("cannot encode the WAV: {e}"))?;
        (path, bytes, trace)
    } else if let Some(path) = csv {
        let mut light = experiment::LightModel::default();
        light.scope.seed = args.seed;
        let trace = experiment::simulate_trace(&scene, &light)?;
        let trace = trace.with_artifacts(&args.artifacts(light.gain))?;
        let bytes = trace.to_csv().into_bytes();
        (path, bytes, trace)
    } else {
        return Err(anyhow::anyhow!("give --csv FILE or --wav FILE"));
    };
    write_atomically(path, &bytes)
        .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", path.display()))?;
    println!("{} samples written to {}", trace.t.len(), path.display());
    if let Some(t) = &trace.truth {
        println!(
            "truth: beta = {}, t0 = {:.6} s ({})",
            t.beta, t.t0, t.origin
        );
    }
    Ok(())
}

fn experiment_analyze(csv: &Path, out: Option<&Path>, json: bool) -> anyhow::Result<()> {
    let is_wav = csv
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("wav"));
    if is_wav {
        let trace = experiment::read_wav(csv)?;
        let a = experiment::analyze_sound(
            &trace,
            &experiment::TrackSettings::default(),
            &experiment::plausibility::Plausibility::default(),
        )?;
        if json {
            println!("{}", a.to_json());
        } else {
            println!("{a}");
        }
        if let Some(dir) = out {
            for p in experiment::write_sound_analysis(&a, dir)? {
                eprintln!("wrote {}", p.display());
            }
        }
        return Ok(());
    }
    let trace = experiment::read_trace(csv)?;
    let analysis = experiment::analyze(&trace, &experiment::AnalysisSettings::default())?;
    if json {
        println!("{}", analysis.to_json());
    } else {
        println!("{analysis}");
    }
    if let Some(dir) = out {
        std::fs::create_dir_all(dir)
            .map_err(|e| anyhow::anyhow!("cannot create {}: {e}", dir.display()))?;
        let written = experiment::write_analysis(&analysis, dir)?;
        for p in written {
            eprintln!("wrote {}", p.display());
        }
    }
    Ok(())
}
