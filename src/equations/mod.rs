//! The registry of checks: one per numbered equation of the paper (1-85) and one per prose claim
//! (`paper/claims.yaml`), each comparing the paper's CLAIM with a REFERENCE that does not depend
//! on it.
//!
//! Every check reads the claimed side through [`Bench::claim`], so that the mutation test can
//! perturb it (by a relative 1e-3) and see the check fail: a check that cannot fail is no check.

pub mod claims;
pub mod friction;
pub mod frictionless;
pub mod kinematics;
pub mod motion;
pub mod oscillation;
pub mod slippage;
pub mod steady;

use crate::finding::{Finding, Worst};
use crate::paper::Paper;
use crate::solve::{Method, Settings};
use std::sync::OnceLock;

/// The paper compiled into the binary, read once. Its three files are checked by the tests, so
/// failing to read them is a defect of this build, not of any input.
pub fn built_in_paper() -> &'static Paper {
    static PAPER: OnceLock<Paper> = OnceLock::new();
    PAPER.get_or_init(|| match Paper::built_in() {
        Ok(p) => p,
        Err(e) => panic!("the built-in paper does not read (a defect of this build): {e}"),
    })
}

/// The equations whose checks take their claimed side from the paper's LaTeX (the others still
/// carry a Rust transcription, checked by the ±1e-3 sweep of tests/registry.rs).
pub const FROM_LATEX: &[u32] = &[
    1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 23, 24, 25, 30, 41, 42, 43, 52, 53, 59, 60, 61, 62,
    63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 83, 84, 85,
];

/// What a check runs with.
#[derive(Debug, Clone, Copy)]
pub struct Bench<'p> {
    /// The paper whose claims are checked: the built-in one, or one read with `--paper DIR`.
    pub paper: &'p Paper,
    /// Relative perturbation applied to every claimed value (0 in normal runs, 1e-3 in the
    /// mutation test).
    pub perturbation: f64,
    /// The solver's relative tolerance for integrations.
    pub rtol: f64,
}

impl Default for Bench<'static> {
    fn default() -> Self {
        Self {
            paper: built_in_paper(),
            perturbation: 0.0,
            rtol: 1e-12,
        }
    }
}

impl<'p> Bench<'p> {
    /// The default bench on another paper.
    pub fn with_paper(paper: &'p Paper) -> Self {
        Self {
            paper,
            ..Bench::default()
        }
    }

    /// The same bench with the claimed side perturbed by relative `p`.
    pub fn perturbed(p: f64) -> Bench<'static> {
        Bench {
            perturbation: p,
            ..Bench::default()
        }
    }

    /// A claimed value, as the check must see it: multiplied by (1 + perturbation). For an
    /// inequality, pass its bound.
    pub fn claim(&self, x: f64) -> f64 {
        x * (1.0 + self.perturbation)
    }

    /// The same bench with integrations at least as accurate as rtol `finest`, for a check that
    /// cannot resolve its claim otherwise (a residual's order of convergence, a growth test
    /// under bisection), whatever accuracy preset the user chose.
    pub fn resolving(&self, finest: f64) -> Self {
        Self {
            rtol: self.rtol.min(finest),
            ..*self
        }
    }

    /// Solver settings for the integrations of a check (DOP853 at this bench's rtol).
    pub fn settings(&self) -> Settings {
        Settings {
            method: Method::Dop853,
            rtol: self.rtol,
            atol: self.rtol * 1e-2,
            ..Settings::default()
        }
    }
}

/// One numbered equation and its check.
#[derive(Debug, Clone, Copy)]
pub struct Equation {
    /// The printed number (1-85).
    pub number: u32,
    /// The LaTeX label in the paper's source.
    pub label: &'static str,
    /// The check.
    pub check: fn(&Bench) -> Finding,
}

/// One prose claim (an entry of `paper/claims.yaml`) and its check.
#[derive(Debug, Clone, Copy)]
pub struct Claim {
    /// The claim's id in `paper/claims.yaml`.
    pub id: &'static str,
    /// The check.
    pub check: fn(&Bench) -> Finding,
}

/// Equations that have no check, and why: each is a defect of the paper's checkability, not a
/// gap to hide. The coverage test requires every other number to have a check.
pub const UNCHECKABLE_EQUATIONS: &[(u32, &str)] = &[(
    82,
    "Moffatt's air-film law: only its exponent 1/3 follows from the paper (eq 78 at beta = 4); its \
     prefactor 2 pi eta a / m comes from Moffatt's viscous dissipation, which the paper cites but \
     does not give, so no reference independent of the claim can be built from the paper",
)];

