//! Sound recordings as people make them: any rate, any coding, a phone's room; the pitch track's
//! independence of the sample rate, its precision against the light signal's, and refusals
//! that list only what failed.

use experiment::plausibility::Plausibility;
use experiment::recording::parse_recording;
use experiment::sound::Voice;
use experiment::{
    analyze, analyze_sound, encode_sound, law_sound, law_trace, AnalysisSettings, Artifacts,
    Channels, Law, LightModel, Microphone, SoundAnalysis, SoundFormat, Trace, TrackSettings,
};
use physics::Disk;
use rubato::{
    Resampler, SincFixedIn, SincInterpolationParameters, SincInterpolationType, WindowFunction,
};

/// Eq 79's law with beta and Omega = 100 rad/s at 7 s before t0.
fn law(beta: f64) -> Law {
    Law {
        beta,
        c: 100f64.powf(beta + 2.0) * 7.0,
    }
}

fn sound_of(s: &Trace) -> Result<SoundAnalysis, String> {
    analyze_sound(s, &TrackSettings::default(), &Plausibility::default()).map_err(|e| e.to_string())
}

/// `v` at `from` S/s resampled to `to` S/s (rubato's windowed sinc), sample j at time j/to: the
/// resampler's output starts aligned with its input (its `output_delay` is already taken out; see
/// `the_resampler_keeps_time`).
fn resample(v: &[f64], from: u32, to: u32) -> Vec<f64> {
    let params = SincInterpolationParameters {
        sinc_len: 256,
        f_cutoff: 0.95,
        interpolation: SincInterpolationType::Cubic,
        oversampling_factor: 256,
        window: WindowFunction::BlackmanHarris2,
    };
    let ratio = f64::from(to) / f64::from(from);
    let mut r = SincFixedIn::<f64>::new(ratio, 1.0, params, 4096, 1).unwrap();
    let mut out: Vec<f64> = Vec::with_capacity((v.len() as f64 * ratio) as usize + 8192);
    let mut pos = 0;
    while pos + r.input_frames_next() <= v.len() {
        let n = r.input_frames_next();
        out.extend(&r.process(&[&v[pos..pos + n]], None).unwrap()[0]);
        pos += n;
    }
    out.extend(&r.process_partial(Some(&[&v[pos..]]), None).unwrap()[0]);
    // Flush the filter's tail with silence.
    for _ in 0..4 {
        out.extend(&r.process_partial::<&[f64]>(None, None).unwrap()[0]);
    }
    let want = (v.len() as f64 * ratio).round() as usize;
    out.truncate(want);
    out
}

/// The tool's own sound (eq 79 exactly, beta = 2, a phone's voice and room, hum) made at 48 kHz,
/// resampled by rubato to 22.05, 44.1 and 96 kHz and written as 16-bit, 24-bit and float WAV
/// and FLAC: each gives beta and t0 within their stated sigma of the 48 kHz analysis, and the
/// truth within 3 sigma.
#[test]
fn the_same_sound_at_every_rate_and_coding_gives_the_same_fit() {
    let mic = Microphone::phone(48_000, 5);
    let art = Artifacts {
        hum: 0.01,
        ..Artifacts::none()
    };
    let made = law_sound(&law(2.0), &mic, &art).unwrap();
    let truth = made.truth.clone().unwrap();
    let base = sound_of(&made).unwrap();
    println!("48 kHz as made: {base}");
    let (b0, t0) = (base.law(), truth.t0);
    assert!(b0.from_phase, "{base}");
    for rate in [22_050, 44_100, 48_000, 96_000] {
        let v = if rate == 48_000 {
            made.v.clone()
        } else {
            resample(&made.v, 48_000, rate)
        };
        for format in [
            SoundFormat::Wav,
            SoundFormat::Wav24,
            SoundFormat::WavFloat,
            SoundFormat::Flac,
        ] {
            let bytes = encode_sound(&v, rate, format).unwrap();
            let name = format!("{rate}-{format:?}");
            let rec = parse_recording(bytes, &name, Channels::Mix).unwrap();
            assert_eq!(rec.info.sample_rate, rate);
            assert_eq!(rec.info.samples, v.len());
            let a = sound_of(&rec.trace).unwrap_or_else(|e| panic!("{name}: {e}"));
            let f = a.law();
            assert!(f.from_phase, "{name}: {a}");
            println!(
                "{name:>16} ({}): beta {:.5} +- {:.5} (vs 48 kHz {:+.2} sigma, truth {:+.2}), \
                 t0 {:.6} +- {:.6} s (vs 48 kHz {:+.2} sigma, truth {:+.2})",
                rec.info.format,
                f.beta,
                f.beta_sigma,
                (f.beta - b0.beta) / f.beta_sigma,
                (f.beta - truth.beta) / f.beta_sigma,
                f.t0,
                f.t0_sigma,
                (f.t0 - b0.t0) / f.t0_sigma,
                (f.t0 - t0) / f.t0_sigma,
            );
            assert!((f.beta - b0.beta).abs() < f.beta_sigma, "{name}: {a}");
            assert!((f.t0 - b0.t0).abs() < f.t0_sigma, "{name}: {a}");
            assert!(
                (f.beta - truth.beta).abs() < 3.0 * f.beta_sigma,
                "{name}: {a}"
            );
            assert!((f.t0 - t0).abs() < 3.0 * f.t0_sigma, "{name}: {a}");
        }
    }
}

