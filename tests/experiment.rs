//! The experiment of section 11: synthetic traces, their analysis, CSV validation, the paper's
//! numbers.

use experiment::fit::crossover;
use experiment::*;
use physics::scene::Scene;
use physics::Disk;
use std::f64::consts::PI;
use studies::coverage;

/// A dissipative spin-down with exponent `beta` lasting about 9 s, started in its adiabatic
/// state (steady b = 0 motion plus the drift of alpha that dissipation imposes) so that little
/// nutation is excited: energy $E = \tfrac32 mga\sin\alpha$ falls at eq 75's rate, so
/// $\dot\alpha = -\tfrac23\epsilon\Omega^\beta/\cos\alpha$ and $\dot\Omega = K\Omega^{\beta+3}$ with
/// $K = \epsilon k a / 3g$; epsilon is chosen from the latter for the duration.
fn spin_down(beta: f64) -> Scene {
    let (a, k, g, alpha0, duration) = (0.0375, 0.25, 9.81, 0.12, 9.0);
    let omega0 = (g / (k * a * f64::sin(alpha0))).sqrt();
    let epsilon = 3.0 * g / (k * a * (beta + 2.0) * omega0.powf(beta + 2.0) * duration);
    let alpha_dot = -2.0 / 3.0 * epsilon * omega0.powf(beta) / alpha0.cos();
    let yaml = format!(
        "name: spin-down-beta-{beta}\n\
         disk: {{ radius: {a}, k: {k}, mass: 0.4, g: {g} }}\n\
         model: dissipative\n\
         dissipation: {{ epsilon: {epsilon:e}, beta: {beta} }}\n\
         start: {{ steady: {{ alpha0: {alpha0}, b: 0.0 }}, perturb: {{ alpha_dot: {alpha_dot:e} }} }}\n\
         stop: {{ time: 30.0, alpha_below: 1.0e-4 }}\n\
         solver: {{ method: dop853, rtol: 1.0e-10, atol: 1.0e-12 }}\n"
    );
    Scene::parse(&yaml, "test").expect("valid scene")
}

/// The dissipative model is not eq 79 exactly: the steady start excites some nutation and the
/// centre of mass drifts off b = 0 as the disk spins down, so 1/Omega departs from the law by
/// about 1 % (the fit's reduced chi2 is 100-750 at 5 mV noise). The fits' uncertainties are
/// statistical and do not cover that departure; here we check that the model's own beta and
/// end time come back to within what that departure allows. The strict checks of bias and
/// coverage are on traces that follow the law exactly (below).
#[test]
fn model_spin_downs_give_back_their_beta_and_t0() {
    for beta in [0.0, 1.0, 2.0, 2.5, 4.0] {
        let trace = simulate_trace(&spin_down(beta), &LightModel::default()).unwrap();
        let tr = trace.truth.clone().unwrap();
        assert!(tr.tau_rem < 1e-3, "{tr:?}");
        let a = analyze(&trace, &AnalysisSettings::default()).unwrap();
        println!("{a}");
        assert!((a.eq84.beta - beta).abs() < 0.2, "beta {beta}: {a}");
        assert!((a.eq85.beta - beta).abs() < 0.2, "beta {beta}: {a}");
        assert!((a.eq84.t0 - tr.t0).abs() < 0.04, "beta {beta}: {a}");
    }
}

