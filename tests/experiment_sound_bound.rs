//! The Cramér-Rao bound on beta from a simulated sound, computed from the simulator's own
//! signal and noise, independently of the analysis
//! (`experiment::synthetic::bound::SoundInformation`, whose documentation states the model and
//! what it leaves out); against the analysis's sigma.

use experiment::plausibility::Plausibility;
use experiment::sound::Voice;
use experiment::synthetic::bound::{cramer_rao, SoundInformation};
use experiment::{
    analyze, analyze_sound, law_sound, law_trace, AnalysisSettings, Artifacts, Law, LightModel,
    Microphone, TrackSettings,
};
use physics::Disk;
use std::f64::consts::TAU;

/// Eq 79's law with beta and Omega = 100 rad/s at 7 s before t0.
fn law(beta: f64) -> Law {
    Law {
        beta,
        c: 100f64.powf(beta + 2.0) * 7.0,
    }
}

/// The microphone of `beta_from_sound_is_about_as_precise_as_from_light`.
fn mic(noise: f64, seed: u64) -> Microphone {
    Microphone {
        sample_rate: 48_000,
        samples: 480_000,
        voice: Voice::phone(),
        noise,
        seed,
        ..Microphone::default()
    }
}

/// The Cramér-Rao bound on beta for the sound of `law` recorded by `m`, from the samples up
/// to `before` seconds before $t_0$.
fn bound_beta(law: &Law, m: &Microphone, before: f64) -> f64 {
    SoundInformation::of_microphone(law, m, before)
        .bound()
        .expect("the sound holds lines within the span")
        .beta_sigma
}

/// How long before $t_0$ the disk of `law` leaves the plane (s): eq 79's premise holds while
/// the contact force $F_z = m(g + \ddot z)$ stays positive, with the centre's height
/// $z = a\sin\alpha$ and the tilt of steady motion $\sin\alpha = g/(k a \Omega^2)$, so it ends
/// where $\ddot z = -g$. Found here from the law by finite differences and bisection, not from
/// the paper's closed form (eq 81).
fn contact_lost(law: &Law, disk: &Disk) -> f64 {
    let z = |tau: f64| disk.a * disk.g / (disk.k * disk.a * law.precession(tau).powi(2));
    let z_ddot = |tau: f64| {
        let h = 1e-3 * tau;
        (z(tau + h) - 2.0 * z(tau) + z(tau - h)) / (h * h)
    };
    let (lo, hi) = numerics::oscillation::bisect(1e-7, 0.1, 1e-6, |tau| z_ddot(tau) > -disk.g);
    0.5 * (lo + hi)
}

/// The bound sums the Fisher information on a grid of cells; summed sample by sample over the
/// whole sound of `beta_from_sound_against_its_cramer_rao_bound`, the same to 1e-4.
#[test]
fn the_grid_bound_is_the_per_sample_sum() {
    let whole = SoundInformation::of_microphone(&law(2.0), &mic(0.003, 1), 0.0);
    let grid = whole.bound().unwrap().beta_sigma;
    let each = cramer_rao(&whole.fisher_per_sample().unwrap())
        .unwrap()
        .beta_sigma;
    assert!(
        (grid / each - 1.0).abs() < 1e-4,
        "grid {grid}, per sample {each}"
    );
}

