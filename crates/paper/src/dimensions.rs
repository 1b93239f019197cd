//! Dimensional analysis of the printed equations: every symbol's unit from
//! `paper/symbols.yaml` (or the equation's own `symbols` map) read as a dimension
//! $M^{p}L^{q}T^{r}$ (the radian is a pure number), propagated through each side of every
//! printed relation; a sum whose terms differ, a function of a quantity that is not a pure
//! number, or two sides that differ is named with both units.
//!
//! An exponent may depend on a parameter: eq 75's $\epsilon$ has the unit $s^{\beta-1}$, so that
//! $P = -\epsilon m a g\Omega^\beta$ is a power for every $\beta$. Units are therefore read
//! with $\beta$ bound to a number, and an equation is homogeneous when it is so at each of
//! [`BETAS`] (a relation between exponents affine in $\beta$ that holds at two values holds at
//! all).

use crate::expr::{Expr, Func, Op, Rel};
use crate::Equation;
use std::fmt;

/// The values of $\beta$ at which units whose exponents depend on it are read.
pub const BETAS: [f64; 3] = [1.0, 2.0, 3.0];

/// A dimension $M^{p}L^{q}T^{r}$: the exponents of mass, length and time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dimension {
    /// Of mass.
    pub mass: f64,
    /// Of length.
    pub length: f64,
    /// Of time.
    pub time: f64,
}

impl Dimension {
    /// A pure number.
    pub const ONE: Dimension = Dimension::new(0.0, 0.0, 0.0);

    /// $M^{p}L^{q}T^{r}$.
    pub const fn new(mass: f64, length: f64, time: f64) -> Self {
        Self { mass, length, time }
    }

    /// The product.
    pub fn times(self, o: Dimension) -> Self {
        Self::new(
            self.mass + o.mass,
            self.length + o.length,
            self.time + o.time,
        )
    }

    /// The quotient.
    pub fn over(self, o: Dimension) -> Self {
        self.times(o.pow(-1.0))
    }

    /// The power `p`.
    pub fn pow(self, p: f64) -> Self {
        Self::new(self.mass * p, self.length * p, self.time * p)
    }

    /// The same dimension, to round-off in the exponents.
    pub fn same(self, o: Dimension) -> bool {
        let d = self.over(o);
        d.mass.abs() < 1e-9 && d.length.abs() < 1e-9 && d.time.abs() < 1e-9
    }

    /// True for a pure number.
    pub fn is_one(self) -> bool {
        self.same(Self::ONE)
    }

    /// The factor of the disk's constants $m$, $a$, $g$ with this dimension, as the paper
    /// writes it (`m a^2`, `sqrt(g/a)`): the unit a printed quantity lacks, named in the
    /// paper's own symbols; `None` when no product of them with half-integer powers has it.
    pub fn as_disk_factor(self) -> Option<String> {
        // m^i a^j g^l: M^i L^(j+l) T^(-2l).
        let (i, l) = (self.mass, -self.time / 2.0);
        let j = self.length - l;
        let half = |x: f64| ((2.0 * x).round() - 2.0 * x).abs() < 1e-9;
        if !(half(i) && half(j) && half(l)) {
            return None;
        }
        let mut parts = Vec::new();
        for (name, p) in [("m", i), ("a", j), ("g", l)] {
            match p {
                p if p.abs() < 1e-9 => {}
                p if (p - 1.0).abs() < 1e-9 => parts.push(name.to_string()),
                p => parts.push(format!("{name}^{}", exponent(p))),
            }
        }
        Some(if parts.is_empty() {
            "1".into()
        } else {
            parts.join(" ")
        })
    }
}

/// An exponent as written: an integer plainly, else to four decimals.
fn exponent(p: f64) -> String {
    if (p - p.round()).abs() < 1e-9 {
        format!("{}", p.round() as i64)
    } else {
        format!("{}", (p * 1e4).round() / 1e4)
    }
}

impl fmt::Display for Dimension {
    /// In SI base units: `kg m^2 s^-3`, `1` for a pure number.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut parts = Vec::new();
        for (name, p) in [("kg", self.mass), ("m", self.length), ("s", self.time)] {
            match p {
                p if p.abs() < 1e-9 => {}
                p if (p - 1.0).abs() < 1e-9 => parts.push(name.to_string()),
                p => parts.push(format!("{name}^{}", exponent(p))),
            }
        }
        if parts.is_empty() {
            f.write_str("1")
        } else {
            f.write_str(&parts.join(" "))
        }
    }
}

/// A unit the reader does not know, with the text it stopped at.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("the unit `{unit}` cannot be read at `{at}`: write it with kg, g, m, cm, s, rad, deg, Hz, N, J, W, Pa, products, `/` and powers such as s^-1 or s^(beta-1)")]
pub struct UnitError {
    /// The unit as written.
    pub unit: String,
    /// Where reading stopped.
    pub at: String,
}

