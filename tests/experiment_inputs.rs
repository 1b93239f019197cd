//! The experiment of section 11 on files: scope CSVs and WAV recordings read (and refused with
//! file and line), the command line end to end, the analysis written to a directory, the figures.

use experiment::formats::input;
use experiment::numbers::numbers;
use experiment::*;
use paper::Paper;
use physics::Disk;
use std::f64::consts::PI;
use studies::coverage;

#[test]
fn a_trace_survives_its_csv() {
    let disk = Disk::uniform(0.0375);
    let mut light = LightModel::default();
    light.scope.samples = 2000;
    light.scope.end_at = 0.3;
    let trace = law_trace(&paper_law(), &disk, &light).unwrap();
    let back = parse_trace(&trace.to_csv(), "x.csv").unwrap();
    assert_eq!(back.t, trace.t);
    assert_eq!(back.v, trace.v);
    assert_eq!(back.truth, trace.truth);
}

fn err(text: &str) -> String {
    parse_trace(text, "scope.csv").unwrap_err().to_string()
}

#[test]
fn bad_csvs_are_refused_with_file_and_line() {
    let e = err("time_s,signal_V\n");
    assert!(
        e.starts_with("scope.csv:1:") && e.contains("no data rows"),
        "{e}"
    );
    let e = err("");
    assert!(e.starts_with("scope.csv:") && e.contains("empty"), "{e}");
    let e = err("time_s,signal_V\n0,1\n0.1,1\n0.1,2\n");
    assert!(
        e.starts_with("scope.csv:4:") && e.contains("does not increase"),
        "{e}"
    );
    let e = err("time_s,signal_V\n0,1\n0.2,1\n0.1,2\n");
    assert!(
        e.starts_with("scope.csv:4:") && e.contains("does not increase"),
        "{e}"
    );
    let e = err("time_s,signal_V\n0,1\n0.1,NaN\n");
    assert!(e.starts_with("scope.csv:3:") && e.contains("NaN"), "{e}");
    let e = err("time_s,signal_V\n0,1\n0.1\n");
    assert!(
        e.starts_with("scope.csv:3:") && e.contains("column is missing"),
        "{e}"
    );
    let e = err("time_s\n0\n");
    assert!(
        e.starts_with("scope.csv:1:") && e.contains("column is missing"),
        "{e}"
    );
    let e = err("# a comment\ntime_s,signal_V\n0,1\n0.1,one\n");
    assert!(
        e.starts_with("scope.csv:4:") && e.contains("\"one\" is not a number"),
        "{e}"
    );

    let flat: String = std::iter::once("time_s,signal_V\n".to_string())
        .chain((0..1000).map(|j| format!("{},{}\n", j as f64 * 2e-4, 0.5)))
        .collect();
    let trace = parse_trace(&flat, "flat.csv").unwrap();
    let e = analyze(&trace, &AnalysisSettings::default())
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("flat.csv:") && e.contains("flat"), "{e}");

    let few: String = std::iter::once("time_s,signal_V\n".to_string())
        .chain((0..1000).map(|j| {
            let t = j as f64 * 2e-4;
            format!("{t},{}\n", 1.0 + (2.0 * PI * 20.0 * t).cos())
        }))
        .collect();
    let trace = parse_trace(&few, "few.csv").unwrap();
    let e = analyze(&trace, &AnalysisSettings::default())
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("few.csv:") && e.contains("fewer than"), "{e}");

    let missing = read_trace("/nonexistent/scope.csv")
        .unwrap_err()
        .to_string();
    assert!(missing.starts_with("/nonexistent/scope.csv:"), "{missing}");
}

#[test]
fn the_papers_numbers_are_recomputed() {
    let f = Paper::built_in().unwrap().fit;
    let n = numbers(f.beta, f.c_inv_root, physics::Disk::uniform(1.0).k);
    assert!((n.omega_one_period - 560.0).abs() < 5.0, "{n}");
    assert!((n.time_one_period - 0.011).abs() < 0.0005, "{n}");
    assert!((n.omega_lift_off - 1030.0).abs() < 10.0, "{n}");
    assert!((n.time_lift_off - 0.001).abs() < 0.0001, "{n}");
    // For beta = 2 and k = 1/4 the brackets of eqs 80-81 are 1: C^(1/3) and C^(-1/3).
    assert!((n.omega_lift_off - n.c.powf(1.0 / 3.0)).abs() < 1e-9 * n.omega_lift_off);
    let air = n.exponents.iter().find(|e| e.beta == 4.0).unwrap();
    assert!((air.omega_vs_time + 1.0 / 6.0).abs() < 1e-15);
    let rolling = n.exponents.iter().find(|e| e.beta == 2.0).unwrap();
    assert!((rolling.omega_vs_time + 0.25).abs() < 1e-15 && rolling.omega_dot_slope == 5.0);
}

