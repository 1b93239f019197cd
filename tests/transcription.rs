//! The transcription checks: where a model keeps a Rust form of a printed formula (for speed in
//! the integrator, or because a scene asks for the paper's own law), that form is evaluated
//! against the parsed LaTeX of `paper/equations.yaml` at random points of its domain, and must
//! agree to round-off. (The rolling model's eqs 23-25 are cross-checked in
//! `equations::motion`'s tests.) A model that drifted from the paper fails here loudly.

use checks::equations::built_in_paper;
use numerics::rng::Rng;
use paper::Bindings;
use physics::disk::Disk;
use physics::model::adiabatic::Adiabatic;
use physics::model::dissipation::PowerLaw;
use physics::model::frictionless::accelerations;
use physics::model::steady::{b_bound, precession_squared};
use physics::model::Motion;
use studies::precision::stable::varpi_squared_printed;

/// Seeded points of a domain (the points need no statistics, only spread): the crate's seeded
/// ChaCha8 source.
struct Points(Rng);

impl Points {
    fn seeded(seed: u64) -> Self {
        Self(Rng::new(seed))
    }

    fn next(&mut self, lo: f64, hi: f64) -> f64 {
        self.0.uniform(lo, hi)
    }
}

fn close(a: f64, b: f64, scale: f64) -> bool {
    (a - b).abs() <= 1e-12 * scale
}

#[test]
fn the_frictionless_model_is_eqs_61_and_62() {
    let paper = built_in_paper();
    let mut p = Points::seeded(61);
    for _ in 0..300 {
        let disk = Disk::new(0.0375, p.next(0.05, 1.0), 0.4, 9.81).unwrap();
        let m = Motion {
            alpha: p.next(0.05, 3.0),
            alpha_dot: p.next(-20.0, 20.0),
            precession: p.next(-50.0, 50.0),
            spin: p.next(-50.0, 50.0),
        };
        let (alpha_ddot, precession_dot) = accelerations(&disk, &m);
        let bind = Bindings::new()
            .scalar("alpha", m.alpha)
            .scalar("alpha_dot", m.alpha_dot)
            .scalar("alpha_ddot", alpha_ddot)
            .scalar("Omega", m.precession)
            .scalar("Omega_dot", precession_dot)
            .scalar("omega_1", m.spin)
            .scalar("k", disk.k)
            .scalar("g", disk.g)
            .scalar("a", disk.a);
        for n in [61, 62] {
            let eq = paper.equation(n);
            let rel = eq.relations()[0];
            let (l, r) = (
                eq.scalar(rel.lhs, &bind).unwrap(),
                eq.scalar(rel.rhs, &bind).unwrap(),
            );
            let scale = l.abs() + r.abs() + disk.g_over_a() + m.precession.powi(2) + m.spin.powi(2);
            assert!(close(l, r, scale), "eq {n}: {l} vs {r} at {m:?}");
        }
    }
}

#[test]
fn the_steady_starts_are_eqs_29_and_30() {
    let paper = built_in_paper();
    let mut p = Points::seeded(29);
    for _ in 0..300 {
        let disk = Disk::new(0.0375, p.next(0.05, 1.0), 0.4, 9.81).unwrap();
        let alpha0 = p.next(0.02, 1.55);
        let bound = b_bound(&disk, alpha0);
        let b = bound + p.next(1e-4, 2.0) * disk.a;
        let bind = Bindings::new()
            .scalar("alpha_0", alpha0)
            .scalar("b", b)
            .scalar("k", disk.k)
            .scalar("g", disk.g)
            .scalar("a", disk.a);
        let eq29 = paper.equation(29);
        let printed = eq29.scalar(eq29.relations()[0].rhs, &bind).unwrap();
        let rust = precession_squared(&disk, alpha0, b);
        assert!(
            close(printed, rust, rust.abs()),
            "eq 29: {printed} vs {rust}"
        );
        let eq30 = paper.equation(30);
        let edge = eq30.scalar(eq30.relations()[0].rhs, &bind).unwrap();
        assert!(close(edge, bound, disk.a), "eq 30: {edge} vs {bound}");
    }
}

#[test]
fn the_adiabatic_law_is_eq_76_as_printed() {
    let paper = built_in_paper();
    let eq = paper.equation(76);
    let last = eq.chains[0].sides.last().unwrap();
    let mut p = Points::seeded(76);
    for _ in 0..300 {
        let disk = Disk::new(0.0375, p.next(0.05, 1.0), 0.4, 9.81).unwrap();
        let law = PowerLaw {
            epsilon: p.next(1e-8, 1e-2),
            beta: p.next(0.0, 4.0),
        };
        let alpha = p.next(1e-3, 0.5);
        let bind = Bindings::new()
            .scalar("dissipation", law.epsilon)
            .scalar("beta", law.beta)
            .scalar("alpha", alpha)
            .scalar("k", disk.k)
            .scalar("g", disk.g)
            .scalar("a", disk.a);
        let printed = eq.scalar(last, &bind).unwrap();
        let rust = Adiabatic::new(disk, law).alpha_dot(alpha);
        assert!(
            close(printed, rust, rust.abs()),
            "eq 76: {printed} vs {rust}"
        );
    }
}

#[test]
fn the_precision_studys_printed_eq_54_is_eq_54() {
    let paper = built_in_paper();
    let mut p = Points::seeded(54);
    for _ in 0..300 {
        let disk = Disk::new(0.0375, p.next(0.05, 1.0), 0.4, 9.81).unwrap();
        let alpha0 = p.next(0.02, 1.55);
        let b = b_bound(&disk, alpha0) + p.next(1e-3, 2.0) * disk.a;
        let bind = Bindings::new()
            .scalar("alpha_0", alpha0)
            .scalar("b", b)
            .scalar("k", disk.k)
            .scalar("a", disk.a);
        let printed = paper.right_side(54, &bind).unwrap();
        let om2 = precession_squared(&disk, alpha0, b);
        let rust = varpi_squared_printed(&disk, alpha0, b) * (disk.k + 1.0) / om2;
        let scale = 1.0 + (b / disk.a).powi(2) * 10.0 + (alpha0.sin().powi(2) / alpha0.cos());
        assert!(close(printed, rust, scale), "eq 54: {printed} vs {rust}");
    }
}

#[test]
fn the_experiments_law_is_eq_79_as_printed() {
    use experiment::Law;
    let paper = built_in_paper();
    let eq = paper.equation(79);
    let last = eq.chains[0].sides.last().unwrap();
    let mut p = Points::seeded(79);
    for _ in 0..300 {
        let law = Law {
            beta: p.next(0.0, 4.0),
            c: 10f64.powf(p.next(3.0, 12.0)),
        };
        let tau = 10f64.powf(p.next(-4.0, 0.0));
        let bind = Bindings::new()
            .scalar("C", law.c)
            .scalar("beta", law.beta)
            .scalar("t_0", tau)
            .scalar("t", 0.0);
        let printed = eq.scalar(last, &bind).unwrap();
        let rust = law.precession(tau);
        assert!(
            close(printed, rust, rust.abs()),
            "eq 79: {printed} vs {rust}"
        );
    }
}