/// A named unit's dimension.
fn named(name: &str) -> Option<Dimension> {
    Some(match name {
        "1" | "rad" | "deg" => Dimension::ONE,
        "kg" | "g" => Dimension::new(1.0, 0.0, 0.0),
        "m" | "cm" => Dimension::new(0.0, 1.0, 0.0),
        "s" => Dimension::new(0.0, 0.0, 1.0),
        "Hz" => Dimension::new(0.0, 0.0, -1.0),
        "N" => Dimension::new(1.0, 1.0, -2.0),
        "J" => Dimension::new(1.0, 2.0, -2.0),
        "W" => Dimension::new(1.0, 2.0, -3.0),
        "Pa" => Dimension::new(1.0, -1.0, -2.0),
        _ => return None,
    })
}

/// Reads a unit as symbols.yaml writes it (`kg m^2/s`, `g/(cm s)`, `s^(beta-1)`), with
/// $\beta$ = `beta`: factors separated by spaces multiply, `/` divides by the factor after it,
/// `^` raises to an integer, a decimal, or a parenthesised expression in `beta`.
pub fn parse_unit(unit: &str, beta: f64) -> Result<Dimension, UnitError> {
    let chars: Vec<char> = unit.chars().collect();
    let mut r = UnitReader {
        s: &chars,
        i: 0,
        beta,
    };
    let d = r.product();
    match d {
        Some(d) if r.i == chars.len() => Ok(d),
        _ => Err(UnitError {
            unit: unit.to_string(),
            at: chars[r.i.min(chars.len())..].iter().collect(),
        }),
    }
}

/// A cursor over a unit's text.
struct UnitReader<'a> {
    s: &'a [char],
    i: usize,
    beta: f64,
}

impl UnitReader<'_> {
    fn peek(&self) -> Option<char> {
        self.s.get(self.i).copied()
    }

    fn skip_spaces(&mut self) {
        while self.peek() == Some(' ') {
            self.i += 1;
        }
    }

    /// Factors, each multiplying or (after `/`) dividing, up to `)` or the end.
    fn product(&mut self) -> Option<Dimension> {
        let mut d = Dimension::ONE;
        loop {
            self.skip_spaces();
            match self.peek() {
                None | Some(')') => return Some(d),
                Some('/') => {
                    self.i += 1;
                    self.skip_spaces();
                    d = d.over(self.factor()?);
                }
                Some(_) => d = d.times(self.factor()?),
            }
        }
    }

    /// A named unit or a parenthesised product, with an optional power.
    fn factor(&mut self) -> Option<Dimension> {
        let base = if self.peek() == Some('(') {
            self.i += 1;
            let d = self.product()?;
            (self.peek() == Some(')')).then_some(())?;
            self.i += 1;
            d
        } else {
            let start = self.i;
            while self
                .peek()
                .is_some_and(|c| c.is_ascii_alphanumeric() && c != '^')
            {
                self.i += 1;
            }
            let name: String = self.s[start..self.i].iter().collect();
            named(&name)?
        };
        if self.peek() == Some('^') {
            self.i += 1;
            let p = self.power()?;
            return Some(base.pow(p));
        }
        Some(base)
    }

    /// A power: `-1`, `2`, `0.5`, `(beta+2)`, `-(beta+1)`.
    fn power(&mut self) -> Option<f64> {
        let sign = if self.peek() == Some('-') {
            self.i += 1;
            -1.0
        } else {
            1.0
        };
        if self.peek() == Some('(') {
            self.i += 1;
            let x = self.sum()?;
            (self.peek() == Some(')')).then_some(())?;
            self.i += 1;
            return Some(sign * x);
        }
        Some(sign * self.number()?)
    }

    fn number(&mut self) -> Option<f64> {
        let start = self.i;
        while self.peek().is_some_and(|c| c.is_ascii_digit() || c == '.') {
            self.i += 1;
        }
        self.s[start..self.i]
            .iter()
            .collect::<String>()
            .parse()
            .ok()
    }

    /// `term (+|- term)*` inside a power's parentheses.
    fn sum(&mut self) -> Option<f64> {
        let mut x = self.term()?;
        loop {
            self.skip_spaces();
            match self.peek() {
                Some('+') => {
                    self.i += 1;
                    x += self.term()?;
                }
                Some('-') => {
                    self.i += 1;
                    x -= self.term()?;
                }
                _ => return Some(x),
            }
        }
    }

    /// `atom (*|/ atom)*`.
    fn term(&mut self) -> Option<f64> {
        let mut x = self.atom()?;
        loop {
            self.skip_spaces();
            match self.peek() {
                Some('*') => {
                    self.i += 1;
                    x *= self.atom()?;
                }
                Some('/') => {
                    self.i += 1;
                    x /= self.atom()?;
                }
                _ => return Some(x),
            }
        }
    }

    /// A number, `beta`, `-atom` or a parenthesised sum.
    fn atom(&mut self) -> Option<f64> {
        self.skip_spaces();
        match self.peek()? {
            '-' => {
                self.i += 1;
                Some(-self.atom()?)
            }
            '(' => {
                self.i += 1;
                let x = self.sum()?;
                (self.peek() == Some(')')).then_some(())?;
                self.i += 1;
                Some(x)
            }
            c if c.is_ascii_digit() => self.number(),
            _ if self.s[self.i..].starts_with(&['b', 'e', 't', 'a']) => {
                self.i += 4;
                Some(self.beta)
            }
            _ => None,
        }
    }
}