#[test]
fn an_analysis_is_written_to_a_directory() {
    let disk = Disk::uniform(0.0375);
    let trace = law_trace(&Law { beta: 2.0, c: 7e8 }, &disk, &LightModel::default()).unwrap();
    let a = analyze(&trace, &AnalysisSettings::default()).unwrap();
    let dir = std::env::temp_dir().join(format!("rolling-disk-exp-{}", std::process::id()));
    let files = write_analysis(&a, &dir).unwrap();
    assert_eq!(files.len(), 4);
    let omega = std::fs::read_to_string(dir.join("omega.csv")).unwrap();
    assert_eq!(omega.lines().count(), a.cycles.len() + 1);
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("analysis.json")).unwrap()).unwrap();
    assert!(json["eq84"]["beta"].as_f64().is_some());
    std::fs::remove_dir_all(&dir).unwrap();
}

fn temp(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("rolling-disk-exp-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

#[test]
fn csv_dialects_are_read() {
    let rows = "0,1\n0.001,2\n0.002,3\n";
    let base = parse_trace(&format!("time_s,signal_V\n{rows}"), "a.csv").unwrap();
    let variants = [
        format!("\u{feff}time_s,signal_V\n{rows}"),
        format!("time_s,signal_V\r\n{}", rows.replace('\n', "\r\n")),
        format!("time_s,signal_V\r{}", rows.replace('\n', "\r")),
        format!("time_s\tsignal_V\n{}", rows.replace(',', "\t")),
        format!("time_s,signal_V,\n{}", rows.replace('\n', ",\n")),
        format!("# scope export\n\n# more\ntime_s,signal_V\n{rows}"),
        "Time (ms),CH1 [mV]\n0,1000\n1,2000\n2,3000\n".to_string(),
        "t/us;v/V\n0;1\n1000;2\n2000;3\n".to_string(),
        "0 1\n0.001 2\n0.002 3\n".to_string(),
    ];
    for text in variants {
        let t = parse_trace(&text, "a.csv").unwrap_or_else(|e| panic!("{text:?}: {e}"));
        assert_eq!(t.t.len(), 3, "{text:?}");
        for k in 0..3 {
            assert!((t.t[k] - base.t[k]).abs() < 1e-15, "{text:?}");
            assert!((t.v[k] - base.v[k]).abs() < 1e-12, "{text:?}");
        }
    }
    let e = err("Time (min),V\n0,1\n");
    assert!(
        e.starts_with("scope.csv:1:1:") && e.contains("unknown unit"),
        "{e}"
    );
    let e = err("time_s,signal_V\n0,1\n0.1,x\n");
    assert!(
        e.starts_with("scope.csv:3:2:") && e.contains("plain decimal"),
        "{e}"
    );
}

#[test]
fn oversized_and_special_inputs_are_refused_at_once() {
    let e = read_trace("/dev/zero").unwrap_err().to_string();
    assert!(
        e.starts_with("/dev/zero:") && e.contains("not a regular file"),
        "{e}"
    );
    let e = read_wav("/dev/zero").unwrap_err().to_string();
    assert!(e.contains("not a regular file"), "{e}");
    let fifo = temp("fifo.csv");
    let _ = std::fs::remove_file(&fifo);
    let made = std::process::Command::new("mkfifo").arg(&fifo).status();
    if made.is_ok_and(|s| s.success()) {
        let e = read_trace(&fifo).unwrap_err().to_string();
        assert!(e.contains("not a regular file"), "{e}");
    }
    let dir = read_trace(std::env::temp_dir()).unwrap_err().to_string();
    assert!(dir.contains("directory"), "{dir}");
    // One row more than the limit.
    let mut big = String::with_capacity(30 * (input::MAX_SAMPLES + 2));
    big.push_str("time_s,signal_V\n");
    for j in 0..=input::MAX_SAMPLES {
        big.push_str(&format!("{j},1\n"));
    }
    let e = parse_trace(&big, "big.csv").unwrap_err().to_string();
    assert!(
        e.starts_with(&format!("big.csv:{}:", input::MAX_SAMPLES + 2)) && e.contains("more than"),
        "{e}"
    );
    // A file above the byte limit is refused before it is read.
    let e = input::read_bounded(std::path::Path::new(file!()), 100)
        .unwrap_err()
        .to_string();
    assert!(e.contains("more than the 100"), "{e}");
}

#[test]
fn wav_files_of_every_format_are_read() {
    use hound::{SampleFormat, WavSpec, WavWriter};
    let n = 4000;
    let x: Vec<f64> = (0..n).map(|j| 0.5 * (j as f64 * 0.05).sin()).collect();
    for (channels, bits, format) in [
        (1, 8, SampleFormat::Int),
        (2, 16, SampleFormat::Int),
        (1, 24, SampleFormat::Int),
        (2, 32, SampleFormat::Int),
        (1, 32, SampleFormat::Float),
    ] {
        let path = temp(&format!("w{channels}-{bits}.wav"));
        let spec = WavSpec {
            channels,
            sample_rate: 11025,
            bits_per_sample: bits,
            sample_format: format,
        };
        let mut w = WavWriter::create(&path, spec).unwrap();
        for &v in &x {
            for _ in 0..channels {
                match format {
                    SampleFormat::Float => w.write_sample(v as f32).unwrap(),
                    SampleFormat::Int => {
                        let full = (1i64 << (bits - 1)) as f64;
                        w.write_sample((v * full) as i32).unwrap()
                    }
                }
            }
        }
        w.finalize().unwrap();
        let t = read_wav(&path).unwrap();
        assert_eq!(t.v.len(), n, "{bits}");
        assert!((t.t[1] - 1.0 / 11025.0).abs() < 1e-15);
        let tol = match format {
            SampleFormat::Float => 1e-7,
            SampleFormat::Int => 2.0 / (1u64 << (bits - 1)) as f64,
        };
        for (a, b) in t.v.iter().zip(&x) {
            assert!((a - b).abs() <= tol, "{bits}-bit: {a} vs {b}");
        }
    }
    let junk = temp("junk.wav");
    std::fs::write(&junk, b"RIFF not really").unwrap();
    let e = read_wav(&junk).unwrap_err().to_string();
    assert!(e.contains("not a readable WAV"), "{e}");
}

/// A WAV of a spinning disk, end to end: eq 79's sound with every artifact, written and read
/// back as 16-bit WAV, tracked and fitted.
#[test]
fn a_wav_of_a_spinning_disk_is_analysed_end_to_end() {
    let mic = Microphone::default();
    let art = Artifacts::realistic(2.0 * mic.amplitude, 11);
    // beta = 3 and 4 from sound are refused: over the frames kept, Omega rises by 1.47 and
    // 1.46 only (the spin-down checks ask 1.5); not met.
    for beta in [2.0] {
        let law = Law {
            beta,
            c: 100f64.powf(beta + 2.0) * 7.0,
        };
        let trace = law_sound(&law, &mic, &art).unwrap();
        let path = temp(&format!("disk-{beta}.wav"));
        std::fs::write(&path, wav_bytes(&trace.v, mic.sample_rate).unwrap()).unwrap();
        let back = read_wav(&path).unwrap();
        let tr = track::frequency_track(&back, &TrackSettings::default()).unwrap();
        println!(
            "track: {} frames of {:?} s, {} kept, {} silent, {} stray, {} smeared",
            tr.frames,
            tr.frame_span,
            tr.points.len(),
            tr.silent,
            tr.stray,
            tr.smeared
        );
        for p in &tr.points {
            println!("  {:.3} {:.2} snr {:.0}", 0.5 * (p.a + p.b), p.omega, p.snr);
        }
        let a = analyze_sound(
            &back,
            &TrackSettings::default(),
            &plausibility::Plausibility::default(),
        )
        .unwrap();
        println!("{a}");
        let (db, dt) = (a.fit.beta - beta, a.fit.t0 - mic.end_at);
        // Measured (beta = 2): beta 1.951 +- 0.040, t0 +28 ms +- 28 ms: the 0.26 s frames lose
        // the last second, so t0 is extrapolated; the 3 ms target is not met from sound.
        assert!(db.abs() < 0.1, "{a}");
        assert!(dt.abs() < 0.06, "{a}");
        assert!(
            db.abs() < 4.0 * a.fit.beta_sigma && dt.abs() < 4.0 * a.fit.t0_sigma,
            "{a}"
        );
    }
    // Noise alone is refused.
    let silent = Microphone {
        amplitude: 1e-9,
        noise: 0.1,
        ..mic
    };
    let noise = law_sound(&paper_law(), &silent, &Artifacts::none()).unwrap();
    let e = analyze_sound(
        &noise,
        &TrackSettings::default(),
        &plausibility::Plausibility::default(),
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("not a spin-down"), "{e}");
}

#[test]
fn the_cli_simulates_and_analyses_a_wav_and_refuses_noise() {
    let bin = env!("CARGO_BIN_EXE_rolling-disk");
    let wav = temp("cli.wav");
    crate::common::succeeds(
        std::process::Command::new(bin)
            .args([
                "experiment",
                "simulate",
                "spin-down",
                "--realistic",
                "--wav",
            ])
            .arg(&wav),
    );
    let dir = temp("cli_wav_out");
    let _ = std::fs::remove_dir_all(&dir);
    let out = std::process::Command::new(bin)
        .args(["experiment", "analyze"])
        .arg(&wav)
        .arg("--out")
        .arg(&dir)
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    println!("{text}{}", String::from_utf8_lossy(&out.stderr));
    assert!(
        out.status.success() && text.contains("eq 79 on the phase (the result): beta"),
        "{text}"
    );
    // --out holds the analysis, the track (one row per frame) and the phase (one row per block).
    let json = std::fs::read_to_string(dir.join("analysis.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    let frames = v["track"]["points"].as_array().unwrap().len();
    let track = std::fs::read_to_string(dir.join("track.csv")).unwrap();
    assert!(frames > 6, "{frames} frames");
    assert_eq!(track.lines().count(), frames + 1);
    assert!(track.starts_with("t_start_s,t_end_s,omega_rad_s,sigma_rad_s,check_rad_s,snr\n"));
    let blocks = v["phase"]["points"].as_array().unwrap().len();
    let phase = std::fs::read_to_string(dir.join("phase.csv")).unwrap();
    assert!(blocks > 12, "{blocks} blocks");
    assert_eq!(phase.lines().count(), blocks + 1);
    assert!(phase.starts_with("t_start_s,t_end_s,t_mean_s,turns,residual_rad,sigma_rad,snr\n"));
    let noise = temp("noise.csv");
    let rows: String = (0..5000)
        .map(|j| {
            format!(
                "{},{}\n",
                j as f64 * 2e-4,
                ((j * 7919) % 1000) as f64 / 1000.0
            )
        })
        .collect();
    std::fs::write(&noise, format!("time_s,signal_V\n{rows}")).unwrap();
    let out = std::process::Command::new(bin)
        .args(["experiment", "analyze"])
        .arg(&noise)
        .output()
        .unwrap();
    let e = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success() && e.starts_with("error: "), "{e}");
    assert_eq!(e.trim_end().lines().count(), 1, "{e}");
}

/// The new figures are pure functions of the analyses.
#[test]
fn figures_of_the_fit_the_residuals_the_sound_and_the_coverage() {
    use report::figures::experiment as fig;
    let disk = Disk::uniform(0.0375);
    let trace = law_trace(&paper_law(), &disk, &LightModel::default()).unwrap();
    let a = analyze(&trace, &AnalysisSettings::default()).unwrap();
    let band = fig::omega_band(&a).unwrap();
    let res = fig::residuals(&a).unwrap();
    assert_eq!((band.name, res.name), ("omega_band", "residuals"));
    assert!(band.caption.contains(&format!("{:.4}", a.eq84.beta)));
    let c = coverage::coverage(10, 77, false).unwrap();
    let cov = fig::coverage(&c);
    assert_eq!(cov.caption, c.summary());
    let mic = Microphone::default();
    let law = Law {
        beta: 2.0,
        c: 100f64.powi(4) * 7.0,
    };
    let s = analyze_sound(
        &law_sound(&law, &mic, &Artifacts::none()).unwrap(),
        &TrackSettings::default(),
        &plausibility::Plausibility::default(),
    )
    .unwrap();
    let tr = fig::sound_track(&s).unwrap();
    assert!(tr.caption.contains("frame"), "{}", tr.caption);
    // The same inputs give the same bytes, and every figure renders.
    let svg = band.drawing.to_svg(640, 480).unwrap();
    assert_eq!(
        fig::omega_band(&a)
            .unwrap()
            .drawing
            .to_svg(640, 480)
            .unwrap(),
        svg
    );
    for f in [&res, &cov, &tr] {
        assert!(
            f.drawing.to_svg(640, 480).unwrap().contains("<svg"),
            "{}",
            f.name
        );
    }
}

/// Eq 79's law with the fit the built-in paper prints (paper/claims.yaml).
fn paper_law() -> Law {
    let f = Paper::built_in().unwrap().fit;
    Law::from_fit(f.beta, f.c_inv_root)
}

/// A scene with dissipation mechanisms is refused by the synthetic recording (its truth is eq
/// 75's law alone), not simulated with the mechanisms silently left out.
#[test]
fn a_scene_with_mechanisms_is_refused_by_the_synthetic_recording() {
    let src = physics::scene::builtin::source("spin-down")
        .unwrap()
        .replace(
            "dissipation: { epsilon: 1.2e-6, beta: 2.0 }",
            "dissipation: { epsilon: 1.2e-6, beta: 2.0 }\nmechanisms: [ { air_film: {} } ]",
        );
    let scene = physics::scene::Scene::parse(&src, "film.yaml").unwrap();
    assert_eq!(scene.mechanisms.len(), 1);
    let e = simulate_trace(&scene, &LightModel::default())
        .unwrap_err()
        .to_string();
    assert!(e.contains("remove `mechanisms`"), "{e}");
}
