//! Equivalent notations of a printed equation: its parsed relations written back as LaTeX in the
//! other ways authors write the same mathematics (`\cdot` or `\times` between scalar factors,
//! `\dfrac`, `/`, `\left( \right)`, `\bigl( \bigr)`, thin spaces, redundant braces, factors and
//! terms in another order, a full stop at the end), and the printed text itself retouched
//! ([`retouch`]). Read back by [`super::parse::parse`], each gives the relations it was written
//! from; `tests/notation.rs` requires every check to give the same verdicts and numbers on them.
//!
//! Written so that reading back gives the same tree node for node: a product or sum keeps its
//! grouping (`a b c` is $(ab)c$; a product grouped the other way is written with a group), so
//! that the numbers are the same to the bit. Reordering swaps the two operands of every product
//! and sum ($ab \to ba$, $a - b \to -b + a$), which floating-point arithmetic also evaluates to
//! the same bits (it is commutative, though not associative).

use super::expr::{Accent, Chain, Expr, Func, Op, Symbol};
use super::parse::GREEK;

/// How a quotient is written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quotient {
    /// `\frac{a}{b}` with this command (`frac`, `dfrac`, `tfrac`).
    Frac(&'static str),
    /// `{a} / {b}`.
    Slash,
}

/// One way of writing the paper's mathematics.
#[derive(Debug, Clone, Copy)]
pub struct Notation {
    /// A short name for messages.
    pub name: &'static str,
    /// Written between two scalar factors: `" "` (juxtaposition), `" \cdot "` or `" \times "`.
    pub product: &'static str,
    /// How a quotient is written.
    pub quotient: Quotient,
    /// Opens and closes a group that the grammar needs (and a function's argument).
    pub group: (&'static str, &'static str),
    /// Space on each side of an operator, a relation and between factors (`\,`, `~`).
    pub space: &'static str,
    /// Every factor, term and side in braces of its own.
    pub braces: bool,
    /// The operands of every product and sum swapped.
    pub reorder: bool,
    /// Between two chains of relations.
    pub separator: &'static str,
    /// After the last relation.
    pub end: &'static str,
}

/// The notations generated for every equation (each differs from the paper's own in several
/// ways at once).
pub const NOTATIONS: [Notation; 5] = [
    Notation {
        name: "cdot, dfrac, thin spaces, full stop",
        product: r" \cdot ",
        quotient: Quotient::Frac("dfrac"),
        group: ("(", ")"),
        space: r"\,",
        braces: false,
        reorder: false,
        separator: r", \qquad ",
        end: ".",
    },
    Notation {
        name: "times, tfrac, left-right, tildes, comma",
        product: r" \times ",
        quotient: Quotient::Frac("tfrac"),
        group: (r"\left(", r"\right)"),
        space: "~",
        braces: false,
        reorder: false,
        separator: r"; \quad ",
        end: ",",
    },
    Notation {
        name: "slash, bigl-bigr, thick spaces, semicolon",
        product: " ",
        quotient: Quotient::Slash,
        group: (r"\bigl(", r"\bigr)"),
        space: r"\;",
        braces: false,
        reorder: false,
        separator: r", \quad ",
        end: ";",
    },
    Notation {
        name: "redundant braces, Big, control spaces",
        product: " ",
        quotient: Quotient::Frac("frac"),
        group: (r"\Big(", r"\Big)"),
        space: r"\ ",
        braces: true,
        reorder: false,
        separator: r", \qquad ",
        end: "",
    },
    Notation {
        name: "factors and terms reordered, cdot, negative thin spaces",
        product: r" \cdot ",
        quotient: Quotient::Frac("frac"),
        group: ("[", "]"),
        space: r"\!",
        braces: false,
        reorder: true,
        separator: r", \qquad ",
        end: ".",
    },
];

/// Binding strengths, loosest first: what an operand must reach to be written without a group.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Binding {
    Sum,
    Quotient,
    Cross,
    Product,
    Factor,
    Atom,
}

/// The chains written in notation `n`.
pub fn write(chains: &[Chain], n: &Notation) -> String {
    let w = Writer(n);
    let chains: Vec<String> = chains
        .iter()
        .map(|c| {
            let mut s = w.side(&c.sides[0]);
            for (rel, side) in c.rels.iter().zip(&c.sides[1..]) {
                s += &format!(" {sp} {} {sp} {}", rel.latex(), w.side(side), sp = n.space);
            }
            s
        })
        .collect();
    format!("{}{}", chains.join(n.separator), n.end)
}

