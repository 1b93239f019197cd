//! The paper's reduced equations of motion (23-25 rolling, 60-62 frictionless) refereed by the
//! independent Newton-Euler model in lab coordinates (`model::lab_frame`), and the lab model's own
//! consistency: energy, L_z, constraint drift, and the steady contact force of eqs 29 and 41.
//!
//! Rule for agreement: DOP853 at rtol 1e-12 (atol 1e-14) over 10 s; each of alpha, Omega and
//! omega_1 must agree to 1e-8 of its range over the run, or of a floor when it barely moves
//! (1 mrad for alpha, 1e-3 sqrt(g/a) for the rates: stricter than the variables' own scales).
//! Heading and path agree to 1e-8 of their range (floors 1 rad and the radius a).

use physics::model::frictionless::Frictionless;
use physics::model::lab_frame::{Contact, LabFrame};
use physics::model::rolling::Rolling;
use physics::model::steady::steady_motion;
use physics::model::{Extras, Model, Motion};
use physics::solve::{solve, Dynamics, Ending, Event, Method, Problem, Settings, Solution, State};
use physics::Disk;
use std::f64::consts::FRAC_PI_2;

pub(crate) const RTOL: f64 = 1e-12;
pub(crate) const AGREE: f64 = 1e-8;
pub(crate) const DT: f64 = 0.01;
pub(crate) const T_END: f64 = 10.0;
const HEADING: f64 = 0.7;
const CENTRE: [f64; 2] = [0.1, -0.2];

pub(crate) fn toy(k: f64) -> Disk {
    Disk::new(0.0375, k, 0.4, 9.81).unwrap()
}

pub(crate) fn settings(rtol: f64) -> Settings {
    Settings {
        method: Method::Dop853,
        rtol,
        atol: rtol * 1e-2,
        ..Settings::default()
    }
}

pub(crate) fn run_at<D: Dynamics<N>, const N: usize>(
    d: &D,
    y0: State<N>,
    t_end: f64,
    rtol: f64,
) -> Solution<N> {
    let sol = solve(Problem::new(d, 0.0, y0, t_end).sampled(DT), &settings(rtol)).unwrap();
    assert_eq!(sol.ending, Ending::TimeReached, "the run ended early");
    sol
}

pub(crate) fn run<D: Dynamics<N>, const N: usize>(d: &D, y0: State<N>, t_end: f64) -> Solution<N> {
    run_at(d, y0, t_end, RTOL)
}

pub(crate) fn wrap(x: f64) -> f64 {
    x.sin().atan2(x.cos())
}

pub(crate) fn range(v: impl Iterator<Item = f64> + Clone) -> f64 {
    let max = v.clone().fold(f64::MIN, f64::max);
    max - v.fold(f64::MAX, f64::min)
}

pub(crate) fn max_of(v: impl Iterator<Item = f64>) -> f64 {
    v.fold(0.0, f64::max)
}

/// Largest difference of alpha, Omega, omega_1 relative to max(range of `paper`, floor), printed.
fn agreement(name: &str, disk: &Disk, lab: &[Motion], paper: &[Motion]) -> [f64; 3] {
    assert_eq!(lab.len(), paper.len());
    let pick = |m: &Motion, i: usize| [m.alpha, m.precession, m.spin][i];
    let rate = 1e-3 * disk.g_over_a().sqrt();
    let floors = [1e-3, rate, rate];
    let (mut abs, mut rel) = ([0.0; 3], [0.0; 3]);
    for i in 0..3 {
        let scale = range(paper.iter().map(|m| pick(m, i))).max(floors[i]);
        abs[i] = max_of(
            lab.iter()
                .zip(paper)
                .map(|(l, p)| (pick(l, i) - pick(p, i)).abs()),
        );
        rel[i] = abs[i] / scale;
    }
    eprintln!(
        "{name}: max |lab - paper| alpha {:.2e} rad, Omega {:.2e} rad/s, omega1 {:.2e} rad/s; \
         relative to range {:.2e} {:.2e} {:.2e}",
        abs[0], abs[1], abs[2], rel[0], rel[1], rel[2]
    );
    rel
}

fn motions<M: Model<N>, const N: usize>(model: &M, sol: &Solution<N>) -> Vec<Motion> {
    sol.y.iter().map(|y| model.motion(y)).collect()
}

