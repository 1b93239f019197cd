//! Tests of figure 1.

use super::draw::dash;
use super::*;
use physics::model::steady::steady_motion;
use physics::Disk;

#[test]
fn the_triad_is_the_papers() {
    for &(alpha, psi) in &[(0.3, 0.0), (1.0, 1.2), (1.4, -2.0)] {
        let t = Triad::new(alpha, psi);
        for v in [t.e1, t.e2, t.e3, t.r, t.z] {
            assert!((v.norm() - 1.0).abs() < 1e-14);
        }
        // 2 = 3 x 1 (right-handed), horizontal; r = 2 x z.
        let e2 = t.e3.cross(&t.e1);
        assert!((e2 - t.e2).norm() < 1e-14);
        assert!(t.e2[2].abs() < 1e-15 && t.r[2].abs() < 1e-15);
        assert!((t.e2.cross(&t.z) - t.r).norm() < 1e-14);
        // 1 makes angle alpha with -z; 3 is alpha below the horizontal.
        assert!((t.e1.dot(&-t.z).acos() - alpha).abs() < 1e-12);
        assert!(((-t.e3[2]).asin() - alpha).abs() < 1e-12);
        // Eq 3: z = -cos(alpha) 1 - sin(alpha) 3.
        let z = t.e1 * -alpha.cos() + t.e3 * -alpha.sin();
        assert!((z - t.z).norm() < 1e-14);
    }
}

#[test]
fn drawn_arrows_point_along_the_triad_and_lengths_follow_eqs_28_29() {
    let disk = Disk::uniform(0.0375);
    let view = View {
        azimuth: -0.9,
        elevation: 0.4,
    };
    let steady = SteadyDisk {
        a: disk.a,
        motion: steady_motion(&disk, 1.0, 0.6 * disk.a).unwrap(),
    };
    let g = Geometry::steady(&steady, 1.9, view);
    assert!((g.b - 0.6 * disk.a).abs() < 1e-15);
    assert!((g.r - (0.6 + 1f64.cos()) * disk.a).abs() < 1e-15);
    // The centre is at height a sin(alpha), horizontal distance b from the axis.
    assert!((g.centre[2] - disk.a * 1f64.sin()).abs() < 1e-15);
    assert!((g.centre[0].hypot(g.centre[1]) - g.b).abs() < 1e-15);
    assert!(g.contact[2].abs() < 1e-15);
    let t = g.triad;
    let mut seen = 0;
    for s in g.shapes() {
        if let Shape::Arrow {
            from, to, label, ..
        } = s
        {
            let d = (to - from).normalize();
            let want = match label.as_str() {
                "1" => t.e1,
                "2" => t.e2,
                "3" => t.e3,
                "r" => t.r,
                "z" => t.z,
                other => panic!("unexpected arrow {other}"),
            };
            assert!((d - want).norm() < 1e-12, "{label}");
            if label.starts_with('2') {
                assert!(d[2].abs() < 1e-15, "2-hat is horizontal");
            }
            if label.starts_with('1') {
                assert!((d.dot(&V3::new(0.0, 0.0, -1.0)).acos() - 1.0).abs() < 1e-12);
            }
            seen += 1;
        }
    }
    assert_eq!(seen, 5);
    // And the projection keeps them: a projected arrow is the projection of its vector.
    let (x, y) = view.project(t.e2);
    let (x0, y0) = view.project(V3::zeros());
    assert!(((x - x0).hypot(y - y0) - 1.0).abs() < 1.0);
}

#[test]
fn dashes_cover_the_line() {
    let d = dash(&[(0, 0), (100, 0)], 10.0, 5.0);
    assert_eq!(d.len(), 7);
    assert_eq!(d[0], vec![(0, 0), (10, 0)]);
}