/// Why the model's t0 comes out early: not the light or the analysis, the model
/// itself. The truth's t0 is where the tilt alpha vanishes (`Truth`); eq 79 says
/// $\alpha \propto (t_0 - t)^{2/(\beta+2)}$, so each instant gives its own estimate
/// $t + 2\alpha/((\beta+2)|\dot\alpha|)$ of t0. On the model's tilt, without light or noise,
/// that estimate is 9.1 ms early one second before the end, 4.8 ms at 0.2 s and 2.7 ms at
/// 0.01 s (measured 2026-11-25; +70 ms six seconds before): the model reaches eq 79 only as
/// alpha goes to 0, and a fit of eq 79 to cycles seconds before the end inherits that
/// (beta free, whole record: t0 -20 ms, beta 2.055; from 1 s before the end: -3.4 ms, beta
/// 1.96). The heading rate keeps to the adiabatic $\Omega^2 = g/(k a \sin\alpha)$ within 0.8 %
/// throughout, a near-constant factor that goes into C, not t0.
#[test]
fn the_models_tilt_reaches_eq_79_only_at_the_end() {
    use experiment::simulate::simulate_motion;
    let m = simulate_motion(&spin_down(2.0), 7.27, 5000.0, 50_000).unwrap();
    let t0 = m.truth.t0;
    let local_t0 = |back: f64| {
        let j = m.t.iter().position(|&x| x >= t0 - back).unwrap();
        let h = 25;
        let rate = (m.alpha[j + h] - m.alpha[j - h]) / (m.t[j + h] - m.t[j - h]);
        m.t[j] + 2.0 * m.alpha[j] / (4.0 * rate.abs()) - t0
    };
    let (far, near) = (local_t0(1.0), local_t0(0.01));
    println!(
        "local t0 from the tilt: {:+.2} ms one second before the end, {:+.2} ms at 10 ms",
        1e3 * far,
        1e3 * near
    );
    assert!(far < -3e-3, "{far}");
    assert!(near.abs() < 0.5 * far.abs(), "{near} {far}");
}

#[test]
fn law_traces_give_back_their_beta_and_t0() {
    let disk = Disk::uniform(0.0375);
    for beta in [0.0, 1.0, 2.0, 2.5, 4.0] {
        // Omega = 100 rad/s seven seconds before t0.
        let law = Law {
            beta,
            c: 100f64.powf(beta + 2.0) * 7.0,
        };
        let trace = law_trace(&law, &disk, &LightModel::default()).unwrap();
        let a = analyze(&trace, &AnalysisSettings::default()).unwrap();
        let s = a.score.unwrap();
        println!("{a}glitches {}, hum {}", a.glitches, a.hum);
        assert!(
            s.beta84_pull.abs() < 3.5 && s.beta85_pull.abs() < 3.5,
            "{a}"
        );
        assert!(s.t0_error_samples.abs() < 3.0, "{a}");
        let ln_c = law.c.ln();
        assert!(
            (a.eq84.ln_c - ln_c).abs() < 4.0 * a.eq84.ln_c_sigma + 1e-3,
            "{a}"
        );
    }
}

/// Coverage on exact-law traces with the scope's noise (5 mV, 8 bits), `runs` seeds: eq 79
/// (which holds exactly) is taken to drift over the window on at most 2 + 2 % of them (the
/// test's false alarms, 3 sigmas on each of two parameters: 2 of 400 and 3 of 500 measured in
/// the stored studies, 2026-11-25), and the fraction of pulls of beta and t0 inside 1 and 1.96 standard uncertainties must be 68.3 % and
/// 95 % within 3 binomial standard deviations (at 120 runs: 4.2 % and 2.0 %; at 30 runs: 8.5 %
/// and 4.0 %), and the pulls' mean must be 0 within 3 standard errors ($3/\sqrt{n}$: 0.27 at
/// 120 runs, 0.55 at 30), which a bias of one sigma fails at either size.
fn check_coverage(runs: usize, seed0: u64) {
    covered(runs, seed0, false);
}

/// The coverage study of `runs` traces from `seed0` (with the bench's artifacts or not), held
/// to the rules of [`check_coverage`]; the study, for further checks.
fn covered(runs: usize, seed0: u64, artifacts: bool) -> coverage::Coverage {
    let c = coverage::coverage(runs, seed0, artifacts).unwrap();
    println!("{}", c.summary());
    assert_eq!(c.refused, 0, "{}", c.summary());
    assert!(c.law_drifts <= 2 + runs / 50, "{}", c.summary());
    let n = runs as f64;
    let sd = |p: f64| (p * (1.0 - p) / n).sqrt();
    for pulls in [&c.beta_pulls, &c.t0_pulls] {
        let (one, two) = (c.fraction(pulls, 1.0), c.fraction(pulls, 1.96));
        assert!((one - 0.683).abs() < 3.0 * sd(0.683), "{}", c.summary());
        assert!((two - 0.95).abs() < 3.0 * sd(0.95), "{}", c.summary());
        let (mean, _) = coverage::Coverage::moments(pulls);
        assert!(mean.abs() < 3.0 / n.sqrt(), "{}", c.summary());
    }
    c
}

