use super::*;
use nalgebra::UnitQuaternion;
use std::f64::consts::FRAC_PI_2;

fn disk() -> Disk {
    crate::disk::toy_disk()
}

/// Generic motions: tilted either way of the vertical, spinning either way, nodding.
fn motions() -> [Motion; 4] {
    [
        Motion {
            alpha: 0.3,
            alpha_dot: 0.7,
            precession: 40.0,
            spin: 3.0,
        },
        Motion {
            alpha: 1.2,
            alpha_dot: -2.0,
            precession: -5.0,
            spin: 11.0,
        },
        Motion {
            alpha: FRAC_PI_2,
            alpha_dot: 0.1,
            precession: 30.0,
            spin: -4.0,
        },
        Motion {
            alpha: 2.0,
            alpha_dot: 0.0,
            precession: 2.0,
            spin: 0.5,
        },
    ]
}

fn contacts() -> [LabFrame; 2] {
    [
        LabFrame::new(disk(), Contact::Rolling),
        LabFrame::new(disk(), Contact::Frictionless),
    ]
}

#[test]
fn paper_variables_survive_the_round_trip() {
    for lab in contacts() {
        for m in motions() {
            for (heading, face) in [(0.0, 0.0), (2.5, -1.0), (-3.0, 3.0)] {
                let y = lab.state_from(&m, heading, [0.3, -0.1], face);
                let (back, h, c, f) = lab.to_paper(&y);
                let pairs = [
                    (back.alpha, m.alpha),
                    (back.alpha_dot, m.alpha_dot),
                    (back.precession, m.precession),
                    (back.spin, m.spin),
                    (h, heading),
                    (c[0], 0.3),
                    (c[1], -0.1),
                    (f, face),
                ];
                for (got, want) in pairs {
                    assert!(
                        (got - want).abs() < 1e-12 * want.abs().max(1.0),
                        "{m:?}: {got} vs {want}"
                    );
                }
            }
        }
    }
}

#[test]
fn a_start_state_is_on_the_constraint() {
    for lab in contacts() {
        for m in motions() {
            let y = lab.state_from(&m, 0.4, [0.0, 0.0], 0.2);
            let s = lab.snapshot(&y);
            assert!((y.fixed_rows::<4>(0).norm() - 1.0).abs() < 1e-15);
            assert!(s.height.abs() < 1e-17);
            let slip = match lab.contact {
                Contact::Rolling => s.contact_velocity.norm(),
                Contact::Frictionless => s.contact_velocity.z.abs(),
            };
            assert!(slip < 1e-15, "{m:?}: {slip}");
        }
    }
}

#[test]
fn rho_dot_is_the_rate_of_the_lowest_rim_point() {
    let lab = &contacts()[0];
    for m in motions() {
        let y = lab.state_from(&m, 0.4, [0.0, 0.0], 0.2);
        let s = lab.snapshot(&y);
        let q = UnitQuaternion::from_quaternion(Quaternion::new(y[0], y[1], y[2], y[3]));
        let at = |dt: f64| {
            let turned = UnitQuaternion::from_scaled_axis(s.omega * dt) * q;
            let mut yt = y;
            // coords are (i, j, k, w); the state holds (w, i, j, k).
            let c = turned.quaternion().coords;
            (yt[0], yt[1], yt[2], yt[3]) = (c.w, c.x, c.y, c.z);
            lab.snapshot(&yt).rho
        };
        let h = 1e-6;
        let numeric = (at(h) - at(-h)) / (2.0 * h);
        let err = (numeric - s.rho_dot).norm() / s.rho_dot.norm().max(1e-3);
        assert!(err < 1e-7, "{m:?}: {err:e}");
    }
}

/// The force makes the contact condition's derivative vanish: the contact point's velocity
/// (rolling) or its vertical velocity (frictionless), differentiated along the flow by central
/// differences, is zero.
#[test]
fn the_force_keeps_the_contact() {
    for lab in contacts() {
        let lab = lab.with_stabilisation(0.0);
        for m in motions() {
            let y = lab.state_from(&m, 0.4, [0.0, 0.0], 0.2);
            let mut dy = State::<13>::zeros();
            lab.rhs(&y, &mut dy);
            let h = 1e-6;
            let vc = |y: &State<13>| lab.snapshot(y).contact_velocity;
            let rate = (vc(&(y + dy * h)) - vc(&(y - dy * h))) / (2.0 * h);
            let rate = match lab.contact {
                Contact::Rolling => rate.norm(),
                Contact::Frictionless => rate.z.abs(),
            };
            let scale = lab.disk.g + lab.disk.a * m.precession * m.precession;
            assert!(rate < 1e-7 * scale, "{:?} {m:?}: {rate:e}", lab.contact);
        }
    }
}

#[test]
fn a_coin_spinning_in_place_needs_no_friction() {
    let d = disk();
    let m = crate::model::steady::steady_motion(&d, 0.3, 0.0).unwrap();
    for lab in contacts() {
        let f = lab.contact_force(&lab.state(&m));
        let err = (f - d.m * d.g * Vector3::z()).norm() / (d.m * d.g);
        assert!(err < 1e-13, "{:?}: {f:?}", lab.contact);
    }
}

#[test]
fn every_quantity_can_be_recorded() {
    let lab = &contacts()[0];
    let y = lab.state(&motions()[0]);
    for q in Quantity::ALL {
        let mut out = Vec::new();
        assert!(lab.record(&y, q, &mut out));
        assert_eq!(out.len(), q.columns().len(), "{q:?}");
    }
}
