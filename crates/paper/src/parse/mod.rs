//! A reader for the LaTeX the paper prints: the subset its 85 equations use, into [`Chain`]s.
//!
//! Written by hand rather than taken from a crate: the LaTeX-to-math crates surveyed (`mathlex`,
//! `latex2mathml`, `pulldown-latex`) either render (to MathML) without an evaluable tree, or parse
//! a calculator's grammar that does not know the physicist's conventions this paper relies on:
//!
//! - **Juxtaposition binds tighter than `/`** on both sides: `5 g / \epsilon (\beta + 2) a k` is
//!   $5g / (\epsilon(\beta+2)ak)$ (eq 78) and `1 / 2 (\beta + 1)` is $1/(2(\beta+1))$ (eq 80),
//!   as the derivations of eqs 78 and 80 require.
//! - **`\times` and `\cdot` bind looser than juxtaposition**: `a \hat{\mathbf 3} \times m g
//!   \hat{\mathbf z}` is $(a\hat{\mathbf 3})\times(mg\hat{\mathbf z})$ (eq 33).
//! - **A function's argument** is a parenthesised group, or else the run of plain scalar symbols
//!   that follows it: `\cos\varpi t` is $\cos(\varpi t)$ (eq 41) while `\sin\alpha \hat{\mathbf 3}`
//!   and `\sin\alpha_0 \cos\alpha_0` stop at the vector and at the next function. Write
//!   `\cos(\alpha) \Omega` if a symbol that follows is not part of the argument.
//! - `\cos^2\alpha` is $(\cos\alpha)^2$; `\omega^2_{10}` is $(\omega_{10})^2$.
//! - `\frac{d X}{dt}` and `\frac{d^2 X}{dt^2}` are the time derivatives of the symbol X, symbols in
//!   their own right that a check binds to measured rates.
//! - A printed equation may hold several relations separated by a comma or a semicolon (eq 18),
//!   and may end with a comma, a full stop or a semicolon.
//! - **`\cdot` and `\times` next to a scalar are products**: `k \cdot a`, `g \cdot 1` and
//!   `2 \times k` are $ka$, $g$ and $2k$; between vectors they are the scalar and the vector
//!   products. A symbol is a vector when the paper writes it as one, as every vector and tensor of
//!   paper/symbols.yaml is: bold (`\mathbf{a}`), with a hat (`\hat{\mathbf{1}}`) or an arrow
//!   (`\vec{\omega}`).
//! - The same mathematics in an author's other notations reads the same: `\dfrac` and `\tfrac`
//!   are `\frac`; `\left( \right)`, `\bigl( \bigr)`, `\Big(` and the like, `[ ]` and braces
//!   group; `\,`, `\;`, `\!`, `\ `, `~`, `\quad` are spaces.
//!
//! Limits, checked before any recursion so that no input can exhaust the stack: at most
//! [`MAX_CHARS`] characters per equation, and groups (parentheses, braces, fractions, powers)
//! nested at most [`MAX_DEPTH`] deep, the parsed sides too.

use super::expr::{Chain, Expr, Func, Op, Rel, Symbol};

/// Where and why the reader stopped.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ParseError {
    /// 1-based column (in characters) of the offending token in the LaTeX.
    pub column: usize,
    /// What was expected, in words.
    pub message: String,
}

/// The most characters one equation's LaTeX may have (the paper's longest has under 300).
pub const MAX_CHARS: usize = 4096;

/// The deepest nesting of groups the reader follows, and of operations in a parsed side (the
/// paper's deepest side is nested about 20 deep).
pub const MAX_DEPTH: usize = 256;

/// One symbol occurrence: the symbol and its column, for messages about unknown symbols.
pub type Occurrence = (Symbol, usize);

mod cases;
mod lex;
mod normalize;
mod symbols;
#[cfg(test)]
mod tests;

pub use lex::GREEK;
use lex::{lex, Tok};