/// Met (measured 2026-11-25, seeds 1000-1119, `cargo test --release --test integration --
/// experiment::stated_intervals_cover_the_truth --exact --include-ignored --nocapture`, 223 s beside the
/// artifact-laden study on the shared 2-core machine): beta inside 1 sigma 64.2 %, 1.96 sigma
/// 95.0 %; t0 67.5 %, 93.3 %; pulls (mean, sd) beta (+0.07, 1.10), t0 (-0.10, 1.04); worst errors
/// beta 0.0004, t0 0.126 ms; none refused. Before the crossings' slope came from a line through
/// six samples and the covariance from the whitened residuals' own (`least_squares`), the same
/// seeds gave beta 65.0 %, 92.5 %; t0 66.7 %, 92.5 %; pulls beta (+0.08, 1.09), t0 (-0.11,
/// 1.03): the stated peak-time sigma was 1.36 times too small at the slow start (see
/// `tests/experiment_coverage_diagnosis.rs`); with the heteroscedastic Newey-West sandwich in
/// between, t0 85.0 % (pulls' sd 1.21). Before each pulse's drift was removed from its timing
/// (`pulse_drift`): beta 59.2 %, 85.0 %; t0 52.5 %, 78.3 %, pulls beta (+0.46, 1.20), t0 (-0.98,
/// 1.25): t0 about one sigma early. Too slow for the normal run:
/// `stated_intervals_cover_the_truth_30_recordings` runs there instead.
#[test]
#[ignore = "slow: 120 recordings, about four minutes on the shared machine"]
fn stated_intervals_cover_the_truth() {
    check_coverage(120, 1000);
}

/// The fast version of [`stated_intervals_cover_the_truth`] for the normal run: 30 other
/// recordings, with the bounds that size allows (3 binomial sd: 68.3 +- 25.5 %, 95 +- 11.9 %;
/// pulls' mean within 0.55). Measured 2026-11-25 (seeds 3000-3029): beta 66.7 %, 93.3 %; t0
/// 66.7 %, 90.0 %; pulls beta (+0.22, 1.04), t0 (-0.23, 1.06); worst t0 0.143 ms.
#[test]
fn stated_intervals_cover_the_truth_30_recordings() {
    check_coverage(30, 3000);
}

/// The full study: 400 other recordings (binomial sd 2.3 % at 68 %, 1.1 % at 95 %). Met
/// (measured 2026-11-25, seeds 5000-5399, `cargo test --release --test integration --
/// experiment::stated_intervals_cover_the_truth_400_recordings --exact --include-ignored --nocapture`, 11 min
/// beside the 500-trace study on the shared machine): none refused; beta inside 1 sigma 66.8 %,
/// 1.96 sigma 93.5 %; t0 69.0 %, 93.8 %; pulls (mean, sd) beta (+0.06, 1.06), t0 (-0.04, 1.05);
/// worst errors beta 0.0004, t0 0.165 ms. The 95 % intervals hold 1.4 and 1.1 binomial sd less
/// than 95 %, the pulls' sd is 1.7 standard errors above 1: within this test's bounds, a shade
/// narrow still.
#[test]
#[ignore = "slow: 400 recordings, about ten minutes"]
fn stated_intervals_cover_the_truth_400_recordings() {
    check_coverage(400, 5000);
}

/// A trace whose disk follows the two-mechanism law (beta 1 below Omega_c = 150 rad/s, 4 above,
/// the time left at Omega_c 2 s), seen through the default light model and scope.
fn crossover_trace() -> (Trace, f64) {
    let disk = Disk::uniform(0.0375);
    let light = LightModel::default();
    let t0 = light.scope.end_at;
    let wc: f64 = 150.0;
    let p = nalgebra::SVector::<f64, 5>::from_column_slice(&[
        1.0,
        4.0,
        t0,
        (2.0 * wc.powi(6)).ln(),
        wc.ln(),
    ]);
    let t = light.scope.times();
    let mut v: Vec<f64> = t
        .iter()
        .map(|&t| {
            if t >= t0 {
                return light.intensity(0.0, 0.0);
            }
            let (phi, om) = crossover::heading(&p, t);
            let s = (disk.g / (disk.k * disk.a * om * om)).min(1.0);
            light.intensity(s.asin(), phi)
        })
        .collect();
    light.scope.record(&mut v);
    let trace = Trace {
        source: "crossover".into(),
        t,
        v,
        truth: None,
    };
    (trace, wc)
}

