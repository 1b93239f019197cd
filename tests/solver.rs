//! The solver layer against problems with known answers.

use physics::solve::arenstorf::{start, Arenstorf, PERIOD};
use physics::solve::{
    solve, solve_with, Dynamics, Ending, Engine, Event, Method, Problem, Settings, State, WithTime,
};

/// Van der Pol's equation in Hairer's scaling, $\epsilon = 10^{-3}$ (stiff-ish).
struct VanDerPol {
    eps: f64,
}

impl Dynamics<2> for VanDerPol {
    fn rhs(&self, y: &State<2>, dy: &mut State<2>) {
        dy[0] = y[1];
        dy[1] = ((1.0 - y[0] * y[0]) * y[1] - y[0]) / self.eps;
    }
}

#[test]
fn reproduces_hairers_van_der_pol_acceptance_problem() {
    let vdp = VanDerPol { eps: 1e-3 };
    let p = Problem::new(&vdp, 0.0, State::<2>::new(2.0, 0.0), 2.0);
    let sol = solve(p, &Settings::dop853(1e-9, 1e-9)).unwrap();
    assert_eq!(sol.ending, Ending::TimeReached);
    let (t, y) = sol.last();
    assert_eq!(t, 2.0);
    let expected = [1.763234540172087, -0.835_688_681_930_191];
    eprintln!(
        "Van der Pol, eps 1e-3, rtol = atol = 1e-9: y(2) = ({:.16}, {:.16}); {} evaluations, {} accepted and {} rejected steps",
        y[0], y[1], sol.stats.evaluations, sol.stats.accepted, sol.stats.rejected
    );
    assert!((y[0] - expected[0]).abs() < 1e-7, "y1(2) = {}", y[0]);
    assert!((y[1] - expected[1]).abs() < 1e-7, "y2(2) = {}", y[1]);
    // The statistics are counted and consistent: DOP853 spends 12 evaluations on an accepted step
    // and 11 on a rejected one (plus a few to start), and this problem rejects some.
    let (acc, rej) = (sol.stats.accepted, sol.stats.rejected);
    assert!(acc > 100 && rej > 0);
    let expected_evals = 12 * acc + 11 * rej;
    assert!(
        sol.stats.evaluations.abs_diff(expected_evals) <= 20,
        "{} evaluations",
        sol.stats.evaluations
    );
    assert_eq!(sol.t.len() as u64, sol.stats.accepted + 1);
}

fn seven_t_six(t: f64, _y: &[f64], dy: &mut [f64]) {
    dy[0] = 7.0 * t.powi(6);
}

#[test]
fn time_dependent_problem_is_integrated_correctly_through_the_layer() {
    // y' = 7 t^6, y(0) = 0: y(1) = 1. An 8th-order method integrates a degree-6 right-hand side
    // exactly; ode_solvers 0.6.2's DOP853 would not, were it handed the time (c12 = c13 = 0).
    let f = WithTime::<_, 1> { f: seven_t_six };
    for method in [Method::Dop853, Method::Dopri5] {
        let s = Settings {
            method,
            rtol: 1e-12,
            atol: 1e-14,
            ..Settings::default()
        };
        let sol = solve(Problem::new(&f, 0.0, State::<2>::new(0.0, 0.0), 1.0), &s).unwrap();
        let (_, y) = sol.last();
        assert!((y[1] - 1.0).abs() < 1e-14, "{method}: t = {}", y[1]);
        assert!((y[0] - 1.0).abs() < 1e-11, "{method}: y(1) = {}", y[0]);
    }
}

/// The defect this layer works around, shown on ode_solvers itself: DOP853 handed the time.
/// If this test starts failing, upstream has fixed its tableau (and `WithTime` is no longer
/// needed for correctness, only for safety).
#[test]
fn upstream_dop853_mishandles_time_dependent_systems() {
    use ode_solvers::{Dop853, System, Vector1};
    struct Raw;
    impl System<f64, Vector1<f64>> for Raw {
        fn system(&self, t: f64, _y: &Vector1<f64>, dy: &mut Vector1<f64>) {
            dy[0] = 7.0 * t.powi(6);
        }
    }
    let mut s = Dop853::new(Raw, 0.0, 1.0, 1.0, Vector1::new(0.0), 1e-12, 1e-14);
    // Upstream either gives up (its error estimate, built on the wrong nodes, looks stiff) or
    // returns a wrong y(1).
    let outcome = s.integrate();
    let y = s.y_out().last().unwrap()[0];
    let (t_end, _) = (s.x_out().last().copied().unwrap(), ());
    let defective = outcome.is_err() || t_end < 1.0 || (y - 1.0).abs() > 1e-9;
    assert!(
        defective,
        "upstream DOP853 now gets y(1) = {y}: the defect is fixed"
    );
}

