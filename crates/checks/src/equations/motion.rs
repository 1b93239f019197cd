//! Checks of the equations of motion for rolling without slipping, eqs 23-25, and of the energy,
//! eq 26, against the independent lab-frame Newton-Euler model (`model::lab_frame`), which owes
//! nothing to the paper's derivation.
//!
//! Eqs 23-25 are checked one by one, as printed: each relation's residual at states of the lab
//! model, with the lab model's own rates, over two seconds of nutating motion for several disks
//! and motions chosen so that every rate is far from zero. A wrong coefficient in one of them
//! fails that one alone. (The Rust form the integrator uses, `model::rolling::rates`, is
//! cross-checked against the printed relations by `rates_satisfy_the_printed_equations`.) Eq 26 is compared with
//! the energy computed directly in the lab, at random states.

use crate::equations::{row, Row};
use crate::finding::{Finding, Method, Tolerance, Worst};
use crate::harness::disk_constants;
use crate::harness::{printed_relations, term_scale, Bench};
use numerics::memo::{bits, Memo};
use numerics::rng::Rng;
use paper::Bindings;
use physics::disk::Disk;
use physics::model::lab_frame::{Contact, LabFrame};
use physics::model::steady::steady_motion;
use physics::model::{Model, Motion};
use physics::solve::{solve, Dynamics, Problem, State};
use std::sync::Arc;

/// The checks of eqs 23-26.
pub const EQUATIONS: &[Row] = &[row(23, eq23), row(24, eq24), row(25, eq25), row(26, eq26)];

/// Starts with every rate of eqs 23-25 well away from zero: perturbed steady motions with
/// b > 0, b = 0 and b < 0 (inside eq 30's bound), and the benchmark scene's start.
fn starts(disk: &Disk) -> Vec<(String, Motion)> {
    let mut out = Vec::new();
    for (alpha0, b_over_a) in [(0.3, 0.0), (1.0, 0.5), (1.2, -0.03)] {
        if let Ok(mut m) = steady_motion(disk, alpha0, b_over_a * disk.a) {
            m.alpha += 0.02;
            m.alpha_dot = 0.5;
            out.push((
                format!("$\\alpha_0 {alpha0}$, $b/a {b_over_a}$, k {}", disk.k),
                m,
            ));
        }
    }
    out.push((
        format!("benchmark start, k {}", disk.k),
        Motion {
            alpha: 1.212,
            alpha_dot: 0.0,
            precession: 10.755388960654598,
            spin: 5.417_805_126_021_373,
        },
    ));
    out
}

/// The residual of each printed relation of eqs 23-25 (equations of motion) is measured at states
/// of the lab-frame model; its rates ($\dot\omega_1$, $\ddot\alpha$, $\dot\Omega$) are the lab
/// model's own, by central differences along its flow (step `FLOW_STEP`).
const FLOW_STEP: f64 = 1e-5;

/// Central differences along the flow with one Richardson step (h = 1e-5 s and h/2): the
/// straight step $y \pm h f(y)$ leaves an $h^2$ error of about 1e-4 relative at h = 1e-5
/// (measured), which the extrapolation cancels, leaving $O(h^4)$ and round-off
/// $\epsilon_{mach}|x|/h$, both below 1e-9 of the terms for rates up to 50 rad/s.
fn flow_differences() -> Tolerance {
    Tolerance {
        value: 1e-7,
        rule: "Richardson-extrapolated central differences along the lab model's flow (h = 1e-5 s): 1e-7 of the sum of the relation's terms and $g/a$".into(),
    }
}

/// The paper's variables and their rates at lab state `y`, bound to the quantities of
/// paper/symbols.yaml.
fn lab_bindings(lab: &LabFrame, disk: &Disk, y: &State<13>) -> Bindings<f64> {
    let mut f = State::<13>::zeros();
    lab.rhs(y, &mut f);
    let m = lab.motion(y);
    let central = |h: f64, g: fn(&Motion) -> f64| {
        (g(&lab.motion(&(y + f * h))) - g(&lab.motion(&(y - f * h)))) / (2.0 * h)
    };
    // Richardson: (4 D(h/2) - D(h)) / 3 cancels the h^2 term of the central difference.
    let rate =
        |g: fn(&Motion) -> f64| (4.0 * central(FLOW_STEP / 2.0, g) - central(FLOW_STEP, g)) / 3.0;
    Bindings::new()
        .scalar("alpha", m.alpha)
        .scalar("alpha_dot", m.alpha_dot)
        .scalar("alpha_ddot", rate(|m| m.alpha_dot))
        .scalar("Omega", m.precession)
        .scalar("Omega_dot", rate(|m| m.precession))
        .scalar("omega_1", m.spin)
        .scalar("omega_1_dot", rate(|m| m.spin))
        .scalar("k", disk.k)
        .scalar("g", disk.g)
        .scalar("a", disk.a)
}

