//! The speed/accuracy study: right-hand sides that allocate nothing, a validated reference, the
//! observed orders, the cheapest settings for an accuracy, and what the presets reach.

use physics::disk::Disk;
use physics::model::adiabatic::Adiabatic;
use physics::model::dissipation::PowerLaw;
use physics::model::frictionless::Frictionless;
use physics::model::rolling::Rolling;
use physics::model::Extras;
use physics::scene::Scene;
use physics::solve::{Dynamics, Method, State};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::hint::black_box;
use studies::precision::{
    cheapest, energy_drift, long_time_drift, measure_preset, study, Accuracy, Cost, PrecisionError,
    Reference, ReferenceOptions, StudyOptions, Timing,
};

/// Counts the allocations made by the current thread (tests run in parallel threads).
struct Counting;

thread_local! {
    static ALLOCATIONS: Cell<u64> = const { Cell::new(0) };
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.with(|c| c.set(c.get() + 1));
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

fn allocations_of<D: Dynamics<N>, const N: usize>(model: &D, y: State<N>) -> u64 {
    let mut dy = State::<N>::zeros();
    let before = ALLOCATIONS.with(Cell::get);
    for _ in 0..1000 {
        model.rhs(black_box(&y), &mut dy);
        black_box(&dy);
    }
    ALLOCATIONS.with(Cell::get) - before
}

/// Every right-hand side, extras included, allocates nothing.
#[test]
fn right_hand_sides_do_not_allocate() {
    let disk = Disk::uniform(0.0375);
    let law = PowerLaw {
        epsilon: 1.2e-6,
        beta: 2.0,
    };
    let y4 = State::<4>::new(1.2, 0.01, 10.7, 5.4);
    let all = Extras {
        heading: true,
        path: true,
        face: true,
    };
    let y8 = State::<8>::from_fn(|i, _| if i < 4 { y4[i] } else { 0.1 });
    // The counter sees this thread's allocations: check it does count.
    let before = ALLOCATIONS.with(Cell::get);
    black_box(vec![1u8; 16]);
    assert_eq!(ALLOCATIONS.with(Cell::get) - before, 1);

    let counts = [
        (
            "rolling",
            allocations_of(&Rolling::<4>::new(disk, Extras::default(), None), y4),
        ),
        (
            "rolling with all extras",
            allocations_of(&Rolling::<8>::new(disk, all, None), y8),
        ),
        (
            "dissipative",
            allocations_of(&Rolling::<4>::new(disk, Extras::default(), Some(law)), y4),
        ),
        (
            "frictionless",
            allocations_of(
                &Frictionless::<3>::new(disk, 5.4, Extras::default()),
                State::<3>::new(1.2, 0.01, 10.7),
            ),
        ),
        (
            "adiabatic",
            allocations_of(&Adiabatic::new(disk, law), State::<1>::new(0.15)),
        ),
    ];
    for (name, n) in counts {
        assert_eq!(n, 0, "the {name} right-hand side allocated {n} times");
    }
}

/// The benchmark scene's reference agrees with DOPRI5 and RK4 to better than 1e-10 (measured
/// 3e-11 and 1e-11), its energy is conserved to 1e-14, and the observed orders in the step size
/// are near the nominal ones: RK4 within 0.3 of 4; the adaptive methods' error-per-work slopes
/// at least their order minus 2 (measured 6.3 for DOPRI5, 6.9 for DOP853: tolerance
/// proportionality is not exact at loose tolerances).
#[test]
fn benchmark_study_is_validated_and_shows_the_orders() {
    let scene = Scene::load("benchmark").expect("built in");
    let s = study(&scene, &StudyOptions::quick()).expect("study");
    let r = &s.reference;
    for a in &r.agreements {
        eprintln!(
            "reference vs {}: {:.1e} at the end, {:.1e} over the trajectory",
            a.label, a.final_error, a.trajectory_error
        );
    }
    assert!(r.uncertainty < 1e-10, "{}", r.uncertainty);
    assert!(r.trace.energy_change.abs() < 1e-14);
    for series in &s.series {
        let p = series.observed_order.expect("enough points to fit");
        eprintln!(
            "{}: observed order {p:.2} over {} points (nominal {})",
            series.method, series.fitted_points, series.nominal_order
        );
        let nominal = f64::from(series.nominal_order);
        match series.method {
            Method::Rk4 => assert!((p - nominal).abs() < 0.3, "{p}"),
            _ => assert!(p > nominal - 2.0, "{p}"),
        }
        // More work, less error: the most expensive point beats the cheapest by far.
        let (first, last) = (&series.points[0], series.points.last().unwrap());
        assert!(last.final_error < 1e-4 * first.final_error);
    }
    // The cheapest way to 1e-6 over the trajectory reaches it, and nothing cheaper does.
    let best = cheapest(&s, 1e-6, Cost::Evaluations).expect("reachable");
    eprintln!(
        "cheapest to 1e-6: {} ({} evaluations)",
        best.label, best.evaluations
    );
    assert!(best.trajectory_error <= 1e-6);
    for p in s.series.iter().flat_map(|s| &s.points) {
        if p.trajectory_error <= 1e-6 {
            assert!(p.evaluations >= best.evaluations);
        }
    }
    // Below the reference's uncertainty nothing can be shown to be reached.
    assert!(cheapest(&s, 1e-16, Cost::WallTime).is_none());
    // Every run is also timed as simulate runs it, sampled at the scene's rate.
    for p in s.series.iter().flat_map(|s| &s.points) {
        let w = p
            .sampled_wall_seconds
            .expect("the own engine's runs are timed sampled");
        assert!(w.is_finite() && w > 0.0, "{}: {w}", p.label);
    }
    // The study is plain data.
    let json = serde_json::to_string(&s).expect("serializes");
    assert!(json.contains("\"observed_order\""));
    assert!(json.contains("\"sampled_wall_seconds\""));
}

/// What each preset reaches on the benchmark scene, against the reference: measured
/// 2.9e-5 (fast, rtol 1e-6), 9.0e-10 (standard, 1e-10), 2.0e-12 (high, 1e-13) over the
/// trajectory; each within 100 x its rtol, each more accurate and more expensive than the last.
#[test]
fn presets_reach_what_they_promise_on_the_benchmark() {
    let scene = Scene::load("benchmark").expect("built in");
    let reference = Reference::compute(&scene, &ReferenceOptions::default()).expect("reference");
    let mut last: Option<(f64, u64)> = None;
    for a in Accuracy::ALL {
        let m = measure_preset(&scene, a, &reference, &Timing::ONCE).expect("runs");
        eprintln!(
            "{a}: {} rtol {:.0e}: error {:.1e} (final {:.1e}), {} evaluations",
            m.settings.method, m.settings.rtol, m.trajectory_error, m.final_error, m.evaluations
        );
        assert!(m.trajectory_error <= 100.0 * m.settings.rtol);
        if let Some((err, evals)) = last {
            assert!(m.trajectory_error < err && m.evaluations > evals);
        }
        last = Some((m.trajectory_error, m.evaluations));
        let applied = a.apply(&scene);
        assert_eq!(applied.settings.max_steps, scene.settings.max_steps);
        assert_eq!(applied.settings.method, a.settings().method);
    }
}

/// Energy drift is refused where it means nothing, with a sentence saying why.
#[test]
fn energy_drift_needs_a_conservative_precessing_scene() {
    let s = Accuracy::High.settings();
    let e = energy_drift(&Scene::load("spin-down").unwrap(), &s, 10.0, 2).unwrap_err();
    assert!(matches!(e, PrecisionError::NotConservative(_)));
    assert!(e.to_string().contains("not conserved"));
    let e = energy_drift(&Scene::load("wheel-straight").unwrap(), &s, 10.0, 2).unwrap_err();
    assert_eq!(e, PrecisionError::NoPrecession);
}

/// The goal: over 1e4 precession periods of the benchmark scene the `high` preset keeps
/// the energy to 1e-12 relative, and the table holds every preset from the fastest.
#[test]
fn high_preset_keeps_the_energy_over_ten_thousand_periods() {
    let table = long_time_drift(&Scene::load("benchmark").unwrap(), 1e4, 20).unwrap();
    assert_eq!(table.rows.len(), 3);
    for r in &table.rows {
        eprintln!(
            "{:<8} {}: max |dE/E| {:.2e} over {:.0} periods, {} evaluations, {:.2} s",
            r.accuracy.to_string(),
            r.drift.settings.method,
            r.drift.max_abs_drift,
            table.periods,
            r.drift.evaluations,
            r.drift.wall_seconds
        );
        assert!(
            r.drift.ending.is_complete(),
            "{}: {:?}",
            r.accuracy,
            r.drift.ending
        );
    }
    let high = &table.rows[2];
    assert_eq!(high.accuracy, Accuracy::High);
    assert!(
        high.drift.max_abs_drift < 1e-12,
        "high: {:e}",
        high.drift.max_abs_drift
    );
    assert!(table.rows[0].drift.max_abs_drift > high.drift.max_abs_drift);

    // With `project: energy`, the DOP853 presets (standard, high) again: the energy stays at
    // round-off by construction, each step costs one more evaluation, and the run still ends.
    assert_eq!(table.projected.len(), 2);
    for (p, free) in table.projected.iter().zip(&table.rows[1..]) {
        eprintln!(
            "{:<8} projected: max |dE/E| {:.2e}, {} evaluations ({} without)",
            p.accuracy.to_string(),
            p.drift.max_abs_drift,
            p.drift.evaluations,
            free.drift.evaluations
        );
        assert_eq!(p.accuracy, free.accuracy);
        assert!(p.drift.ending.is_complete(), "{:?}", p.drift.ending);
        assert!(
            p.drift.max_abs_drift < 1e-14,
            "{}: projected drift {:e}",
            p.accuracy,
            p.drift.max_abs_drift
        );
        assert!(p.drift.evaluations > free.drift.evaluations);
    }
    assert!(table.projected[0].drift.max_abs_drift < table.rows[1].drift.max_abs_drift / 10.0);
}
