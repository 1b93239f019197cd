//! `rolling-disk completions SHELL`: the shell's completion script, generated from the command
//! line's own definition (clap_complete), so that it names every command and option there is.

use clap::CommandFactory;

/// The arguments of `rolling-disk completions`.
#[derive(clap::Args)]
pub struct Args {
    /// The shell: bash, zsh, fish, elvish or powershell. Install, e.g. for bash:
    /// `rolling-disk completions bash > ~/.local/share/bash-completion/completions/rolling-disk`.
    #[arg(value_enum)]
    pub shell: clap_complete::Shell,
}

impl Args {
    /// Runs the command: the script on standard output.
    pub fn run(self) -> anyhow::Result<()> {
        let mut script = Vec::new();
        clap_complete::generate(
            self.shell,
            &mut crate::Cli::command(),
            "rolling-disk",
            &mut script,
        );
        print!("{}", String::from_utf8_lossy(&script));
        Ok(())
    }
}