/// One two-second lab-frame run of [`residuals`], sampled every 0.05 s (`None` when it failed).
struct LabRun {
    name: String,
    disk: Disk,
    lab: LabFrame,
    samples: Option<(Vec<f64>, Vec<State<13>>)>,
}

/// The lab runs from the starts of [`starts`] for k = 0.25, 0.5, 0.1, integrated once per
/// solver setting and shared by eqs 23-25.
fn lab_runs(b: &Bench) -> Arc<Vec<LabRun>> {
    type Key = ([u64; 1], physics::solve::Method);
    static RUNS: Memo<Key, Arc<Vec<LabRun>>> = Memo::new();
    RUNS.get((bits([b.rtol]), b.method), || {
        let settings = b.settings();
        let mut out = Vec::new();
        for k in [0.25, 0.5, 0.1] {
            let Ok(disk) = Disk::new(0.0375, k, 0.4, 9.81) else {
                continue;
            };
            let lab = LabFrame::new(disk, Contact::Rolling);
            for (name, m) in starts(&disk) {
                let run = solve(
                    Problem::new(&lab, 0.0, lab.state_from(&m, 0.0, [0.0, 0.0], 0.0), 2.0)
                        .sampled(0.05),
                    &settings,
                );
                out.push(LabRun {
                    name,
                    disk,
                    lab: lab.clone(),
                    samples: run.ok().map(|r| (r.t, r.y)),
                });
            }
        }
        Arc::new(out)
    })
}

/// Eqs 23-25 share this: each printed relation of eq `n` at states sampled every 0.05 s along
/// two-second lab-frame runs from the starts of [`starts`], for k = 0.25, 0.5, 0.1; the residual
/// relative to the sum of the magnitudes of the relation's terms plus $g/a$ (the problem's own
/// squared rate, so that a relation whose terms all vanish at a point is not divided by zero).
fn residuals(b: &Bench, n: u32) -> Finding {
    let mut worst = Worst::default();
    let eq = b.paper.equation(n);
    for run in lab_runs(b).iter() {
        let Some((ts, ys)) = &run.samples else {
            let name = &run.name;
            worst.add(f64::NAN, 0.0, 1.0, || format!("{name}: the lab run failed"));
            continue;
        };
        for (t, y) in ts.iter().zip(ys) {
            let bind = lab_bindings(&run.lab, &run.disk, y);
            let scale = eq
                .relations()
                .iter()
                .map(|r| term_scale(eq, r.lhs, &bind) + term_scale(eq, r.rhs, &bind))
                .fold(0.0, f64::max)
                + run.disk.g_over_a();
            printed_relations(b, n, &bind, scale, &mut worst, &|| {
                format!("{}, $t = {t:.2}$ s", run.name)
            });
        }
    }
    Finding::from_worst(
        Method::IndependentModel,
        "the printed relation's residual at states of the lab-frame Newton-Euler model, its rates measured along the lab model's flow",
        worst,
        flow_differences())
    .in_unit(match n {
        24 => "1/s^2",
        _ => "rad/s^2",
    })
    .shown_by("figure lab-frame-difference")
}

/// Eq 23: $(2k + 1)\dot\omega_1 + \dot\alpha\Omega\sin\alpha = 0$.
fn eq23(b: &Bench) -> Finding {
    residuals(b, 23)
}

/// Eq 24: $k\Omega^2\sin\alpha\cos\alpha + (2k+1)\omega_1\Omega\sin\alpha - (k+1)\ddot\alpha = \frac{g}{a}\cos\alpha$.
fn eq24(b: &Bench) -> Finding {
    residuals(b, 24)
}

/// Eq 25: $\dot\Omega\sin\alpha + 2\dot\alpha\Omega\cos\alpha + 2\omega_1\dot\alpha = 0$.
fn eq25(b: &Bench) -> Finding {
    residuals(b, 25)
}

