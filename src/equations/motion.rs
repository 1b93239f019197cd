//! Checks of the equations of motion for rolling without slipping, eqs 23-25, and of the energy,
//! eq 26, against the independent lab-frame Newton-Euler model (`model::lab_frame`), which owes
//! nothing to the paper's derivation.
//!
//! Eqs 23-25 are checked by trajectories: the paper's reduced model (`model::rolling::rates`,
//! with the claimed rate of the equation under test read through [`Bench::claim`]) and the lab
//! model start from the same state and are compared over two seconds of nutating motion, for
//! several disks and motions chosen so that every rate is far from zero. Eq 26 is compared with
//! the energy computed directly in the lab, at random states.

use super::{Bench, Equation};
use crate::disk::Disk;
use crate::finding::{Finding, Method, Tolerance, Worst};
use crate::model::lab_frame::{Contact, LabFrame};
use crate::model::rolling::{energy, rates};
use crate::model::steady::steady_motion;
use crate::model::{Model, Motion};
use crate::numerics::rng::Rng;
use crate::solve::{solve, Dynamics, Problem, State};

/// The checks of eqs 23-26.
pub const EQUATIONS: &[Equation] = &[
    Equation {
        number: 23,
        label: "e18",
        check: eq23,
    },
    Equation {
        number: 24,
        label: "e19",
        check: eq24,
    },
    Equation {
        number: 25,
        label: "e20",
        check: eq25,
    },
    Equation {
        number: 26,
        label: "e20a",
        check: eq26,
    },
];

/// Which of eqs 23-25 carries the bench's claim factor.
#[derive(Clone, Copy, PartialEq)]
enum Under {
    Eq23,
    Eq24,
    Eq25,
}

/// The paper's reduced model, eqs 23-25, with the equation under test read as claimed:
/// eq 23 gives $\dot\omega_1 = -\dot\alpha\Omega\sin\alpha/(2k+1)$, eq 24 gives $\ddot\alpha$,
/// eq 25 gives $\dot\Omega = -2\dot\alpha(\Omega\cos\alpha + \omega_1)/\sin\alpha$.
struct Claimed {
    disk: Disk,
    under: Under,
    factor: f64,
}

impl Dynamics<4> for Claimed {
    fn rhs(&self, y: &State<4>, dy: &mut State<4>) {
        let m = Motion {
            alpha: y[0],
            alpha_dot: y[1],
            precession: y[2],
            spin: y[3],
        };
        let r = rates(&self.disk, &m, [0.0; 3]);
        let f = |u: Under| if u == self.under { self.factor } else { 1.0 };
        dy[0] = y[1];
        dy[1] = r.alpha_ddot * f(Under::Eq24);
        dy[2] = r.precession_dot * f(Under::Eq25);
        dy[3] = r.spin_dot * f(Under::Eq23);
    }
}

/// Two independent models, each integrated at rtol over a few hundred steps of a motion that
/// nutates: their differences stay within 1e4 x rtol of each variable's range (measured: about
/// 2e-10 at rtol 1e-12 for the cases here; the lab model's own integration error dominates).
fn two_models(rtol: f64) -> Tolerance {
    Tolerance {
        value: 1e4 * rtol,
        rule: format!("two independent integrations: 1e4 x the solver's rtol ({rtol:e}) of each variable's range"),
    }
}

