//! The `rolling-disk` command line: parse, call the library, print. No physics here. The
//! binary (`src/main.rs`) runs [`main`]; the fuzz target of the arguments parses them with
//! [`parse`].

use clap::{Parser, Subcommand};
use std::ffi::OsString;
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

pub mod cli;

/// The program's version and the commit it is built from ([`report::TOOL_VERSION`]).
pub const VERSION: &str = report::TOOL_VERSION;

/// What `--version` prints after the program's name: the version and commit, then the SHA-256
/// of the built-in paper (the hash every output's provenance names for it). `-V` prints the
/// first line only.
static LONG_VERSION: std::sync::LazyLock<String> = std::sync::LazyLock::new(|| {
    format!(
        "{VERSION}\nbuilt-in paper: sha256 {}",
        paper::Paper::built_in_sha256()
    )
});

/// The command line.
#[derive(Parser)]
#[command(
    name = "rolling-disk",
    version = VERSION,
    long_version = LONG_VERSION.as_str(),
    about = "Reproduces and checks McDonald & McDonald (2001), The Rolling Motion of a Disk on a Horizontal Plane"
)]
pub struct Cli {
    #[command(subcommand)]
    command: Command,
    /// Wall-time budget of each integration and of each analysis or simulation of a recording,
    /// in seconds (default 600): work that takes longer ends and says so instead of running on.
    #[arg(long, global = true, value_name = "SECONDS", allow_negative_numbers = true,
          value_parser = cli::ranges::seconds)]
    max_seconds: Option<f64>,
    /// Prints only what a command is for (its results, its data), not what it wrote where nor
    /// its progress; errors are still said.
    #[arg(long, short, global = true)]
    quiet: bool,
}

/// The commands.
#[derive(Subcommand)]
pub enum Command {
    /// Integrates a scene (a YAML file, or a built-in scene by name) and prints a summary.
    Simulate(cli::simulate::Args),
    /// Writes the reproduction report (HTML, LaTeX and/or JSON) from the built-in scenes.
    Report(cli::report::Args),
    /// Regenerates figures alone, by the paper's names (see `--only`).
    Figures(cli::figures::Args),
    /// Lists the built-in scenes, or prints one as a YAML template to edit.
    Scenes(cli::scenes::Args),
    /// The mutation suite: mutants of each printed equation (constants nudged, signs flipped, sin
    /// for cos, terms and factors dropped, powers raised, inequalities reversed) run through the
    /// equation's own check; prints how many each check kills and every survivor.
    Mutants(cli::mutants::Args),
    /// Checks the paper's equations and prose claims, each against an independent reference.
    Check(cli::check::Args),
    /// Lists the quantities a claim of claims.yaml can name to be checked with no Rust: each with
    /// its parameters, unit, method and tolerance.
    Quantities(cli::quantities::Args),
    /// Measures speed against accuracy for a scene (default: the benchmark scene): error
    /// against a validated reference, right-hand-side evaluations and wall time, per method.
    Precision(cli::precision::Args),
    /// The paper's experiment (section 11): a simulated light signal, and the analysis of a
    /// scope CSV (synthetic or real).
    #[command(subcommand)]
    Experiment(cli::experiment::Command),
    /// An independent program as a reference (M. Batista's Euler disk simulation, built and run
    /// by scripts/peer_run.sh): write its input for a scene, compare its output with this tool.
    #[command(subcommand)]
    Peer(cli::peer::Command),
    /// Prints the completion script of a shell (bash, zsh, fish, elvish, powershell).
    Completions(cli::completions::Args),
    /// Prints the manual page (roff), of the program or of one command.
    Manual(cli::manual::Args),
}

/// Parses `args` (the program's name first) as the command line.
pub fn parse<I, T>(args: I) -> Result<Cli, clap::Error>
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    Cli::try_parse_from(args)
}

/// Runs the command line of this process.
pub fn main() -> ExitCode {
    let cli = Cli::parse();
    cli::stdout::set_quiet(cli.quiet);
    if let Some(seconds) = cli.max_seconds {
        if let Err(message) = physics::budget::set_wall_seconds(seconds) {
            eprintln!("error: {message}");
            return ExitCode::FAILURE;
        }
    }
    // Commands whose studies or checks speak of their own scenes when cut short.
    let budget_said = matches!(
        cli.command,
        Command::Report(_) | Command::Figures(_) | Command::Check(_)
    );
    let result = match cli.command {
        Command::Simulate(a) => a.run(),
        Command::Report(a) => a.run(),
        Command::Figures(a) => a.run(),
        Command::Scenes(a) => a.run(),
        Command::Mutants(a) => a.run(),
        Command::Check(a) => a.run(),
        Command::Quantities(a) => a.run(),
        Command::Precision(a) => a.run(),
        Command::Experiment(c) => c.run(),
        Command::Peer(c) => c.run(),
        Command::Completions(a) => a.run(),
        Command::Manual(a) => a.run(),
    };
    cli::stdout::flush();
    // Work cut short by the budget is said as that, with the stage and the budget that does:
    // always when the command ended as if it were not, and in place of a study's or a check's
    // own error (whose advice would be about its scene); a simulation says where its run ended.
    let result = match (physics::budget::overrun(), &result) {
        (Some(o), Err(_)) if budget_said => Err(anyhow::Error::from(o)),
        (Some(o), Ok(())) => Err(anyhow::Error::from(o)),
        _ => result,
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::from(cli::exit::code_of(&message))
        }
    }
}
