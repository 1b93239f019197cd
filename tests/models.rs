//! The equations of motion as integrated: invariants, steady motion, dissipation.

use physics::disk::Disk;
use physics::model::dissipation::PowerLaw;
use physics::model::frictionless::Frictionless;
use physics::model::rolling::Rolling;
use physics::model::steady::{b_bound, steady_motion, vertical_spin};
use physics::model::{Extras, Model, Motion};
use physics::solve::{solve, Dynamics, Ending, Problem, Settings, State};

fn euler_disk(k: f64) -> Disk {
    Disk::new(0.0375, k, 0.4, 9.81).unwrap()
}

fn tight() -> Settings {
    Settings::dop853(1e-12, 1e-14)
}

/// Largest relative deviation of `f` from its start value along a solution sampled every 10 ms.
fn max_drift<M: Model<N>, const N: usize>(
    model: &M,
    y0: State<N>,
    t: f64,
    f: impl Fn(&State<N>) -> f64,
) -> f64 {
    let sol = solve(Problem::new(model, 0.0, y0, t).sampled(0.01), &tight()).unwrap();
    assert_eq!(sol.ending, Ending::TimeReached);
    let f0 = f(&y0);
    sol.y
        .iter()
        .map(|y| ((f(y) - f0) / f0).abs())
        .fold(0.0, f64::max)
}

#[test]
fn rolling_energy_is_conserved_to_1e_10_over_10_s() {
    // A perturbed steady motion (b > 0), a nutating coin, and the benchmark start, for k = 1/4
    // and k = 1/2 where they exist.
    let starts = |d: &Disk| {
        let mut nutating = steady_motion(d, 0.3, 0.0).unwrap();
        nutating.alpha += 1e-2;
        let mut circle = steady_motion(d, 1.0, 0.05).unwrap();
        circle.alpha_dot = 0.3;
        vec![
            nutating,
            circle,
            Motion {
                alpha: 1.212,
                alpha_dot: 0.0,
                precession: 10.755388960654598,
                spin: 5.417805126021373,
            },
        ]
    };
    for k in [0.25, 0.5] {
        let d = euler_disk(k);
        let model = Rolling::<4>::new(d, Extras::default(), None);
        for m in starts(&d) {
            let drift = max_drift(&model, model.state(&m), 10.0, |y| model.energy(y));
            eprintln!("k = {k}, start {m:?}: energy drift {drift:.2e}");
            assert!(drift < 1e-10, "energy drift {drift:e}");
        }
    }
}

#[test]
fn frictionless_energy_and_lz_are_conserved() {
    // omega_1 is a parameter of this model (eq 60 makes it constant); that eq 60 is right is
    // shown against the independent lab-frame model. Here: E and L_z (eq 63) along the run.
    let d = euler_disk(0.25);
    for spin in [0.0, 3.0] {
        let model = Frictionless::<3>::new(d, spin, Extras::default());
        let mut m = vertical_spin(40.0);
        m.spin = spin;
        m.alpha -= 0.05;
        let y0 = model.state(&m);
        let e = max_drift(&model, y0, 10.0, |y| model.energy(y));
        let lz = max_drift(&model, y0, 10.0, |y| {
            physics::model::rolling::lz(&d, &model.motion(y))
        });
        eprintln!("frictionless, spin {spin}: energy drift {e:.2e}, L_z drift {lz:.2e}");
        assert!(e < 1e-10 && lz < 1e-10, "E {e:e}, L_z {lz:e}");
    }
}

#[test]
fn steady_motion_from_eq_29_stays_steady() {
    let d = euler_disk(0.25);
    let model = Rolling::<4>::new(d, Extras::default(), None);
    let alpha0 = 0.8;
    let negative_b = 0.5 * b_bound(&d, alpha0); // inside eq 30's bound
    for b in [0.0, 0.02, negative_b] {
        let m = steady_motion(&d, alpha0, b).unwrap();
        let sol = solve(
            Problem::new(&model, 0.0, model.state(&m), 10.0).sampled(0.05),
            &tight(),
        )
        .unwrap();
        let drift = sol
            .y
            .iter()
            .map(|y| (y[0] - alpha0).abs())
            .fold(0.0, f64::max);
        eprintln!("b = {b:+.5} m: alpha drift {drift:.2e} rad over 10 s");
        assert!(drift < 1e-9, "b = {b}: alpha drifted by {drift:e}");
    }
}

