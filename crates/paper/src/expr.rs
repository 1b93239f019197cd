//! The expression tree of a printed relation: what the paper's LaTeX says, as data.
//!
//! A printed equation is one or more [`Chain`]s (eq 18 prints two, separated by a comma); a chain
//! is a run of sides joined by relations, `a = b \approx c`, each adjacent pair a claim of its own.

use serde::Serialize;
use std::fmt;

/// A symbol of the paper, in canonical form: an accent or derivative, a base and a subscript.
///
/// `\dot{\alpha}` is `{accent: Dot, base: "alpha"}`, `\omega^2_{10}` is the symbol `omega_10`
/// squared, `\hat{\mathbf{1}}` is `{accent: Hat, bold, base: "1"}`, `\frac{d\hat{\mathbf{1}}}{dt}`
/// is the same with `derivative: 1`.
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
pub struct Symbol {
    /// Time derivatives written as `\frac{d X}{dt}` (1) or `\frac{d^2 X}{dt^2}` (2).
    pub derivative: u8,
    /// The accent on the base.
    pub accent: Accent,
    /// Written bold (`\mathbf`).
    pub bold: bool,
    /// The base: a Greek name without backslash (`alpha`), a Latin letter, a digit, or a word
    /// (`constant` from `\mathrm{constant}`).
    pub base: String,
    /// The subscript as text (`0`, `10`, `cm`, `rel`, `123`), empty if none.
    pub sub: String,
}

/// Accents a symbol can carry.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
pub enum Accent {
    /// None.
    None,
    /// `\dot`: the first time derivative.
    Dot,
    /// `\ddot`: the second time derivative.
    Ddot,
    /// `\hat`: a unit vector.
    Hat,
    /// `\vec`: a vector.
    Vec,
}

impl Symbol {
    /// The symbol in plain words (`alpha_dot`, `Omega_0`, `3-hat`, `dL_cm/dt`, `omega_rel`),
    /// for [`Expr::to_plain`]; the canonical text of [`fmt::Display`] (`hat:bf:3`) is for symbol
    /// tables, and [`Symbol::tex`] is its LaTeX.
    pub fn plain(&self) -> String {
        let mut x = self.base.clone();
        if !self.sub.is_empty() {
            x = format!("{x}_{}", self.sub);
        }
        x = match self.accent {
            Accent::None => x,
            Accent::Dot => format!("{x}_dot"),
            Accent::Ddot => format!("{x}_ddot"),
            Accent::Hat => format!("{x}-hat"),
            Accent::Vec => format!("vec {x}"),
        };
        match self.derivative {
            0 => x,
            1 => format!("d{x}/dt"),
            n => format!("d{n}{x}/dt{n}"),
        }
    }
}

impl Symbol {
    /// A vector (or tensor) by its notation: bold, with a hat or with an arrow, as the paper
    /// writes every vector and tensor it uses; otherwise a scalar.
    pub fn is_vector(&self) -> bool {
        self.bold || matches!(self.accent, Accent::Hat | Accent::Vec)
    }
}

impl fmt::Display for Symbol {
    /// The canonical text of a symbol, as written in symbol tables: `alpha`, `dot:alpha`,
    /// `Omega_0`, `omega_10`, `bf:v_cm`, `hat:bf:1`, `vec:omega_123`, `d/dt:bf:r_cm`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.derivative {
            0 => {}
            1 => f.write_str("d/dt:")?,
            n => write!(f, "d{n}/dt{n}:")?,
        }
        match self.accent {
            Accent::None => {}
            Accent::Dot => f.write_str("dot:")?,
            Accent::Ddot => f.write_str("ddot:")?,
            Accent::Hat => f.write_str("hat:")?,
            Accent::Vec => f.write_str("vec:")?,
        }
        if self.bold {
            f.write_str("bf:")?;
        }
        f.write_str(&self.base)?;
        if !self.sub.is_empty() {
            write!(f, "_{}", self.sub)?;
        }
        Ok(())
    }
}

/// An elementary function of the paper.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Func {
    /// `\sin`
    Sin,
    /// `\cos`
    Cos,
    /// `\tan`
    Tan,
    /// `\cot`
    Cot,
    /// `\sqrt`
    Sqrt,
    /// `\left| x \right|`
    Abs,
}

