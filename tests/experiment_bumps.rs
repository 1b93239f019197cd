//! A handling bump during the spin (the phone knocked, the table struck) is stepped over by the
//! pitch track, not taken for the disk's line: the track says where it was, and the fit is
//! that of the recording without it.

use experiment::plausibility::Plausibility;
use experiment::{analyze_sound, law_sound, Artifacts, Law, Microphone, TrackSettings};
use std::f64::consts::TAU;

#[test]
fn a_bump_during_the_spin_is_stepped_over() {
    let law = Law {
        beta: 2.0,
        c: 100f64.powi(4) * 7.0,
    };
    let mic = Microphone::phone(16_000, 5);
    let mut trace = law_sound(&law, &mic, &Artifacts::none()).expect("a sound");
    // A 40 Hz thump at 5 s, decaying in 30 ms, at nearly full scale: ten times the disk.
    for (t, v) in trace.t.iter().zip(trace.v.iter_mut()) {
        let s = t - 5.0;
        if (0.0..0.3).contains(&s) {
            *v += 0.9 * (-s / 0.03).exp() * (TAU * 40.0 * s).sin();
        }
    }
    let a = analyze_sound(&trace, &TrackSettings::default(), &Plausibility::default())
        .unwrap_or_else(|e| panic!("a bump refuses the spin: {e}"));
    let bumps = &a.track.bumps;
    assert_eq!(bumps.len(), 1, "{bumps:?}");
    assert!(
        bumps[0].0 > 4.97 && bumps[0].0 <= 5.0 && bumps[0].1 < 5.3,
        "{bumps:?}"
    );
    for p in &a.track.points {
        assert!(
            p.b <= bumps[0].0 || p.a >= bumps[0].1,
            "a frame holds the bump: {p:?}"
        );
    }
    assert!((a.law().beta - 2.0).abs() < 0.05, "{a}");
}
