//! Mains hum in a sound recording: subtracted however quiet the room, and followed when the
//! grid's frequency wanders.

use experiment::plausibility::Plausibility;
use experiment::sound::Voice;
use experiment::{
    analyze_sound, law_sound, Artifacts, Law, Microphone, SoundAnalysis, TrackSettings,
};

/// Eq 79's law with beta and Omega = 100 rad/s at 7 s before t0.
fn law(beta: f64) -> Law {
    Law {
        beta,
        c: 100f64.powf(beta + 2.0) * 7.0,
    }
}

fn sound_of(s: &experiment::Trace) -> Result<SoundAnalysis, String> {
    analyze_sound(s, &TrackSettings::default(), &Plausibility::default()).map_err(|e| e.to_string())
}

/// A phone's sound at 44.1 kHz with 2 % hum and the room all but silent (no noise, or 1e-5 rms):
/// the mains lines' residue in the silent lead-in is a pure tone there, which the track must not
/// join to the disk's line. The analysis gives beta and t0 within their sigma of the truth.
#[test]
fn a_near_noiseless_sound_with_hum_is_tracked() {
    for noise in [0.0, 1e-5] {
        let mic = Microphone {
            noise,
            voice: Voice {
                room: noise,
                ..Voice::phone()
            },
            ..Microphone::phone(44_100, 3)
        };
        let art = Artifacts {
            hum: 0.02,
            ..Artifacts::none()
        };
        let s = law_sound(&law(2.0), &mic, &art).unwrap();
        let a = sound_of(&s).unwrap_or_else(|e| panic!("noise {noise}: {e}"));
        println!("noise {noise}: {a}");
        let truth = s.truth.as_ref().unwrap();
        let l = a.law();
        assert!(l.from_phase, "{a}");
        assert!(!a.track.hum.is_empty(), "{a}");
        assert!((l.beta - truth.beta).abs() < l.beta_sigma, "{a}");
        assert!((l.t0 - truth.t0).abs() < l.t0_sigma, "{a}");
    }
}