/// Where a printed equation is not homogeneous, in words, with both units.
#[derive(Debug, Clone, PartialEq)]
pub struct Mismatch {
    /// The relation (as [`crate::Relation::name`] gives it).
    pub relation: String,
    /// What differs: the two sides, two terms of a sum, a function's argument, an exponent.
    pub what: String,
    /// The unit of the first part.
    pub left: Dimension,
    /// The unit of the second (a pure number for a function's argument or an exponent).
    pub right: Dimension,
    /// The value of $\beta$ at which the units were read.
    pub beta: f64,
}

impl Mismatch {
    /// The factor by which the second part's unit exceeds the first's, named in the disk's
    /// constants where it can be (`m a^2`), else in SI base units.
    pub fn factor(&self) -> String {
        let d = self.right.over(self.left);
        d.as_disk_factor().unwrap_or_else(|| d.to_string())
    }

    /// [`Mismatch::factor`] in LaTeX.
    pub fn factor_tex(&self) -> String {
        let d = self.right.over(self.left);
        match d.as_disk_factor() {
            Some(f) => crate::unit_tex::unit_tex_as(&f, true),
            None => crate::unit_tex::unit_tex_as(&d.to_string(), false),
        }
    }
}

impl fmt::Display for Mismatch {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}: {} (${}$ against ${}$: the second is the first times ${}$; $\\beta = {}$)",
            self.relation,
            self.what,
            crate::unit_tex::unit_tex_as(&self.left.to_string(), false),
            crate::unit_tex::unit_tex_as(&self.right.to_string(), false),
            self.factor_tex(),
            self.beta
        )
    }
}

/// The outcome of an equation's dimensional analysis.
#[derive(Debug, Clone, PartialEq)]
pub enum Homogeneity {
    /// Every printed relation is homogeneous at every [`BETAS`].
    Consistent,
    /// The first place where it is not.
    Mismatch(Mismatch),
    /// A unit could not be read.
    Unreadable(String),
}

impl fmt::Display for Homogeneity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Homogeneity::Consistent => f.write_str("consistent"),
            Homogeneity::Mismatch(m) => write!(f, "inconsistent: {m}"),
            Homogeneity::Unreadable(why) => write!(f, "not analysed: {why}"),
        }
    }
}

/// Why a side has no dimension: a part that differs, or a unit that cannot be read.
enum Fault {
    Differs {
        what: String,
        left: Dimension,
        right: Dimension,
    },
    Unit(String),
}

/// The dimensional analysis of every printed relation of `eq` (a proportionality, `\propto`,
/// relates two quantities of any units, and a printed 0 is a zero of any unit: neither is
/// compared).
pub fn analyse(eq: &Equation) -> Homogeneity {
    for beta in BETAS {
        for r in eq.relations() {
            let sides = side(eq, r.lhs, beta).and_then(|l| side(eq, r.rhs, beta).map(|rr| (l, rr)));
            // A printed 0 is a zero of any unit.
            let zero = |e: &Expr| matches!(e, Expr::Num(x) if *x == 0.0);
            let fault = match sides {
                Ok(_) if r.rel == Rel::Propto || zero(r.lhs) || zero(r.rhs) => continue,
                Ok((l, rr)) if l.same(rr) => continue,
                Ok((l, rr)) => Fault::Differs {
                    what: "the two sides differ".into(),
                    left: l,
                    right: rr,
                },
                Err(f) => f,
            };
            return match fault {
                Fault::Differs { what, left, right } => Homogeneity::Mismatch(Mismatch {
                    relation: r.name(),
                    what,
                    left,
                    right,
                    beta,
                }),
                Fault::Unit(why) => Homogeneity::Unreadable(format!("eq {}: {why}", eq.number())),
            };
        }
    }
    Homogeneity::Consistent
}

