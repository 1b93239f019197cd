//! The registry of checks: one per numbered equation of the paper (1-85) and one per prose claim
//! (`paper/claims.yaml`), each comparing the paper's CLAIM with a REFERENCE that does not depend
//! on it.
//!
//! Every check reads the claimed side through [`Bench::claim`], so that the mutation test can
//! perturb it (by a relative 1e-3) and see the check fail: a check that cannot fail is no check.

pub mod air_film;
pub mod claims;
pub mod derivations;
pub mod dissipation;
pub mod frictionless;
pub mod kinematics;
pub mod motion;
pub mod oscillation;
pub mod slippage;
pub mod spin_down_reference;
pub mod steady;
mod steady_reference;

use crate::finding::{Finding, Worst};
use paper::Paper;
use physics::solve::{Method, Settings};
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

/// The equations whose checks take their claimed side from the paper's LaTeX: every checked
/// equation. Their checks are judged by the mutants of their printed text
/// (tests/mutation.rs); a check added with a Rust claim would stay off this list, and be judged
/// by the ±1e-3 sweep of tests/registry.rs, until it reads the LaTeX.
pub const FROM_LATEX: &[u32] = &[
    1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26,
    27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50,
    51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74,
    75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85,
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
    /// The integration method (the `--accuracy` preset's; DOP853 by default).
    pub method: Method,
}

