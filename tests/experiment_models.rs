//! Issue 15's recordings "from both models": the dissipative rolling model and the sliding model
//! (Coulomb friction, lift-off and landing), each with every artifact, analysed end to end.
//!
//! The error of an analysis has two parts, scored separately: the analysis's own (noise, drift,
//! hum, clipping, glitches and dropped samples against eq 84 fitted to the motion's exact
//! passage times over the same cycles, `motion_law::law_of_motion`) and the law's (that fit
//! against the model's own end and exponent: the model is not eq 79 exactly).

use rolling_disk::experiment::motion_law::law_of_motion;
use rolling_disk::experiment::simulate::simulate_motion;
use rolling_disk::experiment::*;
use rolling_disk::scene::Scene;

/// A spin-down of `model` with exponent `beta` lasting about 9 s from its adiabatic start (as in
/// `tests/experiment.rs`); `extra` adds scene keys (friction for the sliding model).
fn spin_down(model: &str, beta: f64, extra: &str) -> Scene {
    let (a, k, g, alpha0, duration) = (0.0375, 0.25, 9.81, 0.12, 9.0);
    let omega0 = (g / (k * a * f64::sin(alpha0))).sqrt();
    let epsilon = 3.0 * g / (k * a * (beta + 2.0) * omega0.powf(beta + 2.0) * duration);
    let alpha_dot = -2.0 / 3.0 * epsilon * omega0.powf(beta) / alpha0.cos();
    let yaml = format!(
        "name: {model}-spin-down-beta-{beta}\n\
         disk: {{ radius: {a}, k: {k}, mass: 0.4, g: {g} }}\n\
         model: {model}\n{extra}\
         dissipation: {{ epsilon: {epsilon:e}, beta: {beta} }}\n\
         start: {{ steady: {{ alpha0: {alpha0}, b: 0.0 }}, perturb: {{ alpha_dot: {alpha_dot:e} }} }}\n\
         stop: {{ time: 30.0, alpha_below: 1.0e-4 }}\n\
         solver: {{ method: dop853, rtol: 1.0e-10, atol: 1.0e-12 }}\n"
    );
    Scene::parse(&yaml, "test").expect("valid scene")
}

/// What one model's artifact-laden recording gives: the analysis against the law of the motion
/// (the analysis's error) and the law of the motion against the truth (the law's).
struct Scored {
    beta: f64,
    analysis_t0_error: f64,
    analysis_beta_error: f64,
    law_t0_error: f64,
    law_beta_error: f64,
    t0_sigma: f64,
}

fn score(scene: &Scene, seed: u64, t_from_end: Option<f64>) -> Scored {
    let light = LightModel::default();
    let sc = &light.scope;
    let motion = simulate_motion(scene, sc.end_at, sc.sample_rate, sc.samples).unwrap();
    let trace = simulate_trace(scene, &light)
        .unwrap()
        .with_artifacts(&Artifacts::realistic(light.gain, seed))
        .unwrap();
    let truth = trace.truth.clone().unwrap();
    let settings = AnalysisSettings {
        t_from: t_from_end.map(|d| truth.t0 - d),
        ..AnalysisSettings::default()
    };
    let a = analyze(&trace, &settings).unwrap();
    let law = law_of_motion(&motion, &light, &a).unwrap();
    let s = Scored {
        beta: a.eq84.beta,
        analysis_t0_error: a.eq84.t0 - law.t0,
        analysis_beta_error: a.eq84.beta - law.beta,
        law_t0_error: law.t0 - truth.t0,
        law_beta_error: law.beta - truth.beta,
        t0_sigma: a.eq84.t0_sigma,
    };
    println!(
        "{} ({}), {}: analysis beta {:.4} +- {:.4}, t0 {:+.3} ms +- {:.3} from the law of the \
         motion; the law of the motion: beta {:+.4}, t0 {:+.3} ms from the truth",
        scene.name,
        truth.origin,
        t_from_end.map_or("whole record".to_string(), |d| format!("last {d} s")),
        a.eq84.beta,
        a.eq84.beta_sigma,
        1e3 * s.analysis_t0_error,
        1e3 * s.t0_sigma,
        s.law_beta_error,
        1e3 * s.law_t0_error,
    );
    s
}