/// Model choice: a two-mechanism trace is recognised as such, with its crossover and both
/// exponents; a single law (eq 79, beta = 2) is not taken for two mechanisms. The later half's
/// refit (`law_stability`) sees the first drift and not the second.
#[test]
fn the_crossover_law_is_chosen_when_and_only_when_the_data_have_one() {
    let (trace, wc) = crossover_trace();
    let a = analyze(&trace, &AnalysisSettings::default()).unwrap();
    println!("{}", a.models.summary);
    for c in &a.models.candidates {
        println!("  {} ({}): dBIC {:.1}", c.name, c.parameters, c.delta_bic);
    }
    let x = a.crossover.clone().unwrap();
    assert_eq!(a.models.candidates[0].name, "two mechanisms", "{a}");
    assert!(a.models.candidates[1].delta_bic > 10.0, "{a}");
    // Its exponents differ as two mechanisms' do: called, decisively, not read as drift.
    assert!(a.models.calls_two() && !a.models.drift, "{a}");
    assert!(a.models.summary.contains("decisive evidence"), "{a}");
    assert!((x.beta_below - 1.0).abs() < 0.3, "{x:?}");
    assert!((x.beta_above - 4.0).abs() < 0.3, "{x:?}");
    assert!((x.omega_c / wc - 1.0).abs() < 0.1, "{x:?}");
    // A law whose exponent changes inside the window is seen to drift by the later half's fit.
    let l = a.law_stability.clone().unwrap();
    println!("{l:?}");
    assert!(l.drifts, "{a}");

    let disk = Disk::uniform(0.0375);
    let law = Law {
        beta: 2.0,
        c: 100f64.powi(4) * 7.0,
    };
    let a = analyze(
        &law_trace(&law, &disk, &LightModel::default()).unwrap(),
        &AnalysisSettings::default(),
    )
    .unwrap();
    println!("{}", a.models.summary);
    for c in &a.models.candidates {
        println!("  {} ({}): dBIC {:.1}", c.name, c.parameters, c.delta_bic);
    }
    assert_ne!(a.models.candidates[0].name, "two mechanisms", "{a}");
    assert!(!a.models.calls_two(), "{a}");
    let l = a.law_stability.clone().unwrap();
    println!("{l:?}");
    assert!(!l.drifts, "{a}");
}

/// A trace of `n` samples at 5 kS/s with signal `f(t)` plus 5 mV of seeded noise.
fn synthetic(name: &str, mut f: impl FnMut(f64) -> f64) -> Trace {
    use rand::SeedableRng;
    use rand_distr::{Distribution, StandardNormal};
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(5);
    let t: Vec<f64> = (0..50_000).map(|j| j as f64 / 5000.0).collect();
    let v = t
        .iter()
        .map(|&t| {
            let g: f64 = StandardNormal.sample(&mut rng);
            f(t) + 0.005 * g
        })
        .collect();
    Trace {
        source: name.into(),
        t,
        v,
        truth: None,
    }
}

/// Pulses of the light signal's shape at heading `phase`.
fn pulses(phase: f64) -> f64 {
    0.1 + 2.0 * (0.5 + 0.5 * phase.cos()).powi(20)
}

/// The signals that are not a spin-down.
fn impostors() -> Vec<Trace> {
    use rand::SeedableRng;
    use rand_distr::{Distribution, StandardNormal};
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(9);
    let noise = synthetic("noise", |_| {
        let g: f64 = StandardNormal.sample(&mut rng);
        1.0 + 0.5 * g
    });
    vec![
        noise,
        synthetic("sine", |t| 1.0 + (2.0 * PI * 20.0 * t).cos()),
        synthetic("pulses at a constant rate", |t| pulses(2.0 * PI * 20.0 * t)),
        synthetic("linear chirp", |t| {
            pulses(2.0 * PI * (15.0 * t + 5.0 * t * t))
        }),
        synthetic("decaying spin-up", |t| {
            // Spun up to 60 Hz, then slowing as exp(-t / 4 s).
            pulses(2.0 * PI * 60.0 * 4.0 * (1.0 - (-t / 4.0).exp()))
        }),
    ]
}

