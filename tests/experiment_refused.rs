//! A refused sound analysis still shows what it saw: with `--out`, `experiment analyze` writes
//! the reason (`refusal.txt`), the pitch track made before the refusal (`track.csv`) and the
//! spectrogram with the track and the reason on it (`spectrogram.svg`), says so, and exits 1;
//! without `--out` it writes nothing. A sound's refusal speaks of tones and lines, never of
//! pulses or a light signal.

use crate::common::{cli_in, temp_dir, write_wav_i16};
use rand::SeedableRng;
use rand_distr::{Distribution, Normal};

/// Three seconds of room noise at 8 kS/s: no tone, so no line to follow.
fn noise_wav(dir: &std::path::Path) -> &'static str {
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
    let normal = Normal::new(0.0f64, 3000.0).expect("a normal law");
    let v: Vec<i16> = (0..24_000)
        .map(|_| normal.sample(&mut rng).round().clamp(-32_000.0, 32_000.0) as i16)
        .collect();
    write_wav_i16(&dir.join("noise.wav"), &v, 8000, 1);
    "noise.wav"
}

#[test]
fn a_refused_sound_writes_its_track_and_spectrogram_with_the_reason() {
    let dir = temp_dir("refused", "out");
    let wav = noise_wav(&dir);
    let (ok, out, err) = cli_in(&dir, &["experiment", "analyze", wav, "--out", "set"]);
    assert!(!ok, "noise is refused: {out}");
    assert!(!err.contains("panicked"), "{err}");
    assert!(err.contains("no rising line to follow"), "{err}");
    assert!(
        err.contains("written to set (refusal.txt, track.csv, spectrogram.svg)"),
        "the refusal says where its files are: {err}"
    );
    let read = |name: &str| std::fs::read_to_string(dir.join("set").join(name)).unwrap_or_default();
    let reason = read("refusal.txt");
    assert!(reason.contains("noise.wav: not a spin-down"), "{reason}");
    assert!(reason.contains("no rising line to follow"), "{reason}");
    assert!(
        read("track.csv").starts_with("t_start_s,t_end_s,omega_rad_s"),
        "the track's header"
    );
    let svg = read("spectrogram.svg");
    assert!(svg.contains("refused:"), "the reason is on the spectrogram");
    assert!(
        svg.contains("no rising line"),
        "the reason is on the spectrogram"
    );
    for word in ["pulse", "light", "peak"] {
        assert!(
            !err.contains(word),
            "a sound's refusal speaks of {word}: {err}"
        );
    }
}

