//! `rolling-disk scenes`: the built-in scenes (a table, or JSON), or one as a YAML template to
//! edit.

use physics::scene::builtin::BUILTIN;
use physics::scene::Scene;

/// The arguments of `rolling-disk scenes`.
#[derive(clap::Args)]
pub struct Args {
    /// Print this built-in scene as a ready-to-edit YAML template.
    #[arg(long, value_name = "NAME", conflicts_with = "json")]
    pub show: Option<String>,
    /// Print the list as JSON (`schemas/scenes.schema.json`): each scene's name, model and
    /// description.
    #[arg(long)]
    pub json: bool,
}

impl Args {
    /// Runs the command.
    pub fn run(self) -> anyhow::Result<()> {
        match self.show {
            Some(name) => checks::select::scene_template(&name)
                .map(|t| print!("{t}"))
                .map_err(anyhow::Error::from),
            None if self.json => scenes_json(),
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

/// The identifier of `scenes --json`'s schema.
pub const SCENES_SCHEMA_ID: &str = "https://rolling-disk.invalid/schemas/scenes.schema.json";

fn scenes_json() -> anyhow::Result<()> {
    let mut list = Vec::new();
    for (name, src) in BUILTIN {
        let scene = Scene::parse(src, &format!("builtin:{name}"))?;
        list.push(serde_json::json!({
            "name": name,
            "model": scene.model.to_string(),
            "description": scene.description.trim(),
        }));
    }
    let doc = serde_json::json!({
        "schema": SCENES_SCHEMA_ID,
        "tool": { "name": "rolling-disk", "version": crate::VERSION },
        "scenes": list,
    });
    println!("{}", serde_json::to_string_pretty(&doc)?);
    Ok(())
}
