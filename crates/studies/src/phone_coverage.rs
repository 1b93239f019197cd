//! The sound analysis on a realistic set: phones' recordings of real spins in real rooms
//! ([`PhoneRoom`]: stereo, hum with its harmonics, handling bumps, reverberation, the phone's
//! high-pass, AGC, DC, clipping, 16-96 kS/s, $\beta$ 1.5-3, 1-60 s of sound), each written as
//! a WAV file's bytes and read back through the tool's own reader, then analysed as
//! `experiment analyze` does.
//!
//! It counts what a user meets: how many recordings are analysed, how close $\beta$ comes
//! ($|\hat\beta - \beta| \le 0.05$), and how often the stated 95 % intervals
//! ($\pm 1.96\,\sigma$) hold $\beta$ and $t_0$; each refusal keeps its message, so the causes
//! can be counted.

use experiment::error::ExperimentError;
use experiment::fit::plausibility::Plausibility;
use experiment::sound_analysis::analysis::analyze_sound;
use experiment::sound_analysis::track::TrackSettings;
use experiment::synthetic::phone_room::PhoneRoom;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

/// One recording's outcome.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PhoneOutcome {
    /// The recording's seed ([`PhoneRoom::draw`]).
    pub seed: u64,
    /// Its rate (S/s), seconds of the disk's sound, and true $\beta$.
    pub rate: u32,
    /// (see `rate`)
    pub sound: f64,
    /// (see `rate`)
    pub beta: f64,
    /// $\hat\beta - \beta$ and $\hat t_0 - t_0$ (s), when analysed.
    pub beta_error: Option<f64>,
    /// (see `beta_error`)
    pub t0_error: Option<f64>,
    /// The stated standard uncertainties, when analysed.
    pub beta_sigma: Option<f64>,
    /// (see `beta_sigma`)
    pub t0_sigma: Option<f64>,
    /// Whether the result came from the phase (else the pitch track).
    pub from_phase: Option<bool>,
    /// The refusal, when refused.
    pub refused: Option<String>,
}

/// The study's counts.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PhoneCoverage {
    /// Recordings.
    pub runs: usize,
    /// Recordings analysed.
    pub analysed: usize,
    /// Of those analysed, how many have $|\hat\beta - \beta| \le 0.05$.
    pub beta_within_005: usize,
    /// Of those analysed, how many have $\beta$ within 1.96 stated sigmas.
    pub beta_covered: usize,
    /// Of those analysed, how many have $t_0$ within 1.96 stated sigmas.
    pub t0_covered: usize,
    /// Each recording's outcome, by seed.
    pub outcomes: Vec<PhoneOutcome>,
}

impl PhoneCoverage {
    /// One line of the counts, as percentages.
    pub fn summary(&self) -> String {
        let pct = |k: usize, n: usize| 100.0 * k as f64 / n.max(1) as f64;
        format!(
            "{} recordings: {} analysed ({:.1} %); of those, |beta error| <= 0.05 on {} ({:.1} %), \
             95 % intervals hold beta on {} ({:.1} %) and t0 on {} ({:.1} %)",
            self.runs,
            self.analysed,
            pct(self.analysed, self.runs),
            self.beta_within_005,
            pct(self.beta_within_005, self.analysed),
            self.beta_covered,
            pct(self.beta_covered, self.analysed),
            self.t0_covered,
            pct(self.t0_covered, self.analysed)
        )
    }
}

/// The study as stored in `snapshots/phone_coverage.json`, with the command that made it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StoredPhoneCoverage {
    /// The command that ran and stored it.
    pub command: String,
    /// The first recording's seed.
    pub seed0: u64,
    /// The study.
    pub study: PhoneCoverage,
}

/// Analyses the recording of seed `seed`.
pub fn phone_outcome(seed: u64) -> Result<PhoneOutcome, ExperimentError> {
    phone_outcome_of(&PhoneRoom::draw(seed))
}

