//! Criterion benchmarks of each right-hand side (the cost $c_f$ of one evaluation).
//! That none allocates is tested in `tests/precision.rs`, not here.

use criterion::Criterion;
use physics::disk::Disk;
use physics::model::adiabatic::Adiabatic;
use physics::model::dissipation::PowerLaw;
use physics::model::frictionless::Frictionless;
use physics::model::rolling::Rolling;
use physics::model::Extras;
use physics::solve::{Dynamics, State};
use std::hint::black_box;

fn rhs<D: Dynamics<N>, const N: usize>(c: &mut Criterion, name: &str, model: &D, y: State<N>) {
    let mut dy = State::<N>::zeros();
    c.bench_function(name, |b| {
        b.iter(|| {
            model.rhs(black_box(&y), &mut dy);
            black_box(dy)
        })
    });
}

fn right_hand_sides(c: &mut Criterion) {
    let disk = Disk::uniform(0.0375);
    let law = PowerLaw {
        epsilon: 1.2e-6,
        beta: 2.0,
    };
    let y4 = State::<4>::new(1.212, 0.01, 10.755388960654598, 5.417805126021373);
    rhs(
        c,
        "rhs/rolling",
        &Rolling::<4>::new(disk, Extras::default(), None),
        y4,
    );
    rhs(
        c,
        "rhs/dissipative",
        &Rolling::<4>::new(disk, Extras::default(), Some(law)),
        y4,
    );
    rhs(
        c,
        "rhs/rolling+heading+path+face",
        &Rolling::<8>::new(
            disk,
            Extras {
                heading: true,
                path: true,
                face: true,
            },
            None,
        ),
        State::<8>::from_fn(|i, _| if i < 4 { y4[i] } else { 0.1 }),
    );
    rhs(
        c,
        "rhs/frictionless",
        &Frictionless::<3>::new(disk, 5.4, Extras::default()),
        State::<3>::new(1.212, 0.01, 10.755),
    );
    rhs(
        c,
        "rhs/adiabatic",
        &Adiabatic::new(disk, law),
        State::<1>::new(0.15),
    );
}

/// Every benchmark of this module.
pub fn all(c: &mut Criterion) {
    right_hand_sides(c);
}
