//! `rolling-disk simulate`: one run of a scene with its progress bar and summary.

use crate::cli::row_stream::RowStream;
use crate::cli::trace_against::{Recorded, TraceAgainst};
use crate::cli::{exit, stdin, stdout};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use physics::run::{columns, run_streamed_rows, Run};
use physics::scene::Scene;
use physics::solve::Ending;
use std::path::{Path, PathBuf};

/// The arguments of `rolling-disk simulate`.
#[derive(clap::Args)]
pub struct Args {
    /// A scene file, or the name of a built-in scene (see `rolling-disk scenes`).
    #[arg(value_parser = crate::cli::utf8::scene())]
    pub scene: String,
    /// Also write the recorded trajectory as CSV to this file.
    #[arg(long, value_name = "FILE")]
    pub csv: Option<PathBuf>,
    /// Also run the scene in another model and print the largest differences
    /// (`lab-frame`: the independent Newton-Euler model).
    #[arg(long, value_name = "MODEL", conflicts_with_all = ["json", "against"])]
    pub compare: Option<String>,
    /// Print the summary as JSON (`schemas/simulate.schema.json`): rows, events, the final
    /// state, why the run stopped.
    #[arg(long)]
    pub json: bool,
    /// Compare the run, row by row, with one recorded by `--csv` (`-`: standard input): say the
    /// first row and column beyond the scene's atol + rtol x |recorded| and exit with status 3
    /// if any is.
    #[arg(long, value_name = "FILE.csv")]
    pub against: Option<PathBuf>,
}

impl Args {
    /// Runs the command.
    pub fn run(self) -> anyhow::Result<()> {
        if self.compare.is_some() {
            return compare(&self.scene, self.csv.as_deref(), self.compare.as_deref());
        }
        simulate(&self.scene, self.csv, self.json, self.against.as_deref())
    }
}

pub(crate) fn progress_bar(t_end: f64) -> ProgressBar {
    let bar = ProgressBar::with_draw_target(Some(1000), ProgressDrawTarget::stderr());
    bar.set_style(
        ProgressStyle::with_template("{spinner} simulated {msg} [{bar:30}] {elapsed}")
            .expect("a valid template")
            .progress_chars("=> "),
    );
    bar.set_message(format!("0 of {t_end} s"));
    bar
}

/// A spinner on stderr naming the stage of work that is not an integration (analysing a
/// recording, simulating one), drawn only once the work has taken a second (and, as every bar
/// here, only when stderr is a terminal).
pub(crate) fn stage_spinner() -> ProgressBar {
    let bar = ProgressBar::hidden();
    bar.set_style(
        ProgressStyle::with_template("{spinner} {msg} {elapsed}").expect("a valid template"),
    );
    let late = bar.clone();
    std::thread::spawn(move || {
        std::thread::sleep(std::time::Duration::from_secs(1));
        if !late.is_finished() {
            late.set_draw_target(ProgressDrawTarget::stderr());
            late.enable_steady_tick(std::time::Duration::from_millis(120));
        }
    });
    bar
}

/// `simulate --compare MODEL`: the scene run in another model, the largest differences.
fn compare(name: &str, csv: Option<&Path>, other: Option<&str>) -> anyhow::Result<()> {
    let scene = stdin::scene(name)?;
    if csv.is_some() {
        return Err(anyhow::anyhow!(
            "--compare writes no trajectory: leave out --csv, or run without --compare"
        ));
    }
    let other = match other {
        Some("lab-frame") => ::studies::compare::lab_frame_for(scene.model)?,
        Some(other) => {
            return Err(anyhow::anyhow!(
                "--compare: {other} is not a model to compare with; use lab-frame"
            ))
        }
        None => return Ok(()),
    };
    let c = ::studies::compare::compare(&scene, other)?;
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
    Ok(())
}

