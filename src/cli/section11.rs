//! `experiment simulate` and `experiment analyze`: the section 11 experiment.

use super::*;

pub(crate) fn experiment_simulate(
    name: &str,
    csv: Option<&Path>,
    wav: Option<(&Path, u32, experiment::SoundFormat)>,
    args: &ArtifactArgs,
) -> anyhow::Result<()> {
    let scene = Scene::load(name)?;
    eprintln!("simulating the recording of {}...", scene.name);
    let (path, bytes, trace) = if let Some((path, rate, format)) = wav {
        let mic = experiment::Microphone::phone(rate, args.seed);
        let a = args.artifacts(2.0 * mic.amplitude);
        let trace = experiment::simulate_sound(&scene, &mic, &a)?;
        let bytes = experiment::encode_sound(&trace.v, rate, format)?;
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

pub(crate) fn experiment_analyze(
    csv: &Path,
    out: Option<&Path>,
    json: bool,
    channel: &str,
) -> anyhow::Result<()> {
    let is_sound = csv.extension().is_some_and(|e| {
        [
            "wav", "wave", "flac", "mp3", "ogg", "oga", "m4a", "mp4", "aac",
        ]
        .iter()
        .any(|x| e.eq_ignore_ascii_case(x))
    });
    if is_sound {
        let channels = match channel {
            "mix" => experiment::Channels::Mix,
            n => experiment::Channels::One(n.parse().map_err(|_| {
                anyhow::anyhow!(
                    "--channel {n}: give a channel number from 1 (1 = left), or mix for the channels' mean"
                )
            })?),
        };
        let rec = experiment::read_recording(csv, channels)?;
        let mut a = experiment::analyze_sound(
            &rec.trace,
            &experiment::TrackSettings::default(),
            &experiment::plausibility::Plausibility::default(),
        )?;
        a.recording = Some(rec.info);
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