#[test]
fn a_refused_sound_without_out_writes_nothing() {
    let dir = temp_dir("refused", "no-out");
    let wav = noise_wav(&dir);
    let (ok, _, err) = cli_in(&dir, &["experiment", "analyze", wav]);
    assert!(!ok);
    assert!(err.contains("no rising line to follow"), "{err}");
    assert!(!err.contains("written to"), "{err}");
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .map(|d| {
            d.filter_map(Result::ok)
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    names.sort();
    assert_eq!(names, vec!["noise.wav".to_string()]);
}

/// Eq 79 with beta = 2 and Omega = 100 rad/s (15.9 Hz) 7 s before t0, recorded at 16 kS/s by a
/// phone (`amplitude` of the disk, `noise` of the recorder) in which the disk is first heard
/// `lead` s into the record.
fn disk(amplitude: f64, noise: f64, lead: f64) -> experiment::Trace {
    let law = experiment::Law {
        beta: 2.0,
        c: 100f64.powi(4) * 7.0,
    };
    let mut mic = experiment::Microphone::phone(16_000, 3);
    mic.amplitude = amplitude;
    mic.noise = noise;
    mic.voice.lead = lead;
    experiment::law_sound(&law, &mic, &experiment::Artifacts::none()).expect("a sound")
}

fn analysed(t: &experiment::Trace) -> Result<experiment::SoundAnalysis, String> {
    experiment::analyze_sound(
        t,
        &experiment::TrackSettings::default(),
        &experiment::plausibility::Plausibility::default(),
    )
    .map_err(|e| e.to_string())
}

/// Its advice applied, a refused recording is analysed: beta within 0.05 of the truth.
fn assert_analysed(t: &experiment::Trace) {
    let a = analysed(t).unwrap_or_else(|e| panic!("the advice applied, still refused: {e}"));
    assert!((a.law().beta - 2.0).abs() < 0.05, "{a}");
}

/// A disk too faint for its line to stand out of the recorder's noise: the refusal says that no
/// line was found and to record closer; recorded closer (the disk 100 times louder over the same
/// noise), it is analysed.
#[test]
fn a_line_lost_in_the_noise_is_refused_with_record_closer_and_closer_works() {
    let e = analysed(&disk(0.003, 0.03, 1.0)).expect_err("a line under the noise is refused");
    assert!(e.contains("no rising line to follow"), "{e}");
    assert!(
        e.contains("did a line of the disk stand out of the noise"),
        "the refusal names what was found: {e}"
    );
    assert!(e.contains("record closer to the disk"), "{e}");
    assert_analysed(&disk(0.3, 0.03, 1.0));
}

/// A disk heard only in its last half second: the refusal says over how long the line was
/// followed and to record the whole spin; the whole spin recorded, it is analysed.
#[test]
fn a_spin_heard_too_briefly_is_refused_with_record_the_whole_spin_and_that_works() {
    let e = analysed(&disk(0.3, 0.003, 8.0)).expect_err("half a second of the line is refused");
    assert!(
        e.contains("the disk's line was followed over"),
        "the refusal names what was found: {e}"
    );
    assert!(e.contains("record the whole spin"), "{e}");
    for word in ["pulse", "light", "peak"] {
        assert!(!e.contains(word), "a sound's refusal speaks of {word}: {e}");
    }
    assert_analysed(&disk(0.3, 0.003, 1.0));
}

/// A sound recording longer than the analysis holds (6,000,000 samples per channel) is refused
/// naming the limit and the cut to make; the cut made as it says (the spin-down's last 749 s of
/// an 8 kS/s recording), it is analysed.
#[test]
fn a_recording_too_long_is_refused_with_the_cut_to_make_and_the_cut_is_analysed() {
    let mut mic = experiment::Microphone::phone(8000, 4);
    mic.voice.lead = 1.0;
    let law = experiment::Law {
        beta: 2.0,
        c: 100f64.powi(4) * 7.0,
    };
    let spin = experiment::law_sound(&law, &mic, &experiment::Artifacts::none()).expect("a sound");
    let mut state: u64 = 11;
    let mut quiet = || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((state >> 61) as i16) - 4
    };
    let lead = 6_000_001 - spin.v.len() + 1000;
    let mut v: Vec<i16> = (0..lead).map(|_| quiet()).collect();
    v.extend(spin.v.iter().map(|x| (x * 32767.0).round() as i16));
    let dir = temp_dir("refused", "too-long");
    write_wav_i16(&dir.join("long.wav"), &v, 8000, 1);
    let (ok, _, err) = cli_in(&dir, &["experiment", "analyze", "long.wav"]);
    assert!(!ok);
    assert!(
        err.contains("more than 6000000 samples per channel (750 s at 8000 S/s)"),
        "{err}"
    );
    assert!(
        err.contains("cut it to the spin-down's last 749 s, for example `ffmpeg -sseof -749 -i long.wav cut.wav`"),
        "{err}"
    );
    write_wav_i16(&dir.join("cut.wav"), &v[v.len() - 749 * 8000..], 8000, 1);
    let (ok, out, err) = cli_in(&dir, &["experiment", "analyze", "cut.wav"]);
    assert!(ok, "the cut is refused: {err}");
    assert!(out.contains("eq 79 on the"), "{out}");
}