fn simulate(
    name: &str,
    csv: Option<PathBuf>,
    json: bool,
    against: Option<&Path>,
) -> anyhow::Result<()> {
    let to_stdout = csv.as_deref().is_some_and(stdin::is_stdin);
    if to_stdout && json {
        return Err(anyhow::anyhow!(
            "--csv - and --json would both write to standard output: give --csv a file"
        ));
    }
    let scene = stdin::scene(name)?;
    if let Some(path) = &csv {
        stdout::check_output(path).map_err(|e| anyhow::anyhow!("--csv {e}"))?;
    }
    let recorded = against.map(Recorded::read).transpose()?;
    let run_columns = columns(&scene);
    let mut compared = recorded
        .as_ref()
        .map(|r| TraceAgainst::new(r, &run_columns, scene.settings.rtol, scene.settings.atol));
    let bar = progress_bar(scene.stop.time);
    let t_end = scene.stop.time;
    let report = |t: f64| {
        bar.set_position((1000.0 * t / t_end) as u64);
        bar.set_message(format!("{t:.3} of {t_end} s"));
    };
    // The rows go to the CSV as the run makes them; none is held.
    let rows = scene.sample.map(|dt| (t_end / dt).floor() as u64 + 2);
    let mut stream = match &csv {
        Some(path) => Some(RowStream::open(path, &run_columns, rows)?),
        None => None,
    };
    let mut last_time = 0.0;
    let width = run_columns.len();
    let mut sink = |rows: &[f64]| {
        if let Some(last) = rows.len().checked_sub(width) {
            last_time = rows[last];
        }
        if let Some(s) = stream.as_mut() {
            rows.chunks_exact(width).for_each(|row| s.write(row));
        }
        if let Some(c) = compared.as_mut() {
            rows.chunks_exact(width).for_each(|row| c.push(row));
        }
    };
    let result = run_streamed_rows(&scene, Some(&report), &mut sink)
        .map_err(|e| anyhow::anyhow!("{}: {e}", scene.source));
    bar.finish_and_clear();
    let result = result?;
    if matches!(
        result.ending,
        Ending::Unstable { .. } | Ending::NonFinite { .. }
    ) {
        // No number of such a run means anything: say why, print none (and write no file).
        return Err(anyhow::anyhow!("{}: {}", scene.source, result.ending));
    }
    if let Some(lost) = &result.contact_lost {
        eprintln!("warning: {}: {lost}", scene.source);
    }
    let (against_text, changed) = compared
        .as_ref()
        .map_or((String::new(), false), |c| c.finish(&run_columns));
    let summary = if json {
        summary_json(&scene, &result, last_time)
    } else {
        summary(&scene, &result, last_time)
    };
    let said = csv.as_ref().map(|path| {
        format!(
            "trajectory: {} rows written to {}",
            result.recorded,
            path.display()
        )
    });
    if let Some(stream) = stream {
        stream.finish()?;
    }
    if to_stdout {
        eprint!("{summary}{against_text}");
    } else {
        print!("{summary}{against_text}");
    }
    if let Some(said) = said {
        if to_stdout {
            eprintln!("{said}");
        } else {
            println!("{said}");
        }
    }
    if !result.ending.is_complete() {
        return Err(anyhow::anyhow!("the run did not finish: {}", result.ending));
    }
    if changed {
        return Err(exit::Status {
            code: exit::CHANGED,
            message: format!(
                "the run of {} differs from its recording {} (see above)",
                scene.name,
                against.map_or(String::new(), |p| p.display().to_string())
            ),
        }
        .into());
    }
    Ok(())
}

/// The identifier of `simulate --json`'s schema.
pub const SIMULATE_SCHEMA_ID: &str = "https://rolling-disk.invalid/schemas/simulate.schema.json";