/// Parses the LaTeX of one printed equation into its chains, and lists every symbol occurrence.
pub fn parse(latex: &str) -> Result<(Vec<Chain>, Vec<Occurrence>), ParseError> {
    let chars = latex.chars().count();
    if chars > MAX_CHARS {
        return Err(ParseError {
            column: MAX_CHARS + 1,
            message: format!(
                "the equation has {chars} characters, more than the {MAX_CHARS} the reader takes \
                 for one equation: split it into several relations or simplify it"
            ),
        });
    }
    let normalized = normalize::normalize(lex(latex)?)?;
    let mut seen = Vec::new();
    for condition in normalized.conditions {
        let (_, symbols) = parse_tokens(condition, chars + 1)?;
        seen.extend(symbols);
    }
    let (chains, symbols) = parse_tokens(normalized.toks, chars + 1)?;
    seen.extend(symbols);
    Ok((chains, seen))
}

/// The chains of a list of tokens (`end` is the column past the last character).
fn parse_tokens(toks: Vec<(Tok, usize)>, end: usize) -> R<(Vec<Chain>, Vec<Occurrence>)> {
    let mut p = Parser {
        toks,
        pos: 0,
        end,
        seen: Vec::new(),
        depth: 0,
        abs_depth: 0,
    };
    let mut chains = vec![p.chain()?];
    loop {
        if p.eat(&Tok::Comma) || p.eat(&Tok::Semicolon) {
            if p.pos == p.toks.len() {
                break;
            }
            chains.push(p.chain()?);
        } else if p.eat(&Tok::Period) {
            if p.pos < p.toks.len() {
                return Err(p.error("the end after the full stop"));
            }
            break;
        } else {
            break;
        }
    }
    if p.pos < p.toks.len() {
        return Err(p.error("an operator or a relation"));
    }
    Ok((chains, p.seen))
}

struct Parser {
    toks: Vec<(Tok, usize)>,
    pos: usize,
    end: usize,
    seen: Vec<Occurrence>,
    /// How many groups deep the reader is (see [`MAX_DEPTH`]).
    depth: usize,
    /// How many `|...|` the reader is inside (a `|` there closes, never opens).
    abs_depth: usize,
}

/// An error at `column` when `e` raises a vector to a power.
fn powers_of_scalars(e: &Expr, column: usize) -> R<()> {
    if let Expr::Bin(Op::Pow, base, _) = e {
        if base.is_vector() {
            return Err(ParseError {
                column,
                message: "a vector to a power: write a square as \\mathbf{v} \\cdot \\mathbf{v}, \
                          or the length's as \\left| \\mathbf{v} \\right|^2"
                    .into(),
            });
        }
    }
    Ok(())
}

/// The depth of the deepest node of `e`, measured without recursion (up to `limit + 1`).
fn tree_depth(e: &Expr, limit: usize) -> usize {
    let mut deepest = 0;
    let mut stack = vec![(e, 1usize)];
    while let Some((node, d)) = stack.pop() {
        deepest = deepest.max(d);
        if deepest > limit {
            break;
        }
        match node {
            Expr::Num(_) | Expr::Pi | Expr::Sym(_) => {}
            Expr::Neg(a) | Expr::Call(_, a) => stack.push((a, d + 1)),
            Expr::Bin(_, a, b) => {
                stack.push((a, d + 1));
                stack.push((b, d + 1));
            }
        }
    }
    deepest
}

type R<T> = Result<T, ParseError>;

impl Parser {
    fn peek(&self) -> Option<&Tok> {
        self.toks.get(self.pos).map(|(t, _)| t)
    }

    fn column(&self) -> usize {
        self.toks.get(self.pos).map_or(self.end, |(_, c)| *c)
    }

    fn error(&self, expected: &str) -> ParseError {
        let found = match self.peek() {
            None => "the end".to_string(),
            Some(Tok::Cmd(c)) => match lex::hint(c) {
                Some(h) => format!("\\{c} ({h})"),
                None => format!("\\{c}"),
            },
            Some(Tok::Num(_, t)) if t.len() > 40 => format!("{}...", &t[..40]),
            Some(Tok::Num(_, t)) => t.clone(),
            Some(Tok::Letter(l)) => l.to_string(),
            Some(Tok::Text(w)) => format!(
                "\\text{{{}}} ({})",
                w.chars().take(40).collect::<String>(),
                lex::hint("text").unwrap_or_default()
            ),
            Some(t @ (Tok::Equals | Tok::Less | Tok::Greater)) => format!(
                "{} (a relation needs a quantity on its left: where words stand between two \
                 relations, write the quantity again after them, as in x = a \\text{{ and }} x = b)",
                match t {
                    Tok::Equals => "=",
                    Tok::Less => "<",
                    _ => ">",
                }
            ),
            Some(Tok::Amp) => {
                "& (an alignment point belongs between the sides of a relation, as in a &= b)"
                    .into()
            }
            Some(Tok::RowEnd) => {
                "\\\\ (a row ends after a relation, or a row starting with & continues it)".into()
            }
            Some(t) => format!("{t:?}").to_lowercase(),
        };
        ParseError {
            column: self.column(),
            message: format!("expected {expected}, found {found}"),
        }
    }

