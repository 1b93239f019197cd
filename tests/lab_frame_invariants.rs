//! The lab-frame model's own consistency (`model::lab_frame`): energy and $L_z$ conserved
//! along its runs and equal to the paper's eqs 26 and 63, and the steady contact force of eqs
//! 29 and 41. Shared setup: `lab_frame.rs`.

use crate::lab_frame::{max_of, perturbed, run, settings, toy, AGREE, DT, RTOL, T_END};
use physics::model::frictionless::{self, Frictionless};
use physics::model::lab_frame::{Contact, LabFrame};
use physics::model::rolling::{self, Rolling};
use physics::model::steady::{precession_squared, steady_motion};
use physics::model::{Extras, Model, Motion};
use physics::solve::{solve, Ending, Problem, Solution};
use physics::Disk;

/// The bound on the drift of an invariant: rtol per accepted step, accumulated linearly.
fn drift_bound<const N: usize>(sol: &Solution<N>) -> f64 {
    RTOL * sol.stats.accepted as f64
}

/// How far an energy formula in the paper's variables may differ from the lab's energy along a
/// run: round-off, plus what the lab's contact drift adds, $mg|h| + m|\mathbf v||\mathbf v_c|$
/// (rolling) or $mg|h| + m|v_z||\dot h|$ (frictionless), relative to the energy.
fn identity_tolerance(lab: &LabFrame, sol: &Solution<13>) -> f64 {
    let d = &lab.disk;
    let e = lab.energy(&sol.y[0]).abs();
    let drift = max_of(sol.y.iter().map(|y| {
        let s = lab.snapshot(y);
        let slip = match lab.contact {
            Contact::Rolling => s.velocity.norm() * s.contact_velocity.norm(),
            Contact::Frictionless => (s.velocity.z * s.contact_velocity.z).abs(),
        };
        d.m * d.g * s.height.abs() + d.m * slip
    }));
    1e-12 + drift / e
}

#[test]
fn energy_is_conserved_and_matches_eq_26() {
    let disk = toy(0.25);
    let start = perturbed(&disk, 0.01);
    let lab = LabFrame::new(disk, Contact::Rolling);
    let sl = run(&lab, lab.state(&start), T_END);
    let paper = Rolling::<4>::new(disk, Extras::default(), None);
    let sp = run(&paper, paper.state(&start), T_END);
    let e0 = lab.energy(&sl.y[0]);
    let lab_drift = max_of(sl.y.iter().map(|y| (lab.energy(y) / e0 - 1.0).abs()));
    let e0p = paper.energy(&sp.y[0]);
    let paper_drift = max_of(sp.y.iter().map(|y| (paper.energy(y) / e0p - 1.0).abs()));
    // Eq 26 is a formula for the lab's energy: evaluated on the lab's own motion it must agree.
    let eq26 = max_of(
        sl.y.iter()
            .map(|y| (rolling::energy(&disk, &lab.motion(y)) / lab.energy(y) - 1.0).abs()),
    );
    let tol = identity_tolerance(&lab, &sl);
    eprintln!(
        "rolling energy over 10 s: lab drift {lab_drift:.2e}, paper (eq 26) drift {paper_drift:.2e} \
         (bound {:.1e}); eq 26 vs lab energy {eq26:.2e} (bound {tol:.1e})",
        drift_bound(&sl)
    );
    assert!(lab_drift < drift_bound(&sl) && paper_drift < drift_bound(&sp));
    assert!(eq26 < tol);
}

#[test]
fn energy_and_lz_are_conserved_without_friction() {
    let disk = toy(0.25);
    let mut start = perturbed(&disk, 0.0);
    start.spin = 0.1 * start.precession;
    let lab = LabFrame::new(disk, Contact::Frictionless);
    let sl = run(&lab, lab.state(&start), T_END);
    let paper = Frictionless::<3>::new(disk, start.spin, Extras::default());
    let sp = run(&paper, paper.state(&start), T_END);
    let (e0, l0) = (lab.energy(&sl.y[0]), lab.lz(&sl.y[0]));
    let e_drift = max_of(sl.y.iter().map(|y| (lab.energy(y) / e0 - 1.0).abs()));
    let l_drift = max_of(sl.y.iter().map(|y| (lab.lz(y) / l0 - 1.0).abs()));
    let e0p = paper.energy(&sp.y[0]);
    let paper_drift = max_of(sp.y.iter().map(|y| (paper.energy(y) / e0p - 1.0).abs()));
    // Eq 63's L_z and the frictionless energy are formulas for the lab's quantities.
    let eq63 = max_of(
        sl.y.iter()
            .map(|y| (rolling::lz(&disk, &lab.motion(y)) / lab.lz(y) - 1.0).abs()),
    );
    let energy = max_of(
        sl.y.iter()
            .map(|y| (frictionless::energy(&disk, &lab.motion(y)) / lab.energy(y) - 1.0).abs()),
    );
    let tol = identity_tolerance(&lab, &sl);
    eprintln!(
        "frictionless over 10 s: lab energy drift {e_drift:.2e}, lab L_z drift {l_drift:.2e}, paper \
         energy drift {paper_drift:.2e} (bound {:.1e}); eq 63 vs lab L_z {eq63:.2e}, energy formula vs \
         lab {energy:.2e} (bound {tol:.1e})",
        drift_bound(&sl)
    );
    assert!(e_drift < drift_bound(&sl) && l_drift < drift_bound(&sl));
    assert!(paper_drift < drift_bound(&sp));
    assert!(eq63 < 1e-12 && energy < tol);
}