fn assert_agrees(rel: &[f64]) {
    for r in rel {
        assert!(*r < AGREE, "disagreement {r:e} > {AGREE:e}: {rel:?}");
    }
}

/// Rolling: the lab model and `Rolling::<7>` (heading and path) from the same start. Returns the
/// relative disagreement of alpha, Omega, omega_1, heading and path.
fn rolling_case(name: &str, disk: Disk, start: Motion, t_end: f64) -> [f64; 5] {
    let lab = LabFrame::new(disk, Contact::Rolling);
    let paper = Rolling::<7>::new(
        disk,
        Extras {
            path: true,
            ..Extras::default()
        },
        None,
    );
    let mut y0 = paper.state(&start);
    (y0[4], y0[5], y0[6]) = (HEADING, CENTRE[0], CENTRE[1]);
    let sp = run(&paper, y0, t_end);
    let sl = run(&lab, lab.state_from(&start, HEADING, CENTRE, 0.0), t_end);
    let [ra, ro, rw] = agreement(name, &disk, &motions(&lab, &sl), &motions(&paper, &sp));
    let heading_scale = range(sp.y.iter().map(|y| y[4])).max(1.0);
    let path_scale = range(sp.y.iter().map(|y| y[5]))
        .max(range(sp.y.iter().map(|y| y[6])))
        .max(disk.a);
    let (mut dh, mut dp) = (0.0f64, 0.0f64);
    for (yl, yp) in sl.y.iter().zip(&sp.y) {
        let (_, heading, centre, _) = lab.to_paper(yl);
        dh = dh.max(wrap(heading - yp[4]).abs());
        dp = dp.max((centre[0] - yp[5]).hypot(centre[1] - yp[6]));
    }
    eprintln!(
        "{name}: max |lab - paper| heading {dh:.2e} rad (range {heading_scale:.3}), centre of mass \
         {dp:.2e} m (range {path_scale:.3e}); relative {:.2e} {:.2e}",
        dh / heading_scale,
        dp / path_scale
    );
    [ra, ro, rw, dh / heading_scale, dp / path_scale]
}

/// Frictionless: the lab model and `Frictionless::<4>` (with heading) from the same start, at
/// tolerance `rtol`. Returns the relative disagreement of alpha, Omega, omega_1 and heading.
fn frictionless_case(name: &str, disk: Disk, start: Motion, rtol: f64) -> [f64; 4] {
    let lab = LabFrame::new(disk, Contact::Frictionless);
    let paper = Frictionless::<4>::new(
        disk,
        start.spin,
        Extras {
            heading: true,
            ..Extras::default()
        },
    );
    let mut y0 = paper.state(&start);
    y0[3] = HEADING;
    let sp = run_at(&paper, y0, T_END, rtol);
    let sl = run_at(
        &lab,
        lab.state_from(&start, HEADING, CENTRE, 0.0),
        T_END,
        rtol,
    );
    let [ra, ro, rw] = agreement(name, &disk, &motions(&lab, &sl), &motions(&paper, &sp));
    let mut dh = 0.0f64;
    for (yl, yp) in sl.y.iter().zip(&sp.y) {
        let (_, heading, centre, _) = lab.to_paper(yl);
        dh = dh.max(wrap(heading - yp[3]).abs());
        // Eq 59: without friction the centre of mass moves only vertically.
        assert_eq!(centre, CENTRE);
    }
    let scale = range(sp.y.iter().map(|y| y[3])).max(1.0);
    eprintln!(
        "{name}: max |lab - paper| heading {dh:.2e} rad, relative {:.2e}",
        dh / scale
    );
    [ra, ro, rw, dh / scale]
}

/// Steady motion at alpha0 = 0.3 with radius b, alpha then perturbed by 1e-3.
pub(crate) fn perturbed(disk: &Disk, b: f64) -> Motion {
    let mut m = steady_motion(disk, 0.3, b).unwrap();
    m.alpha += 1e-3;
    m
}

#[test]
fn steady_coin_agrees() {
    let disk = toy(0.25);
    let start = steady_motion(&disk, 0.3, 0.0).unwrap();
    assert_agrees(&rolling_case("steady coin", disk, start, T_END));
}

#[test]
fn perturbed_steady_motion_agrees() {
    for k in [0.25, 0.5] {
        let disk = toy(k);
        let name = format!("perturbed steady motion, k = {k}, b = 0.01 m");
        assert_agrees(&rolling_case(&name, disk, perturbed(&disk, 0.01), T_END));
    }
}