/// Exact-law sounds at 48 kHz with a phone's room noise and 50 Hz hum: beta within 0.05, t0
/// within 3 ms.
#[test]
fn exact_law_sounds_with_room_noise_and_hum_give_beta_and_t0() {
    for (beta, seed) in [(1.0, 1), (2.0, 2), (3.0, 3)] {
        let mic = Microphone::phone(48_000, seed);
        let art = Artifacts {
            hum: 0.02,
            seed,
            ..Artifacts::none()
        };
        let s = law_sound(&law(beta), &mic, &art).unwrap();
        let a = sound_of(&s).unwrap();
        println!("{a}");
        let t0 = s.truth.as_ref().unwrap().t0;
        let l = a.law();
        assert!(l.from_phase, "{a}");
        assert!((l.beta - beta).abs() < 0.05, "{a}");
        assert!((l.t0 - t0).abs() < 3e-3, "{a}");
        // The pitch track's fit, from which the phase's starts, meets the same bounds.
        assert!((a.fit.beta - beta).abs() < 0.05, "{a}");
        assert!((a.fit.t0 - t0).abs() < 3e-3, "{a}");
        assert!(!a.track.hum.is_empty(), "the hum was not found: {a}");
    }
}

/// Beta's sigma from the sound of a motion against the light signal's of the same motion
/// (eq 79 exactly, beta = 2, the scope's record: 10 s ending at 7.27 s), the sound's sigma the
/// mean over four noise seeds (one seed's sandwich estimate varies by a third), recorded by a
/// phone in a room of `room` rms with mains hum of `hum`; each seed's beta lies within 3 of
/// its sigmas of the truth.
fn sound_sigma_over_light(room: f64, hum: f64) -> f64 {
    let l = law(2.0);
    let light = law_trace(&l, &Disk::uniform(0.0375), &LightModel::default()).unwrap();
    let la = analyze(&light, &AnalysisSettings::default()).unwrap();
    let mut sigmas = Vec::new();
    for seed in 1..=4 {
        let mic = Microphone {
            sample_rate: 48_000,
            samples: 480_000,
            voice: Voice {
                room,
                ..Voice::phone()
            },
            noise: 0.003,
            seed,
            ..Microphone::default()
        };
        let art = Artifacts {
            hum,
            seed,
            ..Artifacts::none()
        };
        let sa = sound_of(&law_sound(&l, &mic, &art).unwrap()).unwrap();
        let s = sa.law();
        assert!(s.from_phase, "{sa}");
        println!(
            "seed {seed}: beta from sound {:.5} +- {:.5}",
            s.beta, s.beta_sigma
        );
        assert!((s.beta - 2.0).abs() < 3.0 * s.beta_sigma, "{sa}");
        sigmas.push(s.beta_sigma);
    }
    let mean = sigmas.iter().sum::<f64>() / sigmas.len() as f64;
    let ratio = mean / la.eq84.beta_sigma;
    println!(
        "room {room}, hum {hum}: beta from light {:.5} +- {:.5}; from sound, mean sigma \
         {mean:.5}: ratio of sigmas {ratio:.2}",
        la.eq84.beta, la.eq84.beta_sigma
    );
    ratio
}

/// In a phone's room (0.01 rms), without hum.
#[test]
#[ignore = "not met: beta's sigma from sound is 2.32 times the light signal's (mean 0.000353 against 0.000152); the Cramer-Rao bound on the whole sound is 1.74 of the light's, on the sound up to 1 ms before t0 (where the phase fit stops at the latest) 2.02, and the fit is at 1.15 of that; a fit within 2x would have to come within 1.147 of the bound on the whole sound, reading it to within 0.1 ms of t0 while its own t0 sigma is 84 us; the disk leaves the plane 1.13 ms before t0, where eq 79 stops holding, and the bound on the sound before that is 2.04 of the light's (tests/experiment_sound_bound.rs, docs/experiment.md)"]
fn beta_from_sound_is_about_as_precise_as_from_light() {
    let ratio = sound_sigma_over_light(Voice::phone().room, 0.0);
    assert!(ratio < 2.0, "{ratio}");
}