/// The rolling model with the work its eq 75 dissipation does, $W = \int P\,dt$ with
/// $P = -\epsilon m a g|\Omega|^\beta$, carried as a fifth state (J): along a run,
/// $E(t) - E(0) = W(t)$ is the energy balance. Without dissipation $W$ stays zero.
struct WithWork {
    /// The rolling model, with its dissipation.
    model: Rolling<4>,
}

impl Dynamics<5> for WithWork {
    fn rhs(&self, y: &State<5>, dy: &mut State<5>) {
        let core = State::<4>::new(y[0], y[1], y[2], y[3]);
        let mut d = State::<4>::zeros();
        self.model.rhs(&core, &mut d);
        dy.fixed_rows_mut::<4>(0).copy_from(&d);
        dy[4] = self
            .model
            .dissipation
            .map_or(0.0, |law| law.power(&self.model.disk, y[2]));
    }
}

#[test]
fn dissipation_removes_energy_at_the_rate_of_eq_75() {
    let d = euler_disk(0.25);
    for beta in [1.0, 2.0, 4.0] {
        let law = PowerLaw {
            epsilon: 1.2e-6 * 30f64.powf(2.0 - beta),
            beta,
        };
        let model = Rolling::<4>::new(d, Extras::default(), Some(law));
        let mut m = steady_motion(&d, 0.3, 0.01).unwrap();
        m.alpha_dot = 0.05;
        let y0 = model.state(&m);

        // 1. Pointwise: dE/dt = grad E . f(y) at states along the run, with the gradient of
        //    eq 26 differentiated by hand (each term is ~1e4 times P, so a finite-difference
        //    gradient would drown P in its own error), against P of eq 75.
        let sol = solve(Problem::new(&model, 0.0, y0, 2.0).sampled(0.01), &tight()).unwrap();
        let (k, ma2) = (d.k, d.m * d.a * d.a);
        let mut worst_rate: f64 = 0.0;
        for y in &sol.y {
            let mut f = State::<4>::zeros();
            model.rhs(y, &mut f);
            let (s, c) = y[0].sin_cos();
            let grad = [
                ma2 * (k * y[2] * y[2] * s * c + d.g_over_a() * c),
                ma2 * (k + 1.0) * y[1],
                ma2 * k * y[2] * s * s,
                ma2 * (2.0 * k + 1.0) * y[3],
            ];
            let rate: f64 = (0..4).map(|i| grad[i] * f[i]).sum();
            let claimed = law.power(&d, y[2]);
            worst_rate = worst_rate.max(((rate - claimed) / claimed).abs());
        }

        // 2. Integrated: the energy lost equals the work of eq 75's power along the run.
        let sys = WithWork {
            model: model.clone(),
        };
        let z0 = State::<5>::new(y0[0], y0[1], y0[2], y0[3], 0.0);
        let sol = solve(Problem::new(&sys, 0.0, z0, 2.0).sampled(0.05), &tight()).unwrap();
        let e0 = model.energy(&y0);
        let mut worst_balance: f64 = 0.0;
        for z in sol.y.iter().skip(1) {
            let e = model.energy(&State::<4>::new(z[0], z[1], z[2], z[3]));
            worst_balance = worst_balance.max(((e - e0 - z[4]) / z[4]).abs());
        }
        eprintln!(
            "beta = {beta}: dE/dt against eq 75 worst relative error {worst_rate:.2e}; energy balance {worst_balance:.2e}"
        );
        assert!(worst_rate < 1e-8, "beta {beta}: rate {worst_rate:e}");
        assert!(
            worst_balance < 1e-8,
            "beta {beta}: balance {worst_balance:e}"
        );
    }
}
