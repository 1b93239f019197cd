//! What the toy's thickness does to the paper's numbers (`studies::thickness`): the Euler's Disk
//! toy (a = 37.5 mm, thickness 12.8 mm, rim fillet 2 mm, mass 0.4 kg) against the thin uniform
//! disk (k = 1/4) of the same radius, both rolling (mu = 10) in the sliding model.
//!
//! The steady precession is found by shooting (the start whose tilt stays put after 1 ms), the
//! period of small oscillations from the tilt's maxima over 1 s, and the spin-down law's constant
//! and the tilt of lost contact (eqs 79-81) from a spin-down under eq 75's power (the module's
//! documentation derives each).

use physics::model::steady::steady_motion;
use studies::thickness::{compute, samples, scene, steady_precession, Shape, STEADY_TILTS};

#[test]
fn thickness_changes_the_steady_motion_and_the_oscillation() {
    let thin_disk = physics::disk::toy_disk();
    let t = compute().unwrap();
    println!("alpha0  Omega thin  Omega toy  change   period thin  period toy  change (rad/s, s)");
    for (s, alpha0) in t.steady.iter().zip(STEADY_TILTS) {
        let eq29 = steady_motion(&thin_disk, alpha0, 0.0).unwrap().precession;
        // The thin disk's shooting reproduces eq 29.
        assert!(
            (s.thin - eq29).abs() < 1e-7 * eq29.abs(),
            "{} vs eq 29's {eq29}",
            s.thin
        );
        println!(
            "{alpha0:.1}  {:10.4}  {:10.4}  {:+6.1} %  {:10.5}  {:10.5}  {:+6.1} %",
            s.thin,
            s.toy,
            100.0 * (s.toy / s.thin - 1.0),
            s.thin_period,
            s.toy_period,
            100.0 * (s.toy_period / s.thin_period - 1.0)
        );
        assert!(s.thin_period > 0.0 && s.toy_period > 0.0);
        // The toy's start found steady stays at its tilt.
        let held =
            samples(&scene(Shape::Toy, alpha0, 0.0, s.toy, s.toy_spin, 0.2, 1e-3, "").unwrap())
                .unwrap()
                .iter()
                .map(|r| (r[1] - alpha0).abs())
                .fold(0.0, f64::max);
        assert!(held < 1e-6, "alpha0 {alpha0}: drifts {held:e} rad in 0.2 s");
    }
    // The thin disk's shooting needs no guess near eq 29's own.
    let far = steady_precession(Shape::Thin, 0.6, 0.0, 2.0 * t.steady[1].eq29).unwrap();
    assert!((far / t.steady[1].eq29 - 1.0).abs() < 1e-7);
}

/// Eqs 79-81 for the toy against the thin disk: the thin disk follows eq 79's law (eq 85's
/// exponent beta + 3 = 5), and the tilt where the fitted law loses contact is eq 80's (through
/// eq 31) within the difference of the law's two fitted constants; the toy's constant C is lower
/// and its tilt of lost contact smaller; neither run comes near losing contact.
#[test]
fn thickness_changes_the_spin_down_constant_not_the_law() {
    let t = compute().unwrap();
    let [thin, toy] = [&t.spin_down[0], &t.spin_down[1]];
    println!(
        "eq 79's printed C {:.4e} 1/s^3; eq 80 (fitted C): Omega_max {:.2} rad/s, alpha {:.4e} rad",
        t.eq79_c, t.eq80_thin.0, t.eq80_thin.1
    );
    for l in [thin, toy] {
        println!(
            "{:?}: C {:.4e} 1/s^3, t0 {:.4} s, eq 85 exponent {:.3}, contact lost at alpha {:.4e} rad ({:.4e} s before t0), least F_z/mg {:.3}",
            l.shape, l.c, l.t0, l.exponent, l.loss_tilt, l.loss_before_t0, l.least_normal.0
        );
    }
    assert!((thin.exponent - 5.0).abs() < 0.1, "{}", thin.exponent);
    assert!((toy.exponent - 5.0).abs() < 0.3, "{}", toy.exponent);
    assert!((thin.loss_tilt / t.eq80_thin.1 - 1.0).abs() < 0.05);
    assert!(toy.c < 0.9 * thin.c, "{} {}", toy.c, thin.c);
    assert!(toy.loss_tilt < thin.loss_tilt);
    assert!(thin.least_normal.0 > 0.5 && toy.least_normal.0 > 0.5);
    // Both runs reach the tilt floor rolling.
    assert!(thin.end.1 <= 1.0001e-4 && toy.end.1 <= 1.0001e-4);
}

/// The fall from unstable steady motion (sec. 7, "to about 60 degrees"): the thin disk in the
/// sliding model (rolling, mu = 10) falls where the fall study's rolling model (eqs 23-25) says,
/// and the toy from the same tilt and b falls to the tilts printed.
#[test]
fn the_toy_falls_from_the_thin_disks_unstable_band() {
    let t = compute().unwrap();
    let fall = studies::sliding::fall::fall(
        &physics::disk::toy_disk(),
        &physics::solve::Settings::dop853(1e-10, 1e-12),
    )
    .unwrap();
    assert!(!t.falls.is_empty());
    for f in &t.falls {
        println!(
            "alpha0 {} deg, b/a {:.4}: Omega0 thin {:.3}, toy {:?} rad/s; falls to thin {:?}, toy {:?} deg",
            f.alpha0_deg, f.b_over_a, f.precession.0, f.precession.1, f.fell_to_deg.0, f.fell_to_deg.1
        );
        let rolling = fall
            .cases
            .iter()
            .find(|c| c.alpha0_deg == f.alpha0_deg && c.mu.is_none())
            .unwrap();
        let (Some(here), Some(there)) = (f.fell_to_deg.0, rolling.fell_to_deg) else {
            panic!("the thin disk did not fall: {f:?} {rolling:?}");
        };
        assert!(
            (here - there).abs() < 0.05,
            "{here} vs the fall study's {there}"
        );
    }
}
