//! `rolling-disk experiment simulate` and `experiment analyze`: the experiment of section 11.

use crate::cli::simulate::stage_spinner;
use crate::cli::stdout;
use files::output::SetWriter;
use physics::budget::Work;
use std::path::{Path, PathBuf};

/// The commands of `rolling-disk experiment`.
#[derive(clap::Subcommand)]
pub enum Command {
    /// Simulates a recording of a spin-down scene: the scope's light signal as CSV (time in s,
    /// signal in V), or the disk's sound as WAV, with optional bench artifacts.
    Simulate {
        /// A dissipative scene (file or built-in name), e.g. spin-down.
        #[arg(default_value = "spin-down")]
        #[arg(value_parser = crate::cli::utf8::scene())]
        scene: String,
        /// Write the scope's light signal to this CSV.
        #[arg(long, value_name = "FILE", required_unless_present = "wav")]
        csv: Option<PathBuf>,
        /// Write the disk's sound (mono) to this file, as WAV or FLAC (see --format).
        #[arg(long, value_name = "FILE", conflicts_with = "csv")]
        wav: Option<PathBuf>,
        /// The sound's sample rate (S/s), 1000 to 384000.
        #[arg(long, value_name = "R", default_value_t = 48000, allow_negative_numbers = true,
              value_parser = clap::value_parser!(u32).range(1000..=384_000))]
        rate: u32,
        /// The sound's coding: 16-bit WAV, 24-bit WAV, 32-bit float WAV, or 16-bit FLAC.
        #[arg(long, value_parser = super::choice::parser::<experiment::SoundFormat>(), default_value = "wav")]
        format: experiment::SoundFormat,
        #[command(flatten)]
        artifacts: ArtifactArgs,
    },
    /// Analyses a recording: a scope CSV (peak times, eqs 84-85) or a WAV (frequency track,
    /// eq 79); fits beta, t0 and C with uncertainties, compares laws, and refuses with a reason
    /// (non-zero exit) what is not a spin-down.
    Analyze {
        /// The recording: a CSV (time and signal columns) or a sound file (WAV, FLAC, MP3, Ogg,
        /// M4A); `-` reads either from standard input, told apart by its first bytes.
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
        /// For a scope CSV: the time column, by its header's name or its number from 1 (the
        /// first column unless given; a Tektronix or Rigol file's own time otherwise).
        #[arg(long, value_name = "NAME|N")]
        time: Option<String>,
        /// For a scope CSV: the photodiode's column, by its header's name (e.g. CH2) or its
        /// number from 1; needed when the file holds more than one signal column.
        #[arg(long, value_name = "NAME|N")]
        signal: Option<String>,
    },
}