/// The dimension of one side of a relation of `eq` at $\beta$ = `beta`.
fn side(eq: &Equation, e: &Expr, beta: f64) -> Result<Dimension, Fault> {
    let pure = |x: &Expr, what: &str| -> Result<(), Fault> {
        let d = side(eq, x, beta)?;
        if d.is_one() {
            Ok(())
        } else {
            Err(Fault::Differs {
                what: format!("{what} ${}$ is not a pure number", x.to_tex()),
                left: d,
                right: Dimension::ONE,
            })
        }
    };
    match e {
        Expr::Num(_) | Expr::Pi => Ok(Dimension::ONE),
        Expr::Sym(s) => match eq.symbols.get(s) {
            Some(info) => {
                parse_unit(&info.unit, beta).map_err(|u| Fault::Unit(format!("${}$: {u}", s.tex())))
            }
            None => Err(Fault::Unit(format!("the symbol ${}$ has no unit", s.tex()))),
        },
        Expr::Neg(a) => side(eq, a, beta),
        Expr::Bin(op @ (Op::Add | Op::Sub), a, b) => {
            let (da, db) = (side(eq, a, beta)?, side(eq, b, beta)?);
            if da.same(db) {
                Ok(da)
            } else {
                Err(Fault::Differs {
                    what: format!(
                        "the terms ${}$ and ${}$ of a {} differ",
                        a.to_tex(),
                        b.to_tex(),
                        if *op == Op::Add { "sum" } else { "difference" }
                    ),
                    left: da,
                    right: db,
                })
            }
        }
        Expr::Bin(Op::Mul | Op::Dot | Op::Cross, a, b) => {
            Ok(side(eq, a, beta)?.times(side(eq, b, beta)?))
        }
        Expr::Bin(Op::Div, a, b) => Ok(side(eq, a, beta)?.over(side(eq, b, beta)?)),
        Expr::Bin(Op::Pow, a, b) => {
            pure(b, "the exponent")?;
            let base = side(eq, a, beta)?;
            if base.is_one() {
                return Ok(Dimension::ONE);
            }
            match number(eq, b, beta) {
                Some(p) => Ok(base.pow(p)),
                None => Err(Fault::Unit(format!(
                    "the exponent ${}$ of ${}$ is not a number",
                    b.to_tex(),
                    a.to_tex()
                ))),
            }
        }
        Expr::Call(Func::Sqrt, a) => Ok(side(eq, a, beta)?.pow(0.5)),
        Expr::Call(Func::Abs, a) => side(eq, a, beta),
        Expr::Call(f, a) => {
            pure(a, &format!("the argument of {}", f.latex()))?;
            Ok(Dimension::ONE)
        }
    }
}

/// The value of an exponent made of numbers, $\pi$ and $\beta$.
fn number(eq: &Equation, e: &Expr, beta: f64) -> Option<f64> {
    match e {
        Expr::Num(x) => Some(*x),
        Expr::Pi => Some(std::f64::consts::PI),
        Expr::Sym(s) => eq
            .symbols
            .get(s)
            .filter(|i| i.quantity == "beta")
            .map(|_| beta),
        Expr::Neg(a) => number(eq, a, beta).map(|x| -x),
        Expr::Bin(op, a, b) => {
            let (x, y) = (number(eq, a, beta)?, number(eq, b, beta)?);
            match op {
                Op::Add => Some(x + y),
                Op::Sub => Some(x - y),
                Op::Mul => Some(x * y),
                Op::Div => Some(x / y),
                Op::Pow => Some(x.powf(y)),
                Op::Dot | Op::Cross => None,
            }
        }
        Expr::Call(..) => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_are_read_with_their_powers() {
        let d = |u: &str| parse_unit(u, 2.0).unwrap();
        assert!(d("kg m^2/s").same(Dimension::new(1.0, 2.0, -1.0)));
        assert!(d("g/(cm s)").same(Dimension::new(1.0, -1.0, -1.0)));
        assert!(d("g cm^-1 s").same(Dimension::new(1.0, -1.0, 1.0)));
        assert!(d("rad/s^2").same(Dimension::new(0.0, 0.0, -2.0)));
        assert!(d("s^(beta-1)").same(Dimension::new(0.0, 0.0, 1.0)));
        assert!(d("rad^(beta+2) s^-(beta+1)").same(Dimension::new(0.0, 0.0, -3.0)));
        assert!(d("1").is_one());
        assert!(parse_unit("furlong", 2.0).is_err());
        assert!(parse_unit("s^(beta", 2.0).is_err());
    }

    #[test]
    fn a_missing_factor_is_named_in_the_disks_constants() {
        let l = Dimension::new(1.0, 2.0, -1.0);
        let omega = Dimension::new(0.0, 0.0, -1.0);
        assert_eq!(l.over(omega).as_disk_factor().unwrap(), "m a^2");
        let rate = Dimension::new(0.0, 0.0, -1.0);
        assert_eq!(rate.as_disk_factor().unwrap(), "a^-0.5 g^0.5");
    }
}
