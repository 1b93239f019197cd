//! Recordings read by their content, not their name (a raw AAC stream, a WAV without an
//! extension), and the synthetic sound at any rate the help states.

use experiment::recording::{parse_recording, ADTS_PRIMING};
use experiment::Channels;
use std::path::{Path, PathBuf};

/// The fixture recordings (see `tests/fixtures/sound/PROVENANCE.md`).
fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/sound")
        .join(name)
}

/// The AAC frames of an M4A file as a raw ADTS stream: each frame behind its 7-byte header (no
/// CRC), the profile, rate index and channels from the track's AudioSpecificConfig.
fn adts_of_m4a(bytes: &[u8]) -> Vec<u8> {
    use symphonia::core::formats::FormatOptions;
    use symphonia::core::io::MediaSourceStream;
    use symphonia::core::meta::MetadataOptions;
    use symphonia::core::probe::Hint;
    let mss = MediaSourceStream::new(
        Box::new(std::io::Cursor::new(bytes.to_vec())),
        Default::default(),
    );
    let mut hint = Hint::new();
    hint.with_extension("m4a");
    let mut reader = symphonia::default::get_probe()
        .format(
            &hint,
            mss,
            &FormatOptions::default(),
            &MetadataOptions::default(),
        )
        .unwrap()
        .format;
    let track = reader.default_track().unwrap();
    let id = track.id;
    let asc = track.codec_params.extra_data.clone().unwrap();
    // AudioSpecificConfig: object type (5 bits), sampling-frequency index (4), channels (4).
    let object = asc[0] >> 3;
    let index = ((asc[0] & 7) << 1) | (asc[1] >> 7);
    let chans = (asc[1] >> 3) & 0xF;
    let mut out = Vec::new();
    while let Ok(packet) = reader.next_packet() {
        if packet.track_id() != id {
            continue;
        }
        let len = packet.data.len() + 7;
        out.extend_from_slice(&[
            0xFF,
            0xF1,
            ((object - 1) << 6) | (index << 2) | (chans >> 2),
            ((chans & 3) << 6) | (len >> 11) as u8,
            (len >> 3) as u8,
            ((len & 7) << 5) as u8 | 0x1F,
            0xFC,
        ]);
        out.extend_from_slice(&packet.data);
    }
    out
}

/// A raw AAC stream (ADTS) of the M4A fixture's own frames, without a name that says what it
/// is, is recognised by its bytes as raw AAC (not MP3), and read with the encoder's priming left
/// out: the same samples as the M4A, whose edit list records its priming.
#[test]
fn raw_adts_aac_is_read_by_content_with_its_priming_left_out() {
    let m4a_bytes = std::fs::read(fixture("spin-down-end.m4a")).unwrap();
    let adts = adts_of_m4a(&m4a_bytes);
    let m4a = parse_recording(m4a_bytes, "spin-down-end.m4a", Channels::Mix).unwrap();
    let raw = parse_recording(adts, "spin-down-end", Channels::Mix).unwrap();
    println!("{}\n{}", m4a.info, raw.info);
    assert!(
        raw.info
            .format
            .starts_with("raw AAC (ADTS), Advanced Audio Coding"),
        "{}",
        raw.info.format
    );
    assert!(
        raw.info
            .format
            .contains(&format!("{ADTS_PRIMING} encoder priming samples left out")),
        "{}",
        raw.info.format
    );
    // The M4A's edit list also cuts the encoder's padding at the end; the raw stream keeps it.
    assert!(raw.trace.v.len() >= m4a.trace.v.len(), "{}", raw.info);
    let worst = m4a
        .trace
        .v
        .iter()
        .zip(&raw.trace.v)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    println!("largest difference from the M4A's samples: {worst:e}");
    assert!(
        worst == 0.0,
        "the raw stream's samples are shifted: {worst:e}"
    );
}

/// Runs the tool in `dir`.
fn tool(dir: &Path, args: &[&str]) -> (bool, String, String) {
    crate::common::cli_in(dir, args)
}

