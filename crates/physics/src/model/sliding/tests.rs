//! Unit tests of the contact laws (the closed forms and limits are in `tests/sliding.rs`).

use super::*;
use crate::model::lab_frame::ContactProblem;

fn toy() -> Disk {
    crate::disk::toy_disk()
}

/// A landing state: the rolling state of `m` moved down through the table at `sink` m/s and
/// sliding at `slip` along the table.
fn landing(model: &Sliding, m: &Motion, sink: f64, slip: [f64; 2]) -> State<14> {
    let mut y = model.start_state(m);
    y[10] += slip[0];
    y[11] += slip[1];
    y[12] -= sink;
    y
}

#[test]
fn impacts_never_gain_energy_and_obey_restitution_and_the_cone() {
    let d = toy();
    let mut checked = 0;
    for mu in [0.0, 0.1, 0.3, 1.0] {
        for e in [0.0, 0.5, 1.0] {
            let model = Sliding::new(d, Friction { mu, restitution: e });
            for alpha in [0.2, 0.7, 1.2, 1.5] {
                for slip in [[0.0, 0.0], [0.3, 0.0], [0.0, -0.5], [1.0, 1.0]] {
                    let m = Motion {
                        alpha,
                        alpha_dot: 1.0,
                        precession: 5.0,
                        spin: 10.0,
                    };
                    let y = landing(&model, &m, 0.4, slip);
                    let s = Snapshot::of(d.a, &y);
                    let vc = s.contact_velocity;
                    let p = model.impact_impulse(&s, &vc, e);
                    let (after, lost) = model.apply_impulse(&y, &p);
                    let scale = model.energy(&y);
                    // The frozen-direction law may gain energy in principle (impact.rs); on
                    // this grid it never does.
                    assert!(
                        lost > -1e-12 * scale,
                        "mu {mu} e {e} alpha {alpha} {slip:?}: {lost}"
                    );
                    assert!(p.z >= 0.0, "the table only pushes");
                    assert!(
                        horizontal(&p).norm() <= mu * p.z * (1.0 + 1e-12) + 1e-15,
                        "outside the cone"
                    );
                    let vz = Snapshot::of(d.a, &after).contact_velocity.z;
                    assert!(
                        (vz + e * vc.z).abs() < 1e-12,
                        "Newton: v+ = -e v- ({vz} vs {})",
                        -e * vc.z
                    );
                    checked += 1;
                }
            }
        }
    }
    assert_eq!(checked, 4 * 3 * 4 * 4);
}

#[test]
fn a_slip_from_rest_starts_in_the_consistent_direction() {
    let d = toy();
    let model = Sliding::new(
        d,
        Friction {
            mu: 0.05,
            restitution: 0.0,
        },
    );
    // Steady motion with b far beyond what mu = 0.05 holds: it must slip from rest, and the
    // contact point must accelerate along the chosen slip direction.
    let m = crate::model::steady::steady_motion(&d, 0.5, 0.02).unwrap();
    let s = Snapshot::of(d.a, &model.start_state(&m));
    let Mode::Slip { anchor, held } = model.mode_from_rest(&s) else {
        panic!("it should slip");
    };
    assert!(held);
    let dir = Vector3::from(anchor);
    let cp = ContactProblem::of(&d, &s);
    let f = model.slip_force(&cp, &s, &dir);
    let acc = horizontal(&(cp.apply(&s, &f.force) - cp.b));
    let cos = acc.dot(&dir) / acc.norm();
    assert!(
        cos > 1.0 - 1e-10,
        "acceleration at {} rad from the slip",
        cos.acos()
    );
    assert!((horizontal(&f.force).norm() - 0.05 * f.force.z).abs() < 1e-12 * f.force.z);
}

#[test]
fn a_large_mu_with_sideways_slip_meets_painleves_paradox() {
    // The slip law's denominator (mod.rs) vanishes for mu > (k + cos^2)/(sin cos) with the
    // slip along +r: at alpha = 1.1 (k = 1/4) that is mu > 1.11.
    let d = toy();
    let model = Sliding::new(
        d,
        Friction {
            mu: 3.0,
            restitution: 0.0,
        },
    );
    let m = Motion {
        alpha: 1.1,
        ..Motion::default()
    };
    let y = model.start_state(&m);
    let s = Snapshot::of(d.a, &y);
    let cp = ContactProblem::of(&d, &s);
    let f = model.slip_force(&cp, &s, &s.r);
    let (sn, cs) = (1.1f64.sin(), 1.1f64.cos());
    let expected = 1.0 + cs * cs / 0.25 - 3.0 / 0.25 * sn * cs;
    assert!(
        (f.consistency - expected).abs() < 1e-12,
        "{} vs {expected}",
        f.consistency
    );
    assert!(f.consistency < 0.0);
}