/// The paper's own text in other notation, without reparsing it: `\frac` as `\dfrac`, every
/// parenthesis as `\left(` `\right)`, a thin space around `=`, and a full stop at the end.
pub fn retouch(latex: &str) -> String {
    let mut out = String::with_capacity(latex.len() * 2);
    let mut rest = latex;
    while let Some(c) = rest.chars().next() {
        let skip = [
            r"\left(", r"\right)", r"\left[", r"\right]", r"\left|", r"\right|",
        ]
        .into_iter()
        .find(|p| rest.starts_with(p));
        if let Some(p) = skip {
            out.push_str(p);
            rest = &rest[p.len()..];
            continue;
        }
        if rest.starts_with(r"\frac") {
            out.push_str(r"\dfrac");
            rest = &rest[r"\frac".len()..];
            continue;
        }
        match c {
            '(' => out.push_str(r"\left("),
            ')' => out.push_str(r"\right)"),
            '=' => out.push_str(r"\,=\,"),
            _ => out.push(c),
        }
        rest = &rest[c.len_utf8()..];
    }
    out.push('.');
    out
}

struct Writer<'n>(&'n Notation);

impl Writer<'_> {
    fn side(&self, e: &Expr) -> String {
        let (s, _) = self.expr(e);
        if self.0.braces {
            format!("{{{s}}}")
        } else {
            s
        }
    }

    /// `e` written so that it reads back at binding strength `level` or tighter.
    fn at(&self, e: &Expr, level: Binding) -> String {
        let (s, l) = self.expr(e);
        if l >= level {
            s
        } else {
            format!("{}{s}{}", self.0.group.0, self.0.group.1)
        }
    }

    fn expr(&self, e: &Expr) -> (String, Binding) {
        let (s, l) = self.node(e);
        if self.0.braces {
            (format!("{{{s}}}"), Binding::Atom)
        } else {
            (s, l)
        }
    }

    fn node(&self, e: &Expr) -> (String, Binding) {
        let n = self.0;
        let sp = n.space;
        match e {
            Expr::Num(x) => (format!("{x}"), Binding::Atom),
            Expr::Pi => (r"\pi".into(), Binding::Atom),
            Expr::Sym(s) => (self.symbol(s), Binding::Atom),
            Expr::Neg(a) => (
                format!("- {sp} {}", self.at(a, Binding::Quotient)),
                Binding::Sum,
            ),
            Expr::Call(f, a) => {
                let arg = self.expr(a).0;
                let s = match f {
                    Func::Sqrt => format!(r"\sqrt{{{arg}}}"),
                    Func::Abs => format!(r"\left| {arg} \right|"),
                    f => {
                        // A function's argument is in parentheses (or `\left(`), never braces.
                        let (open, close) = match n.group {
                            ("{", _) | ("[", _) => ("(", ")"),
                            g => g,
                        };
                        format!("{}{open}{arg}{close}", f.latex())
                    }
                };
                (s, Binding::Factor)
            }
            Expr::Bin(op, a, b) => self.binary(*op, a, b),
        }
    }

    fn binary(&self, op: Op, a: &Expr, b: &Expr) -> (String, Binding) {
        let n = self.0;
        let sp = n.space;
        match op {
            Op::Add | Op::Sub if n.reorder => {
                let first = match op {
                    Op::Add => self.at(b, Binding::Quotient),
                    _ => format!("- {sp} {}", self.at(b, Binding::Quotient)),
                };
                (
                    format!("{first} {sp} + {sp} {}", self.at(a, Binding::Quotient)),
                    Binding::Sum,
                )
            }
            Op::Add | Op::Sub => {
                let sign = if op == Op::Add { "+" } else { "-" };
                let (l, _) = self.expr(a);
                (
                    format!("{l} {sp} {sign} {sp} {}", self.at(b, Binding::Quotient)),
                    Binding::Sum,
                )
            }
            Op::Div => match n.quotient {
                Quotient::Frac(cmd) => (
                    format!(r"\{cmd}{{{}}}{{{}}}", self.expr(a).0, self.expr(b).0),
                    Binding::Factor,
                ),
                Quotient::Slash => (
                    format!(
                        "{} {sp} / {sp} {}",
                        self.at(a, Binding::Quotient),
                        self.at(b, Binding::Cross)
                    ),
                    Binding::Quotient,
                ),
            },
            Op::Dot | Op::Cross => {
                let cmd = if op == Op::Dot { r"\cdot" } else { r"\times" };
                (
                    format!(
                        "{} {sp} {cmd} {sp} {}",
                        self.at(a, Binding::Cross),
                        self.at(b, Binding::Product)
                    ),
                    Binding::Cross,
                )
            }
            Op::Mul => {
                let (a, b) = if n.reorder { (b, a) } else { (a, b) };
                if n.product != " " && a.is_scalar() && b.is_scalar() {
                    (
                        format!(
                            "{} {sp}{}{sp} {}",
                            self.at(a, Binding::Cross),
                            n.product,
                            self.at(b, Binding::Product)
                        ),
                        Binding::Cross,
                    )
                } else {
                    (
                        format!(
                            "{} {sp} {}",
                            self.at(a, Binding::Product),
                            self.at(b, Binding::Factor)
                        ),
                        Binding::Product,
                    )
                }
            }
            Op::Pow => (
                format!("{}^{{{}}}", self.at(a, Binding::Atom), self.expr(b).0),
                Binding::Factor,
            ),
        }
    }

    /// A symbol as the paper writes it: `\dot{\alpha}`, `\hat{\mathbf{1}}`, `\omega_{10}`,
    /// `\mathbf{v}_{\mathrm{cm}}`, `\frac{d^2 \mathbf{r}_{\mathrm{cm}}}{dt^2}`.
    fn symbol(&self, s: &Symbol) -> String {
        let mut x = if GREEK.contains(&s.base.as_str()) {
            format!(r"\{}", s.base)
        } else if s.base.chars().count() == 1 || s.base.chars().all(|c| c.is_ascii_digit()) {
            s.base.clone()
        } else {
            format!(r"\mathrm{{{}}}", s.base)
        };
        if s.bold {
            x = format!(r"\mathbf{{{x}}}");
        }
        x = match s.accent {
            Accent::None => x,
            Accent::Dot => format!(r"\dot{{{x}}}"),
            Accent::Ddot => format!(r"\ddot{{{x}}}"),
            Accent::Hat => format!(r"\hat{{{x}}}"),
            Accent::Vec => format!(r"\vec{{{x}}}"),
        };
        if !s.sub.is_empty() {
            if s.sub.chars().all(|c| c.is_ascii_alphabetic()) && s.sub.len() > 1 {
                x = format!(r"{x}_{{\mathrm{{{}}}}}", s.sub);
            } else {
                x = format!("{x}_{{{}}}", s.sub);
            }
        }
        let frac = match self.0.quotient {
            Quotient::Frac(cmd) => cmd,
            Quotient::Slash => "frac",
        };
        match s.derivative {
            0 => x,
            1 => format!(r"\{frac}{{d {x}}}{{dt}}"),
            k => format!(r"\{frac}{{d^{k} {x}}}{{dt^{k}}}"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse::parse;

    #[test]
    fn every_notation_reads_back_as_the_same_relations() {
        for latex in [
            r"\frac{5 g / \epsilon (\beta + 2) a k}{t_0 - t} = - a \dot{\alpha} \hat{\mathbf{1}} + a \omega_1 \hat{\mathbf{2}}",
            r"I_{11} = 2 k m a^2, \qquad I_{22} = k m a^2 = I_{33}",
            r"\Omega_0^2 = \frac{g}{a k \sin\alpha_0} \cos^2\alpha_0 - \left| b \right|",
            r"\frac{d^2 \mathbf{r}_{\mathrm{cm}}}{dt^2} \times \hat{\mathbf{3}} = g \hat{\mathbf{3}} \times \hat{\mathbf{z}}",
        ] {
            let (chains, _) = parse(latex).unwrap();
            for n in &NOTATIONS {
                let text = write(&chains, n);
                assert_ne!(text, latex);
                let (back, _) =
                    parse(&text).unwrap_or_else(|e| panic!("{}: {text}: {e:?}", n.name));
                if n.reorder {
                    assert_eq!(back.len(), chains.len(), "{text}");
                } else {
                    assert_eq!(back, chains, "{}: {text}", n.name);
                }
            }
            let (back, _) = parse(&retouch(latex)).unwrap();
            assert_eq!(back, chains, "{}", retouch(latex));
        }
    }

    #[test]
    fn a_reordered_product_is_the_same_product_swapped() {
        let (chains, _) = parse(r"x = a b - c").unwrap();
        let text = write(&chains, &NOTATIONS[4]);
        let (back, _) = parse(&text).unwrap();
        let (want, _) = parse(r"x = - c + b a").unwrap();
        assert_eq!(back, want);
    }
}