#[test]
fn wheel_rolling_straight_agrees() {
    let disk = toy(0.25);
    // Eq 52: stable for omega_10^2 > g / (2 (2k+1) a); at twice that rate, tilted by 1 mrad.
    let spin = 2.0 * (disk.g / (2.0 * (2.0 * disk.k + 1.0) * disk.a)).sqrt();
    let start = Motion {
        alpha: FRAC_PI_2 - 1e-3,
        alpha_dot: 0.0,
        precession: 0.0,
        spin,
    };
    assert_agrees(&rolling_case("wheel rolling straight", disk, start, T_END));
}

#[test]
fn falling_disk_agrees() {
    let disk = toy(0.25);
    let start = Motion {
        alpha: FRAC_PI_2 - 0.05,
        alpha_dot: 0.0,
        precession: 1.0,
        spin: 0.0,
    };
    // Until 0.5 s or alpha = 0.2, whichever comes first (located on the paper's model).
    let paper = Rolling::<4>::new(disk, Extras::default(), None);
    let p = Problem::new(&paper, 0.0, paper.state(&start), 0.5)
        .stop_when(Event::new("alpha below 0.2", |y: &State<4>| y[0] - 0.2));
    let t_end = solve(p, &settings(RTOL)).unwrap().last().0;
    eprintln!("falling disk: runs to t = {t_end:.6} s");
    assert_agrees(&rolling_case("falling disk", disk, start, t_end));
}

#[test]
fn frictionless_spin_about_a_vertical_diameter_agrees() {
    let disk = toy(0.25);
    // Eq 65: without friction, stable for |Omega| > sqrt(g / (a k)); at 1.25 times that.
    let precession = 1.25 * (disk.g / (disk.a * disk.k)).sqrt();
    let start = Motion {
        alpha: FRAC_PI_2 - 1e-3,
        alpha_dot: 0.0,
        precession,
        spin: 0.0,
    };
    assert_agrees(&frictionless_case(
        "frictionless vertical spin",
        disk,
        start,
        RTOL,
    ));
}

/// A tilted frictionless disk WITH spin (omega_1 = 0.1 Omega), so that the omega_1 terms of eqs
/// 61-62 act. Its nutation is large (alpha over 0.04 rad, Omega over 15 rad/s) and the lab model's
/// integration error, not the paper, limits the agreement: it shrinks about tenfold per decade of
/// rtol (measured 8e-9 of range at 1e-12, 7e-10 at 1e-13). So this case runs at rtol 1e-13 and
/// asserts that convergence, which a wrong term in eqs 60-62 could not show.
#[test]
fn frictionless_tilted_spinning_disk_agrees() {
    let disk = toy(0.25);
    let mut start = perturbed(&disk, 0.0);
    start.spin = 0.1 * start.precession;
    let coarse = frictionless_case(
        "frictionless tilted disk with spin, rtol 1e-12",
        disk,
        start,
        1e-12,
    );
    let fine = frictionless_case(
        "frictionless tilted disk with spin, rtol 1e-13",
        disk,
        start,
        1e-13,
    );
    assert_agrees(&fine);
    let (c, f) = (max_of(coarse.into_iter()), max_of(fine.into_iter()));
    eprintln!(
        "frictionless tilted disk: worst disagreement {c:.2e} at rtol 1e-12, {f:.2e} at 1e-13"
    );
    assert!(
        c > 4.0 * f,
        "the disagreement does not shrink with the tolerance: not numerical"
    );
}

/// One deliberate error in the paper's eqs 23-25, or none.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Flaw {
    None,
    /// Eq 23: $(2k+1)\dot\omega_1 \to (2(k+1)+1)\dot\omega_1$.
    Eq23KToKPlusOne,
    /// Eq 24: $(2k+1)\omega_1\Omega\sin\alpha \to 2k\,\omega_1\Omega\sin\alpha$.
    Eq24SpinTerm,
    /// Eq 24: $(k+1)\ddot\alpha \to k\ddot\alpha$.
    Eq24Inertia,
    /// Eq 25: $+2\dot\alpha\Omega\cos\alpha \to -2\dot\alpha\Omega\cos\alpha$.
    Eq25Sign,
}