/// The targets on the analysis: beta within 0.1 and t0 within 3 ms, on each model's
/// recording with every artifact; and beta within 0.1 of the model's own. The model's end is
/// where its tilt vanishes; eq 79 fitted to its exact motion ends earlier (printed, and checked
/// to be the law's and not the light's: below 40 ms).
fn check(scene: &Scene) {
    for (seed, window) in [(4, None), (5, Some(2.5))] {
        let s = score(scene, seed, window);
        assert!((s.beta - 2.0).abs() < 0.1, "beta {}", s.beta);
        assert!(
            s.analysis_beta_error.abs() < 0.1,
            "{}",
            s.analysis_beta_error
        );
        assert!(
            s.analysis_t0_error.abs() < 3e-3,
            "analysis t0 {} +- {}",
            s.analysis_t0_error,
            s.t0_sigma
        );
        assert!(s.law_t0_error.abs() < 0.04, "law t0 {}", s.law_t0_error);
        assert!(
            s.law_beta_error.abs() < 0.1,
            "law beta {}",
            s.law_beta_error
        );
    }
}

#[test]
fn the_rolling_models_recording_with_every_artifact_meets_the_targets() {
    check(&spin_down("dissipative", 2.0, ""));
}

#[test]
fn the_sliding_models_recording_with_every_artifact_meets_the_targets() {
    check(&spin_down(
        "sliding",
        2.0,
        "friction: { mu: 0.6, restitution: 0.0 }\n",
    ));
}

/// Why eq 79 misplaces the model's end (the law's part above): eq 76 assumes steady $b = 0$
/// motion, eq 33's $\Omega^2 = g/(ka\sin\alpha)$, at every instant. The model obeys eq 23,
/// $(2k+1)\dot\omega_1 = -\dot\alpha\,\Omega\sin\alpha$ (with eq 75's torque along
/// $-\boldsymbol\omega$, which has no $\hat{\mathbf 1}$ part at $b = 0$): as the disk falls it
/// gains $\omega_1 = b\Omega/a$, so its centre leaves $b = 0$, and by eq 29 its precession runs
/// slower than eq 33's, by $(2k+1)b/(2ka)$ = $3b/a$ for the uniform disk. Measured on the
/// rolling and the sliding models' motions (heading rate by central differences over 2 ms
/// against eq 33 at the same tilt; 2026-11-25): 0.32 % slow 7 s before the end, 0.75 % at 1 s.
/// The model's own state there has $b/a = \omega_1/\Omega$ = 1.05e-3 and 2.51e-3: three times
/// these is the whole departure. Eq 79's constant C would absorb a constant ratio; one that
/// changes over the record moves t0.
#[test]
fn the_models_precession_falls_behind_eq_33_as_the_disk_falls() {
    for scene in [
        spin_down("dissipative", 2.0, ""),
        spin_down("sliding", 2.0, "friction: { mu: 0.6, restitution: 0.0 }\n"),
    ] {
        let light = LightModel::default();
        let sc = &light.scope;
        let m = simulate_motion(&scene, sc.end_at, sc.sample_rate, sc.samples).unwrap();
        let d = &scene.disk;
        let ratio = |back: f64| {
            let j =
                m.t.iter()
                    .position(|&x| x >= m.truth.t_stop - back)
                    .unwrap();
            let h = 5;
            let rate = (m.heading[j + h] - m.heading[j - h]) / (m.t[j + h] - m.t[j - h]);
            let eq33 = (d.g / (d.k * d.a * m.alpha[j].sin())).sqrt();
            rate.abs() / eq33 - 1.0
        };
        let (early, late) = (ratio(7.0), ratio(1.0));
        println!(
            "{}: Omega / eq 33 - 1 = {:+.2e} 7 s before the end, {:+.2e} at 1 s",
            scene.name, early, late
        );
        assert!(
            early < 0.0 && late < 2.0 * early && late > -0.02,
            "{early} {late}"
        );
    }
}