/// The bound against the analysis's sigma and the light signal's, on the sounds of
/// `beta_from_sound_is_about_as_precise_as_from_light` (noise 0.003, the phone's room; four
/// seeds): no fit's own sigma lies below the bound, the bound itself lies within 2x of the light's
/// sigma, and the fit's mean sigma lies within 1.2 of the bound on the sound up to 1 ms before
/// t0, where the fit's blocks stop at the latest.
/// With the room's noise on, the microphone's white noise (0.001 to 0.01) hardly moves the
/// bound; the table prints the bound against the room's level.
#[test]
fn beta_from_sound_against_its_cramer_rao_bound() {
    let l = law(2.0);
    let light = law_trace(&l, &Disk::uniform(0.0375), &LightModel::default()).unwrap();
    let light = analyze(&light, &AnalysisSettings::default()).unwrap();
    let light_last = mic(0.003, 1).end_at - light.window.t_last;
    let light = light.eq84.beta_sigma;
    let bound = bound_beta(&l, &mic(0.003, 1), 0.0);
    // The phase fit's blocks stop at least 1 ms before its t0.
    let analysed = bound_beta(&l, &mic(0.003, 1), 1e-3);
    let mut sigmas = Vec::new();
    let mut betas = Vec::new();
    let mut t0_sigmas = Vec::new();
    for seed in 1..=4 {
        let s = law_sound(&l, &mic(0.003, seed), &Artifacts::none()).unwrap();
        let a = analyze_sound(&s, &TrackSettings::default(), &Plausibility::default()).unwrap();
        let f = a.law();
        assert!(f.from_phase, "{a}");
        // The bound is on the noise's part: the fit's own sigma, not the systematic terms
        // (an unshown high-pass corner, the law's drift) the stated interval adds to it.
        println!(
            "seed {seed}: beta {:.5} +- {:.5} from the fit ({:.5} stated)",
            f.beta, f.beta_terms.fit, f.beta_sigma
        );
        sigmas.push(f.beta_terms.fit);
        betas.push(f.beta);
        t0_sigmas.push(f.t0_terms.fit);
    }
    let mean = sigmas.iter().sum::<f64>() / sigmas.len() as f64;
    let t0_sigma = t0_sigmas.iter().sum::<f64>() / t0_sigmas.len() as f64;
    let rms = (betas.iter().map(|b| (b - 2.0).powi(2)).sum::<f64>() / betas.len() as f64).sqrt();
    println!(
        "light: sigma {light:.6}; Cramer-Rao bound on beta from sound {bound:.6} ({:.2} of the \
         light's), from the sound up to 1 ms before t0 {analysed:.6} ({:.2} of the light's); the \
         fit's mean sigma {mean:.6} ({:.2} of the latter, {:.2} of the light's); rms of beta about the truth {rms:.6}",
        bound / light,
        analysed / light,
        mean / analysed,
        mean / light,
    );
    for &s in &sigmas {
        assert!(s > 0.85 * bound, "a sigma {s} below the bound {bound}");
    }
    // Where the information lies: the bound on the sound up to `gap` before t0, and the turns
    // the gap holds. A fit within 2x of the light must reach closer to t0 than the gap at which
    // the bound itself is 2x, and come within `needed` of the bound on the whole sound.
    let q = 1.0 / (l.beta + 2.0);
    let turns = |gap: f64| l.c.powf(q) * gap.powf(1.0 - q) / (1.0 - q) / TAU;
    let profile: Vec<(f64, f64)> = [1e-4, 2e-4, 5e-4]
        .iter()
        .map(|&gap| (gap, bound_beta(&l, &mic(0.003, 1), gap) / light))
        .collect();
    for (gap, ratio) in &profile {
        println!(
            "bound on the sound up to {:.1} ms ({:.3} turn) before t0: {ratio:.2} of the light's",
            gap * 1e3,
            turns(*gap)
        );
    }
    let needed = 2.0 * light / bound;
    // Eq 79 holds only while the disk touches the plane (the premise of eqs 80-81):
    // the sound after it leaves says nothing about the law, and the bound on the sound before
    // is already above 2x.
    let lost = contact_lost(&l, &Disk::uniform(0.0375));
    let touching = bound_beta(&l, &mic(0.003, 1), lost) / light;
    println!(
        "the disk leaves the plane {:.2} ms ({:.3} turn) before t0; the bound on the sound \
         before that: {touching:.2} of the light's",
        lost * 1e3,
        turns(lost)
    );
    assert!(
        touching > 2.0,
        "the bound while the disk touches: {touching}"
    );
    // The light's fit, for its part, ends before the disk leaves the plane (its last peak
    // used, at the end of its window): the two stand on the same part of the motion.
    println!(
        "the light's last peak used: {:.2} ms before t0",
        light_last * 1e3
    );
    assert!(
        light_last > lost,
        "the light's fit reads {light_last} s before t0"
    );
    println!("a fit within 2x of the light comes within {needed:.3} of the whole sound's bound; the fit's mean t0 sigma {:.0} us", t0_sigma * 1e6);
    assert!(
        analysed > 2.0 * light,
        "the bound up to 1 ms before t0 is {analysed}"
    );
    assert!(profile
        .windows(2)
        .all(|w| w[0].1 < w[1].1 && w[1].1 < analysed / light));
    assert!(bound < 2.0 * light, "bound {bound}, light {light}");
    // What the fit loses to the bound on the sound up to 1 ms before t0 (1.15 of it): its last
    // block ends up to a block's length before that.
    assert!(mean < 1.2 * analysed, "mean sigma {mean}, bound {analysed}");
    let quiet = Microphone {
        voice: Voice {
            room: 0.003,
            ..Voice::phone()
        },
        ..mic(0.003, 1)
    };
    let quiet = bound_beta(&l, &quiet, 0.0) / light;
    // docs/experiment.md states these numbers.
    crate::common::experiment_docs_say(&[
        format!("a quiet room (0.003 rms) the bound is {quiet:.2} times the light's"),
        format!(
            "is {:.2} times the light signal's on the same motion",
            mean / light
        ),
        format!("{:.2} times the light's on the whole sound", bound / light),
        format!(
            "{:.2} times on the part up to 1 ms before t",
            analysed / light
        ),
        format!("the fit's sigma is {:.2} times the latter", mean / analysed),
        format!(
            "{:.2}, {:.2} and {:.2} times the light's up to 0.1, 0.2 and 0.5 ms before t₀ \
             ({:.3}, {:.3} and {:.3} of a turn)",
            profile[0].1,
            profile[1].1,
            profile[2].1,
            turns(1e-4),
            turns(2e-4),
            turns(5e-4)
        ),
        format!("within {needed:.3} of the bound on the whole sound"),
        format!("its own t₀ is uncertain by {:.0} µs", t0_sigma * 1e6),
        format!(
            "leaves the plane {:.2} ms ({:.3} of a turn) before t₀",
            lost * 1e3,
            turns(lost)
        ),
        format!("the bound on the sound before that is {touching:.2} times the light's"),
        format!(
            "the light's fit reads its last peak {:.1} ms before t₀",
            light_last * 1e3
        ),
    ]);
    print_bound_against_the_room(&l, light);
}

/// Prints the bound on beta from the sound of `l` against the room's level and the
/// microphone's noise, in units of the light's sigma `light`.
fn print_bound_against_the_room(l: &Law, light: f64) {
    for room in [0.0, 0.001, 0.003, 0.01] {
        let row: Vec<String> = [0.001, 0.003, 0.01]
            .iter()
            .map(|&noise| {
                let m = Microphone {
                    voice: Voice {
                        room,
                        ..Voice::phone()
                    },
                    ..mic(noise, 1)
                };
                let b = bound_beta(l, &m, 0.0);
                format!("noise {noise}: {b:.6} ({:.2} of the light's)", b / light)
            })
            .collect();
        println!("room {room}: {}", row.join("; "));
    }
}
