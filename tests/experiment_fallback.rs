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