/// What a bench recording adds (all off by default).
#[derive(clap::Args)]
pub struct ArtifactArgs {
    /// All of a realistic bench's artifacts: drift 5 %, 50 Hz hum 2 %, clipping of the top
    /// 15 %, 2 glitches/s, 1 % dropped samples (of the signal's span).
    #[arg(long)]
    realistic: bool,
    /// Baseline drift, rms, as a fraction of the signal's span (0 to 1).
    #[arg(long, value_name = "FRACTION", allow_negative_numbers = true, value_parser = crate::cli::ranges::fraction)]
    drift: Option<f64>,
    /// Mains hum amplitude as a fraction of the signal's span (0 to 1).
    #[arg(long, value_name = "FRACTION", allow_negative_numbers = true, value_parser = crate::cli::ranges::fraction)]
    hum: Option<f64>,
    /// Mains frequency (Hz, 10 to 1000).
    #[arg(long, value_name = "HZ", default_value_t = 50.0, allow_negative_numbers = true, value_parser = crate::cli::ranges::mains_hz)]
    mains: f64,
    /// Clip above this fraction of the signal's range (above 0, at most 1).
    #[arg(long, value_name = "FRACTION", allow_negative_numbers = true, value_parser = crate::cli::ranges::clip)]
    clip: Option<f64>,
    /// Isolated glitches per second (0 to 1000).
    #[arg(long, value_name = "RATE", allow_negative_numbers = true, value_parser = crate::cli::ranges::glitches)]
    glitches: Option<f64>,
    /// Fraction of samples dropped (0 to below 0.5).
    #[arg(long, value_name = "FRACTION", allow_negative_numbers = true, value_parser = crate::cli::ranges::dropped)]
    dropped: Option<f64>,
    /// Noise seed of the scope or microphone, and of the artifacts.
    #[arg(long, default_value_t = 1, allow_negative_numbers = true)]
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

impl Command {
    /// Runs the command.
    pub fn run(self) -> anyhow::Result<()> {
        match self {
            Command::Simulate {
                scene,
                csv,
                wav,
                rate,
                format,
                artifacts,
            } => experiment_simulate(
                &scene,
                csv.as_deref(),
                wav.as_deref().map(|w| (w, rate, format)),
                &artifacts,
            ),
            Command::Analyze {
                csv,
                out,
                json,
                channel,
                time,
                signal,
            } => {
                let columns = experiment::scope_layout::ColumnChoice {
                    time: time
                        .as_deref()
                        .map(experiment::scope_layout::ColumnRef::parse),
                    signal: signal
                        .as_deref()
                        .map(experiment::scope_layout::ColumnRef::parse),
                };
                experiment_analyze(&csv, out.as_deref(), json, &channel, &columns)
            }
        }
    }
}

fn experiment_simulate(
    name: &str,
    csv: Option<&Path>,
    wav: Option<(&Path, u32, experiment::SoundFormat)>,
    args: &ArtifactArgs,
) -> anyhow::Result<()> {
    let scene = crate::cli::stdin::scene(name)?;
    // The output is checked before anything is computed (a scene given as its own output too).
    for (option, path) in [("--csv", csv), ("--wav", wav.map(|w| w.0))] {
        if let Some(path) = path {
            stdout::check_output(path).map_err(|e| anyhow::anyhow!("{option} {e}"))?;
        }
    }
    stdout::progress(&format!("simulating the recording of {}...", scene.name));
    let bar = stage_spinner();
    let note = |stage: &str| bar.set_message(stage.to_string());
    let work =
        Work::start(format!("the simulated recording of {}", scene.name)).with_progress(&note);
    let made = if let Some((path, rate, format)) = wav {
        work.stage("simulating the sound")?;
        let mic = experiment::Microphone::phone(rate, args.seed);
        let a = args.artifacts(2.0 * mic.amplitude);
        let trace = experiment::simulate_sound(&scene, &mic, &a)?;
        work.stage("encoding the sound")?;
        let bytes = experiment::encode_sound(&trace.v, rate, format)?;
        Ok((path, bytes, trace))
    } else if let Some(path) = csv {
        work.stage("simulating the light signal")?;
        let mut light = experiment::LightModel::default();
        light.scope.seed = args.seed;
        let trace = experiment::simulate_trace(&scene, &light)?;
        work.stage("adding the bench's artifacts")?;
        let artifacts = args.artifacts(light.gain);
        let trace = trace.with_artifacts(&artifacts)?;
        work.stage("writing the CSV")?;
        let notes = experiment::synthetic::scope::header_notes(&light.scope, &artifacts);
        let bytes = trace.to_csv_noting(&notes).into_bytes();
        Ok((path, bytes, trace))
    } else {
        Err(anyhow::anyhow!("give --csv FILE or --wav FILE"))
    };
    bar.finish_and_clear();
    let (path, bytes, trace) = made?;
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

/// A recording to analyse: a file, or the bytes of standard input (`-`).
enum Recording<'a> {
    /// A file, read by the experiment's readers.
    File(&'a Path),
    /// Standard input, read whole.
    Stdin(Vec<u8>),
}

/// Whether `bytes` begin as a sound file does (RIFF/RF64 WAV, FLAC, Ogg, CAF, AIFF, MP3 with its ID3
/// tag or a frame's sync bits, raw AAC, M4A/MP4): a scope CSV is text and begins with none of
/// them.
fn sound_bytes(bytes: &[u8]) -> bool {
    let magic: [&[u8]; 8] = [
        b"RIFF", b"RF64", b"RIFX", b"fLaC", b"OggS", b"ID3", b"caff", b"FORM",
    ];
    magic.iter().any(|m| bytes.starts_with(m))
        || bytes.first() == Some(&0xFF)
        || bytes.get(4..8) == Some(b"ftyp".as_slice())
}

fn experiment_analyze(
    csv: &Path,
    out: Option<&Path>,
    json: bool,
    channel: &str,
    columns: &experiment::scope_layout::ColumnChoice,
) -> anyhow::Result<()> {
    let channels = match channel {
        "mix" => experiment::Channels::Mix,
        n => experiment::Channels::One(n.parse().map_err(|_| {
            anyhow::anyhow!(
                "--channel {n}: give a channel number from 1 (1 = left), or mix for the channels' mean"
            )
        })?),
    };
    // The output set is checked before any work, and written whole or not at all.
    let set = out.map(stdout::begin_set).transpose()?;
    // A recording by its first bytes whatever its name; by its extension where the bytes cannot
    // be read or are damaged (the sound reader then says why).
    let (recording, is_sound, shown) = if crate::cli::stdin::is_stdin(csv) {
        let bytes =
            crate::cli::stdin::read("the recording", experiment::formats::input::MAX_BYTES)?;
        let is_sound = sound_bytes(&bytes);
        let shown = crate::cli::stdin::NAME.to_string();
        (Recording::Stdin(bytes), is_sound, shown)
    } else {
        let is_sound = experiment::recording::is_recording(csv)
            || csv.extension().is_some_and(|e| {
                [
                    "wav", "wave", "flac", "mp3", "ogg", "oga", "m4a", "mp4", "aac",
                ]
                .iter()
                .any(|x| e.eq_ignore_ascii_case(x))
            });
        (Recording::File(csv), is_sound, csv.display().to_string())
    };
    if is_sound && (columns.time.is_some() || columns.signal.is_some()) {
        anyhow::bail!(
            "{shown}: --time and --signal choose a scope CSV's columns, and this is a sound \
             recording: leave them out (choose a sound's channel with --channel N or mix)"
        );
    }
    let bar = stage_spinner();
    let note = |stage: &str| bar.set_message(format!("{shown}: {stage}"));
    let work = Work::start(format!("the analysis of {shown}")).with_progress(&note);
    let analysed = analyse(
        recording,
        (is_sound, channels, columns),
        json,
        set.as_ref(),
        &work,
    );
    bar.finish_and_clear();
    let (text, files, refused) = match analysed? {
        Analysed::Done(text, files) => (Some(text), files, None),
        Analysed::Refused(error, files) => (None, files, Some(error)),
    };
    let mut dir = None;
    if let Some(set) = set {
        let shown: Vec<PathBuf> = files.iter().map(|p| set.final_path(p)).collect();
        dir = shown
            .first()
            .and_then(|p| p.parent())
            .map(|d| d.display().to_string());
        set.commit(&files)?;
        // On standard error: standard output carries the analysis.
        if !stdout::quiet() {
            for p in shown {
                eprintln!("wrote {}", p.display());
            }
        }
    }
    if let Some(error) = refused {
        return Err(match dir {
            Some(d) => anyhow::anyhow!(
                "{error}; the reason, the pitch track made before it and the spectrogram with \
                 both on it are written to {d} (refusal.txt, track.csv, spectrogram.svg)"
            ),
            None => error.into(),
        });
    }
    if let Some(text) = text {
        println!("{text}");
    }
    Ok(())
}

/// What [`analyse`] gives: the text to print and the files written into the output set, or a
/// sound analysis's refusal with the files that show it (the reason, the track, the
/// spectrogram), written into the output set.
enum Analysed {
    Done(String, Vec<PathBuf>),
    Refused(experiment::ExperimentError, Vec<PathBuf>),
}

/// Reads and analyses the recording within `work`: the text to print and the files written
/// into the output set.
fn analyse(
    recording: Recording<'_>,
    (is_sound, channels, columns): (
        bool,
        experiment::Channels,
        &experiment::scope_layout::ColumnChoice,
    ),
    json: bool,
    set: Option<&SetWriter>,
    work: &Work<'_>,
) -> anyhow::Result<Analysed> {
    work.stage("reading")?;
    Ok(if is_sound {
        let rec = match recording {
            Recording::File(path) => experiment::read_recording(path, channels)?,
            Recording::Stdin(bytes) => {
                experiment::recording::parse_recording(bytes, crate::cli::stdin::NAME, channels)?
            }
        };
        let analysed = experiment::analyze_sound_keeping_track(
            &rec.trace,
            &experiment::TrackSettings::default(),
            &experiment::plausibility::Plausibility::default(),
            work,
        );
        let mut a = match (analysed, set) {
            (Ok(a), _) => a,
            // Out of time: nothing more is done.
            (Err(r), _) if matches!(r.error, experiment::ExperimentError::OverBudget(_)) => {
                return Err(r.error.into())
            }
            (Err(r), None) => return Err(r.error.into()),
            (Err(r), Some(set)) => {
                let mut f = r.write(set.dir())?;
                f.extend(crate::cli::sound_figures::write_refused(
                    &r,
                    &rec.trace,
                    set.dir(),
                )?);
                return Ok(Analysed::Refused(r.error, f));
            }
        };
        a.recording = Some(rec.info);
        let text = if json { a.to_json() } else { a.to_string() };
        let files = match set {
            Some(set) => {
                let mut f = experiment::write_sound_analysis(&a, set.dir())?;
                f.extend(crate::cli::sound_figures::write(&a, &rec.trace, set.dir())?);
                f
            }
            None => Vec::new(),
        };
        Analysed::Done(text, files)
    } else {
        let (trace, column) = match recording {
            Recording::File(path) => experiment::read_trace_columns(path, columns)?,
            Recording::Stdin(bytes) => {
                let name = crate::cli::stdin::NAME;
                let text = String::from_utf8(bytes).map_err(|e| {
                    anyhow::anyhow!(
                        "{name}: not UTF-8 text (byte {} is invalid) and not a sound file by its \
                         first bytes: pipe a scope CSV saved as UTF-8, or a WAV, FLAC, MP3, Ogg \
                         or M4A file",
                        e.utf8_error().valid_up_to() + 1
                    )
                })?;
                experiment::parse_trace_columns(&text, name, columns)?
            }
        };
        let analysis =
            experiment::analyze_within(&trace, &experiment::AnalysisSettings::default(), work)
                .map_err(|e| match e {
                    // Which column was flat: the photodiode may be on another channel.
                    experiment::ExperimentError::FlatSignal { .. } => anyhow::anyhow!(
                        "{e}; the column analysed is the {column}: if the photodiode is on \
                         another column, choose it with --signal NAME or --signal NUMBER"
                    ),
                    e => e.into(),
                })?;
        let text = if json {
            analysis.to_json()
        } else {
            analysis.to_string()
        };
        let files = match set {
            Some(set) => experiment::write_analysis(&analysis, set.dir())?,
            None => Vec::new(),
        };
        Analysed::Done(text, files)
    })
}
