//! Mutants of a printed equation, made from its parsed LaTeX: the errors a transcription or a
//! derivation could make. A check that cannot tell a mutant from the printed equation is weak,
//! unless the mutant is mathematically equivalent or lies outside the checked domain.

use super::expr::{Chain, Expr, Func, Op};

/// One mutant: what was changed, in words, and the mutated chains.
#[derive(Debug, Clone)]
pub struct Mutant {
    /// What was changed (e.g. "the constant 2 -> 2.002 in side 1 of relation 1").
    pub change: String,
    /// The equation's chains with the change.
    pub chains: Vec<Chain>,
}

/// Every mutant of an equation: each numeric constant scaled by 1 + 1e-3 and increased by 1,
/// each sign flipped (a minus dropped, a sum made a difference and back), each sine swapped
/// with a cosine (and tangent with cotangent), each term of a sum and each factor of a product
/// dropped, the two factors of each cross product swapped (the handedness error), each integer
/// power raised by one, each inequality reversed.
pub fn mutants(chains: &[Chain]) -> Vec<Mutant> {
    let mut out = Vec::new();
    for (ci, chain) in chains.iter().enumerate() {
        for (si, side) in chain.sides.iter().enumerate() {
            let n = count(side);
            for node in 0..n {
                for (what, replacement) in node_mutants(side, node) {
                    let mut chains = chains.to_vec();
                    chains[ci].sides[si] = replacement;
                    out.push(Mutant {
                        change: format!("{what} in side {} of chain {}", si + 1, ci + 1),
                        chains,
                    });
                }
            }
        }
        for (ri, rel) in chain.rels.iter().enumerate() {
            if rel.is_inequality() {
                let mut chains = chains.to_vec();
                chains[ci].rels[ri] = rel.reversed();
                out.push(Mutant {
                    change: format!(
                        "{} reversed to {} in chain {}",
                        rel.latex(),
                        rel.reversed().latex(),
                        ci + 1
                    ),
                    chains,
                });
            }
        }
    }
    out
}

fn count(e: &Expr) -> usize {
    1 + match e {
        Expr::Num(_) | Expr::Pi | Expr::Sym(_) => 0,
        Expr::Neg(a) | Expr::Call(_, a) => count(a),
        Expr::Bin(_, a, b) => count(a) + count(b),
    }
}

/// The mutants of node `target` (pre-order index) of `e`.
fn node_mutants(e: &Expr, target: usize) -> Vec<(String, Expr)> {
    let mut out = Vec::new();
    let node = nth(e, target);
    let mut push = |what: String, replacement: Expr| {
        out.push((what, replace(e, target, &replacement)));
    };
    match node {
        Expr::Num(x) if *x == 0.0 => push("the constant 0 -> 1".into(), Expr::Num(1.0)),
        Expr::Num(x) => {
            push(
                format!("the constant {x} -> {}", x * (1.0 + 1e-3)),
                Expr::Num(x * (1.0 + 1e-3)),
            );
            push(
                format!("the constant {x} -> {}", x + 1.0),
                Expr::Num(x + 1.0),
            );
        }
        Expr::Neg(a) => push(
            format!("the sign of ${}$ dropped", Expr::Neg(a.clone()).to_tex()),
            (**a).clone(),
        ),
        Expr::Call(f, a) => {
            let swapped = match f {
                Func::Sin => Some(Func::Cos),
                Func::Cos => Some(Func::Sin),
                Func::Tan => Some(Func::Cot),
                Func::Cot => Some(Func::Tan),
                _ => None,
            };
            if let Some(g) = swapped {
                push(
                    format!("${}$ -> ${}$", f.latex(), g.latex()),
                    Expr::Call(g, a.clone()),
                );
            }
        }
        Expr::Bin(op @ (Op::Add | Op::Sub), a, b) => {
            let flipped = if *op == Op::Add { Op::Sub } else { Op::Add };
            push(
                format!("{:?} -> {:?} before ${}$", op, flipped, b.to_tex()),
                Expr::Bin(flipped, a.clone(), b.clone()),
            );
            push(format!("the term ${}$ dropped", b.to_tex()), (**a).clone());
            push(format!("the term ${}$ dropped", a.to_tex()), (**b).clone());
        }
        Expr::Bin(Op::Mul, a, b) => {
            push(
                format!("the factor ${}$ dropped", b.to_tex()),
                (**a).clone(),
            );
            push(
                format!("the factor ${}$ dropped", a.to_tex()),
                (**b).clone(),
            );
        }
        Expr::Bin(Op::Cross, a, b) => push(
            format!("${}$ and ${}$ swapped", a.to_tex(), b.to_tex()),
            Expr::Bin(Op::Cross, b.clone(), a.clone()),
        ),
        Expr::Bin(Op::Pow, a, b) => {
            if let Expr::Num(n) = **b {
                push(
                    format!("the power {n} -> {}", n + 1.0),
                    Expr::Bin(Op::Pow, a.clone(), Box::new(Expr::Num(n + 1.0))),
                );
            }
        }
        _ => {}
    }
    out
}