#[test]
fn what_is_not_a_spin_down_is_refused_with_a_reason() {
    for t in impostors() {
        let e = analyze(&t, &AnalysisSettings::default())
            .map(|a| a.to_string())
            .expect_err("an impostor was fitted");
        let msg = e.to_string();
        println!("{msg}");
        assert!(msg.starts_with(&format!("{}:", t.source)), "{msg}");
        match t.source.as_str() {
            "noise" => assert!(msg.contains("no pulse stands out of the noise"), "{msg}"),
            _ => assert!(msg.contains("not a spin-down"), "{msg}"),
        }
    }
}

/// Each artifact alone and all together, on an exact-law trace (beta = 2, t0 = 7.27 s).
#[test]
fn artifacts_leave_beta_and_t0_within_the_targets() {
    let disk = Disk::uniform(0.0375);
    let law = Law {
        beta: 2.0,
        c: 100f64.powi(4) * 7.0,
    };
    let clean = law_trace(&law, &disk, &LightModel::default()).unwrap();
    let r = Artifacts::realistic(2.0, 3);
    let none = Artifacts::none();
    let each = [
        (
            "drift",
            Artifacts {
                drift: r.drift,
                ..none
            },
        ),
        ("hum", Artifacts { hum: r.hum, ..none }),
        (
            "clip",
            Artifacts {
                clip: r.clip,
                ..none
            },
        ),
        (
            "glitches",
            Artifacts {
                glitches_per_s: r.glitches_per_s,
                glitch: r.glitch,
                ..none
            },
        ),
        (
            "dropped",
            Artifacts {
                dropped: r.dropped,
                ..none
            },
        ),
        ("all", r),
    ];
    for (name, art) in each {
        let t = clean.with_artifacts(&art).unwrap();
        let a = analyze(&t, &AnalysisSettings::default()).unwrap();
        let (db, dt) = (a.eq84.beta - 2.0, a.eq84.t0 - 7.27);
        println!(
            "{name}: beta {:.4} +- {:.4}, t0 error {:+.3} ms +- {:.3}, reduced chi2 {:.2}, hum {:.4} V, glitches {}",
            a.eq84.beta, a.eq84.beta_sigma, 1e3 * dt, 1e3 * a.eq84.t0_sigma, a.eq84.reduced_chi2, a.hum, a.glitches
        );
        assert!(db.abs() < 0.1 && dt.abs() < 3e-3, "{name}: {a}");
        assert!(db.abs() < 4.0 * a.eq84.beta_sigma, "{name}: {a}");
        assert!(dt.abs() < 4.0 * a.eq84.t0_sigma, "{name}: {a}");
        if name.contains("hum") || name == "all" {
            assert!(
                a.hum > 0.5 * art.hum && a.hum < 1.5 * art.hum,
                "{name}: {}",
                a.hum
            );
        } else {
            assert_eq!(a.hum, 0.0, "{name}: hum found where there is none");
        }
    }
}

/// 60 Hz hum of 0.04 V: found, and subtracted with one set of coefficients for the whole
/// record (the median over its 1 s blocks): subtracted block by block, the last block's fit
/// would carry the pulses' leakage as Omega sweeps past 2 pi x 60 Hz, and the hum left after t0
/// would be timed as pulses. Measured with seed 3: beta 2.0003 +- 0.0002, t0 -0.12 ms.
#[test]
fn sixty_hertz_hum_leaves_beta_and_t0_within_the_targets() {
    let disk = Disk::uniform(0.0375);
    let law = Law {
        beta: 2.0,
        c: 100f64.powi(4) * 7.0,
    };
    let art = Artifacts {
        hum: 0.04,
        mains: 60.0,
        seed: 3,
        ..Artifacts::none()
    };
    let t = law_trace(&law, &disk, &LightModel::default())
        .unwrap()
        .with_artifacts(&art)
        .unwrap();
    let a = analyze(&t, &AnalysisSettings::default()).unwrap();
    println!("{a}");
    assert!(
        (a.eq84.beta - 2.0).abs() < 0.1 && (a.eq84.t0 - 7.27).abs() < 3e-3,
        "{a}"
    );
}