impl Func {
    /// The LaTeX command (for [`Expr::to_latex`]).
    pub fn latex(self) -> &'static str {
        match self {
            Func::Sin => r"\sin",
            Func::Cos => r"\cos",
            Func::Tan => r"\tan",
            Func::Cot => r"\cot",
            Func::Sqrt => r"\sqrt",
            Func::Abs => r"\abs",
        }
    }
}

/// A binary operation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Op {
    /// `+`
    Add,
    /// `-`
    Sub,
    /// Juxtaposition (a scalar times a scalar or a vector).
    Mul,
    /// `/` or `\frac`.
    Div,
    /// `\cdot`: a scalar product, or a tensor contracted with a vector.
    Dot,
    /// `\times`: the vector product.
    Cross,
    /// A power `x^{y}`.
    Pow,
}

/// An expression.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum Expr {
    /// A number as printed.
    Num(f64),
    /// $\pi$.
    Pi,
    /// A symbol, bound by the check to a quantity.
    Sym(Symbol),
    /// A unary minus.
    Neg(Box<Expr>),
    /// A binary operation.
    Bin(Op, Box<Expr>, Box<Expr>),
    /// A function applied to its argument.
    Call(Func, Box<Expr>),
}

impl Expr {
    /// A binary node.
    pub fn bin(op: Op, a: Expr, b: Expr) -> Expr {
        Expr::Bin(op, Box::new(a), Box::new(b))
    }

    /// True when the expression is a scalar by its notation ([`Symbol::is_vector`]): numbers,
    /// functions, powers, and sums, products and quotients of scalars. A scalar or vector
    /// product of two vectors, which may be either, is not counted.
    pub fn is_scalar(&self) -> bool {
        match self {
            Expr::Num(_) | Expr::Pi | Expr::Call(..) | Expr::Bin(Op::Pow, ..) => true,
            Expr::Sym(s) => !s.is_vector(),
            Expr::Neg(a) | Expr::Bin(Op::Div, a, _) => a.is_scalar(),
            Expr::Bin(Op::Add | Op::Sub | Op::Mul, a, b) => a.is_scalar() && b.is_scalar(),
            Expr::Bin(Op::Dot | Op::Cross, ..) => false,
        }
    }

    /// True when the expression is a vector (or tensor) by its notation: a vector symbol, or a
    /// sum, product, quotient or vector product with one. A scalar product, which may be
    /// either, is not counted.
    pub fn is_vector(&self) -> bool {
        match self {
            Expr::Num(_) | Expr::Pi | Expr::Call(..) => false,
            Expr::Bin(Op::Pow | Op::Dot, ..) => false,
            Expr::Bin(Op::Cross, ..) => true,
            Expr::Sym(s) => s.is_vector(),
            Expr::Neg(a) | Expr::Bin(Op::Div, a, _) => a.is_vector(),
            Expr::Bin(Op::Add | Op::Sub | Op::Mul, a, b) => a.is_vector() || b.is_vector(),
        }
    }

    /// Every symbol of the expression, in order of first appearance.
    pub fn symbols(&self, out: &mut Vec<Symbol>) {
        match self {
            Expr::Num(_) | Expr::Pi => {}
            Expr::Sym(s) => {
                if !out.contains(s) {
                    out.push(s.clone());
                }
            }
            Expr::Neg(a) | Expr::Call(_, a) => a.symbols(out),
            Expr::Bin(_, a, b) => {
                a.symbols(out);
                b.symbols(out);
            }
        }
    }

    /// A plain rendering with explicit parentheses, for messages and for the mutation list: it
    /// shows how the reader understood the printed text (`5 g / \epsilon (\beta+2) a k` is
    /// `(5 g) / (\epsilon (\beta+2) a k)`).
    pub fn to_latex(&self) -> String {
        self.render(false)
    }

    /// [`Expr::to_latex`] in plain words ([`Symbol::plain`], `cos` for `\cos`, `x` for
    /// `\times`), for a note printed on a terminal as it is; a finding's text writes a formula
    /// as LaTeX between dollar signs ([`Expr::to_tex`]).
    pub fn to_plain(&self) -> String {
        self.render(true)
    }

