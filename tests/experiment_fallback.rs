//! A phase fit that cannot be right is not the result: the pitch track's fit is reported, and
//! the analysis says which and why.

use experiment::plausibility::Plausibility;
use experiment::{analyze_sound, law_sound, Artifacts, Law, Microphone, TrackSettings};

/// A phone's sound of eq 79 exactly: its phase fit is plausible and is the result; the same
/// analysis with the phase's t0 moved 1 s before the last tracked pitch, or with beta's sigma
/// above beta, reports the pitch track's fit instead and says why.
#[test]
fn an_implausible_phase_fit_falls_back_to_the_pitch() {
    let law = Law {
        beta: 2.0,
        c: 100f64.powi(4) * 7.0,
    };
    let mic = Microphone::phone(16_000, 3);
    let s = law_sound(&law, &mic, &Artifacts::none()).unwrap();
    let a = analyze_sound(&s, &TrackSettings::default(), &Plausibility::default()).unwrap();
    assert_eq!(a.phase_implausible(), None, "{a}");
    assert!(a.law().from_phase, "{a}");
    assert!(
        a.to_string().contains("eq 79 on the phase (the result)"),
        "{a}"
    );
    let json: serde_json::Value = serde_json::from_str(&a.to_json()).unwrap();
    assert_eq!(json["result"]["fitted_on"], "phase", "{json}");
    assert!(json["result"]["why_not_phase"].is_null(), "{json}");

    let last = a.track.points.last().map(|q| 0.5 * (q.a + q.b)).unwrap();
    let mut early = a.clone();
    early.phase.as_mut().unwrap().t0 = last - 1.0;
    let mut loose = a.clone();
    let p = loose.phase.as_mut().unwrap();
    p.beta_sigma = 2.0 * p.beta;
    for (b, why) in [
        (&early, "before the last tracked pitch"),
        (&loose, "is not determined"),
    ] {
        let l = b.law();
        let text = b.to_string();
        println!(
            "{}",
            text.lines().find(|x| x.contains("on the phase")).unwrap()
        );
        assert!(!l.from_phase, "{text}");
        assert_eq!((l.beta, l.t0), (b.fit.beta, b.fit.t0));
        assert!(
            text.contains("not the result")
                && text.contains(why)
                && text.contains("the pitch's fit is reported"),
            "{text}"
        );
        // The JSON says it too.
        let json: serde_json::Value = serde_json::from_str(&b.to_json()).unwrap();
        assert_eq!(json["result"]["fitted_on"], "pitch", "{json}");
        assert!(
            json["result"]["why_not_phase"]
                .as_str()
                .is_some_and(|w| w.contains(why)),
            "{json}"
        );
        assert_eq!(json["result"]["law"]["beta"], b.fit.beta, "{json}");
    }
}

