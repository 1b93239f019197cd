//! The paper's printed forms read from its text, for whatever draws or uses them outside the
//! checks (the stability map, the frequency figure, the claims about eqs 54-56, the corrections'
//! downstream numbers): the right side of a printed relation evaluated with its symbols bound, a
//! printed relation solved for one of its symbols, eq 54 read as the quadratic in $b/a$ it is,
//! and the constants of the sec. 11 fit as paper/claims.yaml states them.
//!
//! Nothing here writes a paper formula: every number comes from the parsed LaTeX or the YAML, so
//! a `--paper DIR` with an edited eq 54 redraws the map from the edit.

use super::ClaimEntry;
use super::{Bindings, EvalError, Paper, PaperError, Relation};
use numerics::oscillation::try_bisect;

/// The experimental fit of sec. 11 as the paper prints it (claims `beta-two-fits-data` and
/// `fit-c-quarter`). Its disk is the uniform one, whose $k = 1/4$ the model computes
/// ([`physics::Disk::uniform`]); the paper's own $k$ is a claim it checks (`k-uniform-disk`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fit {
    /// $\beta$ of eq 79.
    pub beta: f64,
    /// $C^{-1/(\beta+2)}$ (s).
    pub c_inv_root: f64,
}

impl Fit {
    /// $C$ of eq 79 (units $s^{-(\beta+1)}$).
    pub fn c(&self) -> f64 {
        self.c_inv_root.powf(-(self.beta + 2.0))
    }
}

/// The claims whose `claimed_value` is the fit, in the order of [`Fit`]'s fields.
const FIT_CLAIMS: [&str; 2] = ["beta-two-fits-data", "fit-c-quarter"];

/// The fit read from the claims, or the sentence that says which entry lacks its number.
pub(super) fn read_fit(claims: &[ClaimEntry], file: &str) -> Result<Fit, PaperError> {
    let value = |id: &str| -> Result<f64, PaperError> {
        claims
            .iter()
            .find(|c| c.id == id)
            .and_then(|c| c.claimed_value)
            .filter(|x| x.is_finite() && *x > 0.0)
            .ok_or_else(|| PaperError::Structure {
                file: file.to_string(),
                message: format!(
                    "claim `{id}`, key `claimed_value`: a positive number is needed (sec. 11's \
                     fit is read from the claims {}); restore the entry or give its number",
                    FIT_CLAIMS.join(", ")
                ),
            })
    };
    Ok(Fit {
        beta: value(FIT_CLAIMS[0])?,
        c_inv_root: value(FIT_CLAIMS[1])?,
    })
}

impl Paper {
    /// The claimed side of eq `n`'s first printed relation with the symbols bound by `bind`:
    /// its right side, or its left side where only that one has every symbol bound (the
    /// relation written with its sides in the other order, `b = a`, gives what `a = b` gives).
    pub fn right_side(&self, n: u32, bind: &Bindings<f64>) -> Result<f64, EvalError> {
        let eq = self.equation(n);
        let rel = eq
            .relations()
            .into_iter()
            .next()
            .ok_or_else(|| EvalError::Unbound(format!("eq {n} prints no relation")))?;
        // A side with a symbol the caller does not bind is a probe: what it found without a
        // value is kept only when neither side gives the value.
        crate::unvalued::probing(
            || match (eq.scalar(rel.rhs, bind), eq.scalar(rel.lhs, bind)) {
                (Err(EvalError::Unbound(_)), Ok(left)) => Ok(left),
                (right, _) => right,
            },
            Result::is_err,
        )
    }