/// `simulate --rate` makes a sound at rates the solver could not sample every sample of (above
/// about 106 kS/s for the default phone's 10 s), up to the help's 384000; and a WAV renamed
/// without an extension is analysed as the sound it is (its bytes say so), not read as a CSV.
#[test]
fn any_stated_rate_simulates_and_a_wav_without_extension_is_analysed() {
    let dir = crate::common::temp_dir("formats", "rates");
    for rate in ["106000", "384000"] {
        let wav = format!("r{rate}.wav");
        let (ok, out, err) = tool(
            &dir,
            &[
                "experiment",
                "simulate",
                "spin-down",
                "--rate",
                rate,
                "--wav",
                &wav,
            ],
        );
        assert!(ok, "--rate {rate}: {out}{err}");
        let (_, got) = crate::common::read_wav_i16(&dir.join(&wav));
        assert_eq!(got.to_string(), rate);
    }
    std::fs::rename(dir.join("r106000.wav"), dir.join("recording")).unwrap();
    let (ok, out, err) = tool(&dir, &["experiment", "analyze", "recording"]);
    let _ = std::fs::remove_dir_all(&dir);
    assert!(ok, "{out}{err}");
    assert!(out.contains("beta"), "{out}");
    assert!(!err.contains("CSV") && !out.contains("CSV"), "{out}{err}");
}

/// The heading at the sound's rate where the solver samples every other sample (the samples
/// between by a cubic) agrees with the heading where it samples every one: the same scene at
/// 318 kS/s over 2.0 s (stride 2) and over 1.7 s (stride 1), 95,400 samples apart. The
/// interpolated samples differ from the solver's by no more than the two runs' solver-sampled
/// samples differ from each other (their integrations start from different states).
#[test]
fn the_heading_between_sampled_rows_is_the_solvers() {
    let scene = physics::scene::Scene::load("spin-down").unwrap();
    let rate = 318_000.0;
    let long = experiment::simulate::simulate_motion(&scene, 2.0, rate, 600_000).unwrap();
    let short = experiment::simulate::simulate_motion(&scene, 1.7, rate, 500_000).unwrap();
    let shift = 95_400;
    // (largest difference, samples compared) on the long run's sampled and interpolated samples.
    let mut sampled = (0.0f64, 0usize);
    let mut between = (0.0f64, 0usize);
    for (j, h) in short.heading.iter().enumerate() {
        let l = long.heading[j + shift];
        if h.is_finite() && l.is_finite() {
            let s = if (j + shift) % 2 == 0 {
                &mut sampled
            } else {
                &mut between
            };
            s.0 = s.0.max((h - l).abs());
            s.1 += 1;
        }
    }
    println!("heading differences: sampled {sampled:?}, interpolated {between:?} (rad, samples)");
    assert!(
        sampled.1 > 200_000 && between.1 > 200_000,
        "{sampled:?} {between:?}"
    );
    assert!(
        between.0 <= 2.0 * sampled.0 + 1e-9,
        "{sampled:?} {between:?}"
    );
}

/// 16-bit big-endian PCM samples of a signal of full scale 1, interleaved over `ch` channels
/// (each channel the signal times its number).
fn pcm16_be(v: &[f64], ch: usize) -> Vec<u8> {
    let mut out = Vec::new();
    for x in v {
        for c in 1..=ch {
            let s = (x * c as f64 / ch as f64 * 32767.0).round() as i16;
            out.extend_from_slice(&s.to_be_bytes());
        }
    }
    out
}

/// An AIFF file as its specification lays it out: `FORM`, `COMM` (channels, frames, 16 bits,
/// the rate as an 80-bit extended float) and `SSND`.
fn aiff_bytes(v: &[f64], rate: u32, ch: usize) -> Vec<u8> {
    let data = pcm16_be(v, ch);
    let e = 31 - rate.leading_zeros();
    let mut comm = (ch as u16).to_be_bytes().to_vec();
    comm.extend_from_slice(&(v.len() as u32).to_be_bytes());
    comm.extend_from_slice(&16u16.to_be_bytes());
    comm.extend_from_slice(&(16383 + e as u16).to_be_bytes());
    comm.extend_from_slice(&(u64::from(rate) << (63 - e)).to_be_bytes());
    let mut body = b"AIFF".to_vec();
    body.extend_from_slice(b"COMM");
    body.extend_from_slice(&(comm.len() as u32).to_be_bytes());
    body.extend_from_slice(&comm);
    body.extend_from_slice(b"SSND");
    body.extend_from_slice(&(data.len() as u32 + 8).to_be_bytes());
    body.extend_from_slice(&[0; 8]);
    body.extend_from_slice(&data);
    let mut file = b"FORM".to_vec();
    file.extend_from_slice(&(body.len() as u32).to_be_bytes());
    file.extend_from_slice(&body);
    file
}

