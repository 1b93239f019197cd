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