/// Starts with every rate of eqs 23-25 well away from zero: perturbed steady motions with
/// b > 0, b = 0 and b < 0 (inside eq 30's bound), and the benchmark scene's start.
fn starts(disk: &Disk) -> Vec<(String, Motion)> {
    let mut out = Vec::new();
    for (alpha0, b_over_a) in [(0.3, 0.0), (1.0, 0.5), (1.2, -0.03)] {
        if let Ok(mut m) = steady_motion(disk, alpha0, b_over_a * disk.a) {
            m.alpha += 0.02;
            m.alpha_dot = 0.5;
            out.push((format!("alpha0 {alpha0}, b/a {b_over_a}, k {}", disk.k), m));
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

fn trajectories(b: &Bench, under: Under) -> Finding {
    let mut worst = Worst::default();
    let settings = b.settings();
    let (t_end, dt) = (2.0, 0.01);
    for k in [0.25, 0.5, 0.1] {
        let disk = Disk::new(0.0375, k, 0.4, 9.81).expect("a valid disk");
        let lab = LabFrame::new(disk, Contact::Rolling);
        let claimed = Claimed {
            disk,
            under,
            factor: b.claim(1.0),
        };
        for (name, m) in starts(&disk) {
            let y0 = State::<4>::new(m.alpha, m.alpha_dot, m.precession, m.spin);
            let paper = solve(
                Problem::new(&claimed, 0.0, y0, t_end).sampled(dt),
                &settings,
            );
            let reference = solve(
                Problem::new(&lab, 0.0, lab.state_from(&m, 0.0, [0.0, 0.0], 0.0), t_end)
                    .sampled(dt),
                &settings,
            );
            let (Ok(paper), Ok(reference)) = (paper, reference) else {
                worst.add(f64::NAN, 0.0, 1.0, || {
                    format!("{name}: a run could not start")
                });
                continue;
            };
            let n = paper.t.len().min(reference.t.len());
            let lab_motion: Vec<Motion> = reference.y[..n].iter().map(|y| lab.motion(y)).collect();
            let pick = |m: &Motion, i: usize| [m.alpha, m.precession, m.spin][i];
            for (i, var) in ["alpha", "Omega", "omega_1"].iter().enumerate() {
                let values: Vec<f64> = lab_motion.iter().map(|m| pick(m, i)).collect();
                let range = values.iter().copied().fold(f64::MIN, f64::max)
                    - values.iter().copied().fold(f64::MAX, f64::min);
                // A floor for a variable that barely moves: 1 mrad for alpha, 1e-3 sqrt(g/a) for rates.
                let floor = if i == 0 {
                    1e-3
                } else {
                    1e-3 * disk.g_over_a().sqrt()
                };
                let scale = range.max(floor);
                for (j, (y, v)) in paper.y.iter().zip(&values).enumerate() {
                    worst.add(y[[0, 2, 3][i]], *v, scale, || {
                        format!("{name}: {var} at t = {:.2} s", paper.t[j])
                    });
                }
            }
        }
    }
    Finding::from_worst(
        Method::IndependentModel,
        "alpha, Omega, omega_1 of the reduced model against the lab-frame Newton-Euler model, relative to each one's range",
        worst,
        two_models(b.rtol),
        false,
    )
    .shown_by("figure lab-frame-difference")
}

/// Eq 23: $(2k + 1)\dot\omega_1 + \dot\alpha\Omega\sin\alpha = 0$.
fn eq23(b: &Bench) -> Finding {
    trajectories(b, Under::Eq23)
}

/// Eq 24: $k\Omega^2\sin\alpha\cos\alpha + (2k+1)\omega_1\Omega\sin\alpha - (k+1)\ddot\alpha = \frac{g}{a}\cos\alpha$.
fn eq24(b: &Bench) -> Finding {
    trajectories(b, Under::Eq24)
}

/// Eq 25: $\dot\Omega\sin\alpha + 2\dot\alpha\Omega\cos\alpha + 2\omega_1\dot\alpha = 0$.
fn eq25(b: &Bench) -> Finding {
    trajectories(b, Under::Eq25)
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
            worst.add(
                b.claim(energy(&disk, &m)),
                reference,
                reference.abs(),
                || format!("k {k}, {m:?}"),
            );
        }
    }
    Finding::from_worst(
        Method::IndependentModel,
        "eq 26's energy against the energy computed in the lab frame for the same rolling state",
        worst,
        Tolerance::roundoff(),
        false,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::finding::Verdict;

    #[test]
    fn each_equation_holds_and_fails_when_perturbed() {
        for e in EQUATIONS {
            let f = (e.check)(&Bench::default());
            assert_eq!(f.verdict, Verdict::Holds, "eq {}: {f:?}", e.number);
            eprintln!("eq {}: error {:.2e} ({})", e.number, f.error, f.at);
            for p in [1e-3, -1e-3] {
                let f = (e.check)(&Bench::perturbed(p));
                assert_eq!(
                    f.verdict,
                    Verdict::Fails,
                    "eq {} under {p}: {f:?}",
                    e.number
                );
            }
        }
    }
}
