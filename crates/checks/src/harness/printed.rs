//! A printed relation's two sides compared at a point, the claimed side read through
//! [`Bench::claim`]: the residual of an equality, its terms' size, an equation's final form.

use super::Bench;
use crate::finding::Worst;

pub use paper::printed::{solve_printed, solve_printed_with};

/// The size of an expression's terms: the sum of the magnitudes of the terms of its top-level
/// sums (vectors by their norms), so that a relation whose sides nearly cancel (`... = 0`) is
/// measured against the size of what cancels.
pub fn term_scale(eq: &paper::Equation, e: &paper::Expr, bind: &paper::Bindings<f64>) -> f64 {
    use paper::expr::Op;
    use paper::{Expr, Value};
    match e {
        Expr::Bin(Op::Add | Op::Sub, a, b) => term_scale(eq, a, bind) + term_scale(eq, b, bind),
        Expr::Neg(a) => term_scale(eq, a, bind),
        // A term with a symbol this check does not bind only adds nothing to the scale: a probe,
        // whose symbols without a value are not the check's (paper::unvalued).
        _ => match paper::unvalued::probing(|| eq.eval(e, bind), |_| false) {
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
pub fn printed_relations(
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
pub fn printed_relation(
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
pub fn last_side(eq: &paper::Equation, bind: &paper::Bindings<f64>) -> f64 {
    eq.chains[0]
        .sides
        .last()
        .and_then(|e| eq.scalar(e, bind).ok())
        .unwrap_or(f64::NAN)
}

/// The square $x^2$ of `quantity` that makes the printed relation `rel` hold, for relations in
/// which it appears only squared (eqs 49-51, 54: $\varpi^2$), read from the printed text: the
/// residual (left - right) is evaluated at $x$ = 0, $X$ and $2X$; it must be $r_0 + c x^2$ (else NaN,
/// with the printed form not of that shape), and then $x^2 = -r_0/c$. This reads an unstable
/// motion's negative $\varpi^2$ too, which no real $\varpi$ could be bound to.
pub fn implied_square(
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