/// The dissipative model with all artifacts. The model is not eq 79 exactly (its early, larger
/// tilts, its nutation): the fit's scatter is far above the peak-timing noise and the scaled
/// errors are reported; the targets are checked as measured.
///
/// With seed 4 the drift and the hum together can hide the hum from its detection: the
/// pulses' harmonics leak into the 1 s blocks' hum fits where they sweep past 50 Hz, and one
/// leaking block (0.08 V, against the 0.04 V hum) would dominate a sum of the blocks'
/// amplitudes; the hum is judged by the blocks' median instead.
/// Measured (with the pulses' drift removed from their timing): whole record beta
/// 2.0537 +- 0.0103, t0 -20.0 ms +- 3.9; last 2.5 s beta 1.9861 +- 0.0031, t0 -6.3 ms +- 0.6
/// (without artifacts: 2.0546 and -20.3 ms); a 3 ms bound on t0 is not met: the model's own
/// tilt reaches eq 79 only at the end (`the_models_tilt_reaches_eq_79_only_at_the_end`). 30 ms
/// is checked.
#[test]
fn the_model_spin_down_with_artifacts_gives_beta_and_t0() {
    let trace = simulate_trace(&spin_down(2.0), &LightModel::default())
        .unwrap()
        .with_artifacts(&Artifacts::realistic(2.0, 4))
        .unwrap();
    let tr = trace.truth.clone().unwrap();
    for (label, t_from) in [("whole record", None), ("last 2.5 s", Some(tr.t0 - 2.5))] {
        let s = AnalysisSettings {
            t_from,
            ..AnalysisSettings::default()
        };
        let a = analyze(&trace, &s).unwrap();
        println!(
            "model, {label}: beta {:.4} +- {:.4} (truth {}), t0 error {:+.3} ms +- {:.3}, reduced chi2 {:.1}",
            a.eq84.beta,
            a.eq84.beta_sigma,
            tr.beta,
            1e3 * (a.eq84.t0 - tr.t0),
            1e3 * a.eq84.t0_sigma,
            a.eq84.reduced_chi2
        );
        assert!((a.eq84.beta - tr.beta).abs() < 0.1, "{a}");
        assert!((a.eq84.t0 - tr.t0).abs() < 0.03, "{a}");
        assert!(a.hum > 0.5 * 0.04 && a.hum < 1.5 * 0.04, "hum {}", a.hum);
    }
}

/// Coverage on artifact-laden exact-law traces (realistic drift, 50 Hz hum, clipping, glitches,
/// 1 % of samples dropped, each trace its own seeds): none refused, eq 79 taken to drift on at
/// most 2 + 2 % of them (as for clean traces), the 95 % intervals within
/// about 3 binomial sd of 95 %, the 68 % ones of 68.3 %, the pulls' mean within 3 standard
/// errors of 0, and the worst errors within the targets.
fn check_artifact_coverage(runs: usize, seed0: u64) {
    let c = covered(runs, seed0, true);
    assert!(
        c.worst_beta_error < 0.1 && c.worst_t0_error < 3e-3,
        "{}",
        c.summary()
    );
}

/// Met (measured 2026-11-25, seeds 2000-2119, same command with
/// `stated_intervals_cover_the_truth_on_artifact_laden_traces`, 223 s): none of 120 refused; beta
/// inside 1 sigma 68.3 %, 1.96 sigma 93.3 %; t0 70.0 %, 93.3 %; pulls (mean, sd) beta (+0.10,
/// 0.97), t0 (-0.09, 0.99); worst errors beta 0.0003, t0 0.135 ms. With peak-time sigmas and
/// covariance of $\max(s^2, 1)$ and AR(1) instead (see `least_squares`): 63.3 %, 91.7 %; t0
/// 64.2 %, 91.7 %; pulls (+0.17, 1.14), (-0.19, 1.14). A hum fitted on samples chosen from the
/// signal comes out 10-25 % short (more with drift), and where drift and hum meet one block's
/// leakage can hide it; so the hum is fitted on samples chosen from its residuals and judged by
/// the blocks' median, and a re-timed pulse is kept only where its two neighbours agree.
#[test]
#[ignore = "slow: 120 recordings, about four minutes on the shared machine"]
fn stated_intervals_cover_the_truth_on_artifact_laden_traces() {
    check_artifact_coverage(120, 2000);
}

