//! A diagnostic, not a test of a claim: for each phone recording of `ROLLING_DISK_SEEDS`
//! (comma-separated seeds of [`PhoneRoom::draw`]), every frame the track walks, the line it
//! follows and the disk's true fundamental at the frame's middle, to see which line the track
//! follows against the truth. Run with
//! `ROLLING_DISK_SEEDS=8,151 cargo test --release -p experiment --lib track::diagnosis -- --ignored --nocapture`.

use super::*;
use crate::fit::plausibility::Plausibility;
use crate::sound_analysis::analysis::analyze_sound;
use crate::synthetic::phone_room::PhoneRoom;

#[test]
#[ignore = "a diagnostic: prints each seed's frames against the truth"]
fn print_the_frames_against_the_truth() {
    let seeds = std::env::var("ROLLING_DISK_SEEDS").unwrap_or_else(|_| "8".into());
    for seed in seeds
        .split(',')
        .filter_map(|s| s.trim().parse::<u64>().ok())
    {
        let room = PhoneRoom::draw(seed);
        let trace = room
            .record()
            .unwrap()
            .read_back(&format!("phone-{seed}.wav"))
            .unwrap();
        let fs = 1.0 / trace.sample_interval();
        let (lead, t0) = (room.lead, room.t0());
        let truth = |t: f64| {
            if t > lead && t < t0 {
                room.law.precession(t0 - t) / (2.0 * PI)
            } else {
                f64::NAN
            }
        };
        println!(
            "seed {seed}: {} S/s, beta {:.3}, lead {:.2} s, t0 {:.3} s, f from {:.1} Hz, high-pass {:.0} Hz, hum {} x {} Hz ({:?}), bumps {:?}, agc {:.2}, shudder {:.2} s",
            room.sample_rate, room.law.beta, lead, t0, truth(lead + 1e-6), room.high_pass,
            room.hum.lines.len(), room.hum.mains, room.hum.lines, room.bumps, room.agc, room.shudder
        );
        let s = TrackSettings::default();
        for (search, min_snr) in [0.5, 0.25, 0.125]
            .into_iter()
            .flat_map(|x| [(x, s.min_snr), (x, s.min_snr / 3.0)])
        {
            let mut s = s;
            s.search = search;
            s.min_snr = min_snr;
            s.max_frame = s.max_frame.min(search);
            let hum = hum_lines(&trace.v, fs);
            let mut v = trace.v.clone();
            subtract_hum(&mut v, fs, &hum);
            let (frames, smeared) = march(&v, trace.t[0], fs, &s, &hum);
            let line = the_line(&frames);
            println!(
                "  search {search} s, min_snr {min_snr}: hum {hum:.1?}, {} frames, smeared end {smeared}",
                frames.len()
            );
            for (fr, on) in frames.iter().zip(&line) {
                let m = 0.5 * (fr.a + fr.b);
                let f0 = truth(m);
                match fr.est {
                    Some(e) => println!(
                        "    {:7.3}-{:7.3} {} {} f {:8.2} +- {:6.2} check {:8.2} snr {:8.1} | truth {:8.2} ratio {:6.3}",
                        fr.a, fr.b, if fr.searched { "S" } else { "." }, if fr.jumped { "J" } else if fr.still { "H" } else if *on { "L" } else { "-" },
                        e.f, e.sigma, e.check, e.snr, f0, e.f / f0
                    ),
                    None => println!(
                        "    {:7.3}-{:7.3} {} silent                                                  | truth {f0:8.2}",
                        fr.a, fr.b, if fr.searched { "S" } else { "." }
                    ),
                }
            }
        }
        match analyze_sound(&trace, &s, &Plausibility::default()) {
            Ok(a) => {
                let l = a.law();
                println!(
                    "  analysed: beta {:.4} +- {:.4} (err {:+.4}), t0 err {:+.4} +- {:.4} s, from phase {}",
                    l.beta, l.beta_sigma, l.beta - room.law.beta, l.t0 - t0, l.t0_sigma, l.from_phase
                );
            }
            Err(e) => println!("  refused: {e}"),
        }
    }
}

/// A diagnostic, not a test of a claim: for each phone recording of `ROLLING_DISK_SEEDS`, the
/// room's mains lines and, at each harmonic of the grid, every block's neighbours' median power
/// and the line's power over it ([`block_ratios`]) and whether the line was found as hum. Run
/// with `ROLLING_DISK_SEEDS=78,101 cargo test --release -p experiment --lib
/// track::diagnosis::print_the_hum_blocks -- --ignored --nocapture`.
#[test]
#[ignore = "a diagnostic: prints each seed's hum lines block by block"]
fn print_the_hum_blocks() {
    use crate::sound_analysis::mains::hum::low_copy;
    use crate::sound_analysis::mains::stands_out::block_ratios;
    let seeds = std::env::var("ROLLING_DISK_SEEDS").unwrap_or_else(|_| "78".into());
    for seed in seeds
        .split(',')
        .filter_map(|s| s.trim().parse::<u64>().ok())
    {
        let room = PhoneRoom::draw(seed);
        let trace = room.record().unwrap().read_back("phone.wav").unwrap();
        let fs = 1.0 / trace.sample_interval();
        let found = hum_lines(&trace.v, fs);
        println!(
            "seed {seed}: lead {:.2} s, t0 {:.2} s, span {:.2} s, mains {} Hz (wander {:.3}), lines {:.4?}, bumps {:?}; found {found:.2?}",
            room.lead,
            room.t0(),
            trace.v.len() as f64 / fs,
            room.hum.mains,
            room.hum.wander,
            room.hum.lines,
            room.bumps
        );
        let (low, fs_low) = low_copy(&trace.v, fs);
        for k in 1..=room.hum.lines.len().max(3) {
            let f = k as f64 * room.hum.mains;
            let b = block_ratios(&low, fs_low, f, (2.0 * fs_low) as usize);
            let cells: Vec<String> = b
                .iter()
                .map(|(floor, r)| format!("{floor:.1e}:{r:.1}"))
                .collect();
            println!("  {f:6.1} Hz: {}", cells.join(" "));
        }
    }
}
