//! The phase fit's turn count against the pitch track's: a slip of one turn is refused, a law
//! that drifts over the record is not (`experiment::turn_count`).

use experiment::plausibility::Plausibility;
use experiment::turn_count::{TurnCount, SIGMAS};
use experiment::{analyze_sound, simulate_sound, Artifacts, Microphone, TrackSettings};
use nalgebra::{SMatrix, SVector};
use physics::scene::Scene;

/// The parameters of the law `p` = $(\beta, t_0, \ln C)$ with $\ln C$ moved so that it counts
/// `extra` turns more than `p` from `from` to `to`.
fn with_extra_turns(p: &SVector<f64, 3>, extra: f64, span: (f64, f64)) -> SVector<f64, 3> {
    let zero = SMatrix::<f64, 3, 3>::zeros();
    let count = |q: &SVector<f64, 3>| TurnCount::of(q, p, &zero, span).phase;
    let target = count(p) + extra;
    let mut q = *p;
    for _ in 0..20 {
        let h = 1e-6;
        let mut up = q;
        up[2] += h;
        let slope = (count(&up) - count(&q)) / h;
        q[2] += (target - count(&q)) / slope;
    }
    q
}

/// A law that counts one turn more or fewer than the track's is miscounted; a fifth of a turn,
/// or a whole turn where the track's own count is uncertain by more than a third of one, is
/// not.
#[test]
fn a_slip_of_one_turn_is_called_and_a_fraction_is_not() {
    let track = SVector::<f64, 3>::new(2.0, 8.49, 20.26);
    let span = (1.0, 8.42);
    // A track whose count is known to a few hundredths of a turn (its parameters' errors, much
    // larger, are correlated so as to keep the count; here they are taken small and apart).
    let cov = SMatrix::<f64, 3, 3>::from_diagonal(&SVector::<f64, 3>::new(
        2e-4f64.powi(2),
        5e-5f64.powi(2),
        1e-3f64.powi(2),
    ));
    for (extra, miscounted) in [(1.0, true), (-1.0, true), (0.2, false), (-0.45, false)] {
        let phase = with_extra_turns(&track, extra, span);
        let c = TurnCount::of(&phase, &track, &cov, span);
        println!("{extra:+} turns: {c}");
        assert!(((c.phase - c.track) - extra).abs() < 1e-9, "{c}");
        assert!(c.sigma < 1.0 / SIGMAS, "{c}");
        assert_eq!(c.miscounted(), miscounted, "{c}");
    }
    // A law whose t0 falls inside the span counts its turns to its t0.
    let early = SVector::<f64, 3>::new(2.0, 8.41, 20.26);
    let c = TurnCount::of(&early, &early, &cov, span);
    assert!(
        c.track.is_finite() && c.phase == c.track && !c.miscounted(),
        "{c}"
    );
    // With the track's count uncertain by a turn, a one-turn difference cannot be told.
    let loose = cov * 1e4;
    let c = TurnCount::of(&with_extra_turns(&track, 1.0, span), &track, &loose, span);
    assert!(c.sigma > 1.0 / SIGMAS && !c.miscounted(), "{c}");
}

/// The simulated spin-down's sound, recorded by a phone with every bench artifact, does not
/// follow eq 79 exactly: the phase's and the track's beta and t0 differ by more than three of
/// the track's sigmas. Their turn counts agree within a tenth of a turn, and the phase is used.
#[test]
fn a_drifting_law_is_not_taken_for_a_miscount() {
    let scene = Scene::load("spin-down").unwrap();
    let mic = Microphone::phone(48_000, 1);
    let s = simulate_sound(&scene, &mic, &Artifacts::realistic(2.0 * mic.amplitude, 1)).unwrap();
    let a = analyze_sound(&s, &TrackSettings::default(), &Plausibility::default()).unwrap();
    let p = a.phase.as_ref().unwrap_or_else(|| panic!("{a}"));
    let f = &a.fit;
    println!("{a}");
    assert!(
        (p.t0 - f.t0).abs() > 3.0 * f.t0_sigma,
        "the fits agree: t0 {} and {} +- {}",
        p.t0,
        f.t0,
        f.t0_sigma
    );
    let law = p.law.as_ref().expect("the later half's fit");
    assert!(law.drifts, "{a}");
    let c = a.turn_count.expect("the turns counted");
    assert!((c.phase - c.track).abs() < 0.1 && c.sigma < 0.2, "{c}");
}