/// Analyses the recording of `room` (its seed names the file).
pub fn phone_outcome_of(room: &PhoneRoom) -> Result<PhoneOutcome, ExperimentError> {
    let seed = room.seed;
    let rec = room.record()?;
    let mut o = PhoneOutcome {
        seed,
        rate: room.sample_rate,
        sound: room.sound,
        beta: room.law.beta,
        beta_error: None,
        t0_error: None,
        beta_sigma: None,
        t0_sigma: None,
        from_phase: None,
        refused: None,
    };
    let file = format!("phone-{seed}.wav");
    // The generator's WAV failing is not a refusal of the analysis; the reader's is.
    let analysed = rec.read_wav(rec.wav()?, &file).and_then(|trace| {
        analyze_sound(&trace, &TrackSettings::default(), &Plausibility::default())
    });
    match analysed {
        Ok(a) => {
            let l = a.law();
            o.beta_error = Some(l.beta - room.law.beta);
            o.t0_error = Some(l.t0 - room.t0());
            o.beta_sigma = Some(l.beta_sigma);
            o.t0_sigma = Some(l.t0_sigma);
            o.from_phase = Some(l.from_phase);
        }
        Err(e) => o.refused = Some(e.to_string()),
    }
    Ok(o)
}

/// Runs `runs` recordings with seeds `seed0`, `seed0 + 1`, ... (in parallel, gathered in order).
pub fn phone_coverage(runs: usize, seed0: u64) -> Result<PhoneCoverage, ExperimentError> {
    let outcomes = (0..runs as u64)
        .into_par_iter()
        .map(|k| phone_outcome(seed0 + k))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(tally(outcomes))
}

