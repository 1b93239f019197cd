//! The short spin's analysis on the phone study's recordings and on made cases: what it finds,
//! and each of its refusals provoked.

use super::*;
use crate::sound_analysis::analysis::analyze_sound;
use crate::sound_analysis::track::TrackSettings;
use crate::synthetic::phone_room::PhoneRoom;

/// A diagnostic, not a test of a claim: for each phone recording of `ROLLING_DISK_SEEDS`,
/// the track's frames, the short spin's seed against the truth, and the blocks it holds.
#[test]
#[ignore = "a diagnostic: prints each seed's short-spin seed and blocks"]
fn print_the_seeds_and_blocks() {
    let seeds = std::env::var("ROLLING_DISK_SEEDS").unwrap_or_else(|_| "75".into());
    for n in seeds
        .split(',')
        .filter_map(|s| s.trim().parse::<u64>().ok())
    {
        let room = PhoneRoom::draw(n);
        let trace = recording(n);
        let a = analyze_sound(&trace, &TrackSettings::default(), &Plausibility::default());
        let track = match &a {
            Ok(a) => a.track.clone(),
            Err(_) => {
                let w = physics::budget::Work::start("the diagnostic".to_string());
                match crate::sound_analysis::analysis::analyze_sound_keeping_track(
                    &trace,
                    &TrackSettings::default(),
                    &Plausibility::default(),
                    &w,
                ) {
                    Ok(a) => a.track,
                    Err(r) => match r.track {
                        Some(t) => t,
                        None => continue,
                    },
                }
            }
        };
        let truth = SVector::<f64, 3>::new(room.law.beta, room.t0(), room.law.c.ln());
        println!(
            "seed {n}: truth beta {:.3} t0 {:.4} ln C {:.3}, lead {:.2}, high-pass {:.0}",
            truth[0], truth[1], truth[2], room.lead, room.high_pass
        );
        for p in &track.points {
            println!(
                "  frame {:.3}-{:.3} f {:.2} +- {:.2} Hz (true {:.2})",
                p.a,
                p.b,
                p.omega / TAU,
                p.sigma / TAU,
                room.law.precession(room.t0() - 0.5 * (p.a + p.b)) / TAU
            );
        }
        let mut v = trace.v.clone();
        subtract_hum(&mut v, track.sample_rate, &track.hum);
        let rec = Samples {
            x: &v,
            t_start: trace.t[0],
            dt: 1.0 / track.sample_rate,
        };
        let Some(first) = track.points.first().map(|p| p.a) else {
            continue;
        };
        let seeded = seed(&rec, &track, first);
        println!("  seed {seeded:?}");
        for (name, law) in [("truth", Some(truth)), ("seed", seeded.map(|s| s.0))] {
            let Some(law) = law else { continue };
            let s = BlockSettings {
                min_snr: 0.0,
                ..BlockSettings::default()
            };
            let bl = blocks(&rec, &law, 0.0, (first, law[1] - 1e-3), false, &s);
            println!("  blocks by the {name}: {}", bl.len());
            for b in &bl {
                println!(
                    "    {:.3}-{:.3} turns {} base {} snrs {:?}",
                    b.a,
                    b.b,
                    b.turns,
                    b.base,
                    b.snrs.map(|x| x.round())
                );
            }
        }
        match a {
            Ok(a) => println!("  analysed: {}", a.law().beta - room.law.beta),
            Err(e) => println!("  refused: {e}"),
        }
    }
}

#[test]
fn students_quantile_matches_the_table() {
    // Two-sided 95 % points of Student's t (Abramowitz & Stegun, table 26.10).
    for (nu, t) in [
        (5.0, 2.5706),
        (6.0, 2.4469),
        (10.0, 2.2281),
        (20.0, 2.0860),
        (60.0, 2.0003),
    ] {
        let got = student_975(nu);
        assert!((got / t - 1.0).abs() < 5e-5, "nu = {nu}: {got} against {t}");
    }
}

/// The phone study's recording of `seed` ([`PhoneRoom::draw`]) as the tool reads it.
fn recording(seed: u64) -> Trace {
    PhoneRoom::draw(seed)
        .record()
        .unwrap()
        .read_back("phone.wav")
        .unwrap()
}