/// $\ddot x = -x$ from (1, 0): $x = \cos t$ crosses zero at $\pi/2$.
struct Oscillator;

impl Dynamics<2> for Oscillator {
    fn rhs(&self, y: &State<2>, dy: &mut State<2>) {
        dy[0] = y[1];
        dy[1] = -y[0];
    }
}

#[test]
fn stop_event_is_located_in_time() {
    for method in [Method::Dop853, Method::Dopri5, Method::Rk4] {
        let s = Settings {
            method,
            rtol: 1e-12,
            atol: 1e-14,
            step: 1e-3,
            ..Settings::default()
        };
        let p = Problem::new(&Oscillator, 0.0, State::<2>::new(1.0, 0.0), 10.0)
            .stop_when(Event::new("x below 0", |y: &State<2>| y[0]));
        let sol = solve(p, &s).unwrap();
        let Ending::Event { t, index, .. } = sol.ending else {
            panic!("{method}: no event: {:?}", sol.ending)
        };
        assert_eq!(index, 0);
        // RK4 with h = 1e-3 has a global error near 1e-13 here, so all three locate it to 1e-9 s.
        assert!(
            (t - std::f64::consts::FRAC_PI_2).abs() < 1e-9,
            "{method}: t = {t}"
        );
        assert_eq!(sol.last().0, t);
    }
}

#[test]
fn sampling_gives_evenly_spaced_accurate_points() {
    let p = Problem::new(&Oscillator, 0.0, State::<2>::new(1.0, 0.0), 3.0).sampled(0.25);
    let sol = solve(p, &Settings::dop853(1e-12, 1e-14)).unwrap();
    assert_eq!(sol.t.len(), 13);
    for (i, (t, y)) in sol.t.iter().zip(&sol.y).enumerate() {
        assert!((t - 0.25 * i as f64).abs() < 1e-15);
        assert!((y[0] - t.cos()).abs() < 1e-11, "x({t}) = {}", y[0]);
    }
}

/// $\dot y = y^2$ from 1 blows up at t = 1: the run must end with a reason, not a panic.
struct BlowUp;

impl Dynamics<1> for BlowUp {
    fn rhs(&self, y: &State<1>, dy: &mut State<1>) {
        dy[0] = y[0] * y[0];
    }
}

#[test]
fn finite_time_singularity_ends_with_a_reason() {
    for method in [Method::Dop853, Method::Dopri5] {
        let s = Settings {
            method,
            ..Settings::default()
        };
        let sol = solve(Problem::new(&BlowUp, 0.0, State::<1>::new(1.0), 2.0), &s).unwrap();
        assert!(!sol.ending.is_complete(), "{method}: {:?}", sol.ending);
        let (t, _) = sol.last();
        assert!(t > 0.99 && t < 1.0 + 1e-6, "{method}: ended at {t}");
        eprintln!("{method}: {}", sol.ending);
    }
}

#[test]
fn bad_settings_are_refused_with_a_reason() {
    let mut s = Settings::dop853(0.0, 1e-12);
    let p = || Problem::new(&Oscillator, 0.0, State::<2>::new(1.0, 0.0), 1.0);
    assert!(solve(p(), &s).unwrap_err().to_string().contains("rtol"));
    s.rtol = 1e-6;
    s.atol = -1.0;
    assert!(solve(p(), &s).unwrap_err().to_string().contains("atol"));
    let rk = Settings {
        method: Method::Rk4,
        step: 1e-12,
        ..Settings::default()
    };
    assert!(solve(p(), &rk).unwrap_err().to_string().contains("steps"));
}

#[test]
fn own_dop853_closes_the_arenstorf_orbit() {
    // Global error falls with the tolerance, and at 1e-12 the orbit closes to 1e-7 (its
    // close approaches to the moon amplify the local errors by about 1e4).
    let mut last_gap = f64::INFINITY;
    for (rtol, bound) in [(1e-6, 1e-1), (1e-9, 1e-4), (1e-12, 1e-7)] {
        let p = Problem::new(&Arenstorf, 0.0, start(), PERIOD);
        let sol = solve(p, &Settings::dop853(rtol, rtol)).unwrap();
        assert_eq!(sol.ending, Ending::TimeReached);
        let gap = (sol.last().1 - start()).amax();
        eprintln!(
            "Arenstorf, rtol = atol = {rtol:.0e}: gap after one period {gap:.2e}, {} evaluations, {} accepted, {} rejected",
            sol.stats.evaluations, sol.stats.accepted, sol.stats.rejected
        );
        assert!(gap < bound && gap < last_gap, "rtol {rtol}: gap {gap}");
        last_gap = gap;
    }
}