/// The counts of `outcomes`.
pub fn tally(outcomes: Vec<PhoneOutcome>) -> PhoneCoverage {
    let analysed: Vec<&PhoneOutcome> = outcomes.iter().filter(|o| o.refused.is_none()).collect();
    let count = |f: &dyn Fn(&PhoneOutcome) -> bool| analysed.iter().filter(|o| f(o)).count();
    let within = |e: Option<f64>, s: Option<f64>| match (e, s) {
        (Some(e), Some(s)) => e.abs() <= 1.96 * s,
        _ => false,
    };
    let (beta_within_005, beta_covered, t0_covered) = (
        count(&|o| o.beta_error.is_some_and(|e| e.abs() <= 0.05)),
        count(&|o| within(o.beta_error, o.beta_sigma)),
        count(&|o| within(o.t0_error, o.t0_sigma)),
    );
    PhoneCoverage {
        runs: outcomes.len(),
        analysed: analysed.len(),
        beta_within_005,
        beta_covered,
        t0_covered,
        outcomes,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The study on `ROLLING_DISK_RUNS` recordings (default 40) from `ROLLING_DISK_SEED0`
    /// (default 1), printed with every refusal; with `ROLLING_DISK_WITHOUT` (see [`without`]),
    /// the same rooms without the nuisances named.
    #[test]
    #[ignore = "slow: tens of recordings; prints the study"]
    fn print_the_study() {
        let env = |k: &str, d: u64| {
            std::env::var(k)
                .ok()
                .and_then(|v| v.parse().ok())
                .unwrap_or(d)
        };
        let c = phone_coverage(
            env("ROLLING_DISK_RUNS", 40) as usize,
            env("ROLLING_DISK_SEED0", 1),
        )
        .unwrap();
        let c = match std::env::var("ROLLING_DISK_WITHOUT") {
            Ok(w) => {
                let outcomes: Vec<PhoneOutcome> = c
                    .outcomes
                    .iter()
                    .map(|o| phone_outcome_of(&without(PhoneRoom::draw(o.seed), &w)).unwrap())
                    .collect();
                println!("without {w}");
                tally(outcomes)
            }
            Err(_) => c,
        };
        for o in &c.outcomes {
            println!("{o:?}");
            // With ROLLING_DISK_WAV_DIR, each refused recording is written there to be looked at.
            if let (Some(_), Ok(dir)) = (&o.refused, std::env::var("ROLLING_DISK_WAV_DIR")) {
                let room = PhoneRoom::draw(o.seed);
                println!("  {room:?}");
                let wav = room.record().unwrap().wav().unwrap();
                std::fs::write(format!("{dir}/phone-{}.wav", o.seed), wav).unwrap();
            }
        }
        println!("{}", c.summary());
    }

    /// `room` without the nuisances named in `what` (comma-separated: high-pass, stereo,
    /// reverb, hum, agc, bumps, clip, rattle), to change one factor at a time.
    fn without(mut room: PhoneRoom, what: &str) -> PhoneRoom {
        for w in what.split(',') {
            match w {
                "high-pass" => room.high_pass = 1.0,
                "stereo" => room.stereo.0 = 0.0,
                "reverb" => room.reverb.1 = 0.0,
                "hum" => room.hum.lines.clear(),
                "agc" => room.agc = 0.0,
                "bumps" => room.bumps.retain(|b| b.0 < room.lead),
                "clip" => room.clip = 1e3,
                "rattle" => room.rattle = 0.0,
                other => panic!("no nuisance {other}"),
            }
        }
        room
    }

    /// One JSON line per recording of `ROLLING_DISK_RUNS` (default 40) from
    /// `ROLLING_DISK_SEED0` (default 1) or of the seeds in `ROLLING_DISK_SEEDS`, without the nuisances of `ROLLING_DISK_WITHOUT` when
    /// set: both fits' errors and sigmas, the stated terms and the phase fit's diagnostics, to
    /// read what each nuisance does to each fit.
    #[test]
    #[ignore = "slow: tens of recordings; prints both fits of each"]
    fn print_both_fits() {
        let env = |k: &str, d: u64| {
            std::env::var(k)
                .ok()
                .and_then(|v| v.parse().ok())
                .unwrap_or(d)
        };
        let (runs, seed0) = (env("ROLLING_DISK_RUNS", 40), env("ROLLING_DISK_SEED0", 1));
        let what = std::env::var("ROLLING_DISK_WITHOUT").ok();
        // ROLLING_DISK_SEEDS (comma-separated), when set, in place of the run of seeds.
        let seeds: Vec<u64> = match std::env::var("ROLLING_DISK_SEEDS") {
            Ok(list) => list.split(',').filter_map(|s| s.parse().ok()).collect(),
            Err(_) => (seed0..seed0 + runs).collect(),
        };
        let lines: Vec<String> = seeds
            .into_par_iter()
            .map(|seed| {
                let mut room = PhoneRoom::draw(seed);
                if let Some(w) = &what {
                    room = without(room, w);
                }
                let trace = room.record().unwrap().read_back("x.wav").unwrap();
                let (b, t0) = (room.law.beta, room.t0());
                match analyze_sound(&trace, &TrackSettings::default(), &Plausibility::default()) {
                    Ok(a) => {
                        let l = a.law();
                        let x = &a.fit;
                        let phase = a.phase.as_ref().map(|p| {
                            serde_json::json!({
                                "beta_err": p.beta - b, "beta_sigma": p.beta_sigma,
                                "t0_err": p.t0 - t0, "t0_sigma": p.t0_sigma,
                                "n": p.n, "chi2": p.chi2_dof, "corner": p.corner,
                                "corner_used": p.corner.is_some() && p.corner_not_used.is_none(),
                                "corner_not_used": p.corner_not_used,
                                "law_drifts": p.law.as_ref().map(|l| l.drifts),
                                "structure": p.structure.map(|s| (s.lag_one_z, s.runs_z)),
                                "last_block_before_t0": t0 - p.points.last().map_or(f64::NAN, |q| q.b),
                            })
                        });
                        serde_json::json!({
                            "seed": seed, "rate": room.sample_rate, "sound": room.sound,
                            "high_pass": room.high_pass, "reverb": room.reverb, "agc": room.agc,
                            "clip": room.clip, "hum": !room.hum.lines.is_empty(),
                            "from_phase": l.from_phase,
                            "beta_err": l.beta - b, "beta_sigma": l.beta_sigma,
                            "t0_err": l.t0 - t0, "t0_sigma": l.t0_sigma,
                            "beta_terms": l.beta_terms, "t0_terms": l.t0_terms,
                            "pitch": {"beta_err": x.beta - b, "beta_sigma": x.beta_sigma,
                                      "t0_err": x.t0 - t0, "t0_sigma": x.t0_sigma, "n": x.n,
                                      "chi2": x.chi2_dof},
                            "phase": phase, "why_not_phase": a.phase_implausible(),
                            "phase_refused": a.phase_refused,
                        })
                        .to_string()
                    }
                    Err(e) => serde_json::json!({"seed": seed, "refused": e.to_string()}).to_string(),
                }
            })
            .collect();
        for l in lines {
            println!("FIT {l}");
        }
    }

    /// The analyses of the seeds in `ROLLING_DISK_SEEDS` (comma-separated), as `experiment
    /// analyze` prints them, with the truth.
    #[test]
    #[ignore = "prints the analyses of chosen recordings"]
    fn print_analyses() {
        let seeds = std::env::var("ROLLING_DISK_SEEDS").unwrap_or_default();
        for seed in seeds.split(',').filter_map(|s| s.parse::<u64>().ok()) {
            let room = PhoneRoom::draw(seed);
            let trace = room.record().unwrap().read_back("x.wav").unwrap();
            match analyze_sound(&trace, &TrackSettings::default(), &Plausibility::default()) {
                Ok(a) => println!("seed {seed}, high-pass {:.0} Hz\n{a}", room.high_pass),
                Err(e) => println!("seed {seed}: {e}"),
            }
        }
    }

    /// The rooms and pitch tracks of the seeds in `ROLLING_DISK_SEEDS` (comma-separated).
    #[test]
    #[ignore = "prints the tracks of chosen recordings"]
    fn print_tracks() {
        let seeds = std::env::var("ROLLING_DISK_SEEDS").unwrap_or_default();
        for seed in seeds.split(',').filter_map(|s| s.parse::<u64>().ok()) {
            let room = PhoneRoom::draw(seed);
            let f0 = room.law.precession(room.sound) / std::f64::consts::TAU;
            println!(
                "seed {seed}: {} S/s, sound {:.2} s from {f0:.1} Hz, lead {:.2}, high-pass {:.0} Hz, hum {:?} at {}, agc {:.2}, clip {:.2}, bumps {:?}, reverb {:?}, harmonics {:?}",
                room.sample_rate, room.sound, room.lead, room.high_pass, room.hum.lines, room.hum.mains, room.agc, room.clip, room.bumps, room.reverb, room.harmonics
            );
            let trace = room.record().unwrap().read_back("x.wav").unwrap();
            match experiment::sound_analysis::track::frequency_track(
                &trace,
                &TrackSettings::default(),
            ) {
                Ok(t) => {
                    println!(
                        "  frames {} silent {} stray {} smeared {} hum {:?}",
                        t.frames, t.silent, t.stray, t.smeared, t.hum
                    );
                    for p in &t.points {
                        let tau = room.t0() - 0.5 * (p.a + p.b);
                        println!(
                            "  {:.3}-{:.3} f {:.2} Hz (true {:.2}) snr {:.0}",
                            p.a,
                            p.b,
                            p.omega / std::f64::consts::TAU,
                            room.law.precession(tau) / std::f64::consts::TAU,
                            p.snr
                        );
                    }
                }
                Err(e) => println!("  {e}"),
            }
        }
    }

    /// Writes a phone's 60 s stereo recording at 48 kHz (seed 2's room, with its sound made
    /// 58 s long) to `ROLLING_DISK_WAV`, for timing `experiment analyze` on it.
    #[test]
    #[ignore = "writes a file for timing the analysis"]
    fn write_a_minute_of_stereo() {
        let Ok(path) = std::env::var("ROLLING_DISK_WAV") else {
            return;
        };
        let mut room = PhoneRoom::draw(2);
        room.sample_rate = 48_000;
        room.lead = 1.0;
        room.sound = 58.0;
        room.tail = 1.0;
        room.law.c = (std::f64::consts::TAU * 8.0).powf(room.law.beta + 2.0) * room.sound;
        let rec = room.record().unwrap();
        std::fs::write(&path, rec.wav().unwrap()).unwrap();
        println!("{path}: {:?}, t0 = {} s", room.law, room.t0());
    }
}