    /// Eq 54's right side, $(k+1)\varpi^2/\Omega_0^2$, at tilt $\alpha_0$ as a quadratic in
    /// $\rho = b/a$: `[A, B, C]` with value $A + B\rho + C\rho^2$, read from the printed form at
    /// $\rho = -1, 0, 1$ and confirmed at $\rho = 2$ (an edit that is no longer a quadratic in
    /// $b/a$ is an error, not a silently wrong map).
    pub fn eq54_quadratic(&self, k: f64, alpha0: f64) -> Result<[f64; 3], EvalError> {
        let q = |rho: f64| {
            let bind = Bindings::new()
                .scalar("k", k)
                .scalar("alpha_0", alpha0)
                .scalar("a", 1.0)
                .scalar("b", rho);
            self.right_side(54, &bind)
        };
        let (m, z, p, two) = (q(-1.0)?, q(0.0)?, q(1.0)?, q(2.0)?);
        let coef = [z, 0.5 * (p - m), 0.5 * (p + m) - z];
        let predicted = coef[0] + 2.0 * coef[1] + 4.0 * coef[2];
        let scale = [m, z, p, two].iter().map(|x| x.abs()).fold(1.0, f64::max);
        if (predicted - two).abs() > 1e-9 * scale {
            return Err(EvalError::Unbound(format!(
                "eq 54's right side is not a quadratic in b/a at k = {k}, alpha_0 = {alpha0}"
            )));
        }
        Ok(coef)
    }

    /// The tilt in (0, 90 deg) where eq 54's coefficient of $b/a$ (the paper's bracket) turns
    /// from positive to negative (rad), by bisection on its sign.
    pub fn eq54_bracket_zero(&self, k: f64) -> Result<f64, EvalError> {
        let negative = |al: f64| self.eq54_quadratic(k, al).map(|q| q[1] < 0.0);
        let (lo, hi) = (1e-9, std::f64::consts::FRAC_PI_2 - 1e-9);
        if negative(lo)? || !negative(hi)? {
            return Err(EvalError::Unbound(
                "eq 54's coefficient of b/a does not turn from positive to negative between 0 \
                 and 90 degrees"
                    .into(),
            ));
        }
        // To the last bit (the loop ends when the midpoint is an end).
        try_bisect(lo, hi, |_, _| false, |al| negative(al).ok())
            .map(|(lo, hi)| 0.5 * (lo + hi))
            .ok_or_else(|| {
                EvalError::Unbound("eq 54 cannot be evaluated near its bracket's zero".into())
            })
    }
}

/// The value of `quantity` that makes the printed relation `rel` of `eq` hold, the others bound
/// by `bind`: the root of (left side - right side) in `[lo, hi]` (see [`solve_residual`]).
/// `None` when the relation does not change sign there or cannot be evaluated. This is how a
/// printed relation is read as a definition of one of its symbols (the $t_0$ of eqs 77-79, the
/// $C$ of eq 79, $\varpi$ of eq 54) without writing that symbol's formula in Rust.
pub fn solve_printed(
    eq: &super::Equation,
    rel: &Relation<'_>,
    quantity: &'static str,
    bind: &Bindings<f64>,
    lo: f64,
    hi: f64,
) -> Option<f64> {
    use super::{Expr, Symbol, Value};
    // The relation's symbols looked up once, not at every evaluation: each occurrence, known by
    // its address in the relation (borrowed for the whole solve), with the value bound to its
    // quantity, or `None` for the unknown. The lookups by name were most of the report's time
    // in these solves (perf, 2026-11-24). Anything unresolved takes the general path, which
    // says nothing more but fails the same way.
    fn each<'a>(e: &'a Expr, f: &mut dyn FnMut(&'a Symbol)) {
        match e {
            Expr::Sym(s) => f(s),
            Expr::Neg(a) | Expr::Call(_, a) => each(a, f),
            Expr::Bin(_, a, b) => {
                each(a, f);
                each(b, f);
            }
            Expr::Num(_) | Expr::Pi => {}
        }
    }
    let mut slots: Vec<(*const Symbol, Option<Value<f64>>)> = Vec::new();
    let mut resolved = true;
    for side in [rel.lhs, rel.rhs] {
        each(side, &mut |s| {
            let value = eq.symbols.get(s).and_then(|info| {
                if info.quantity == quantity {
                    Some(None)
                } else {
                    bind.get(&info.quantity).map(Some)
                }
            });
            match value {
                Some(v) => slots.push((s as *const Symbol, v)),
                None => resolved = false,
            }
        });
    }
    if !resolved {
        let bind_at = |x: f64| {
            let mut b = bind.clone();
            b.set(quantity, Value::Scalar(x));
            b
        };
        return solve_printed_with(eq, rel, &bind_at, lo, hi);
    }
    let residual = |x: f64| -> Option<f64> {
        let lookup = |s: &Symbol| -> Result<Value<f64>, EvalError> {
            let slot = slots.iter().find(|(p, _)| std::ptr::eq(*p, s));
            Ok(slot.and_then(|(_, v)| *v).unwrap_or(Value::Scalar(x)))
        };
        let l = super::eval::eval(rel.lhs, &lookup).ok()?.scalar().ok()?;
        let r = super::eval::eval(rel.rhs, &lookup).ok()?.scalar().ok()?;
        let d = l - r;
        d.is_finite().then_some(d)
    };
    solve_residual(&residual, lo, hi)
}

