//! `rolling-disk manual`: the manual page (roff), generated from the command line's own
//! definition (clap_mangen): the program's page, or one command's.

use clap::CommandFactory;

/// The arguments of `rolling-disk manual`.
#[derive(clap::Args)]
pub struct Args {
    /// One command's page (e.g. `check`, `experiment`) instead of the program's. Read it with
    /// `rolling-disk manual | man -l -`.
    #[arg(value_name = "COMMAND")]
    pub command: Option<String>,
}

impl Args {
    /// Runs the command: the page on standard output.
    pub fn run(self) -> anyhow::Result<()> {
        let program = crate::Cli::command();
        let (page, title) = match &self.command {
            None => (program, "rolling-disk".to_string()),
            Some(name) => {
                let found = program
                    .get_subcommands()
                    .find(|c| c.get_name() == name)
                    .cloned();
                let Some(found) = found else {
                    let names: Vec<&str> =
                        program.get_subcommands().map(|c| c.get_name()).collect();
                    anyhow::bail!(
                        "manual: no command is called {name:?}; the commands are: {}",
                        names.join(", ")
                    );
                };
                (found, format!("rolling-disk-{name}"))
            }
        };
        let mut roff = Vec::new();
        clap_mangen::Man::new(page).title(title).render(&mut roff)?;
        print!("{}", String::from_utf8_lossy(&roff));
        Ok(())
    }
}