/// The summary of a run as JSON (`schemas/simulate.schema.json`): the scene, the model, the
/// solver, the rows recorded, the events, the final state, why and when the run stopped, the
/// energy and the solver's work; one document and a newline.
pub(crate) fn summary_json(scene: &Scene, r: &Run, t_end: f64) -> String {
    use serde_json::json;
    let m = &r.last;
    let rk4 = scene.settings.method == physics::solve::Method::Rk4;
    let energy_kind = if scene.dissipation.is_some()
        || !scene.mechanisms.is_empty()
        || scene.friction.is_some()
    {
        "lost"
    } else {
        "drift"
    };
    let stop_event = match &r.ending {
        Ending::Event { name, t, .. } => json!({ "name": name, "t": t }),
        _ => serde_json::Value::Null,
    };
    let events: Vec<serde_json::Value> = r
        .contact_events
        .iter()
        .map(|e| json!({ "t": e.t, "from": e.from, "to": e.to, "what": e.what }))
        .collect();
    let doc = json!({
        "schema": SIMULATE_SCHEMA_ID,
        "tool": { "name": "rolling-disk", "version": crate::VERSION },
        "scene": { "name": scene.name, "source": scene.source },
        "model": r.model.to_string(),
        "states": r.states,
        "solver": {
            "method": scene.settings.method.to_string(),
            "rtol": if rk4 { None } else { Some(scene.settings.rtol) },
            "atol": if rk4 { None } else { Some(scene.settings.atol) },
            "step": if rk4 { Some(scene.settings.step) } else { None },
        },
        "rows": r.recorded,
        "columns": columns(scene),
        "stop": {
            "reason": r.ending.to_string(),
            "complete": r.ending.is_complete(),
            "t": t_end,
            "event": stop_event,
        },
        "final": {
            "alpha": m.alpha,
            "alpha_dot": m.alpha_dot,
            "precession": m.precession,
            "spin": m.spin,
        },
        "energy": { "kind": energy_kind, "start": r.energy.0, "end": r.energy.1, "relative_change": r.energy_change },
        "work": {
            "evaluations": r.stats.evaluations,
            "extra_evaluations": r.stats.extra_evaluations,
            "accepted": r.stats.accepted,
            "rejected": r.stats.rejected,
        },
        "events": events,
        "contact_lost": r.contact_lost.map(|l| json!({ "t": l.t, "normal_force": l.normal_force })),
    });
    let mut text = serde_json::to_string_pretty(&doc).unwrap_or_default();
    text.push('\n');
    text
}

/// The summary of a run that ended at `t_end`, one line per item.
pub(crate) fn summary(scene: &Scene, r: &Run, t_end: f64) -> String {
    use std::fmt::Write as _;
    let mut s = String::new();
    let m = &r.last;
    let _ = writeln!(s, "scene       {} ({})", scene.name, scene.source);
    let _ = writeln!(s, "model       {}, {} states integrated", r.model, r.states);
    if scene.settings.method == physics::solve::Method::Rk4 {
        let _ = writeln!(
            s,
            "solver      rk4, fixed step {:e} s (rtol and atol are not used)",
            scene.settings.step
        );
    } else {
        let _ = writeln!(
            s,
            "solver      {} rtol {:e} atol {:e}",
            scene.settings.method, scene.settings.rtol, scene.settings.atol
        );
    }
    let _ = writeln!(s, "ended       {} (t = {t_end:.6} s)", r.ending);
    if let Some(lost) = &r.contact_lost {
        let _ = writeln!(s, "not physics {lost}");
    }
    let _ = writeln!(
        s,
        "final       alpha = {:.12} rad, alpha_dot = {:.12e} rad/s, Omega = {:.12} rad/s, omega_1 = {:.12} rad/s",
        m.alpha, m.alpha_dot, m.precession, m.spin
    );
    let label = if scene.dissipation.is_some()
        || !scene.mechanisms.is_empty()
        || scene.friction.is_some()
    {
        "energy lost"
    } else {
        "energy drift"
    };
    let _ = writeln!(
        s,
        "{label:11} {:.3e} relative (E0 = {:.9e} J, E_end = {:.9e} J)",
        r.energy_change, r.energy.0, r.energy.1
    );
    let _ = writeln!(
        s,
        "work        {} right-hand-side evaluations ({} more to locate events and sample), {} accepted and {} rejected steps",
        r.stats.evaluations, r.stats.extra_evaluations, r.stats.accepted, r.stats.rejected
    );
    if scene.model.has_coulomb_friction() {
        let _ = writeln!(
            s,
            "contact     {} switches and impacts",
            r.contact_events.len()
        );
        for e in &r.contact_events {
            let arrow = format!("{} -> {}", e.from, e.to);
            if e.what.starts_with(&arrow) {
                let _ = writeln!(s, "  t = {:.9} s  {}", e.t, e.what);
            } else {
                let _ = writeln!(s, "  t = {:.9} s  {arrow}: {}", e.t, e.what);
            }
        }
    }
    s
}