/// A Core Audio file as Apple's specification lays it out: `caff` version 1, a `desc` chunk
/// (rate, `lpcm`, big-endian integers of 16 bits) and a `data` chunk.
fn caf_bytes(v: &[f64], rate: u32, ch: usize) -> Vec<u8> {
    let data = pcm16_be(v, ch);
    let mut file = b"caff\x00\x01\x00\x00desc".to_vec();
    file.extend_from_slice(&32i64.to_be_bytes());
    file.extend_from_slice(&f64::from(rate).to_be_bytes());
    file.extend_from_slice(b"lpcm");
    file.extend_from_slice(&0u32.to_be_bytes());
    for n in [2 * ch as u32, 1, ch as u32, 16] {
        file.extend_from_slice(&n.to_be_bytes());
    }
    file.extend_from_slice(b"data");
    file.extend_from_slice(&(data.len() as i64 + 4).to_be_bytes());
    file.extend_from_slice(&0u32.to_be_bytes());
    file.extend_from_slice(&data);
    file
}

/// AIFF and Core Audio (CAF) files are read by their content, whatever their name, and give the
/// samples written, channel by channel; an Ogg Opus file, which no decoder here reads, is named
/// as what its bytes say it is, with the conversion to do.
#[test]
fn aiff_and_caf_are_read_and_opus_is_named_by_its_bytes() {
    let v: Vec<f64> = (0..4410).map(|j| 0.5 * (j as f64 * 0.07).sin()).collect();
    for (bytes, what) in [
        (aiff_bytes(&v, 44_100, 2), "AIFF"),
        (caf_bytes(&v, 44_100, 2), "Core Audio (CAF)"),
    ] {
        for (k, gain) in [(1usize, 0.5), (2, 1.0)] {
            let r = parse_recording(bytes.clone(), "take1", Channels::One(k)).unwrap();
            assert!(r.info.format.starts_with(what), "{}", r.info);
            assert_eq!(
                (r.info.sample_rate, r.info.channels, r.trace.v.len()),
                (44_100, 2, v.len()),
                "{}",
                r.info
            );
            let err = r
                .trace
                .v
                .iter()
                .zip(&v)
                .map(|(a, b)| (a - gain * b).abs())
                .fold(0.0, f64::max);
            assert!(err < 1.0 / 32767.0, "{what} channel {k}: {err}");
        }
    }
    let mut opus = b"OggS\x00\x02".to_vec();
    opus.resize(28, 0);
    opus.extend_from_slice(b"OpusHead\x01\x01");
    opus.resize(200, 0);
    let e = parse_recording(opus, "take1", Channels::Mix)
        .unwrap_err()
        .to_string();
    println!("{e}");
    assert!(
        e.starts_with("take1: Ogg Opus recording: this tool has no Opus decoder")
            && e.contains("ffmpeg -i FILE.opus FILE.wav"),
        "{e}"
    );
}

/// A file whose content is no format read is refused naming its first bytes and the formats
/// read (never "save the CSV as UTF-8"); a WAV cut short says it is truncated; a text in
/// another encoding names the line of its first byte that is not UTF-8.
#[test]
fn unknown_content_names_its_bytes_and_a_cut_wav_says_truncated() {
    let dir = crate::common::temp_dir("formats", "content");
    let junk: Vec<u8> = (0..4000u32).map(|j| (j * 7919 % 251) as u8).collect();
    std::fs::write(dir.join("capture.bin"), &junk).unwrap();
    let (ok, _, err) = tool(&dir, &["experiment", "analyze", "capture.bin"]);
    assert!(!ok, "{err}");
    assert!(
        err.contains("the first bytes are 00 8a 19 a3") && err.contains("WAV, FLAC"),
        "{err}"
    );
    assert!(!err.contains("UTF-8"), "{err}");
    let v: Vec<f64> = (0..48_000).map(|j| 0.3 * (j as f64 * 0.05).sin()).collect();
    let wav = experiment::wav_bytes(&v, 48_000).unwrap();
    std::fs::write(dir.join("cut.wav"), &wav[..20_000]).unwrap();
    let (ok, _, err) = tool(&dir, &["experiment", "analyze", "cut.wav"]);
    assert!(!ok, "{err}");
    assert!(
        err.contains("truncated: it ends after 9978 of the 48000 samples"),
        "{err}"
    );
    std::fs::write(dir.join("head.wav"), &wav[..30]).unwrap();
    let (ok, _, err) = tool(&dir, &["experiment", "analyze", "head.wav"]);
    assert!(
        !ok && err.contains("truncated: its 30 bytes end inside the header"),
        "{err}"
    );
    std::fs::write(
        dir.join("latin.csv"),
        b"time_s,signal_V\n0,1\n# \xb5s\n0.1,2\n",
    )
    .unwrap();
    let (ok, _, err) = tool(&dir, &["experiment", "analyze", "latin.csv"]);
    let _ = std::fs::remove_dir_all(&dir);
    assert!(
        !ok && err.contains("line 3: byte") && err.contains("UTF-8"),
        "{err}"
    );
}