impl Default for Bench<'static> {
    fn default() -> Self {
        Self {
            paper: built_in_paper(),
            perturbation: 0.0,
            rtol: 1e-12,
            method: Method::Dop853,
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
            // A tolerance tightened past the preset's is the high-order method's job.
            method: if finest < self.rtol {
                Method::Dop853
            } else {
                self.method
            },
            ..*self
        }
    }

    /// Solver settings for the integrations of a check: this bench's method and rtol, atol =
    /// 1e-2 rtol (the presets' rule).
    pub fn settings(&self) -> Settings {
        Settings {
            method: self.method,
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

/// Whether an equation FOLLOWS from its printed premises (their LaTeX as the reference), as
/// opposed to whether it is true (its [`Equation::check`]); see [`derivations`].
#[derive(Debug, Clone, Copy)]
pub struct Derivation {
    /// The printed number of the equation derived.
    pub number: u32,
    /// The check.
    pub check: fn(&Bench) -> Finding,
}

/// Every registered derivation check, by number.
pub fn derivations() -> Vec<Derivation> {
    derivations::DERIVATIONS.to_vec()
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
pub const UNCHECKABLE_EQUATIONS: &[(u32, &str)] = &[];

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
        "fit-c-quarter",
        "a fit to the authors' unpublished data; the constant the other sec. 11 numbers are computed from",
    ),
    (
        "nutation-disappears-below-0p1",
        "the equations give no threshold at 0.1 rad: the beat ratio there is about 0.1, not small",
    ),
    (
        "contact-speed-exceeds-sound",
        "names no number; its content (Omega unbounded) is checked by finite-time-singularity",
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
        dissipation::EQUATIONS,
        air_film::EQUATIONS,
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
    eq: &paper::Equation,
    e: &paper::Expr,
    bind: &paper::Bindings<f64>,
) -> f64 {
    use paper::expr::Op;
    use paper::{Expr, Value};
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
    bind: &paper::Bindings<f64>,
    scale: f64,
    w: &mut Worst,
    at: &dyn Fn() -> String,
) {
    for i in 0..b.paper.equation(n).relations().len() {
        printed_relation(b, n, i, bind, scale, w, at);
    }
}

/// [`printed_relations`] for relation `index` alone (0 for the first).
pub(crate) fn printed_relation(
    b: &Bench,
    n: u32,
    index: usize,
    bind: &paper::Bindings<f64>,
    scale: f64,
    w: &mut Worst,
    at: &dyn Fn() -> String,
) {
    use paper::Value;
    let eq = b.paper.equation(n);
    let Some(r) = eq.relations().get(index).copied() else {
        w.add(f64::NAN, 0.0, 1.0, || {
            format!("eq {n} has no relation {}", index + 1)
        });
        return;
    };
    if r.rel.is_inequality() {
        return;
    }
    let sides = eq
        .eval(r.lhs, bind)
        .and_then(|l| eq.eval(r.rhs, bind).map(|rr| (l, rr)));
    let name = || format!("eq {n} {}", r.name());
    // The sides' unit: that of a side of the chain that is one symbol (every side of a chain
    // of equalities has the same), this relation's own sides first.
    let chain = &eq.chains[r.chain].sides;
    let unit = [r.lhs, r.rhs]
        .into_iter()
        .chain(chain.iter())
        .find_map(|e| match e {
            paper::Expr::Sym(s) => eq.symbols.get(s).map(|i| i.unit.as_str()),
            _ => None,
        })
        .unwrap_or("");
    match sides {
        Ok((Value::Scalar(l), Value::Scalar(rr))) => w.add_in(b.claim(rr), l, scale, unit, || {
            format!("{}: {}", name(), at())
        }),
        Ok((l, rr)) => match (l.vector(), rr.vector()) {
            (Ok(l), Ok(rr)) => {
                for i in 0..3 {
                    w.add_in(b.claim(rr[i]), l[i], scale, unit, || {
                        format!("{}, lab component {}: {}", name(), ["x", "y", "z"][i], at())
                    });
                }
            }
            (Err(e), _) | (_, Err(e)) => w.add(f64::NAN, 0.0, 1.0, || format!("{}: {e}", name())),
        },
        Err(e) => w.add(f64::NAN, 0.0, 1.0, || {
            format!("{}: cannot be evaluated: {e}", name())
        }),
    }
}

/// The value of an equation's last printed side (its final form) with the symbols bound by
/// `bind`; NaN if it cannot be evaluated (a symbol the caller does not provide, say after an
/// author's edit), so that the check using it fails and says so.
pub(crate) fn last_side(eq: &paper::Equation, bind: &paper::Bindings<f64>) -> f64 {
    eq.chains[0]
        .sides
        .last()
        .and_then(|e| eq.scalar(e, bind).ok())
        .unwrap_or(f64::NAN)
}

pub(crate) use paper::printed::{solve_printed, solve_printed_with};

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
    quantity: &'static str,
    bind: &paper::Bindings<f64>,
    bracket: (f64, f64),
    probes: [f64; 2],
) -> PrintedThreshold {
    use paper::Value;
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

/// The square $x^2$ of `quantity` that makes the printed relation `rel` hold, for relations in
/// which it appears only squared (eqs 49-51, 54: $\varpi^2$), read from the printed text: the
/// residual (left - right) is evaluated at $x$ = 0, $X$ and $2X$; it must be $r_0 + c x^2$ (else NaN,
/// with the printed form not of that shape), and then $x^2 = -r_0/c$. This reads an unstable
/// motion's negative $\varpi^2$ too, which no real $\varpi$ could be bound to.
pub(crate) fn implied_square(
    eq: &paper::Equation,
    rel: &paper::Relation<'_>,
    quantity: &'static str,
    bind: &paper::Bindings<f64>,
) -> f64 {
    use paper::Value;
    let residual = |x: f64| -> f64 {
        let mut b = bind.clone();
        b.set(quantity, Value::Scalar(x));
        match (eq.scalar(rel.lhs, &b), eq.scalar(rel.rhs, &b)) {
            (Ok(l), Ok(r)) => l - r,
            _ => f64::NAN,
        }
    };
    // Probes at x = 0, X, 2X with X^2 of the size of the answer, so that the difference
    // r(X) - r(0) keeps its digits.
    // A first pass estimates c, the second probes where c X^2 is as large as r(0).
    let r0 = residual(0.0);
    let mut x = r0.abs().sqrt().max(1e-6);
    let mut answer = f64::NAN;
    for _ in 0..2 {
        let (r1, r2) = (residual(x), residual(2.0 * x));
        let c = (r1 - r0) / (x * x);
        let quadratic =
            (r2 - r0 - 4.0 * c * x * x).abs() <= 1e-9 * (r0.abs() + 4.0 * (c * x * x).abs());
        if !quadratic || c == 0.0 || !c.is_finite() {
            return f64::NAN;
        }
        answer = -r0 / c;
        x = (r0 / c).abs().sqrt().max(1e-300);
    }
    answer
}

/// The disk's constants under the paper's names: the mass $m$, gravity $g$, the radius $a$ and
/// the inertia factor $k$ of eq 18 ($I_{11} = 2kma^2$, $I_{22} = I_{33} = kma^2$).
pub(crate) fn disk_constants(d: &physics::disk::Disk) -> paper::Bindings<f64> {
    paper::Bindings::new()
        .scalar("m", d.m)
        .scalar("g", d.g)
        .scalar("a", d.a)
        .scalar("k", d.k)
}