/// Eq 26: $E = \frac{m a^2}{2}\left[(2k+1)\omega_1^2 + (k+1)\dot\alpha^2 + k\Omega^2\sin^2\alpha + \frac{2g}{a}\sin\alpha\right]$,
/// against $\frac12 m|\mathbf v|^2 + \frac12\boldsymbol\omega\cdot I\boldsymbol\omega + m g z$ computed
/// in the lab for the same rolling state, at random states (tilts from 0.05 to pi - 0.05, rates
/// up to 50 rad/s, both signs), for several k.
fn eq26(b: &Bench) -> Finding {
    let mut rng = Rng::new(26);
    let mut worst = Worst::default();
    for k in [0.1, 0.25, 0.5, 0.9] {
        let disk = Disk::new(0.0375, k, 0.4, 9.81).expect("a valid disk");
        let lab = LabFrame::new(disk, Contact::Rolling);
        for _ in 0..50 {
            let m = Motion {
                alpha: rng.uniform(0.05, std::f64::consts::PI - 0.05),
                alpha_dot: rng.uniform(-20.0, 20.0),
                precession: rng.uniform(-50.0, 50.0),
                spin: rng.uniform(-50.0, 50.0),
            };
            let y = lab.state_from(&m, rng.uniform(0.0, std::f64::consts::TAU), [0.0, 0.0], 0.0);
            let reference = lab.energy(&y);
            // The lab's own kinetic and potential parts, from its state.
            let snap = lab.snapshot(&y);
            let inertia = nalgebra::Matrix3::from_diagonal(&nalgebra::Vector3::new(2.0 * k, k, k))
                * (disk.m * disk.a * disk.a);
            let i_lab = snap.rotation.matrix() * inertia * snap.rotation.matrix().transpose();
            let potential = disk.m * disk.g * snap.centre.z;
            let bind = disk_constants(&disk)
                .scalar("E", reference)
                .scalar("T", reference - potential)
                .scalar("V", potential)
                .scalar("v_cm_speed", snap.velocity.norm())
                .vector("omega_vec", snap.omega)
                .value("I_tensor", paper::Value::Tensor(i_lab))
                .scalar("z_cm", snap.centre.z)
                .scalar("alpha", m.alpha)
                .scalar("alpha_dot", m.alpha_dot)
                .scalar("Omega", m.precession)
                .scalar("omega_1", m.spin);
            printed_relations(b, 26, &bind, reference.abs(), &mut worst, &|| {
                format!(
                    "k {k}, $\\alpha = {}$ rad, $\\dot\\alpha = {}$ rad/s, $\\Omega = {}$ rad/s, $\\omega_1 = {}$ rad/s",
                    m.alpha, m.alpha_dot, m.precession, m.spin
                )
            });
        }
    }
    Finding::from_worst(
        Method::IndependentModel,
        "every printed form of eq 26's energy against the energy computed in the lab frame for the same rolling state",
        worst,
        Tolerance::roundoff())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::finding::Verdict;
    use physics::model::rolling::rates;

    #[test]
    fn each_equation_holds_and_eq26_fails_when_perturbed() {
        for e in EQUATIONS {
            let f = (e.check)(&Bench::default());
            assert_eq!(f.verdict, Verdict::Holds, "eq {}: {f:?}", e.number);
        }
        // Eqs 23-25 are mutated in their LaTeX by tests/mutation.rs.
        for p in [1e-3, -1e-3] {
            assert_eq!(eq26(&Bench::perturbed(p)).verdict, Verdict::Fails);
        }
    }

    /// The transcription check: the Rust form the integrator uses (`model::rolling::rates`)
    /// satisfies the printed eqs 23-25 at random states, to round-off.
    #[test]
    fn rates_satisfy_the_printed_equations() {
        let b = Bench::default();
        let mut rng = Rng::new(2325);
        for _ in 0..200 {
            let disk = Disk::new(0.0375, rng.uniform(0.05, 1.0), 0.4, 9.81).unwrap();
            let m = Motion {
                alpha: rng.uniform(0.05, 3.0),
                alpha_dot: rng.uniform(-20.0, 20.0),
                precession: rng.uniform(-50.0, 50.0),
                spin: rng.uniform(-50.0, 50.0),
            };
            let r = rates(&disk, &m, [0.0; 3]);
            let bind = disk_constants(&disk)
                .scalar("alpha", m.alpha)
                .scalar("alpha_dot", m.alpha_dot)
                .scalar("alpha_ddot", r.alpha_ddot)
                .scalar("Omega", m.precession)
                .scalar("Omega_dot", r.precession_dot)
                .scalar("omega_1", m.spin)
                .scalar("omega_1_dot", r.spin_dot);
            for n in [23, 24, 25] {
                let eq = b.paper.equation(n);
                let rel = eq.relations()[0];
                let scale = term_scale(eq, rel.lhs, &bind) + term_scale(eq, rel.rhs, &bind);
                let (l, r) = (
                    eq.scalar(rel.lhs, &bind).unwrap(),
                    eq.scalar(rel.rhs, &bind).unwrap(),
                );
                assert!(
                    (l - r).abs() <= 1e-12 * scale,
                    "eq {n}: {l} vs {r} at {m:?}"
                );
            }
        }
    }
}