/// [`solve_printed`] where the bindings depend on the unknown `x` in other ways too (eq 27's
/// $\omega_{10} = \rho\Omega_0$ with $\Omega_0$ the unknown).
pub fn solve_printed_with(
    eq: &super::Equation,
    rel: &Relation<'_>,
    bind_at: &dyn Fn(f64) -> Bindings<f64>,
    lo: f64,
    hi: f64,
) -> Option<f64> {
    let residual = |x: f64| -> Option<f64> {
        let b = bind_at(x);
        let l = eq.scalar(rel.lhs, &b).ok()?;
        let r = eq.scalar(rel.rhs, &b).ok()?;
        let d = l - r;
        d.is_finite().then_some(d)
    };
    solve_residual(&residual, lo, hi)
}

/// The root in `[lo, hi]` of a residual that changes sign there (`None` if it does not, or
/// cannot be evaluated at an end).
fn solve_residual(residual: &dyn Fn(f64) -> Option<f64>, lo: f64, hi: f64) -> Option<f64> {
    let (lo, hi) = (lo.min(hi), lo.max(hi));
    let (f_lo, f_hi) = (residual(lo)?, residual(hi)?);
    if f_lo == 0.0 {
        return Some(lo);
    }
    if f_lo.signum() == f_hi.signum() {
        return None;
    }
    // Algorithm 748 (Alefeld, Potra and Shi) from the `root1d` crate, to four ulps: the residual
    // is smooth in the unknown, and this takes some 10 evaluations where bisection to the last
    // bit of brackets as wide as eq 79's (1e-12 to 1e12 s) took about 90 (perf, 2026-11-24:
    // the solved printed relations were a fifth of the report's time). Should a probe inside
    // the bracket fail to evaluate (a square root of a negative number), bisection to the last
    // bit, which probes other points, decides.
    let fast = root1d::toms748(|x| residual(x).ok_or(()), lo, hi)
        .rtol(4.0 * f64::EPSILON)
        .atol(0.0)
        .root();
    if let Ok(x) = fast {
        return Some(x);
    }
    let side = |x: f64| residual(x).map(|f| f.signum() != f_lo.signum());
    try_bisect(lo, hi, |_, _| false, side).map(|(lo, hi)| 0.5 * (lo + hi))
}