/// Prose claims (ids of paper/claims.yaml) that have no check, and why.
pub const UNCHECKABLE_CLAIMS: &[(&str, &str)] = &[
    (
        "transition-observed-range",
        "an observation on the authors' video frames",
    ),
    (
        "drag-exponent-moffatt-revised",
        "reports another paper's revised model, not given here",
    ),
    (
        "last-analysable-cycle",
        "an observation on the authors' unpublished scope record",
    ),
    (
        "t0-range",
        "an observation on the authors' unpublished scope record",
    ),
    (
        "beta-two-fits-data",
        "a judgement on the authors' unpublished data",
    ),
    (
        "nutation-disappears-below-0p1",
        "the equations give no threshold at 0.1 rad: the beat ratio there is about 0.1, not small",
    ),
    (
        "contact-speed-exceeds-sound",
        "names no number; its content (Omega unbounded) is checked by finite-time-singularity",
    ),
    (
        "summary-nutation-10-15-deg",
        "a range at whole-degree precision that no 1e-3 change of the claim can move across: \
         the coincidence tilt is 9.65 deg (linearization) or 11.46 deg (eq 58)",
    ),
];

/// Every registered equation check, by number.
pub fn equations() -> Vec<Equation> {
    let mut all: Vec<Equation> = [
        kinematics::EQUATIONS,
        motion::EQUATIONS,
        steady::EQUATIONS,
        slippage::EQUATIONS,
        oscillation::EQUATIONS,
        frictionless::EQUATIONS,
        friction::EQUATIONS,
    ]
    .concat();
    all.sort_by_key(|e| e.number);
    all
}

/// Every registered claim check.
pub fn claims() -> Vec<Claim> {
    claims::CLAIMS.to_vec()
}

/// The worst of several order fits: the first failing, else the largest order error.
pub(crate) fn worst_order(findings: Vec<(String, Finding)>) -> Finding {
    let mut best: Option<Finding> = None;
    for (label, mut f) in findings {
        f.at = format!("{label}: {}", f.at);
        best = Some(match best {
            None => f,
            Some(b) => {
                let bad = |x: &Finding| matches!(x.verdict, crate::finding::Verdict::Fails);
                if (bad(&f) && !bad(&b)) || (bad(&f) == bad(&b) && f.error > b.error) {
                    f
                } else {
                    b
                }
            }
        });
    }
    best.expect("at least one fit")
}

/// The size of an expression's terms: the sum of the magnitudes of the terms of its top-level
/// sums (vectors by their norms), so that a relation whose sides nearly cancel (`... = 0`) is
/// measured against the size of what cancels.
pub(crate) fn term_scale(
    eq: &crate::paper::Equation,
    e: &crate::paper::Expr,
    bind: &crate::paper::Bindings<f64>,
) -> f64 {
    use crate::paper::expr::Op;
    use crate::paper::{Expr, Value};
    match e {
        Expr::Bin(Op::Add | Op::Sub, a, b) => term_scale(eq, a, bind) + term_scale(eq, b, bind),
        Expr::Neg(a) => term_scale(eq, a, bind),
        _ => match eq.eval(e, bind) {
            Ok(Value::Scalar(x)) => x.abs(),
            Ok(Value::Vector(v)) => v.norm(),
            Ok(Value::Tensor(m)) => m.norm(),
            Err(_) => 0.0,
        },
    }
}

/// Compares the two sides of every printed relation of eq `n` at one point, the symbols bound
/// to the reference's values by `bind`: the claimed side (the right one) is read through
/// [`Bench::claim`], vectors component by component, `scale` turns differences into relative
/// errors. A relation that cannot be evaluated (a symbol this check does not provide, say after
/// an author's edit) is recorded as an infinite error with the reason, so the check fails and
/// says why. Inequalities are not compared here (their checks locate the threshold).
pub(crate) fn printed_relations(
    b: &Bench,
    n: u32,
    bind: &crate::paper::Bindings<f64>,
    scale: f64,
    w: &mut Worst,
    at: &dyn Fn() -> String,
) {
    use crate::paper::Value;
    let eq = b.paper.equation(n);
    for r in eq.relations() {
        if r.rel.is_inequality() {
            continue;
        }
        let sides = eq
            .eval(r.lhs, bind)
            .and_then(|l| eq.eval(r.rhs, bind).map(|rr| (l, rr)));
        let name = || format!("eq {n} {}", r.name());
        match sides {
            Ok((Value::Scalar(l), Value::Scalar(rr))) => {
                w.add(b.claim(rr), l, scale, || format!("{}: {}", name(), at()))
            }
            Ok((l, rr)) => match (l.vector(), rr.vector()) {
                (Ok(l), Ok(rr)) => {
                    for i in 0..3 {
                        w.add(b.claim(rr[i]), l[i], scale, || {
                            format!("{}, lab component {}: {}", name(), ["x", "y", "z"][i], at())
                        });
                    }
                }
                (Err(e), _) | (_, Err(e)) => {
                    w.add(f64::NAN, 0.0, 1.0, || format!("{}: {e}", name()))
                }
            },
            Err(e) => w.add(f64::NAN, 0.0, 1.0, || {
                format!("{}: cannot be evaluated: {e}", name())
            }),
        }
    }
}