fn nth(e: &Expr, mut n: usize) -> &Expr {
    fn walk<'a>(e: &'a Expr, n: &mut usize) -> Option<&'a Expr> {
        if *n == 0 {
            return Some(e);
        }
        *n -= 1;
        match e {
            Expr::Num(_) | Expr::Pi | Expr::Sym(_) => None,
            Expr::Neg(a) | Expr::Call(_, a) => walk(a, n),
            Expr::Bin(_, a, b) => walk(a, n).or_else(|| walk(b, n)),
        }
    }
    walk(e, &mut n).unwrap_or(e)
}

fn replace(e: &Expr, target: usize, with: &Expr) -> Expr {
    fn walk(e: &Expr, n: &mut usize, with: &Expr) -> Expr {
        if *n == 0 {
            *n = usize::MAX;
            return with.clone();
        }
        if *n != usize::MAX {
            *n -= 1;
        }
        match e {
            Expr::Num(_) | Expr::Pi | Expr::Sym(_) => e.clone(),
            Expr::Neg(a) => Expr::Neg(Box::new(walk(a, n, with))),
            Expr::Call(f, a) => Expr::Call(*f, Box::new(walk(a, n, with))),
            Expr::Bin(op, a, b) => {
                let a = walk(a, n, with);
                Expr::Bin(*op, Box::new(a), Box::new(walk(b, n, with)))
            }
        }
    }
    walk(e, &mut { target }, with)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse::parse;

    #[test]
    fn mutants_of_a_small_relation() {
        let (chains, _) = parse(r"b > - \frac{a k \cos\alpha_0}{2k + 1}").unwrap();
        let m = mutants(&chains);
        let changes: Vec<&str> = m.iter().map(|m| m.change.as_str()).collect();
        assert!(
            changes.iter().any(|c| c.starts_with("> reversed")),
            "{changes:?}"
        );
        assert!(
            changes.iter().any(|c| c.contains(r"$\cos$ -> $\sin$")),
            "{changes:?}"
        );
        assert!(changes.iter().any(|c| c.contains("sign of")), "{changes:?}");
        assert!(
            changes.iter().any(|c| c.contains("constant 2 -> 3")),
            "{changes:?}"
        );
        // Every mutant differs from the printed chain.
        assert!(m.iter().all(|m| m.chains != chains));
    }

    #[test]
    fn a_cross_product_has_its_factors_swapped() {
        let (chains, _) =
            parse(r"\mathbf{N}_{\mathrm{cm}} = \mathbf{a} \times \mathbf{F}").unwrap();
        let m = mutants(&chains);
        assert_eq!(
            m.len(),
            1,
            "{:?}",
            m.iter().map(|m| &m.change).collect::<Vec<_>>()
        );
        assert!(m[0].change.contains("swapped"), "{}", m[0].change);
        let Expr::Bin(Op::Cross, a, f) = &chains[0].sides[1] else {
            panic!("parsed as {:?}", chains[0].sides[1]);
        };
        assert_eq!(
            m[0].chains[0].sides[1],
            Expr::Bin(Op::Cross, f.clone(), a.clone())
        );
    }
}