    fn eat(&mut self, t: &Tok) -> bool {
        if self.peek() == Some(t) {
            self.pos += 1;
            true
        } else {
            false
        }
    }

    fn eat_cmd(&mut self, name: &str) -> bool {
        if matches!(self.peek(), Some(Tok::Cmd(c)) if c == name) {
            self.pos += 1;
            true
        } else {
            false
        }
    }

    fn expect(&mut self, t: &Tok, what: &str) -> R<()> {
        if self.eat(t) {
            Ok(())
        } else {
            Err(self.error(what))
        }
    }

    fn chain(&mut self) -> R<Chain> {
        let mut sides = vec![self.side()?];
        let mut rels = Vec::new();
        while let Some(rel) = self.relation() {
            rels.push(rel);
            sides.push(self.side()?);
        }
        Ok(Chain { sides, rels })
    }

    /// One side of a relation, no deeper than [`MAX_DEPTH`] operations (a side is evaluated,
    /// printed and mutated by recursion).
    fn side(&mut self) -> R<Expr> {
        let column = self.column();
        let e = self.expr()?;
        if tree_depth(&e, MAX_DEPTH) > MAX_DEPTH {
            return Err(ParseError {
                column,
                message: format!(
                    "the side starting here is nested more than {MAX_DEPTH} operations deep (a \
                     long run of terms or factors, or groups within groups): split it"
                ),
            });
        }
        Ok(e)
    }