/// The fast version for the normal run: 30 other artifact-laden recordings, with the bounds
/// that size allows. Measured 2026-11-25 (seeds 4000-4029): none refused; 1.96 sigma beta
/// 96.7 %, t0 93.3 % (1 sigma 76.7 %, 76.7 %); worst t0 0.171 ms (with the former peak-time
/// sigmas and covariance: 90.0 % and 93.3 %, worst t0 0.140 ms). Seed 4025 was refused (R^2 0.939) until a glitch on
/// the record's first sample, which begins inside a pulse, was removed like the others.
#[test]
fn stated_intervals_cover_the_truth_on_30_artifact_laden_traces() {
    check_artifact_coverage(30, 4000);
}

/// The full study: 500 other artifact-laden recordings. Met (measured 2026-11-25, seeds
/// 10000-10499, `cargo test --release --test integration -- experiment::stated_intervals_cover_the_truth_full_study
/// --exact --include-ignored --nocapture`, 18 min beside the 400-trace study on the shared
/// machine): none refused; beta inside 1 sigma 67.6 %, 1.96 sigma 94.8 %; t0 67.2 %, 94.6 %; pulls
/// (mean, sd) beta (+0.15, 1.02), t0 (-0.15, 1.03); worst errors beta 0.0016, t0 1.813 ms; eq 79
/// taken to drift on 3 (their intervals widened by the law's part). Before the law's drift was
/// tested: 67.4 %, 94.8 %; t0 67.0 %, 94.4 %.
#[test]
#[ignore = "slow: 500 artifact-laden recordings, about 15 minutes"]
fn stated_intervals_cover_the_truth_full_study() {
    let c = coverage::coverage(500, 10_000, true).unwrap();
    println!("{}", c.summary());
    assert!(c.law_drifts <= 12, "{}", c.summary());
    // Binomial sd at 500 runs: 2.1 % at 68 %, 1.0 % at 95 %; bounds at 3 sd.
    for pulls in [&c.beta_pulls, &c.t0_pulls] {
        let (one, two) = (c.fraction(pulls, 1.0), c.fraction(pulls, 1.96));
        assert!((0.62..=0.75).contains(&one), "{}", c.summary());
        assert!((0.92..=0.98).contains(&two), "{}", c.summary());
    }
}

/// On the report's own record (the built-in spin-down scene, eq 75 with beta = 2) eq 84 ends
/// before the last pulse the disk makes: flagged in the text and the JSON; the eq 84 line quotes
/// the total uncertainty; the model choice reads the two-mechanism law's small change of
/// exponent as the single law's drift and does not call two mechanisms.
#[test]
fn the_reports_record_is_flagged_for_an_early_end_and_not_called_two_mechanisms() {
    let scene = Scene::load("spin-down").unwrap();
    let trace = simulate_trace(&scene, &LightModel::default()).unwrap();
    let a = analyze(&trace, &AnalysisSettings::default()).unwrap();
    let text = a.to_string();
    println!("{text}");
    let e = a.early_end.clone().unwrap_or_else(|| panic!("{text}"));
    assert!(e.before > 0.005 && e.before < 0.02, "{e:?}");
    assert!(e.last_peak <= trace.truth.as_ref().unwrap().t0, "{e:?}");
    assert!(text.contains("the law ends too early"), "{text}");
    assert!(a.to_json().contains("\"early_end\": {"), "{text}");
    let (_, t0_total) = a.stated_sigmas();
    assert!(t0_total > 2.0 * a.eq84.t0_sigma, "{text}");
    assert!(text.contains(&format!(
        "t0 = {:.6} +- {:.6} s (total",
        a.eq84.t0, t0_total
    )));
    assert!(a.models.drift && !a.models.calls_two(), "{text}");
    assert!(
        text.contains("one law that drifts over the window"),
        "{text}"
    );
}
