//! `rolling-disk scenes`: the built-in scenes, or one as a YAML template to edit.

use physics::scene::builtin::BUILTIN;
use physics::scene::Scene;

/// The arguments of `rolling-disk scenes`.
#[derive(clap::Args)]
pub struct Args {
    /// Print this built-in scene as a ready-to-edit YAML template.
    #[arg(long, value_name = "NAME")]
    pub show: Option<String>,
}

impl Args {
    /// Runs the command.
    pub fn run(self) -> anyhow::Result<()> {
        match self.show {
            Some(name) => checks::select::scene_template(&name)
                .map(|t| print!("{t}"))
                .map_err(anyhow::Error::from),
            None => scenes(),
        }
    }
}

fn scenes() -> anyhow::Result<()> {
    for (name, src) in BUILTIN {
        let scene = Scene::parse(src, &format!("builtin:{name}"))?;
        let first_sentence = scene.description.split(". ").next().unwrap_or("");
        println!("{name:28} {:13} {first_sentence}", scene.model.to_string());
    }
    Ok(())
}