/// Worst |F_lab - F_claim| / mg along a 1 s steady run at alpha0 = 0.3, radius b, where
/// F_claim = mg z - m Omega^2 b r with the given Omega^2.
fn steady_force_error(disk: &Disk, b: f64, omega_squared: f64) -> f64 {
    let lab = LabFrame::new(*disk, Contact::Rolling);
    let start = steady_motion(disk, 0.3, b).unwrap();
    let sol = run(&lab, lab.state(&start), 1.0);
    let mg = disk.m * disk.g;
    max_of(sol.y.iter().map(|y| {
        let claim = mg * nalgebra::Vector3::z() - disk.m * omega_squared * b * lab.snapshot(y).r;
        (lab.contact_force(y) - claim).norm() / mg
    }))
}

#[test]
fn steady_contact_force_is_the_centripetal_force_of_eq_29() {
    let disk = toy(0.25);
    for b_over_a in [0.1, 0.01, 1e-3] {
        let b = b_over_a * disk.a;
        let err = steady_force_error(&disk, b, precession_squared(&disk, 0.3, b));
        eprintln!("steady contact force, b/a = {b_over_a:e}: |F_lab - (mg z - m b Omega0^2 r)| = {err:.2e} mg");
        assert!(err < AGREE);
    }
}

#[test]
fn eq_41_holds_to_second_order_in_b_over_a() {
    // Eq 41 puts eq 31's Omega0^2 = g / (a k sin alpha0) (b = 0) in the centripetal force, so
    // its error is m b (Omega0^2(0) - Omega0^2(b)) = O(mg (b/a)^2).
    let disk = toy(0.25);
    let omega_squared_41 = disk.g / (disk.a * disk.k * 0.3f64.sin());
    let ratios: Vec<f64> = (0..5).map(|i| 1e-2 * 10f64.powf(-0.5 * i as f64)).collect();
    let errors: Vec<f64> = ratios
        .iter()
        .map(|r| steady_force_error(&disk, r * disk.a, omega_squared_41))
        .collect();
    let (x, y): (Vec<f64>, Vec<f64>) = ratios
        .iter()
        .zip(&errors)
        .map(|(r, e)| (r.ln(), e.ln()))
        .unzip();
    let n = x.len() as f64;
    let (mx, my) = (x.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    let order = x
        .iter()
        .zip(&y)
        .map(|(a, b)| (a - mx) * (b - my))
        .sum::<f64>()
        / x.iter().map(|a| (a - mx).powi(2)).sum::<f64>();
    for (r, e) in ratios.iter().zip(&errors) {
        eprintln!(
            "eq 41 at b/a = {r:.3e}: |F_lab - F_41| = {e:.3e} mg, / (b/a)^2 = {:.2}",
            e / (r * r)
        );
    }
    eprintln!("eq 41: fitted order of the error in b/a = {order:.4}");
    assert!((order - 2.0).abs() < 0.05, "order {order}");
}

/// Worst (|q| - 1, contact height, contact speed) over a 10 s run of `lab` from `start`.
fn drifts(lab: &LabFrame, start: &Motion) -> [f64; 3] {
    // Samples re-integrated from the step before each, so that the drift is the model's over the
    // steps the settings ask for (a run sampled on its dense output takes more, tighter steps).
    let mut problem = Problem::new(lab, 0.0, lab.state(start), T_END).sampled(DT);
    problem.dense_samples = false;
    let sol = solve(problem, &settings(RTOL)).unwrap();
    assert_eq!(sol.ending, Ending::TimeReached, "the run ended early");
    let mut d = [0.0f64; 3];
    for y in &sol.y {
        let s = lab.snapshot(y);
        let speed = match lab.contact {
            Contact::Rolling => s.contact_velocity.norm(),
            Contact::Frictionless => s.contact_velocity.z.abs(),
        };
        let q = y.fixed_rows::<4>(0).norm();
        d = [
            d[0].max((q - 1.0).abs()),
            d[1].max(s.height.abs()),
            d[2].max(speed),
        ];
    }
    d
}

#[test]
fn drift_is_controlled() {
    let disk = toy(0.25);
    let mut spinning = perturbed(&disk, 0.0);
    spinning.spin = 0.1 * spinning.precession;
    for (name, contact, start) in [
        (
            "rolling, perturbed steady motion b = 0.01 m",
            Contact::Rolling,
            perturbed(&disk, 0.01),
        ),
        (
            "frictionless, tilted disk with spin",
            Contact::Frictionless,
            spinning,
        ),
    ] {
        let lab = LabFrame::new(disk, contact);
        let on = drifts(&lab, &start);
        let off = drifts(&lab.clone().with_stabilisation(0.0), &start);
        eprintln!(
            "{name}: max ||q|-1|, |h| (m), |contact speed| (m/s) over 10 s: stabilised {:.1e} {:.1e} {:.1e}; \
             unstabilised {:.1e} {:.1e} {:.1e}",
            on[0], on[1], on[2], off[0], off[1], off[2]
        );
        // Stabilised: the norm at round-off, the contact within 1e-11 of the scales a and sqrt(g a).
        let (a, v) = (disk.a, (disk.g * disk.a).sqrt());
        assert!(
            on[0] < 1e-14 && on[1] < 1e-11 * a && on[2] < 1e-11 * v,
            "{on:?}"
        );
        // Unstabilised, the constraint still holds to integration error, so the force is right (a
        // relative error of 1e-9 in it would lift the disk by 5e-7 m in 10 s)...
        assert!(off[1] < 1e-8 && off[2] < 1e-8, "{off:?}");
        // ... but the contact height wanders off further.
        assert!(off[1] > 10.0 * on[1], "{off:?} vs {on:?}");
    }
}
