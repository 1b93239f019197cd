//! Recordings from both models: the dissipative rolling model and the sliding model
//! (Coulomb friction, lift-off and landing), each with every artifact, analysed end to end.
//!
//! The error of an analysis has two parts, scored separately: the analysis's own (noise, drift,
//! hum, clipping, glitches and dropped samples against eq 84 fitted to the motion's exact
//! passage times over the same cycles, `motion_law::law_of_motion`) and the law's (that fit
//! against the model's own end and exponent: the model is not eq 79 exactly).

use experiment::motion_law::law_of_motion;
use experiment::simulate::simulate_motion;
use experiment::*;
use physics::scene::Scene;

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
    /// Eq 84's t0 and beta against the model's own end and exponent, in the stated uncertainty
    /// (the fit's, and the law's where eq 79 drifts over the window).
    truth_t0_pull: f64,
    truth_beta_pull: f64,
    drifts: bool,
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
        truth_t0_pull: (a.eq84.t0 - truth.t0) / a.stated_sigmas().1,
        truth_beta_pull: (a.eq84.beta - truth.beta) / a.stated_sigmas().0,
        drifts: a.law_stability.as_ref().is_some_and(|l| l.drifts),
    };
    println!(
        "{} ({}), {}: analysis beta {:.4} +- {:.4}, t0 {:+.3} ms +- {:.3} from the law of the \
         motion; the law of the motion: beta {:+.4}, t0 {:+.3} ms from the truth; the law \
         drifts over the window: {} (t0's stated uncertainty {:.3} ms); pulls against the \
         truth in the stated uncertainty: beta {:+.2}, t0 {:+.2}",
        scene.name,
        truth.origin,
        t_from_end.map_or("whole record".to_string(), |d| format!("last {d} s")),
        a.eq84.beta,
        a.eq84.beta_sigma,
        1e3 * s.analysis_t0_error,
        1e3 * s.t0_sigma,
        s.law_beta_error,
        1e3 * s.law_t0_error,
        s.drifts,
        1e3 * a.stated_sigmas().1,
        s.truth_beta_pull,
        s.truth_t0_pull,
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
        // Eq 79 drifts over the model's record, and the later half's shift is stated as the
        // law's uncertainty. Over the whole record the model's own end and exponent are then
        // inside the stated 95 % intervals (measured 2026-11-25, rolling and sliding alike:
        // pulls t0 -1.66, beta +0.93). Over the last 2.5 s the law drifts less inside the
        // window than it errs in extrapolating to the end: t0 is 2.5 stated sigmas early
        // (6.2 ms, stated 0.42 ms stat and 2.4 ms law), inside 3 and not inside 1.96.
        assert!(
            s.drifts,
            "the law's drift over the model's record was not seen"
        );
        let bound = if window.is_none() { 1.96 } else { 3.0 };
        assert!(
            s.truth_t0_pull.abs() < bound && s.truth_beta_pull.abs() < bound,
            "pulls against the model's truth beta {:+.2}, t0 {:+.2}",
            s.truth_beta_pull,
            s.truth_t0_pull
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

/// How much of the law's part is the precession's lag behind eq 33: eq 84 fitted (equal
/// weights) to the passages of the model's heading through whole turns, and to the passages
/// of the heading the disk would have if it precessed at eq 33's rate for its tilt,
/// $\psi_{33} = \int\sqrt{g/(ka\sin\alpha)}\,dt$, over the record up to 60 ms before the end
/// (about where the analysis's last cycle is). Measured 2026-11-25: the model's heading gives
/// beta 2.065, t0 21.1 ms early; eq 33's heading from the same tilt gives beta 2.007, t0 7.2
/// ms early. So the lag (the centre's drift off b = 0) makes two thirds of the early t0 and
/// nearly all of the excess in beta; the rest is the tilt's own departure from eq 78's
/// $\alpha \propto (t_0 - t)^{2/(\beta+2)}$.
#[test]
fn the_precessions_lag_makes_most_of_the_laws_early_t0() {
    use experiment::fit::fit_eq84;
    use std::f64::consts::TAU;
    let scene = spin_down("dissipative", 2.0, "");
    let d = scene.disk;
    let m = simulate_motion(&scene, 7.27, 20_000.0, 200_000).unwrap();
    let t0 = m.truth.t0;
    let sign = (m.heading[1] - m.heading[0]).signum();
    let eq33 = |a: f64| sign * (d.g / (d.k * d.a * a.sin())).sqrt();
    let mut psi33 = vec![0.0; m.t.len()];
    for j in 1..m.t.len() {
        psi33[j] = if m.alpha[j].is_finite() {
            psi33[j - 1] + 0.5 * (eq33(m.alpha[j]) + eq33(m.alpha[j - 1])) * (m.t[j] - m.t[j - 1])
        } else {
            f64::NAN
        };
    }
    let fit = |psi: &[f64]| {
        let mut p = Vec::new();
        let mut n = (psi[0] / TAU).floor();
        for j in 0..m.t.len() - 1 {
            if m.t[j + 1] > t0 - 0.06 {
                break;
            }
            let target = (n + sign.max(0.0)) * TAU;
            if (psi[j] - target) * (psi[j + 1] - target) <= 0.0 && psi[j] != psi[j + 1] {
                p.push(m.t[j] + (m.t[j + 1] - m.t[j]) * (target - psi[j]) / (psi[j + 1] - psi[j]));
                n += sign;
            }
        }
        let idx: Vec<usize> = (0..p.len() - 1).collect();
        let f = fit_eq84(&p[..p.len() - 1], &p[1..], &idx, &vec![1e-10; p.len()]).unwrap();
        (f.beta, f.t0 - t0, p.len())
    };
    let (bm, tm, nm) = fit(&m.heading);
    let (b33, t33, n33) = fit(&psi33);
    println!(
        "model heading: beta {bm:.4}, t0 {:+.2} ms ({nm} passages); eq 33 from its tilt: beta \
         {b33:.4}, t0 {:+.2} ms ({n33} passages)",
        1e3 * tm,
        1e3 * t33
    );
    assert!(tm < -0.015 && (bm - 2.0) > 0.04, "{bm} {tm}");
    assert!(
        t33.abs() < 0.5 * tm.abs() && (b33 - 2.0).abs() < 0.25 * (bm - 2.0),
        "{b33} {t33}"
    );
}
