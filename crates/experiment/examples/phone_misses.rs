//! A diagnosis, with the truth, of the phone recordings ([`PhoneRoom`]) whose 95 % interval
//! misses $\beta$: for each, the corner the harmonics read against the room's true high-pass,
//! whether its lead was taken out, what the phase fit gives with the true corner's lead taken
//! out and with none, and the pull with each of the room's nuisances removed in turn. Printed;
//! nothing is stored:
//!
//! `ROLLING_DISK_SEEDS=13,120 cargo run --release -p experiment --example phone_misses`

use experiment::fit::plausibility::Plausibility;
use experiment::formats::channel::Channels;
use experiment::formats::decimate::to_band;
use experiment::formats::recording::parse_recording;
use experiment::sound_analysis::analysed::SoundAnalysis;
use experiment::sound_analysis::analysis::analyze_sound;
use experiment::sound_analysis::high_pass::Corner;
use experiment::sound_analysis::phase_blocks::{Block, BlockSettings, Samples};
use experiment::sound_analysis::phase_fit::{fit_phase_reading, PhaseFit, ReadCorner};
use experiment::sound_analysis::track::TrackSettings;
use experiment::synthetic::phone_room::PhoneRoom;
use experiment::trace::Trace;
use nalgebra::SVector;
use rayon::prelude::*;
use std::f64::consts::TAU;

/// The misses of the stored phone study (`snapshots/phone_coverage.json`, main 6285c6b1).
const STORED_MISSES: &str =
    "13,3,120,126,173,148,97,149,67,31,63,146,66,111,197,143,123,37,2,22,118,154,156,103,137,39,136,95,132";

/// `room` recorded, read back as the study reads it, and analysed.
fn analysed(room: &PhoneRoom) -> Result<(SoundAnalysis, Trace), String> {
    let rec = room.record().map_err(|e| e.to_string())?;
    let r = parse_recording(
        rec.wav().map_err(|e| e.to_string())?,
        "x.wav",
        Channels::Mix,
    )
    .map_err(|e| e.to_string())?;
    let mut trace = r.trace;
    trace.truth = Some(rec.truth.clone());
    let a = analyze_sound(&trace, &TrackSettings::default(), &Plausibility::default())
        .map_err(|e| e.to_string())?;
    Ok((a, trace))
}

/// The analysis's phase fit done again with the corner read by `read`, from the same start.
fn refit(a: &SoundAnalysis, trace: &Trace, read: ReadCorner<'_>) -> Option<PhaseFit> {
    let band = to_band(&trace.v, a.track.sample_rate);
    let samples = match &band {
        Some((x, q)) => Samples {
            x,
            t_start: trace.t[0],
            dt: *q as f64 / a.track.sample_rate,
        },
        None => Samples {
            x: &trace.v,
            t_start: trace.t[0],
            dt: 1.0 / a.track.sample_rate,
        },
    };
    let f = &a.fit;
    fit_phase_reading(
        &samples,
        &a.track.hum,
        a.track.points.first()?.a,
        SVector::<f64, 3>::new(f.beta, f.t0, f.ln_c),
        f.t0_sigma,
        &BlockSettings::default(),
        read,
    )
    .ok()
}

/// A phase fit's $\beta$ error, stated total sigma and pull against `beta`.
fn pull(p: &PhaseFit, beta: f64) -> String {
    let e = p.beta - beta;
    let each: Vec<String> = p.harmonics.as_ref().map_or(Vec::new(), |a| {
        a.fits
            .iter()
            .map(|f| format!("h{} {:+.4}+-{:.4}", f.h, f.beta - beta, f.beta_sigma))
            .collect()
    });
    format!(
        "err {e:+.4} fit {:.4} hp {:.4} harm {:.4} law {:.4} pull {:+.1} [{}]",
        p.beta_sigma,
        p.beta_high_pass,
        p.beta_harmonics(),
        p.law.as_ref().map_or(0.0, |l| l.beta_systematic()),
        e / p.beta_total(),
        each.join(" ")
    )
}

