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
    let to_stdout = stdout::write_to(path, &bytes)?;
    let mut said = format!("{} samples written to {}", trace.t.len(), path.display());
    if let Some(t) = &trace.truth {
        said.push_str(&format!(
            "\ntruth: beta = {}, t0 = {:.6} s ({})",
            t.beta, t.t0, t.origin
        ));
    }
    if to_stdout {
        eprintln!("{said}");
    } else {
        println!("{said}");
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
    let channels = match channel {
        "mix" => experiment::Channels::Mix,
        n => experiment::Channels::One(n.parse().map_err(|_| {
            anyhow::anyhow!(
                "--channel {n}: give a channel number from 1 (1 = left), or mix for the channels' mean"
            )
        })?),
    };
    // The output set is checked before any work, and written whole or not at all.
    let set = out.map(SetWriter::begin).transpose()?;
    let (text, files) = if is_sound {
        let rec = experiment::read_recording(csv, channels)?;
        let mut a = experiment::analyze_sound(
            &rec.trace,
            &experiment::TrackSettings::default(),
            &experiment::plausibility::Plausibility::default(),
        )?;
        a.recording = Some(rec.info);
        let text = if json { a.to_json() } else { a.to_string() };
        let files = match &set {
            Some(set) => experiment::write_sound_analysis(&a, set.dir())?,
            None => Vec::new(),
        };
        (text, files)
    } else {
        let trace = experiment::read_trace(csv)?;
        let analysis = experiment::analyze(&trace, &experiment::AnalysisSettings::default())?;
        let text = if json {
            analysis.to_json()
        } else {
            analysis.to_string()
        };
        let files = match &set {
            Some(set) => experiment::write_analysis(&analysis, set.dir())?,
            None => Vec::new(),
        };
        (text, files)
    };
    if let Some(set) = set {
        let shown: Vec<PathBuf> = files.iter().map(|p| set.final_path(p)).collect();
        set.commit(&files)?;
        for p in shown {
            eprintln!("wrote {}", p.display());
        }
    }
    println!("{text}");
    Ok(())
}
