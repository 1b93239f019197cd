//! A long recording: an hour at 48 kS/s in stereo, the disk spun in its last minute and room
//! noise before, read in pieces and decimated (`experiment::formats::long`), and analysed.

use crate::common::{cli_in, temp_dir};
use experiment::{law_sound, Artifacts, Law, Microphone};

/// Writes `seconds` of 16-bit stereo at 48 kS/s to `path`: quiet room noise, then the last
/// 60 s of it a phone's minute of the disk (eq 79 with beta = 2, the spin-down ending 1.5 s
/// before the minute's end), the second channel 31 samples later at 0.8 of the level, each
/// channel with its own noise.
/// Returns $t_0$ in record time.
pub fn write_long_spin(path: &std::path::Path, seconds: usize) -> f64 {
    let rate = 48_000u32;
    let minute = Microphone {
        samples: 2_880_000,
        end_at: 58.5,
        ..Microphone::phone(rate, 3)
    };
    let law = Law {
        beta: 2.0,
        c: 100f64.powi(4) * 58.0,
    };
    let spin = law_sound(&law, &minute, &Artifacts::none()).expect("a valid recording");
    let spec = hound::WavSpec {
        channels: 2,
        sample_rate: rate,
        bits_per_sample: 16,
        sample_format: hound::SampleFormat::Int,
    };
    let mut w = hound::WavWriter::create(path, spec).expect("a WAV to write");
    let total = seconds * rate as usize;
    let lead = total - spin.v.len();
    let mut state = 7u64;
    let mut noise = || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((state >> 33) as f64 / (1u64 << 31) as f64 - 0.5) * 2e-3
    };
    let at = |j: usize| if j >= lead { spin.v[j - lead] } else { 0.0 };
    let q = |x: f64| (x.clamp(-1.0, 1.0) * 32767.0).round() as i16;
    for j in 0..total {
        w.write_sample(q(at(j) + noise())).unwrap();
        w.write_sample(q(0.8 * at(j.saturating_sub(31)) + noise()))
            .unwrap();
    }
    w.finalize().unwrap();
    lead as f64 / f64::from(rate) + 58.5
}

/// An hour at 48 kS/s, stereo 16-bit (691 MB): read in pieces, its two channels mixed,
/// decimated 6:1, and the spin in its last minute analysed, beta and t0 within 0.05 and 50 ms
/// of the truth. (The channels' delay is measured on 32 blocks spread over the hour, of which
/// the spin fills one or two: it need not stand out of the noise's, and is not asserted.)
/// (About two minutes of CPU with the writing; the memory and time of the analysis alone are
/// measured with
/// `/usr/bin/time -v rolling-disk experiment analyze hour.wav` on the file this writes, kept
/// with ROLLING_DISK_KEEP_HOUR=1.)
#[test]
#[ignore = "slow: writes and analyses an hour of 48 kHz stereo (691 MB)"]
fn an_hour_of_stereo_at_48_khz_is_read_in_pieces_and_its_spin_analysed() {
    let dir = temp_dir("long", "hour");
    let t0 = write_long_spin(&dir.join("hour.wav"), 3600);
    let (ok, out, err) = cli_in(&dir, &["experiment", "analyze", "hour.wav", "--json"]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let used = v["recording"]["used"].as_str().unwrap_or_default();
    assert!(used.contains("decimated 6:1 to 8000 S/s"), "{used}");
    assert!(used.starts_with("mix of 2"), "{used}");
    let (beta, t) = (
        v["result"]["law"]["beta"].as_f64().unwrap(),
        v["result"]["law"]["t0"].as_f64().unwrap(),
    );
    println!("beta {beta}, t0 {t} (truth 2, {t0})");
    assert!((beta - 2.0).abs() < 0.05, "{beta}");
    assert!((t - t0).abs() < 0.05, "{t} against {t0}");
    if std::env::var("ROLLING_DISK_KEEP_HOUR").is_err() {
        std::fs::remove_dir_all(&dir).ok();
    } else {
        println!("kept {}", dir.display());
    }
}

/// A minute at 48 kS/s in stereo (the hour's last minute alone, 11.5 MB) is read whole, not
/// decimated, and analysed as well. With ROLLING_DISK_KEEP_MINUTE=1 the file is kept, for
/// timing the analysis (`/usr/bin/time -v rolling-disk experiment analyze minute.wav`).
#[test]
#[ignore = "writes 11.5 MB; run to time the 60 s analysis on the file it keeps"]
fn a_minute_of_stereo_is_read_whole_and_analysed() {
    let dir = temp_dir("long", "minute");
    let t0 = write_long_spin(&dir.join("minute.wav"), 60);
    let (ok, out, err) = cli_in(&dir, &["experiment", "analyze", "minute.wav", "--json"]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let used = v["recording"]["used"].as_str().unwrap_or_default();
    assert!(!used.contains("decimated"), "{used}");
    let (beta, t) = (
        v["result"]["law"]["beta"].as_f64().unwrap(),
        v["result"]["law"]["t0"].as_f64().unwrap(),
    );
    assert!((beta - 2.0).abs() < 0.05, "{beta}");
    assert!((t - t0).abs() < 0.05, "{t} against {t0}");
    if std::env::var("ROLLING_DISK_KEEP_MINUTE").is_err() {
        std::fs::remove_dir_all(&dir).ok();
    } else {
        println!("kept {}", dir.display());
    }
}