/// One recording's diagnosis.
fn diagnose(seed: u64) -> String {
    let room = PhoneRoom::draw(seed);
    let beta = room.law.beta;
    let mut out = format!(
        "seed {seed}: {} S/s, {:.1} s, beta {beta:.2}, high-pass {:.0} Hz, reverb {:.2}/{:.2}, \
         agc {:.2}, clip {:.2}, hum {}, bumps in spin {}\n",
        room.sample_rate,
        room.sound,
        room.high_pass,
        room.reverb.0,
        room.reverb.1,
        room.agc,
        room.clip,
        room.hum.lines.len(),
        room.bumps.iter().filter(|b| b.0 > room.lead).count()
    );
    let (a, trace) = match analysed(&room) {
        Ok(x) => x,
        Err(e) => return out + &format!("  refused: {e}\n"),
    };
    let l = a.law();
    out += &format!(
        "  result from {}: err {:+.4} sigma {:.4} pull {:+.1}; short spin {}; why not phase {:?}\n",
        if l.from_phase { "phase" } else { "pitch" },
        l.beta - beta,
        l.beta_sigma,
        (l.beta - beta) / l.beta_sigma,
        a.short_spin.is_some(),
        a.phase_implausible()
    );
    let Some(p) = &a.phase else {
        return out + &format!("  no phase fit: {:?}\n", a.phase_refused);
    };
    out += &format!(
        "  phase: {}; chi2 {:.2}, n {}; corner {:?} Hz (true {:.1}), not used {:?}; structure {:?}\n",
        pull(p, beta),
        p.chi2_dof,
        p.n,
        p.corner.map(|(f, s)| (
            (f * 10.0).round() / 10.0,
            (s * 10.0).round() / 10.0,
            ((f / room.high_pass - 1.0) * 1000.0).round() / 10.0
        )),
        room.high_pass,
        p.corner_not_used,
        p.structure.map(|s| (s.lag_one_z, s.runs_z))
    );
    let wc = TAU * room.high_pass;
    let truth = move |_: &[Block], _: &[f64]| {
        Some(Corner {
            omega_c: wc,
            sigma: 1e-9 * wc,
            shown: f64::INFINITY,
        })
    };
    let none = |_: &[Block], _: &[f64]| None;
    for (name, read) in [
        (
            "true corner",
            &truth as &dyn Fn(&[Block], &[f64]) -> Option<Corner>,
        ),
        ("no corner", &none),
    ] {
        out += &match refit(&a, &trace, read) {
            Some(q) => format!(
                "  {name}: {}; chi2 {:.2}; not used {:?}\n",
                pull(&q, beta),
                q.chi2_dof,
                q.corner_not_used
            ),
            None => format!("  {name}: the fit failed\n"),
        };
    }
    for what in [
        "high-pass",
        "reverb",
        "agc",
        "clip",
        "hum",
        "bumps",
        "rattle",
        "stereo",
    ] {
        let mut r = room.clone();
        match what {
            "high-pass" => r.high_pass = 1.0,
            "reverb" => r.reverb.1 = 0.0,
            "agc" => r.agc = 0.0,
            "clip" => r.clip = 1e3,
            "hum" => r.hum.lines.clear(),
            "bumps" => r.bumps.retain(|b| b.0 < r.lead),
            "rattle" => r.rattle = 0.0,
            _ => r.stereo.0 = 0.0,
        }
        out += &match analysed(&r) {
            Ok((b, _)) => {
                let lb = b.law();
                let ph = b
                    .phase
                    .as_ref()
                    .map_or("no phase".into(), |q| pull(q, beta));
                format!(
                    "  without {what}: {} pull {:+.1}; phase {ph}\n",
                    if lb.from_phase { "phase" } else { "pitch" },
                    (lb.beta - beta) / lb.beta_sigma
                )
            }
            Err(e) => format!("  without {what}: refused ({e})\n"),
        };
    }
    out
}

/// The diagnosis of the seeds in `ROLLING_DISK_SEEDS` (comma-separated; the stored study's
/// misses by default), printed.
fn main() {
    let seeds = std::env::var("ROLLING_DISK_SEEDS").unwrap_or_else(|_| STORED_MISSES.into());
    let seeds: Vec<u64> = seeds.split(',').filter_map(|s| s.parse().ok()).collect();
    let lines: Vec<String> = seeds.into_par_iter().map(diagnose).collect();
    for l in lines {
        print!("{l}");
    }
}