/// In a quiet room (0.003 rms, where the Cramér-Rao bound on the sound is 0.76 of the light's
/// sigma: tests/experiment_sound_bound.rs) with 2 % of 50 Hz hum, the sound's sigma is within
/// twice the light's.
#[test]
fn beta_from_sound_in_a_quiet_room_is_about_as_precise_as_from_light() {
    let ratio = sound_sigma_over_light(0.003, 0.02);
    assert!(ratio < 2.0, "{ratio}");
    crate::common::experiment_docs_say(&[format!(
        "with 2 % of hum the fit's sigma is {ratio:.2} times the light's"
    )]);
}

/// What is not a spin-down is refused, with only the checks that failed.
#[test]
fn noise_tones_chirps_and_spin_ups_are_refused_with_what_failed() {
    let fs = 48_000.0;
    let n = 480_000;
    let make = |name: &str, f: &dyn Fn(f64) -> f64| -> Trace {
        // Phase by the midpoint rule of the frequency f(t) (Hz).
        let (mut psi, mut v) = (0.0, Vec::with_capacity(n));
        let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
        for j in 0..n {
            let t = j as f64 / fs;
            psi += std::f64::consts::TAU * f(t + 0.5 / fs) / fs;
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let u = (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
            v.push(0.3 * (psi.sin() + 0.5 * (2.0 * psi).sin()) + 0.01 * u);
        }
        Trace {
            source: name.into(),
            t: (0..n).map(|j| j as f64 / fs).collect(),
            v,
            truth: None,
        }
    };
    let cases: Vec<(&str, Trace)> = vec![
        ("tone", make("tone", &|_| 40.0)),
        ("chirp", make("chirp", &|t| 20.0 + 8.0 * t)),
        (
            "spin-up",
            make("spin-up", &|t| 60.0 * (1.0 - (-t / 2.0).exp()) + 5.0),
        ),
    ];
    for (name, tr) in &cases {
        let e = sound_of(tr).unwrap_err();
        println!("{name}: {e}");
        assert!(
            e.contains("not a spin-down") || e.contains("cannot be fitted"),
            "{e}"
        );
        assert_only_failures(&e);
    }
    let mut noise = make("noise", &|_| 40.0);
    let mut state: u64 = 7;
    for x in &mut noise.v {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        *x = ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 0.5;
    }
    let e = sound_of(&noise).unwrap_err();
    println!("noise: {e}");
    assert!(e.contains("not a spin-down"), "{e}");
    assert_only_failures(&e);
}

/// Every number a refusal quotes fails its threshold.
fn assert_only_failures(e: &str) {
    let after = |key: &str| -> Option<f64> {
        let i = e.find(key)? + key.len();
        let num: String = e[i..]
            .chars()
            .take_while(|c| c.is_ascii_digit() || *c == '.' || *c == '-')
            .collect();
        num.parse().ok()
    };
    if let Some(tau) = after("Kendall tau of t and Omega ") {
        assert!(tau < 0.5, "a passed Kendall check is listed: {e}");
    }
    if let Some(rise) = after("rises by a factor ") {
        assert!(rise < 1.5, "a passed rise check is listed: {e}");
    }
    if let Some(r2) = after("(R^2 = ") {
        assert!(r2 < 0.99, "a passed R^2 check is listed: {e}");
    }
}

/// A header-only or one-sample WAV is refused as a WAV (not as a CSV); a stereo recording's
/// channel can be chosen; a channel it does not have is refused with the count.
#[test]
fn short_wavs_and_channels_are_handled_as_sound() {
    for samples in [0usize, 1] {
        let v = vec![0.1; samples];
        let bytes = encode_sound(&v, 48_000, SoundFormat::Wav).unwrap();
        let e = parse_recording(bytes.clone(), "short.wav", Channels::Mix)
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("short.wav: WAV") && !e.contains("CSV"), "{e}");
        assert!(e.contains(&format!("{samples} sample(s)")), "{e}");
        let e = experiment::wav::parse_wav(&bytes, "short.wav")
            .unwrap_err()
            .to_string();
        assert!(!e.contains("CSV"), "{e}");
    }
    // Stereo: channel 1 a 50 Hz tone, channel 2 silence.
    let spec = hound::WavSpec {
        channels: 2,
        sample_rate: 8000,
        bits_per_sample: 16,
        sample_format: hound::SampleFormat::Int,
    };
    let mut cur = std::io::Cursor::new(Vec::new());
    {
        let mut w = hound::WavWriter::new(&mut cur, spec).unwrap();
        for j in 0..8000 {
            let x = (std::f64::consts::TAU * 50.0 * j as f64 / 8000.0).sin();
            w.write_sample((16000.0 * x) as i16).unwrap();
            w.write_sample(0i16).unwrap();
        }
        w.finalize().unwrap();
    }
    let bytes = cur.into_inner();
    let rms = |c: Channels| {
        let r = parse_recording(bytes.clone(), "st.wav", c).unwrap();
        let v = &r.trace.v;
        ((v.iter().map(|x| x * x).sum::<f64>()) / v.len() as f64).sqrt()
    };
    let (mix, one, two) = (
        rms(Channels::Mix),
        rms(Channels::One(1)),
        rms(Channels::One(2)),
    );
    assert!(
        (one - 16000.0 / 32768.0 / 2f64.sqrt()).abs() < 1e-3,
        "{one}"
    );
    assert!((mix - one / 2.0).abs() < 1e-9 && two == 0.0, "{mix} {two}");
    let e = parse_recording(bytes, "st.wav", Channels::One(3))
        .unwrap_err()
        .to_string();
    assert!(e.contains("channel 3") && e.contains("has 2"), "{e}");
    let e = parse_recording(b"hello, world".to_vec(), "x.mp3", Channels::Mix)
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("x.mp3: ") && e.contains("export"), "{e}");
}

