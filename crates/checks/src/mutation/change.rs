//! What a mutant changes, read off the difference between its chains and the printed ones: a
//! constant, an exponent, a sign, a relation, or the form (a term or factor dropped, a function
//! swapped). An order-of-magnitude estimate's reading fixes its exponent exactly and lets its
//! constant move within a factor, so only a mutant that moves a constant can be "within the
//! reading"; one that moves an exponent and still reads as the estimate is a survivor.

use paper::{Chain, Expr};
use std::fmt;

/// The class of a mutant's change.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Change {
    /// A number outside every exponent: the law's constant.
    Constant,
    /// Anything inside the exponent of a power: the law's scaling.
    Exponent,
    /// A sign: a minus dropped, `+` for `-` or `-` for `+`.
    Sign,
    /// A relation reversed.
    Relation,
    /// A term or factor dropped, a function or the order of a product changed.
    Form,
}

impl fmt::Display for Change {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Change::Constant => "a constant",
            Change::Exponent => "an exponent",
            Change::Sign => "a sign",
            Change::Relation => "a relation",
            Change::Form => "the form",
        })
    }
}

/// The class of the first difference between `printed` and `mutant` (a mutant changes one
/// node); [`Change::Form`] when the chains differ in shape.
pub(crate) fn change(printed: &[Chain], mutant: &[Chain]) -> Change {
    for (p, m) in printed.iter().zip(mutant) {
        if p.rels != m.rels {
            return Change::Relation;
        }
        for (a, b) in p.sides.iter().zip(&m.sides) {
            if let Some(c) = differs(a, b, false) {
                return c;
            }
        }
    }
    Change::Form
}

/// The class of the first node where `a` and `b` differ, `None` where they are equal;
/// `in_exponent` once the walk has entered the exponent of a power.
fn differs(a: &Expr, b: &Expr, in_exponent: bool) -> Option<Change> {
    use paper::expr::Op;
    if a == b {
        return None;
    }
    match (a, b) {
        (Expr::Bin(o, a1, a2), Expr::Bin(p, b1, b2)) if o == p => {
            differs(a1, b1, in_exponent).or_else(|| differs(a2, b2, in_exponent || *o == Op::Pow))
        }
        (Expr::Neg(x), Expr::Neg(y)) => differs(x, y, in_exponent),
        (Expr::Call(f, x), Expr::Call(g, y)) if f == g => differs(x, y, in_exponent),
        _ if in_exponent => Some(Change::Exponent),
        (Expr::Num(_), Expr::Num(_)) => Some(Change::Constant),
        (Expr::Neg(x), y) | (y, Expr::Neg(x)) if **x == *y => Some(Change::Sign),
        (Expr::Bin(o, a1, a2), Expr::Bin(p, b1, b2))
            if matches!((o, p), (Op::Add, Op::Sub) | (Op::Sub, Op::Add))
                && a1 == b1
                && a2 == b2 =>
        {
            Some(Change::Sign)
        }
        _ => Some(Change::Form),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use paper::mutate::mutants;
    use paper::parse::parse;

    /// Eq 82's mutants: the 2 of 2 pi moves a constant; the 1 and the 3 of the exponent 1/3
    /// move the exponent; `t_0 - t` made `t_0 + t` moves a sign.
    #[test]
    fn eq_82s_mutants_are_classed_by_what_they_change() {
        let (chains, _) =
            parse(r"\alpha = \left( \frac{2 \pi \eta a}{m} (t_0 - t) \right)^{1/3}").unwrap();
        let classed: Vec<(String, Change)> = mutants(&chains)
            .into_iter()
            .map(|m| (m.change.clone(), change(&chains, &m.chains)))
            .collect();
        let class_of = |what: &str| {
            classed
                .iter()
                .find(|(c, _)| c.starts_with(what))
                .map(|(_, k)| *k)
        };
        assert_eq!(class_of("the constant 2 -> 3"), Some(Change::Constant));
        assert_eq!(class_of("the constant 1 -> 1.001"), Some(Change::Exponent));
        assert_eq!(class_of("the constant 3 -> 3.00"), Some(Change::Exponent));
        assert_eq!(class_of("Sub -> Add"), Some(Change::Sign));
        assert_eq!(class_of("the term $t$ dropped"), Some(Change::Form));
    }

    #[test]
    fn a_reversed_inequality_and_a_dropped_minus_are_told_apart() {
        let (chains, _) = parse(r"b > - \frac{a k \cos\alpha_0}{2k + 1}").unwrap();
        let ms = mutants(&chains);
        let of = |what: &str| {
            ms.iter()
                .find(|m| m.change.contains(what))
                .map(|m| change(&chains, &m.chains))
        };
        assert_eq!(of("reversed"), Some(Change::Relation));
        assert_eq!(of("sign of"), Some(Change::Sign));
        assert_eq!(of(r"$\cos$ -> $\sin$"), Some(Change::Form));
    }
}