/// 8 s at 8 kS/s of a tone falling from 40 Hz by 2 % a second, with its second harmonic,
/// over a recorder's faint noise: a line the track follows over many frames, and that does
/// not rise.
fn falling_tone() -> Trace {
    use rand::SeedableRng;
    use rand_distr::{Distribution, Normal};
    let (fs, n) = (8000.0, 64_000);
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
    let normal = Normal::new(0.0f64, 0.003).unwrap();
    let v = (0..n)
        .map(|j| {
            let t = j as f64 / fs;
            let w = TAU * 40.0 * (t - 0.01 * t * t);
            0.3 * (w.sin() + 0.5 * (2.0 * w).sin()) + normal.sample(&mut rng)
        })
        .collect();
    Trace {
        source: "tone.wav".into(),
        t: (0..n).map(|j| j as f64 / fs).collect(),
        v,
        truth: None,
    }
}

/// The refusal of `seed`'s recording.
fn refusal(seed: u64) -> String {
    let a = analyze_sound(
        &recording(seed),
        &TrackSettings::default(),
        &Plausibility::default(),
    );
    a.map(|a| a.to_string()).expect_err("refused").to_string()
}

#[test]
fn a_spin_of_two_seconds_is_analysed_from_its_phase_and_its_interval_holds() {
    // 1.98 s of sound from 19.9 Hz at 44.1 kS/s, hum, AGC and a high-pass at 62 Hz: the
    // track holds 7 frames of the line, fewer than the 8 its own fit is judged on.
    let trace = recording(75);
    let a = analyze_sound(&trace, &TrackSettings::default(), &Plausibility::default())
        .expect("analysed as a short spin");
    assert!(a.track.points.len() < SOUND_MIN_FRAMES, "{a}");
    assert!(
        a.short_spin
            .as_deref()
            .is_some_and(|w| w.contains("fewer than the 8")),
        "{a}"
    );
    let (l, truth) = (a.law(), trace.truth.unwrap());
    assert!(l.from_phase, "{a}");
    assert!((l.beta - truth.beta).abs() <= 1.96 * l.beta_sigma, "{a}");
    assert!((l.t0 - truth.t0).abs() <= 1.96 * l.t0_sigma, "{a}");
    assert!(l.beta_sigma < 0.05 && l.t0_sigma < 0.005, "{a}");
    assert!(
        a.to_string()
            .contains("a short spin: the track alone is refused"),
        "{a}"
    );
}

/// Seed 169 (3.44 s of sound from 8.4 Hz behind a 171 Hz high-pass): search frames of
/// 0.125 s hold one period of its fundamental, and a track made of them follows a tone near
/// three times it; the 0.5 s frames hold the fundamental, so the track keeps them, every
/// frame within 1 % of the truth, and the short spin's phase, read from the third harmonic
/// (the line heard in most blocks), holds the truth in its intervals.
#[test]
fn a_short_spin_keeps_frames_that_hold_its_fundamental_and_reads_the_line_heard() {
    let room = PhoneRoom::draw(169);
    let trace = recording(169);
    let a = analyze_sound(&trace, &TrackSettings::default(), &Plausibility::default())
        .expect("analysed as a short spin");
    assert!(a.short_spin.is_some(), "{a}");
    for p in &a.track.points {
        let truth = room.law.precession(room.t0() - 0.5 * (p.a + p.b));
        assert!(
            (p.omega / truth - 1.0).abs() < 0.01,
            "{p:?} against {truth}"
        );
    }
    let ph = a.phase.as_ref().expect("the phase's fit");
    assert!(ph.points.len() >= MIN_SHORT_BLOCKS, "{a}");
    let (l, truth) = (a.law(), trace.truth.clone().unwrap());
    assert!(l.from_phase, "{a}");
    assert!((l.beta - truth.beta).abs() <= 1.96 * l.beta_sigma, "{a}");
    assert!((l.t0 - truth.t0).abs() <= 1.96 * l.t0_sigma, "{a}");
}