/// The resampling keeps time: a 7 Hz line's phase after resampling from 48 kHz lies within
/// 30 us of the original's (t0's sigma from sound is about 80 us).
#[test]
fn the_resampler_keeps_time() {
    for to in [22_050u32, 44_100, 96_000] {
        let w = std::f64::consts::TAU * 7.0;
        let v: Vec<f64> = (0..96_000)
            .map(|j| (w * j as f64 / 48_000.0).sin())
            .collect();
        let r = resample(&v, 48_000, to);
        // The phase over one second (seven whole cycles) in the middle.
        let (mut c, mut s) = (0.0, 0.0);
        for (j, x) in r.iter().enumerate().skip(to as usize / 2).take(to as usize) {
            let ph = w * j as f64 / f64::from(to);
            c += x * ph.cos();
            s += x * ph.sin();
        }
        let lag = -c.atan2(s) / w;
        println!("{to} S/s: lag {:+.1} us", 1e6 * lag);
        assert!(lag.abs() < 30e-6, "{to}: {lag}");
    }
}

/// The tool's own sound encoded as MP3, Ogg Vorbis and M4A/AAC (`tests/fixtures/sound`, see its
/// PROVENANCE.md) gives the beta and t0 of the WAV of the same samples within their stated
/// sigma, with the file's format reported and the encoder's priming left out.
#[test]
fn compressed_recordings_give_the_wavs_fit() {
    let dir = std::env::temp_dir().join(format!("rolling-disk-compressed-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let full = dir.join("full.wav");
    crate::common::succeeds(
        std::process::Command::new(env!("CARGO_BIN_EXE_rolling-disk"))
            .args([
                "experiment",
                "simulate",
                "spin-down",
                "--rate",
                "44100",
                "--seed",
                "1",
            ])
            .arg("--wav")
            .arg(&full),
    );
    let rec = experiment::read_recording(&full, Channels::Mix).unwrap();
    let cut = &rec.trace.v[132_300..];
    let wav = parse_recording(
        encode_sound(cut, 44_100, SoundFormat::Wav).unwrap(),
        "cut.wav",
        Channels::Mix,
    )
    .unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    let base = sound_of(&wav.trace).unwrap();
    let b = base.law();
    println!("WAV: {base}");
    assert!(b.from_phase, "{base}");
    let fixtures = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/sound");
    for (file, format) in [
        ("spin-down-end.mp3", "MP3"),
        ("spin-down-end.ogg", "Ogg, Vorbis"),
        ("spin-down-end.m4a", "M4A/MP4, Advanced Audio Coding"),
    ] {
        let r = experiment::read_recording(fixtures.join(file), Channels::Mix).unwrap();
        assert!(
            r.info.format.starts_with(format),
            "{file}: {}",
            r.info.format
        );
        assert_eq!(r.info.sample_rate, 44_100, "{file}");
        assert_eq!(r.info.samples, cut.len(), "{file}: {}", r.info);
        let a = sound_of(&r.trace).unwrap_or_else(|e| panic!("{file}: {e}"));
        // The phase fit's own sigmas (the noise's, without the law's drift, which the WAV shares).
        let f = a.phase.as_ref().unwrap_or_else(|| panic!("{file}: {a}"));
        println!(
            "{file} ({}): beta {:.5} +- {:.5} ({:+.2} sigma from the WAV's), t0 {:.6} +- {:.6} s \
             ({:+.2} sigma)",
            r.info.format,
            f.beta,
            f.beta_sigma,
            (f.beta - b.beta) / f.beta_sigma,
            f.t0,
            f.t0_sigma,
            (f.t0 - b.t0) / f.t0_sigma
        );
        assert!((f.beta - b.beta).abs() < f.beta_sigma, "{file}: {a}");
        assert!((f.t0 - b.t0).abs() < f.t0_sigma, "{file}: {a}");
    }
}