    /// The rendering: plain words (`plain`) or the canonical symbol text.
    fn render(&self, plain: bool) -> String {
        match self {
            Expr::Num(x) => format_number(*x),
            Expr::Pi if plain => "pi".into(),
            Expr::Pi => r"\pi".into(),
            Expr::Sym(s) if plain => s.plain(),
            Expr::Sym(s) => s.to_string(),
            Expr::Neg(a) => format!("-({})", a.render(plain)),
            Expr::Call(f, a) if plain => {
                format!(
                    "{}({})",
                    f.latex().trim_start_matches('\\'),
                    a.render(plain)
                )
            }
            Expr::Call(f, a) => format!("{}({})", f.latex(), a.render(plain)),
            Expr::Bin(op, a, b) => {
                let (a, b) = (a.render(plain), b.render(plain));
                match op {
                    Op::Add => format!("({a} + {b})"),
                    Op::Sub => format!("({a} - {b})"),
                    Op::Mul => format!("{a} {b}"),
                    Op::Div => format!("({a})/({b})"),
                    Op::Dot if plain => format!("({a} . {b})"),
                    Op::Cross if plain => format!("({a} x {b})"),
                    Op::Dot => format!("({a} \\cdot {b})"),
                    Op::Cross => format!("({a} \\times {b})"),
                    Op::Pow => format!("({a})^{{{b}}}"),
                }
            }
        }
    }
}

/// A number without a trailing `.0` when it is an integer.
pub fn format_number(x: f64) -> String {
    if x.fract() == 0.0 && x.abs() < 1e15 {
        format!("{}", x as i64)
    } else {
        format!("{x}")
    }
}

/// A relation between two adjacent sides of a chain.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Rel {
    /// `=`
    Eq,
    /// `\approx`: equal to the order the equation's entry claims.
    Approx,
    /// `\equiv`: a definition.
    Equiv,
    /// `<`
    Lt,
    /// `>`
    Gt,
    /// `\leq`
    Le,
    /// `\geq`
    Ge,
    /// `\propto`: a constant ratio.
    Propto,
}

impl Rel {
    /// True for `<`, `>`, `\leq`, `\geq`.
    pub fn is_inequality(self) -> bool {
        matches!(self, Rel::Lt | Rel::Gt | Rel::Le | Rel::Ge)
    }

    /// Whether `lhs REL rhs` is true (for `=`-like relations: exactly equal).
    pub fn holds(self, lhs: f64, rhs: f64) -> bool {
        match self {
            Rel::Lt => lhs < rhs,
            Rel::Gt => lhs > rhs,
            Rel::Le => lhs <= rhs,
            Rel::Ge => lhs >= rhs,
            Rel::Eq | Rel::Approx | Rel::Equiv | Rel::Propto => lhs == rhs,
        }
    }

    /// The relation with its direction reversed (`<` for `>`); others unchanged.
    pub fn reversed(self) -> Rel {
        match self {
            Rel::Lt => Rel::Gt,
            Rel::Gt => Rel::Lt,
            Rel::Le => Rel::Ge,
            Rel::Ge => Rel::Le,
            r => r,
        }
    }

    /// The LaTeX of the relation.
    pub fn latex(self) -> &'static str {
        match self {
            Rel::Eq => "=",
            Rel::Approx => r"\approx",
            Rel::Equiv => r"\equiv",
            Rel::Lt => "<",
            Rel::Gt => ">",
            Rel::Le => r"\leq",
            Rel::Ge => r"\geq",
            Rel::Propto => r"\propto",
        }
    }
}

/// Sides joined by relations: `sides[i] rels[i] sides[i+1]`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Chain {
    /// The sides, left to right.
    pub sides: Vec<Expr>,
    /// The relations between adjacent sides (one fewer than the sides).
    pub rels: Vec<Rel>,
}

#[cfg(test)]
mod plain_tests {
    use crate::parse::parse;

    fn plain(latex: &str) -> String {
        let (chains, _) = parse(latex).unwrap();
        chains[0]
            .sides
            .iter()
            .map(|s| s.to_plain())
            .collect::<Vec<_>>()
            .join(" | ")
    }

    #[test]
    fn symbols_read_back_in_plain_words() {
        assert_eq!(plain(r"\mathbf{a} = a \hat{\mathbf{3}}"), "a | a 3-hat");
        assert_eq!(
            plain(r"\dot{\alpha} = \Omega_0 \cos\alpha"),
            "alpha_dot | Omega_0 cos(alpha)"
        );
        assert_eq!(
            plain(r"\frac{d \mathbf{L}_{\mathrm{cm}}}{dt} = \mathbf{a} \times \mathbf{F}"),
            "dL_cm/dt | (a x F)"
        );
    }
}
