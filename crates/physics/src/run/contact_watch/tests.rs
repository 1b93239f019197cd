//! A sampled run's loss of contact, looked for at the steps' ends, is the first row whose
//! normal force is negative, to the bit, as a check of every row finds it.

use crate::run::run;
use crate::scene::Scene;

/// The uniform disk let fall from rest at 1.4 rad, rolling: the rim leaves the table at about
/// 0.18 s, inside a step of about 12 ms.
fn falling(sample: f64, method: &str, record: &str) -> Scene {
    scene(
        sample,
        method,
        record,
        "alpha: 1.4, alpha_dot: 0.0, precession: 0.0, spin: 0.0",
        0.3,
    )
}

/// A rolling scene of the uniform disk from the explicit `start`, stopped at `time` or where
/// the tilt falls below 0.05 rad.
fn scene(sample: f64, method: &str, record: &str, start: &str, time: f64) -> Scene {
    let yaml = format!(
        "name: falling
description: a disk let fall from rest, rolling
disk: {{ radius: 0.0375, k: 0.25, mass: 0.4, g: 9.81 }}
model: rolling
start: {{ explicit: {{ {start} }} }}
stop: {{ time: {time}, alpha_below: 0.05 }}
record: [{record}]
sample: {sample:e}
solver: {{ method: {method}, rtol: 1.0e-10, atol: 1.0e-12 }}
"
    );
    Scene::parse(&yaml, "falling.yaml").expect("a valid scene")
}

/// The first recorded row whose normal force column is negative: its time and force.
fn first_negative_row(scene: &Scene) -> (f64, f64) {
    let r = run(scene, None).expect("it runs");
    let t = r.column("t_s").expect("the time");
    let f = r.column("normal_force_N").expect("the normal force");
    let i = f
        .iter()
        .position(|&f| f < 0.0)
        .expect("the rim leaves the table");
    (t[i], f[i])
}

#[test]
fn a_sampled_run_loses_contact_at_the_first_row_with_a_negative_normal_force() {
    // Rows finer than the steps, about as fine, and coarser; the own DOP853 (samples on its
    // dense output) and DOPRI5 (samples re-integrated by ode_solvers).
    for method in ["dop853", "dopri5"] {
        for sample in [1e-4, 5e-4, 1e-2, 3e-2] {
            let with_force = falling(sample, method, "alpha, normal_force");
            let (t, f) = first_negative_row(&with_force);
            assert!(
                t > 0.1,
                "{method} every {sample} s: lost at {t} s, not mid-run"
            );
            for record in ["alpha, normal_force", "alpha, energy", "spin"] {
                let scene = falling(sample, method, record);
                let lost = run(&scene, None)
                    .expect("it runs")
                    .contact_lost
                    .expect("a loss of contact");
                assert_eq!(
                    (lost.t.to_bits(), lost.normal_force.to_bits()),
                    (t.to_bits(), f.to_bits()),
                    "{method} every {sample} s recording [{record}]: {lost:?} against ({t}, {f})"
                );
            }
        }
    }
}

#[test]
fn a_run_that_starts_off_the_table_loses_contact_at_its_first_row() {
    // Falling fast already (coin-bounce's start): a alpha_dot^2 > g, the rim leaves at once.
    let start = "alpha: 1.3, alpha_dot: -30.0, precession: 5.0, spin: 20.0";
    let lost = run(&scene(5e-4, "dop853", "alpha", start, 0.3), None)
        .expect("it runs")
        .contact_lost
        .expect("a loss of contact");
    assert_eq!(lost.t, 0.0);
    assert!(lost.normal_force < 0.0, "{lost:?}");
}

#[test]
fn a_run_that_keeps_contact_loses_none() {
    // The same fall stopped before the rim leaves.
    let start = "alpha: 1.4, alpha_dot: 0.0, precession: 0.0, spin: 0.0";
    let r = run(&scene(5e-4, "dop853", "alpha", start, 0.15), None).expect("it runs");
    assert!(r.contact_lost.is_none(), "{:?}", r.contact_lost);
}

/// The normal force a step's end takes from the right-hand side there
/// ([`crate::model::Model::normal_force_from_rates`]) is the row's $F_z$ within the bound it
/// states, and that bound is a round-off's, far below the weight: over 20,000 states of the
/// rolling and the dissipative disk, tilts from 0.01 to 1.56 rad, rates up to 200 rad/s.
#[test]
fn the_force_from_the_rates_is_the_rows_within_its_round_off_bound() {
    use crate::disk::Disk;
    use crate::model::dissipation::PowerLaw;
    use crate::model::rolling::Rolling;
    use crate::model::{Extras, Model};
    use crate::solve::{Dynamics, State};
    use rand::{Rng, SeedableRng};
    let disk = Disk::new(0.0375, 0.25, 0.4, 9.81).expect("a disk");
    let models = [
        Rolling::<4>::new(disk, Extras::default(), None),
        Rolling::<4>::new(
            disk,
            Extras::default(),
            Some(PowerLaw {
                epsilon: 1e-4,
                beta: 2.0,
            }),
        ),
    ];
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(5);
    let (mut worst, mut signs_apart) = (0.0f64, 0);
    for model in &models {
        for _ in 0..10_000 {
            let y = State::<4>::from([
                rng.random_range(0.01..1.56),
                rng.random_range(-200.0..200.0),
                rng.random_range(-200.0..200.0),
                rng.random_range(-200.0..200.0),
            ]);
            let mut dy = State::<4>::zeros();
            model.rhs(&y, &mut dy);
            let (fz, bound) = model
                .normal_force_from_rates(&y, &dy)
                .expect("the rolling disk has one");
            let row = model
                .record_row(&y, &[], true, &mut Vec::new())
                .normal_force
                .expect("the row's normal force");
            assert!(
                (fz - row).abs() <= bound,
                "at {y:?}: {fz} from the rates, {row} from the row, bound {bound}"
            );
            worst = worst.max(bound / (disk.m * disk.g));
            signs_apart += usize::from((fz < 0.0) != (row < 0.0));
        }
    }
    assert!(worst < 1e-7, "the bound reaches {worst} of the weight");
    assert_eq!(signs_apart, 0);
}