/// A quiet room with 2 % mains hum: the pitch track is pulled by the hum beyond its scatter and
/// the fits disagree by more than three of their sigmas, but the phase's residuals are noise, so
/// the disagreement is not counted and beta's stated sigma is the phase's own (beta right within
/// three of it). The same analysis with residuals that drift (structure) is not the result: the
/// pitch's fit is reported; with the law's drift across the record stated, or without the hum
/// found, the phase is the result in doubt and the disagreement is counted; the text and JSON
/// say which and why.
#[test]
fn a_disagreement_widens_the_phase_only_where_the_phase_is_in_doubt() {
    use experiment::sound::Voice;
    use experiment::sound_analysis::residual_structure::Structure;
    let law = Law {
        beta: 2.0,
        c: 100f64.powi(4) * 7.0,
    };
    let mic = Microphone {
        sample_rate: 48_000,
        samples: 480_000,
        voice: Voice {
            room: 0.003,
            ..Voice::phone()
        },
        noise: 0.003,
        seed: 1,
        ..Microphone::default()
    };
    let art = Artifacts {
        hum: 0.02,
        seed: 1,
        ..Artifacts::none()
    };
    let s = law_sound(&law, &mic, &art).unwrap();
    let a = analyze_sound(&s, &TrackSettings::default(), &Plausibility::default()).unwrap();
    let p = a.phase.as_ref().expect("the phase is fitted");
    assert!(!a.track.hum.is_empty(), "{a}");
    assert!(p.structure.is_some_and(|s| !s.shown()), "{a}");
    assert!(
        (p.beta - a.fit.beta).abs() > 3.0 * p.beta_sigma.hypot(a.fit.beta_sigma),
        "the fits must disagree for the case to test anything: {a}"
    );
    assert_eq!(a.phase_in_doubt(), None, "{a}");
    let l = a.law();
    assert!(l.from_phase, "{a}");
    assert_eq!(l.beta_terms.disagreement, 0.0, "{a}");
    assert!((l.beta - 2.0).abs() < 3.0 * l.beta_sigma, "{a}");
    let text = a.to_string();
    assert!(
        text.contains("not counted in the phase's uncertainty"),
        "{text}"
    );
    let json: serde_json::Value = serde_json::from_str(&a.to_json()).unwrap();
    assert!(
        json["result"]["disagreement"]
            .as_str()
            .is_some_and(|w| w.contains("not counted")),
        "{json}"
    );

    // A corner whose sigma is larger than itself is no corner read: its number is not printed.
    let mut loose = a.clone();
    let q = loose.phase.as_mut().unwrap();
    q.corner = Some((4.665e8, 1.3e26));
    q.corner_not_used = Some("it is within 3 of its sigmas of zero".into());
    let text = loose.to_string();
    let stated = text.lines().find(|x| x.contains("stated:")).unwrap();
    assert!(
        stated.contains("determine no high-pass's corner") && !stated.contains("466500000"),
        "{stated}"
    );

    // The same blocks with residuals that drift by three sigmas over the record: the heading
    // does not hold, so the phase's fit is not the result and the pitch's is reported.
    let mut drifting = a.clone();
    let q = drifting.phase.as_mut().unwrap();
    let n = q.points.len() as f64;
    let (r, sig): (Vec<f64>, Vec<f64>) = q
        .points
        .iter()
        .enumerate()
        .map(|(k, b)| {
            let r = b.residual + 3.0 * b.sigma * (k as f64 / n * std::f64::consts::TAU).sin();
            (r, b.sigma)
        })
        .unzip();
    q.structure = Structure::of(&r, &sig);
    assert!(q.structure.is_some_and(|s| s.shown()), "{:?}", q.structure);
    let why = drifting.phase_implausible().expect("not the result");
    assert!(why.contains("residuals show structure"), "{why}");
    let l = drifting.law();
    assert!(!l.from_phase);
    assert_eq!((l.beta, l.beta_sigma), (a.fit.beta, a.fit.beta_sigma));
    let text = drifting.to_string();
    println!(
        "{}",
        text.lines().find(|x| x.contains("on the phase")).unwrap()
    );
    assert!(
        text.contains("not the result: its residuals show structure")
            && text.contains("the pitch's fit is reported")
            && text.contains("structure, so the phase's fit is not the result"),
        "{text}"
    );
    let json: serde_json::Value = serde_json::from_str(&drifting.to_json()).unwrap();
    assert_eq!(json["result"]["fitted_on"], "pitch", "{json}");
    assert!(
        json["result"]["why_not_phase"]
            .as_str()
            .is_some_and(|w| w.contains("residuals show structure")),
        "{json}"
    );

    // The same structure with eq 79's drift across the record measured: the shift is stated in
    // the uncertainty, so the phase's fit stays the result, in doubt, its disagreement counted.
    let mut stated = drifting.clone();
    let q = stated.phase.as_mut().unwrap();
    q.law.as_mut().expect("the later half is fitted").drifts = true;
    assert_eq!(stated.phase_implausible(), None, "{stated}");
    let why = stated.phase_in_doubt().expect("in doubt");
    assert!(why.contains("residuals show structure"), "{why}");
    let l = stated.law();
    assert!(l.from_phase, "{stated}");
    assert_eq!(l.beta_terms.disagreement, (p.beta - a.fit.beta).abs());
    assert!(
        stated.to_string().contains("counted where beyond"),
        "{stated}"
    );

    // The same analysis had no mains hum been found: nothing known biases the pitch track alone,
    // so the phase's fit is in doubt and the disagreement is counted in its uncertainty.
    let mut unhummed = a.clone();
    unhummed.track.hum.clear();
    let why = unhummed.phase_in_doubt().expect("in doubt");
    assert!(why.contains("no mains hum was found"), "{why}");
    let l = unhummed.law();
    assert!(l.from_phase);
    assert_eq!(l.beta_terms.disagreement, (p.beta - a.fit.beta).abs());
    assert!(l.beta_sigma >= (p.beta - a.fit.beta).abs());
    let text = unhummed.to_string();
    println!(
        "{}",
        text.lines().find(|x| x.contains("disagreement:")).unwrap()
    );
    assert!(
        text.contains("counted where beyond") && text.contains("no mains hum was found"),
        "{text}"
    );
    let json: serde_json::Value = serde_json::from_str(&unhummed.to_json()).unwrap();
    assert!(
        json["result"]["disagreement"]
            .as_str()
            .is_some_and(|w| w.contains("no mains hum was found")),
        "{json}"
    );
}
