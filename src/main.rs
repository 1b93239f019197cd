//! The `rolling-disk` command line: parse, call the library, print. No physics here.

use ::checks::check::{run_checks, Checked, Selection, Tally};
use ::checks::equations::{built_in_paper, Bench};
use ::studies::precision::{self, Accuracy};
use clap::{Parser, Subcommand};
use files::atomic::write_atomically;
use files::output::SetWriter;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use paper::Paper;
use physics::run::{run, Run};
use physics::scene::{builtin::BUILTIN, Scene};
use physics::solve::Ending;
use std::path::Path;
use std::path::PathBuf;
use std::process::ExitCode;

/// `print!` through [`cli::stdout::write`]: a closed pipe ends the program quietly.
macro_rules! print {
    ($($arg:tt)*) => { $crate::cli::stdout::write(format_args!($($arg)*)) };
}

/// `println!` through [`cli::stdout::write`]: a closed pipe ends the program quietly.
macro_rules! println {
    () => { $crate::cli::stdout::write(format_args!("\n")) };
    ($($arg:tt)*) => {
        $crate::cli::stdout::write(format_args!("{}\n", format_args!($($arg)*)))
    };
}

mod cli;
use cli::*;

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
        /// A coarse sweep, each setting timed once.
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
    /// An independent program as a reference (M. Batista's Euler disk simulation, built and run
    /// by scripts/peer_run.sh): write its input for a scene, compare its output with this tool.
    #[command(subcommand)]
    Peer(PeerCommand),
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
enum PeerCommand {
    /// Writes the peer's response file for a sliding scene with a thickness.
    Export {
        /// A scene file, or the name of a built-in scene.
        scene: String,
        /// Write to this file instead of standard output.
        #[arg(long, value_name = "FILE")]
        out: Option<PathBuf>,
    },
    /// Reads the peer's result.txt, runs the scene here, prints the largest differences.
    Compare {
        /// The scene the peer ran (as exported).
        scene: String,
        /// The peer's result.txt.
        result: PathBuf,
        /// Print the comparison as JSON.
        #[arg(long)]
        json: bool,
    },
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
        /// Write the disk's sound (mono) to this file, as WAV or FLAC (see --format).
        #[arg(long, value_name = "FILE", conflicts_with = "csv")]
        wav: Option<PathBuf>,
        /// The sound's sample rate (S/s), 1000 to 384000.
        #[arg(long, value_name = "R", default_value_t = 48000)]
        rate: u32,
        /// The sound's coding: 16-bit WAV, 24-bit WAV, 32-bit float WAV, or 16-bit FLAC.
        #[arg(long, value_enum, default_value = "wav")]
        format: experiment::SoundFormat,
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
        /// For a sound recording: the channel analysed, from 1, or `mix` for their mean.
        #[arg(long, value_name = "N|mix", default_value = "mix")]
        channel: String,
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
        if let Err(message) = physics::budget::set_wall_seconds(seconds) {
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
        Command::Scenes { show: Some(name) } => ::checks::select::scene_template(&name)
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
            rate,
            format,
            artifacts,
        }) => experiment_simulate(
            &scene,
            csv.as_deref(),
            wav.as_deref().map(|w| (w, rate, format)),
            &artifacts,
        ),
        Command::Peer(PeerCommand::Export { scene, out }) => peer_export(&scene, out.as_deref()),
        Command::Peer(PeerCommand::Compare {
            scene,
            result,
            json,
        }) => peer_compare(&scene, &result, json),
        Command::Experiment(ExperimentCommand::Analyze {
            csv,
            out,
            json,
            channel,
        }) => experiment_analyze(&csv, out.as_deref(), json, &channel),
    };
    cli::stdout::flush();
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::FAILURE
        }
    }
}
