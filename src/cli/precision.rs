//! `rolling-disk precision`: the speed/accuracy study of a scene, and what a preset reaches.

use physics::scene::Scene;
use studies::precision;
use studies::precision::Accuracy;

/// The arguments of `rolling-disk precision`.
#[derive(clap::Args)]
pub struct Args {
    /// A scene file or built-in scene name.
    #[arg(default_value = "benchmark")]
    #[arg(value_parser = crate::cli::utf8::scene())]
    pub scene: String,
    /// Print the study as JSON.
    #[arg(long)]
    pub json: bool,
    /// A coarse sweep, each setting timed once.
    #[arg(long)]
    pub quick: bool,
    /// Also name the cheapest method and tolerance reaching this accuracy (e.g. 1e-8).
    #[arg(long, value_name = "ERROR", allow_negative_numbers = true)]
    pub target: Option<f64>,
}

impl Args {
    /// Runs the command.
    pub fn run(self) -> anyhow::Result<()> {
        precision(&self.scene, self.json, self.quick, self.target)
    }
}

/// States what a preset actually reaches, measured on the benchmark scene against the validated
/// reference, and what it costs.
pub(crate) fn print_preset_accuracy(a: Accuracy) -> anyhow::Result<()> {
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
    if let Some(t) = target {
        if !(t.is_finite() && t > 0.0 && t < 1.0) {
            return Err(anyhow::anyhow!(
                "--target {t}: give the error to reach as a number between 0 and 1, such as 1e-8"
            ));
        }
    }
    let scene = crate::cli::stdin::scene(name)?;
    let opts = if quick {
        precision::StudyOptions::quick()
    } else {
        precision::StudyOptions::default()
    };
    crate::cli::stdout::progress(&format!("measuring {}, progress below...", scene.name));
    let progress = |done: usize, total: usize, what: &str| {
        crate::cli::stdout::progress(&format!("  [{done:>2}/{total}] {what}"));
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
        "{:<22} {:>11} {:>11} {:>11} {:>12} {:>12}  ending",
        "method", "evaluations", "wall (s)", "sampled (s)", "final error", "trajectory"
    );
    for s in &study.series {
        for p in &s.points {
            let sampled = p
                .sampled_wall_seconds
                .map_or_else(|| "-".to_string(), |w| format!("{w:.3e}"));
            println!(
                "{:<22} {:>11} {:>11.3e} {:>11} {:>12.2e} {:>12.2e}  {}",
                p.label,
                p.evaluations,
                p.wall_seconds,
                sampled,
                p.final_error,
                p.trajectory_error,
                p.ending
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