/// The value of `quantity` that makes the printed relation `rel` of `eq` hold, the others bound
/// by `bind`: the root of (left side - right side) in `[lo, hi]`, located by bisection to the
/// last bit. `None` when the relation does not change sign there or cannot be evaluated. This is
/// how a check reads a printed relation as a definition of one of its symbols (the $t_0$ of
/// eqs 77-79, the $C$ of eq 79) without writing that symbol's formula in Rust.
pub(crate) fn solve_printed(
    eq: &crate::paper::Equation,
    rel: &crate::paper::Relation<'_>,
    quantity: &str,
    bind: &crate::paper::Bindings<f64>,
    lo: f64,
    hi: f64,
) -> Option<f64> {
    use crate::paper::Value;
    let residual = |x: f64| -> Option<f64> {
        let mut b = bind.clone();
        b.set(quantity, Value::Scalar(x));
        let l = eq.scalar(rel.lhs, &b).ok()?;
        let r = eq.scalar(rel.rhs, &b).ok()?;
        let d = l - r;
        d.is_finite().then_some(d)
    };
    let (mut lo, mut hi) = (lo.min(hi), lo.max(hi));
    let (mut f_lo, f_hi) = (residual(lo)?, residual(hi)?);
    if f_lo == 0.0 {
        return Some(lo);
    }
    if f_lo.signum() == f_hi.signum() {
        return None;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        let f_mid = residual(mid)?;
        if f_mid.signum() == f_lo.signum() {
            lo = mid;
            f_lo = f_mid;
        } else {
            hi = mid;
        }
    }
    Some(0.5 * (lo + hi))
}

/// A printed inequality of eq `n` (its first) read as a threshold on `quantity`: the value where
/// its two sides meet, solved for in `[lo, hi]` from the printed text (NaN if none), and whether
/// it holds at the two probes `below` and `above` the reference's edge.
pub(crate) struct PrintedThreshold {
    /// Where the printed sides meet.
    pub edge: f64,
    /// Whether the printed inequality holds at the probe below and at the probe above.
    pub holds: [bool; 2],
    /// The inequality, for messages.
    pub relation: String,
}

/// Reads eq `n`'s first inequality as a threshold on `quantity` (see [`PrintedThreshold`]).
pub(crate) fn printed_threshold(
    b: &Bench,
    n: u32,
    quantity: &str,
    bind: &crate::paper::Bindings<f64>,
    bracket: (f64, f64),
    probes: [f64; 2],
) -> PrintedThreshold {
    use crate::paper::Value;
    let eq = b.paper.equation(n);
    let rels = eq.relations();
    let Some(rel) = rels.iter().find(|r| r.rel.is_inequality()).copied() else {
        return PrintedThreshold {
            edge: f64::NAN,
            holds: [false, false],
            relation: format!("eq {n} prints no inequality"),
        };
    };
    let edge = solve_printed(eq, &rel, quantity, bind, bracket.0, bracket.1).unwrap_or(f64::NAN);
    let holds = probes.map(|x| {
        let mut bb = bind.clone();
        bb.set(quantity, Value::Scalar(x));
        match (eq.scalar(rel.lhs, &bb), eq.scalar(rel.rhs, &bb)) {
            (Ok(l), Ok(r)) => rel.rel.holds(l, r),
            _ => false,
        }
    });
    PrintedThreshold {
        edge,
        holds,
        relation: rel.name(),
    }
}

/// Adds a threshold's comparison to `w`: the printed edge (read through [`Bench::claim`])
/// against the reference's, and the printed direction against the reference's verdicts at the
/// probes (`allowed[i]`: the motion exists or is stable there). A direction that disagrees is an
/// infinite error, with the reason.
pub(crate) fn add_threshold(
    b: &Bench,
    w: &mut Worst,
    printed: &PrintedThreshold,
    reference_edge: f64,
    allowed: [bool; 2],
    at: &dyn Fn() -> String,
) {
    w.add(
        b.claim(printed.edge),
        reference_edge,
        reference_edge.abs(),
        || format!("{}: {}", printed.relation, at()),
    );
    if printed.holds != allowed {
        w.add(f64::INFINITY, reference_edge, 1.0, || {
            format!(
                "{}: the printed inequality {} below the edge and {} above it, where the reference {} and {}: {}",
                printed.relation,
                if printed.holds[0] { "holds" } else { "fails" },
                if printed.holds[1] { "holds" } else { "fails" },
                if allowed[0] { "allows" } else { "forbids" },
                if allowed[1] { "allows" } else { "forbids" },
                at()
            )
        });
    }
}
