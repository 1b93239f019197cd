//! Exploratory (to be replaced).
use rolling_disk::model::frictionless::Frictionless;
use rolling_disk::model::lab_frame::{Contact, LabFrame};
use rolling_disk::model::rolling::Rolling;
use rolling_disk::model::steady::steady_motion;
use rolling_disk::model::{Extras, Model, Motion};
use rolling_disk::solve::{solve, Dynamics, Method, Problem, Settings, State};
use rolling_disk::Disk;

fn settings(rtol: f64) -> Settings {
    Settings {
        method: Method::Dop853,
        rtol,
        atol: rtol * 1e-2,
        ..Settings::default()
    }
}

fn run<D: Dynamics<N>, const N: usize>(
    d: &D,
    y0: State<N>,
    t_end: f64,
    rtol: f64,
) -> Vec<State<N>> {
    let s = solve(
        Problem::new(d, 0.0, y0, t_end).sampled(0.01),
        &settings(rtol),
    )
    .unwrap();
    eprintln!("  {:?} {} evals", s.ending, s.stats.total_evaluations());
    s.y
}

#[test]
fn self_convergence() {
    let disk = Disk::new(0.0375, 0.25, 0.4, 9.81).unwrap();
    let mut m = steady_motion(&disk, 0.3, 0.01).unwrap();
    m.alpha += 1e-3;
    for lam in [0.0, 5.0, 16.17, 50.0, 100.0, 200.0, 500.0, 1000.0, 3000.0] {
        let lab = LabFrame::new(disk, Contact::Rolling).with_stabilisation(lam);
        let refl = run(&lab, lab.state(&m), 10.0, 1e-14);
        for rtol in [1e-12] {
            let y = run(&lab, lab.state(&m), 10.0, rtol);
            let mut d = [0.0f64; 3];
            for (a, b) in y.iter().zip(&refl) {
                let (p, q) = (lab.motion(a), lab.motion(b));
                d[0] = d[0].max((p.alpha - q.alpha).abs());
                d[1] = d[1].max((p.precession - q.precession).abs());
                d[2] = d[2].max((p.spin - q.spin).abs());
            }
            eprintln!("lab lam {lam} rtol {rtol}: self error {d:?}");
        }
    }
    let red = Rolling::<4>::new(disk, Extras::default(), None);
    let refr = run(&red, red.state(&m), 10.0, 1e-14);
    for rtol in [1e-12, 1e-13] {
        let y = run(&red, red.state(&m), 10.0, rtol);
        let mut d = [0.0f64; 3];
        for (a, b) in y.iter().zip(&refr) {
            let (p, q) = (red.motion(a), red.motion(b));
            d[0] = d[0].max((p.alpha - q.alpha).abs());
            d[1] = d[1].max((p.precession - q.precession).abs());
            d[2] = d[2].max((p.spin - q.spin).abs());
        }
        eprintln!("reduced rtol {rtol}: self error {d:?}");
    }
}

#[test]
fn explore() {
    let disk = Disk::new(0.0375, 0.25, 0.4, 9.81).unwrap();
    for (name, mut m, lam) in [
        ("steady coin", steady_motion(&disk, 0.3, 0.0).unwrap(), None),
        (
            "perturbed b",
            steady_motion(&disk, 0.3, 0.01).unwrap(),
            Some(1e-3),
        ),
        (
            "perturbed b lam0",
            steady_motion(&disk, 0.3, 0.01).unwrap(),
            Some(-1.0),
        ),
    ] {
        if let Some(p) = lam {
            m.alpha += 1e-3;
            let _ = p;
        }
        for rtol in [1e-10, 1e-12, 1e-13] {
            let mut lab = LabFrame::new(disk, Contact::Rolling);
            if lam == Some(-1.0) {
                lab = lab.with_stabilisation(0.0);
            }
            let red = Rolling::<4>::new(disk, Extras::default(), None);
            let t = std::time::Instant::now();
            let yl = run(&lab, lab.state(&m), 10.0, rtol);
            eprintln!("  lab {:?}", t.elapsed());
            let yr = run(&red, red.state(&m), 10.0, rtol);
            let mut dmax = [0.0f64; 3];
            let mut rng = [(f64::MAX, f64::MIN); 3];
            let (mut hq, mut hh, mut hv) = (0.0f64, 0.0f64, 0.0f64);
            for (a, b) in yl.iter().zip(&yr) {
                let ml = lab.motion(a);
                let mr = red.motion(b);
                let pl = [ml.alpha, ml.precession, ml.spin];
                let pr = [mr.alpha, mr.precession, mr.spin];
                for i in 0..3 {
                    dmax[i] = dmax[i].max((pl[i] - pr[i]).abs());
                    rng[i].0 = rng[i].0.min(pr[i]);
                    rng[i].1 = rng[i].1.max(pr[i]);
                }
                let s = lab.snapshot(a);
                hq = hq.max((a.fixed_rows::<4>(0).norm() - 1.0).abs());
                hh = hh.max(s.height.abs());
                hv = hv.max(s.contact_velocity.norm());
            }
            let e0 = lab.energy(&yl[0]);
            let e1 = lab.energy(yl.last().unwrap());
            eprintln!("{name} rtol {rtol}: diff {dmax:?} ranges {:?} drift q {hq:e} h {hh:e} vc {hv:e} dE/E {:e}", rng.map(|r| r.1 - r.0), (e1-e0)/e0);
        }
    }
    let _ = Frictionless::<3>::new(disk, 0.0, Extras::default());
    let _: Motion = Motion::default();
}
