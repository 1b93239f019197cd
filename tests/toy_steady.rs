//! Eqs 29-30 for the Euler's Disk toy (`studies::toy_steady`): the closed form of the solid's
//! steady motions, checked on the sliding model's rolling equations, which it does not use.

use studies::thickness::Shape;
use studies::toy_steady::{compute, OFFSET};

/// On the allowed side of the toy's edge the model has exactly one steady precession, the
/// closed form's to 1e-10; on the other side it has none; the closed form's start keeps its tilt
/// to 1e-7 rad over 0.1 s while 0.1 % more precession moves it by far more.
#[test]
fn the_toys_condition_on_b_is_the_models() {
    let t = compute().unwrap();
    println!("deg   thin b*/a   toy b*/a  side   Omega0(b=0) thin  toy     roots in/out  shot-1    held     missed");
    for r in &t.rows {
        println!(
            "{:4.0}  {:+.5}  {:+.5}  {}  {:9.3}  {:>9}  {}/{}  {:+.1e}  {:.1e}  {:.1e}",
            r.alpha0_deg,
            r.thin_edge,
            r.toy_edge,
            if r.toy_above { "b > b*" } else { "b < b*" },
            r.thin_b0,
            r.toy_b0.map_or("none".into(), |w| format!("{w:.3}")),
            r.roots_allowed,
            r.roots_forbidden,
            r.shot_error,
            r.held,
            r.missed
        );
        assert_eq!(r.roots_allowed, 1, "{r:?}");
        assert_eq!(r.roots_forbidden, 0, "{r:?}");
        assert!(r.shot_error.abs() < 1e-10, "{r:?}");
        assert!(r.held < 1e-7 && r.missed > 100.0 * r.held, "{r:?}");
        // The toy spins in place exactly where b = 0 is on its allowed side.
        let zero_allowed = (0.0 > r.toy_edge) == r.toy_above;
        assert_eq!(r.toy_b0.is_some(), zero_allowed, "{r:?}");
    }
    let (lo, hi) = t.no_spin_in_place_deg;
    println!("the toy cannot spin in place between {lo:.2} and {hi:.2} deg (offset {OFFSET} a)");
    assert!(70.0 < lo && lo < hi && hi < 85.0, "{lo} {hi}");
    // The rows on either side of that band agree with it.
    for r in &t.rows {
        let inside = lo < r.alpha0_deg && r.alpha0_deg < hi;
        assert_eq!(r.toy_b0.is_none(), inside, "{r:?}");
    }
}

/// The closed form at b = 0 is the shooting of `studies::thickness` at its four tilts.
#[test]
fn the_closed_form_is_the_thickness_studys_shooting() {
    let toy = Shape::Toy.rolling();
    let t = studies::thickness::compute().unwrap();
    for s in &t.steady {
        let w = toy.steady(s.alpha0, 0.0).unwrap();
        println!(
            "alpha0 {}: shot {:.9}, closed form {:.9} rad/s",
            s.alpha0, s.toy, w.precession
        );
        assert!((s.toy / w.precession - 1.0).abs() < 1e-7);
        assert!((s.toy_spin / w.spin - 1.0).abs() < 1e-7);
    }
}