    /// Enters a group: an error once more than [`MAX_DEPTH`] deep, before recursing further.
    fn enter(&mut self) -> R<()> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(ParseError {
                column: self.column(),
                message: format!(
                    "groups (parentheses, braces, fractions, powers) nested more than \
                     {MAX_DEPTH} deep: simplify the expression"
                ),
            });
        }
        Ok(())
    }

    fn relation(&mut self) -> Option<Rel> {
        let rel = match self.peek()? {
            Tok::Equals => Rel::Eq,
            Tok::Less => Rel::Lt,
            Tok::Greater => Rel::Gt,
            Tok::Cmd(c) => match c.as_str() {
                "approx" => Rel::Approx,
                "equiv" => Rel::Equiv,
                "leq" | "le" => Rel::Le,
                "geq" | "ge" => Rel::Ge,
                "propto" => Rel::Propto,
                _ => return None,
            },
            _ => return None,
        };
        self.pos += 1;
        Some(rel)
    }

    /// Sums and differences, with an optional leading sign.
    fn expr(&mut self) -> R<Expr> {
        self.enter()?;
        let e = self.sum();
        self.depth -= 1;
        e
    }

    fn sum(&mut self) -> R<Expr> {
        let mut e = if self.eat(&Tok::Minus) {
            Expr::Neg(Box::new(self.term()?))
        } else {
            self.eat(&Tok::Plus);
            self.term()?
        };
        loop {
            let (column, op) = (self.column(), self.peek().cloned());
            let op = match op {
                Some(Tok::Plus) => Op::Add,
                Some(Tok::Minus) => Op::Sub,
                _ => return Ok(e),
            };
            self.pos += 1;
            let t = self.term()?;
            if (e.is_scalar() && t.is_vector()) || (e.is_vector() && t.is_scalar()) {
                return Err(ParseError {
                    column,
                    message: "a sum of a scalar and a vector: both terms must be scalars or \
                              both vectors (a vector is written bold, with a hat or an arrow)"
                        .into(),
                });
            }
            e = Expr::bin(op, e, t);
        }
    }

    /// Quotients written with `/`: looser than juxtaposition on both sides.
    fn term(&mut self) -> R<Expr> {
        let mut e = self.cross()?;
        while self.eat(&Tok::Slash) {
            e = Expr::bin(Op::Div, e, self.cross()?);
        }
        Ok(e)
    }

    /// `\times` and `\cdot` between runs of factors, left to right: the vector and scalar
    /// products, or a plain product where a side is a scalar.
    fn cross(&mut self) -> R<Expr> {
        let (mut e, mut pending) = self.run(None)?;
        while let Some((op, first)) = pending {
            let (rhs, next) = self.run(Some(first))?;
            pending = next;
            let op = if e.is_scalar() || rhs.is_scalar() {
                Op::Mul
            } else {
                op
            };
            e = Expr::bin(op, e, rhs);
        }
        Ok(e)
    }

    /// A run of factors: juxtaposed, or joined by `\cdot` or `\times` between two scalar
    /// factors (`m \cdot g` is `m g`, so `a \hat{3} \times m \cdot g \hat{z}` is
    /// $a\hat 3 \times (m g \hat z)$). Where a `\cdot` or `\times` has a vector factor on a
    /// side, the run ends; the operator and the factor after it are returned for [`Self::cross`].
    fn run(&mut self, first: Option<Expr>) -> R<(Expr, Option<(Op, Expr)>)> {
        let mut e = match first {
            Some(f) => f,
            None => self.factor()?,
        };
        let mut last_scalar = e.is_scalar();
        loop {
            if self.starts_factor() {
                let f = self.factor()?;
                last_scalar = f.is_scalar();
                e = Expr::bin(Op::Mul, e, f);
                continue;
            }
            let op = if self.eat_cmd("times") {
                Op::Cross
            } else if self.eat_cmd("cdot") {
                Op::Dot
            } else {
                return Ok((e, None));
            };
            let f = self.factor()?;
            if last_scalar && f.is_scalar() {
                e = Expr::bin(Op::Mul, e, f);
                continue;
            }
            return Ok((e, Some((op, f))));
        }
    }

    fn starts_factor(&self) -> bool {
        match self.peek() {
            Some(Tok::Num(..) | Tok::Letter(_) | Tok::LParen | Tok::LBrace | Tok::LBrack) => true,
            Some(Tok::Pipe) => self.abs_depth == 0,
            Some(Tok::Cmd(c)) => !matches!(
                c.as_str(),
                "times"
                    | "cdot"
                    | "right"
                    | "approx"
                    | "equiv"
                    | "leq"
                    | "le"
                    | "geq"
                    | "ge"
                    | "propto"
                    | "over"
            ),
            _ => false,
        }
    }

    /// An atom and the powers written after it.
    fn factor(&mut self) -> R<Expr> {
        let column = self.column();
        let mut e = self.atom()?;
        while self.eat(&Tok::Caret) {
            let p = self.script()?;
            e = Expr::bin(Op::Pow, e, p);
        }
        powers_of_scalars(&e, column)?;
        Ok(e)
    }

    /// A superscript: a braced expression or a single token.
    fn script(&mut self) -> R<Expr> {
        if self.eat(&Tok::LBrace) {
            let e = self.expr()?;
            self.expect(&Tok::RBrace, "} closing the superscript")?;
            return Ok(e);
        }
        match self.peek().cloned() {
            Some(Tok::Num(x, t)) => {
                self.pos += 1;
                // `^23` would be 2 then 3 in TeX; the paper never writes it.
                if t.len() > 1 {
                    return Err(ParseError {
                        column: self.column(),
                        message: format!("write ^{{{t}}} with braces"),
                    });
                }
                Ok(Expr::Num(x))
            }
            _ => self.atom(),
        }
    }

    fn atom(&mut self) -> R<Expr> {
        let col = self.column();
        match self.peek().cloned() {
            Some(Tok::Num(x, _)) => {
                self.pos += 1;
                Ok(Expr::Num(x))
            }
            Some(Tok::LParen) => {
                self.pos += 1;
                let e = self.expr()?;
                self.expect(&Tok::RParen, ") closing the (")?;
                Ok(e)
            }
            Some(Tok::LBrace) => {
                self.pos += 1;
                let e = self.expr()?;
                self.expect(&Tok::RBrace, "} closing the {")?;
                Ok(e)
            }
            Some(Tok::LBrack) => {
                self.pos += 1;
                let e = self.expr()?;
                self.expect(&Tok::RBrack, "] closing the [")?;
                Ok(e)
            }
            Some(Tok::Letter('d')) if self.looks_like_slash_derivative() => {
                self.slash_derivative(col)
            }
            Some(Tok::Letter(_)) => self.symbol_with_scripts(col),
            Some(Tok::Pipe) if self.abs_depth == 0 => {
                self.pos += 1;
                self.abs_depth += 1;
                let e = self.expr();
                self.abs_depth -= 1;
                let e = e?;
                self.expect(&Tok::Pipe, "| closing the |")?;
                Ok(Expr::Call(Func::Abs, Box::new(e)))
            }
            Some(Tok::Cmd(c)) => match c.as_str() {
                "pi" => {
                    self.pos += 1;
                    Ok(Expr::Pi)
                }
                "frac" => {
                    self.pos += 1;
                    self.fraction(col)
                }
                "sqrt" => {
                    self.pos += 1;
                    let e = self.braced("the argument of \\sqrt")?;
                    Ok(Expr::Call(Func::Sqrt, Box::new(e)))
                }
                "sin" | "cos" | "tan" | "cot" => {
                    self.pos += 1;
                    self.function(&c)
                }
                "left" => {
                    self.pos += 1;
                    self.delimited()
                }
                _ => self.symbol_with_scripts(col),
            },
            _ => Err(self.error("a number, a symbol or a (")),
        }
    }

    fn braced(&mut self, what: &str) -> R<Expr> {
        self.expect(&Tok::LBrace, &format!("{{ opening {what}"))?;
        let e = self.expr()?;
        self.expect(&Tok::RBrace, &format!("}} closing {what}"))?;
        Ok(e)
    }

    /// `\left( ... \right)`, `\left[ ... \right]`, `\left| ... \right|`.
    fn delimited(&mut self) -> R<Expr> {
        let (close, abs) = match self.peek() {
            Some(Tok::LParen) => (Tok::RParen, false),
            Some(Tok::LBrack) => (Tok::RBrack, false),
            Some(Tok::Pipe) => (Tok::Pipe, true),
            _ => return Err(self.error("(, [ or | after \\left")),
        };
        self.pos += 1;
        let saved = self.abs_depth;
        self.abs_depth = 0;
        let e = self.expr();
        self.abs_depth = saved;
        let e = e?;
        if !self.eat_cmd("right") {
            return Err(self.error("\\right"));
        }
        self.expect(&close, "the delimiter matching \\left")?;
        Ok(if abs {
            Expr::Call(Func::Abs, Box::new(e))
        } else {
            e
        })
    }

    /// `\sin`, `\cos`, `\tan`, `\cot`, with an optional power and the argument rule of the
    /// module's documentation.
    fn function(&mut self, name: &str) -> R<Expr> {
        let column = self.column();
        let f = match name {
            "sin" => Func::Sin,
            "cos" => Func::Cos,
            "tan" => Func::Tan,
            _ => Func::Cot,
        };
        let power = if self.eat(&Tok::Caret) {
            Some(self.script()?)
        } else {
            None
        };
        let arg = match self.peek() {
            Some(Tok::LParen) => self.atom()?,
            Some(Tok::LBrace) => self.braced(&format!("the argument of \\{name}"))?,
            Some(Tok::Cmd(c)) if c == "left" => self.atom()?,
            _ => {
                let mut arg = self.plain_symbol()?;
                while self.starts_plain_symbol() {
                    arg = Expr::bin(Op::Mul, arg, self.plain_symbol()?);
                }
                arg
            }
        };
        if arg.is_vector() {
            return Err(ParseError {
                column,
                message: format!(
                    "\\{name} of a vector: its argument must be a scalar (an angle, or \
                     \\left| \\mathbf{{v}} \\right| for a vector's length)"
                ),
            });
        }
        let call = Expr::Call(f, Box::new(arg));
        Ok(match power {
            Some(p) => Expr::bin(Op::Pow, call, p),
            None => call,
        })
    }
}