#[test]
fn a_short_spin_whose_phase_misses_the_tracks_frames_or_beta_range_is_refused() {
    let trace = recording(75);
    let track = analyze_sound(&trace, &TrackSettings::default(), &Plausibility::default())
        .unwrap()
        .track;
    let checks = Plausibility::default();
    // One frame moved 10 % off the line the phase follows.
    let mut moved = track.clone();
    moved.points[2].omega *= 1.1;
    let why = analysed(&trace, &moved, &checks, "x").expect_err("refused");
    assert!(
        why.contains("misses a frame of the track by") && why.contains("do not follow one line"),
        "{why}"
    );
    // Beta outside a range that leaves out every beta of the set (1.5-3).
    let narrow = Plausibility {
        beta_range: (0.0, 1.0),
        ..Plausibility::default()
    };
    let why = analysed(&trace, &track, &narrow, "x").expect_err("refused");
    assert!(why.contains("outside 0 .. 1"), "{why}");
    // A rise asked for beyond what the blocks, 1.98 s from 19.9 Hz to t0, can hold.
    let steep = Plausibility {
        min_rise: 10.0,
        ..Plausibility::default()
    };
    let why = analysed(&trace, &track, &steep, "x").expect_err("refused");
    assert!(why.contains("over its blocks, less than the 10"), "{why}");
    // A line that runs to the recording's end leaves no end time to search.
    let mut late = track.clone();
    let end = trace.t[0] + trace.v.len() as f64 / track.sample_rate;
    let last = late.points.len() - 1;
    late.points[last].b = end;
    let why = analysed(&trace, &late, &checks, "x").expect_err("refused");
    assert!(why.contains("runs to the recording's end"), "{why}");
    // A track that holds the line in one frame only.
    let mut one = track.clone();
    one.points.truncate(1);
    let why = analysed(&trace, &one, &checks, "x").expect_err("refused");
    assert!(
        why.contains("1 frame of the track holds the line, fewer than the 2"),
        "{why}"
    );
}

#[test]
fn short_spins_the_phase_cannot_stand_in_for_are_refused_saying_why() {
    // 1046: 1.26 s of sound, one frame on a line; 47: the shudder's ring after t0, the
    // disk under the noise in every frame; 72: 1.01 s of sound from 11 Hz, 14 turns, too
    // few for 8 blocks of two.
    let cases: [(u64, &str); 3] = [
        (
            1046,
            "1 frame of the track holds the line, fewer than the 2",
        ),
        (
            47,
            "the line the track followed does not rise (1499.5 Hz to 1499.8 Hz)",
        ),
        (
            72,
            "the phase of the short spin could not be fitted (5 phase blocks",
        ),
    ];
    for (seed, what) in cases {
        let r = refusal(seed);
        assert!(
            r.contains("nor can it be analysed as a short spin: "),
            "seed {seed}: {r}"
        );
        assert!(r.contains(what), "seed {seed}: {r}");
        assert!(
            !r.contains("pulse") && !r.contains("light"),
            "seed {seed}: {r}"
        );
    }
}

#[test]
fn a_track_whose_own_fit_is_refused_is_analysed_from_its_phase_alone() {
    // 6.2 s of sound at 44.1 kS/s, hum, AGC, clipping: 16 frames of the line, whose own fit
    // is refused, and the phase seeded from them stands.
    let trace = recording(175);
    let a = analyze_sound(&trace, &TrackSettings::default(), &Plausibility::default())
        .expect("analysed from its phase alone");
    assert!(a.track.points.len() >= SOUND_MIN_FRAMES, "{a}");
    assert!(a.short_spin.is_some(), "{a}");
    let (l, truth) = (a.law(), trace.truth.unwrap());
    assert!(l.from_phase, "{a}");
    assert!((l.beta - truth.beta).abs() <= 1.96 * l.beta_sigma, "{a}");
    assert!((l.t0 - truth.t0).abs() <= 1.96 * l.t0_sigma, "{a}");
    assert!(
        a.to_string()
            .contains("analysed from its phase alone: the track alone is refused"),
        "{a}"
    );
}

#[test]
fn tracks_of_enough_frames_the_phase_cannot_stand_in_for_are_refused_saying_why() {
    // The phase fit that cannot be made at all ("could not be fitted") is provoked on the
    // short-spin path (seed 72, above); no recording of the study provokes it here.
    let cases: [(u64, &str); 1] = [(6, "misses a frame of the track by")];
    let falling = analyze_sound(
        &falling_tone(),
        &TrackSettings::default(),
        &Plausibility::default(),
    )
    .map(|a| a.to_string())
    .expect_err("a falling tone is refused")
    .to_string();
    assert!(
        falling.contains("nor can it be analysed from its phase alone: ")
            && falling.contains("the line the track followed does not rise ("),
        "{falling}"
    );
    for (seed, what) in cases {
        let r = refusal(seed);
        assert!(
            r.contains("nor can it be analysed from its phase alone: "),
            "seed {seed}: {r}"
        );
        assert!(r.contains(what), "seed {seed}: {r}");
    }
}
