//! The order of a relation's sides: `b = a` and `a = b` are one claim, read the same way.
//!
//! The paper writes a definition or a result with the quantity it gives on the left
//! ($\omega_{10} = \frac{b}{a}\Omega_0$, $P = -\epsilon m a g \Omega^\beta$), and the checks take
//! that side as the quantity and the other as its claimed value. A chain written the other way
//! round, with the lone symbol at its end ($\frac{b}{a}\Omega_0 = \omega_{10}$), is read reversed
//! (sides and relations, an inequality's direction turned: $x < b$ is $b > x$), so that an
//! author's order cannot change a verdict, a cause or a number. A chain with a lone symbol at both
//! ends ($I_{22} = k m a^2 = I_{33}$) is ordered by the symbols' canonical text; one with a lone
//! symbol at neither end is read as written: its checks compare both sides as they are.
//!
//! A lone symbol here is a quantity's letter (Latin, Greek or a digit, with its accents,
//! subscript and derivative), not an upright word such as $\mathrm{constant}$, which names no
//! quantity to define.

use super::expr::{Chain, Expr};
use super::parse::GREEK;

/// True when `e` is a lone symbol that a relation can define.
fn defined(e: &Expr) -> bool {
    match e {
        Expr::Sym(s) => {
            s.base.chars().count() == 1
                || GREEK.contains(&s.base.as_str())
                || s.base.chars().all(|c| c.is_ascii_digit())
        }
        _ => false,
    }
}

/// True when the chain is to be read from its end (see the module's documentation).
fn reversed(c: &Chain) -> bool {
    let (Some(first), Some(last)) = (c.sides.first(), c.sides.last()) else {
        return false;
    };
    match (defined(first), defined(last)) {
        (false, true) => true,
        (true, true) => match (first, last) {
            (Expr::Sym(a), Expr::Sym(b)) => a.to_string() > b.to_string(),
            _ => false,
        },
        _ => false,
    }
}

/// The chain in the order the checks read it.
pub fn oriented(c: Chain) -> Chain {
    if !reversed(&c) {
        return c;
    }
    Chain {
        sides: c.sides.into_iter().rev().collect(),
        rels: c.rels.into_iter().rev().map(|r| r.reversed()).collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse::parse;

    fn read(latex: &str) -> Vec<Chain> {
        parse(latex).unwrap().0.into_iter().map(oriented).collect()
    }

    #[test]
    fn either_order_reads_the_same() {
        for (a, b) in [
            (
                r"\omega_{10} = \frac{b}{a} \Omega_0 = \Omega_0 c",
                r"\Omega_0 c = \frac{b}{a} \Omega_0 = \omega_{10}",
            ),
            (r"b > - \frac{a k}{2 k + 1}", r"- \frac{a k}{2 k + 1} < b"),
            (r"I_{22} = k m a^2 = I_{33}", r"I_{33} = k m a^2 = I_{22}"),
            (r"\mu \geq \frac{x}{y}", r"\frac{x}{y} \leq \mu"),
        ] {
            assert_eq!(read(a), read(b), "{a} vs {b}");
        }
        // Written as the checks read it, a chain is unchanged.
        let (printed, _) = parse(r"\omega_{10} = \frac{b}{a} \Omega_0").unwrap();
        assert_eq!(read(r"\omega_{10} = \frac{b}{a} \Omega_0"), printed);
        // An upright word at the end defines nothing.
        let (printed, _) = parse(r"k m a^2 \Omega = L_z = \mathrm{constant}").unwrap();
        assert_eq!(read(r"k m a^2 \Omega = L_z = \mathrm{constant}"), printed);
    }

    #[test]
    fn every_printed_equation_is_read_in_its_printed_order() {
        let p = crate::Paper::built_in().unwrap();
        let entries: Vec<crate::EquationEntry> =
            serde_yaml::from_str(crate::load::EQUATIONS).unwrap();
        for (e, entry) in p.equations.iter().zip(&entries) {
            let (printed, _) = parse(&entry.latex).unwrap();
            assert_eq!(e.chains, printed, "eq {}", e.number());
        }
    }
}