#[test]
fn own_dop853_takes_the_same_steps_as_the_published_algorithm_in_ode_solvers() {
    // ode_solvers 0.6.2 implements Hairer's controller and norm faithfully (only slowly): on an
    // autonomous problem both engines must make the same decisions. They sum the stages in
    // different orders, and the error estimate (a difference of large stage sums on this
    // stiff-ish problem) carries that round-off into the step sizes, so the step ends drift
    // apart slowly (at rtol 1e-6 the first 533 of 674 agree to 1e-6): the counts of accepted
    // and rejected steps are compared, and the final states.
    let vdp = VanDerPol { eps: 1e-3 };
    for rtol in [1e-6, 1e-9, 1e-12] {
        let s = Settings::dop853(rtol, rtol);
        let own = solve(Problem::new(&vdp, 0.0, State::<2>::new(2.0, 0.0), 2.0), &s).unwrap();
        let up = solve_with(
            Problem::new(&vdp, 0.0, State::<2>::new(2.0, 0.0), 2.0),
            &s,
            Engine::OdeSolvers,
        )
        .unwrap();
        eprintln!(
            "Van der Pol rtol {rtol:.0e}: own {:?}, ode_solvers {:?}",
            own.stats, up.stats
        );
        let rej = own.stats.rejected.abs_diff(up.stats.rejected);
        assert!(
            rej * 50 <= own.stats.rejected.max(50),
            "rtol {rtol}: {rej} rejections apart"
        );
        let gap = (own.last().1 - up.last().1).amax();
        assert!(gap < 1e3 * rtol, "rtol {rtol}: final states {gap:e} apart");
        let diff = own.stats.accepted.abs_diff(up.stats.accepted);
        assert!(
            diff * 50 <= own.stats.accepted,
            "rtol {rtol}: {diff} steps apart"
        );
    }
}

#[test]
fn events_and_samples_use_the_dense_output_and_keep_the_steps() {
    // The crate's own DOP853 (not the default engine): events on its dense output.
    let s = Settings::dop853(1e-12, 1e-14);
    // A run that samples on its dense output integrates at the tolerances divided by
    // K = 2 rtol^(-1/9) (physics' `driver::dense_tolerances`), so that its samples are as
    // accurate as the tolerance asks; the plain run here integrates at those.
    let k = 2.0 * s.rtol.powf(-1.0 / 9.0);
    let tight = Settings::dop853(s.rtol / k, s.atol / k);
    let plain = solve_with(
        Problem::new(&Oscillator, 0.0, State::<2>::new(1.0, 0.0), 10.0),
        &tight,
        Engine::Own,
    )
    .unwrap();
    let mut p = Problem::new(&Oscillator, 0.0, State::<2>::new(1.0, 0.0), 10.0).sampled(0.001);
    p.dense_samples = true;
    let sampled = solve_with(p, &s, Engine::Own).unwrap();
    // The sampled run takes the same steps as the plain run at those tolerances; its samples
    // come from the dense output, three more evaluations for each step that holds one, none
    // per sample.
    assert_eq!(sampled.stats.evaluations, plain.stats.evaluations);
    assert_eq!(sampled.stats.accepted, plain.stats.accepted);
    assert!(sampled.stats.extra_evaluations > 0);
    assert!(sampled.stats.extra_evaluations <= 3 * sampled.stats.accepted);
    assert_eq!(sampled.t.len(), 10_001);
    let worst = sampled
        .t
        .iter()
        .zip(&sampled.y)
        .map(|(t, y)| (y[0] - t.cos()).abs())
        .fold(0.0, f64::max);
    assert!(worst < 1e-11, "samples off by {worst:e}");
    let p = Problem::new(&Oscillator, 0.0, State::<2>::new(1.0, 0.0), 10.0)
        .stop_when(Event::new("x below 0", |y: &State<2>| y[0]));
    let ev = solve_with(p, &s, Engine::Own).unwrap();
    assert_eq!(
        ev.stats.extra_evaluations, 3,
        "one dense output for the event step"
    );
    let Ending::Event { t, .. } = ev.ending else {
        panic!("{:?}", ev.ending)
    };
    assert!((t - std::f64::consts::FRAC_PI_2).abs() < 1e-11, "t = {t}");
}