/// $\varpi/\Omega_0$ that the printed eq `n` gives (its first relation solved for $\varpi$ with
/// $\Omega_0 = 3.7$, any value but 1 showing a dropped factor), the other symbols bound by
/// `bind`; `None` where the relation has no real root (an unstable motion of eq 54).
pub fn printed_ratio(paper: &Paper, n: u32, bind: &Bindings<f64>) -> Option<f64> {
    let omega0 = 3.7;
    let eq = paper.equation(n);
    let bind = bind.clone().scalar("Omega_0", omega0);
    let rel = eq.relations().into_iter().next()?;
    solve_printed(eq, &rel, "varpi", &bind, 0.0, 100.0 * omega0).map(|x| x / omega0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn paper() -> Paper {
        Paper::built_in().unwrap()
    }

    #[test]
    fn the_fit_is_read_from_the_claims() {
        let f = paper().fit;
        assert_eq!((f.beta, f.c_inv_root), (2.0, 0.0055));
        assert!((f.c() - 0.0055f64.powi(-4)).abs() < 1e-9 * f.c());
    }

    #[test]
    fn a_claims_file_without_the_fit_is_refused_naming_the_entry() {
        let built_in = super::super::Texts::BUILT_IN;
        let claims = built_in.claims.replace("id: fit-c-quarter", "id: x");
        let e = Paper::from_texts(
            super::super::PaperSource::BuiltIn,
            super::super::Texts {
                claims: &claims,
                ..built_in
            },
        )
        .unwrap_err()
        .to_string();
        assert!(
            e.contains("claims.yaml") && e.contains("`fit-c-quarter`"),
            "{e}"
        );
    }

    #[test]
    fn eq_54_reads_as_a_quadratic_and_an_edit_that_is_not_one_is_refused() {
        let p = paper();
        let (k, a0) = (0.25f64, 1.2f64);
        let [a, b, c] = p.eq54_quadratic(k, a0).unwrap();
        let (s, co) = a0.sin_cos();
        // The printed coefficients, by hand, for this test only.
        assert!((a - (3.0 * k * co * co + s * s)).abs() < 1e-12);
        assert!((b - ((6.0 * k + 1.0) * co - (2.0 * k + 1.0) * s * s / co)).abs() < 1e-12);
        assert!((c - 2.0 * (2.0 * k + 1.0)).abs() < 1e-12);
        let cubic = p
            .with_latex(
                54,
                r"\frac{\varpi^2}{\Omega_0^2} (k + 1) = 3 k + \frac{b^3}{a^3}",
            )
            .unwrap();
        assert!(cubic.eq54_quadratic(k, a0).is_err());
    }

    #[test]
    fn the_pre_resolved_solve_agrees_with_the_general_one_to_the_bit() {
        let p = paper();
        let eq = p.equation(79);
        let bind = Bindings::new()
            .scalar("dissipation", 1.2e-6)
            .scalar("beta", 2.0)
            .scalar("g", 9.8)
            .scalar("a", 0.0375)
            .scalar("k", 0.25)
            .scalar("Omega", 250.0)
            .scalar("t", 3.0)
            .scalar("C", 0.0055f64.powi(-4));
        let mut solved = 0;
        for rel in eq.relations() {
            let fast = solve_printed(eq, &rel, "t_0", &bind, 3.0 + 1e-12, 3.0 + 1e12);
            let bind_at = |x: f64| bind.clone().scalar("t_0", x);
            let general = solve_printed_with(eq, &rel, &bind_at, 3.0 + 1e-12, 3.0 + 1e12);
            // (The second relation, between two forms that both scale with t_0 - t, has no
            // root in t_0 at these values: None on both paths.)
            assert_eq!(
                fast.map(f64::to_bits),
                general.map(f64::to_bits),
                "{}",
                rel.name()
            );
            solved += usize::from(fast.is_some_and(|t0| t0 > 3.0));
        }
        assert!(solved >= 1);
        // A symbol left unbound gives no root, on either path.
        let rel = eq.relations()[1];
        let unbound = Bindings::new().scalar("Omega", 250.0).scalar("t", 3.0);
        assert_eq!(solve_printed(eq, &rel, "t_0", &unbound, 3.0, 1e6), None);
    }

    #[test]
    fn eq_55_solved_for_varpi_is_its_right_side() {
        let p = paper();
        let bind = Bindings::new().scalar("k", 0.25).scalar("alpha_0", 0.7);
        let r = printed_ratio(&p, 55, &bind).unwrap();
        assert!((r - p.right_side(55, &bind).unwrap()).abs() < 1e-12);
    }
}