/// The test's own transcription of eqs 23-25 with one flaw in it.
struct Mutant {
    disk: Disk,
    flaw: Flaw,
}

impl Dynamics<4> for Mutant {
    fn rhs(&self, y: &State<4>, dy: &mut State<4>) {
        let (k, f) = (self.disk.k, self.flaw);
        let (s, c) = y[0].sin_cos();
        let (ad, om, w) = (y[1], y[2], y[3]);
        let k23 = if f == Flaw::Eq23KToKPlusOne {
            k + 1.0
        } else {
            k
        };
        let spin24 = if f == Flaw::Eq24SpinTerm {
            2.0 * k
        } else {
            2.0 * k + 1.0
        };
        let inertia24 = if f == Flaw::Eq24Inertia { k } else { k + 1.0 };
        let sign25 = if f == Flaw::Eq25Sign { -1.0 } else { 1.0 };
        dy[0] = ad;
        dy[1] = (k * om * om * s * c + spin24 * w * om * s - self.disk.g_over_a() * c) / inertia24;
        dy[2] = -(sign25 * 2.0 * ad * om * c + 2.0 * w * ad) / s;
        dy[3] = -ad * om * s / (2.0 * k23 + 1.0);
    }
}

#[test]
fn the_comparison_catches_a_wrong_term_in_eqs_23_to_25() {
    let disk = toy(0.25);
    let start = perturbed(&disk, 0.01);
    let lab = LabFrame::new(disk, Contact::Rolling);
    let sl = run(&lab, lab.state(&start), T_END);
    let lab_m = motions(&lab, &sl);
    for flaw in [
        Flaw::None,
        Flaw::Eq23KToKPlusOne,
        Flaw::Eq24SpinTerm,
        Flaw::Eq24Inertia,
        Flaw::Eq25Sign,
    ] {
        let mutant = Mutant { disk, flaw };
        let y0 = State::<4>::new(start.alpha, start.alpha_dot, start.precession, start.spin);
        let sm = run(&mutant, y0, T_END);
        let paper_m: Vec<Motion> =
            sm.y.iter()
                .map(|y| Motion::from_state(y.as_slice(), y[3]))
                .collect();
        let worst =
            max_of(agreement(&format!("mutant {flaw:?}"), &disk, &lab_m, &paper_m).into_iter());
        if flaw == Flaw::None {
            assert!(
                worst < AGREE,
                "the unflawed transcription disagrees: {worst:e}"
            );
        } else {
            assert!(
                worst > 1e-3,
                "{flaw:?} slipped through: worst disagreement {worst:e}"
            );
        }
    }
}

/// Eq 61 without its $\dot\alpha^2\sin\alpha\cos\alpha$ term: the frictionless path is refereed too.
struct FrictionlessMutant {
    disk: Disk,
    spin: f64,
}

impl Dynamics<3> for FrictionlessMutant {
    fn rhs(&self, y: &State<3>, dy: &mut State<3>) {
        let k = self.disk.k;
        let (s, c) = y[0].sin_cos();
        let (ad, om, w) = (y[1], y[2], self.spin);
        dy[0] = ad;
        dy[1] =
            (k * om * om * s * c + 2.0 * k * w * om * s - self.disk.g_over_a() * c) / (k + c * c);
        dy[2] = -(2.0 * ad * om * c + 2.0 * w * ad) / s;
    }
}

#[test]
fn the_comparison_catches_a_missing_term_in_eq_61() {
    let disk = toy(0.25);
    let mut start = perturbed(&disk, 0.0);
    start.spin = 0.1 * start.precession;
    let lab = LabFrame::new(disk, Contact::Frictionless);
    let sl = run(&lab, lab.state(&start), T_END);
    let mutant = FrictionlessMutant {
        disk,
        spin: start.spin,
    };
    let sm = run(
        &mutant,
        State::<3>::new(start.alpha, start.alpha_dot, start.precession),
        T_END,
    );
    let paper_m: Vec<Motion> =
        sm.y.iter()
            .map(|y| Motion::from_state(y.as_slice(), start.spin))
            .collect();
    let rel = agreement(
        "frictionless mutant, eq 61 without alpha_dot^2",
        &disk,
        &motions(&lab, &sl),
        &paper_m,
    );
    assert!(
        max_of(rel.into_iter()) > 1e-3,
        "the missing term slipped through: {rel:?}"
    );
}
