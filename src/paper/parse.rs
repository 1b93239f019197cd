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
//! - A printed equation may hold several relations separated by a comma (eq 18).

use super::expr::{Accent, Chain, Expr, Func, Op, Rel, Symbol};

/// Where and why the reader stopped.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ParseError {
    /// 1-based column (in characters) of the offending token in the LaTeX.
    pub column: usize,
    /// What was expected, in words.
    pub message: String,
}

/// One symbol occurrence: the symbol and its column, for messages about unknown symbols.
pub type Occurrence = (Symbol, usize);

#[derive(Debug, Clone, PartialEq)]
enum Tok {
    Cmd(String),
    LBrace,
    RBrace,
    LParen,
    RParen,
    LBrack,
    RBrack,
    Caret,
    Under,
    Plus,
    Minus,
    Slash,
    Comma,
    Equals,
    Less,
    Greater,
    Pipe,
    /// A number and its text as printed (`10`, `1.8`).
    Num(f64, String),
    Letter(char),
}

/// Commands that only make space.
const SPACES: &[&str] = &["quad", "qquad", ",", ";", "!", " ", ":"];

fn lex(s: &str) -> Result<Vec<(Tok, usize)>, ParseError> {
    let chars: Vec<char> = s.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let col = i + 1;
        if c.is_whitespace() {
            i += 1;
            continue;
        }
        let tok = match c {
            '\\' => {
                let start = i + 1;
                let mut j = start;
                while j < chars.len() && chars[j].is_ascii_alphabetic() {
                    j += 1;
                }
                if j == start {
                    j = (start + 1).min(chars.len());
                }
                let name: String = chars[start..j].iter().collect();
                i = j;
                if name.is_empty() {
                    return Err(ParseError {
                        column: col,
                        message: "a backslash at the end".into(),
                    });
                }
                if SPACES.contains(&name.as_str()) {
                    continue;
                }
                out.push((Tok::Cmd(name), col));
                continue;
            }
            '{' => Tok::LBrace,
            '}' => Tok::RBrace,
            '(' => Tok::LParen,
            ')' => Tok::RParen,
            '[' => Tok::LBrack,
            ']' => Tok::RBrack,
            '^' => Tok::Caret,
            '_' => Tok::Under,
            '+' => Tok::Plus,
            '-' => Tok::Minus,
            '/' => Tok::Slash,
            ',' => Tok::Comma,
            '=' => Tok::Equals,
            '<' => Tok::Less,
            '>' => Tok::Greater,
            '|' => Tok::Pipe,
            d if d.is_ascii_digit() || d == '.' => {
                let mut j = i;
                while j < chars.len() && (chars[j].is_ascii_digit() || chars[j] == '.') {
                    j += 1;
                }
                let text: String = chars[i..j].iter().collect();
                let x: f64 = text.parse().map_err(|_| ParseError {
                    column: col,
                    message: format!("'{text}' is not a number"),
                })?;
                i = j;
                out.push((Tok::Num(x, text), col));
                continue;
            }
            l if l.is_ascii_alphabetic() => Tok::Letter(l),
            other => {
                return Err(ParseError {
                    column: col,
                    message: format!("the character '{other}' is not part of the paper's notation"),
                })
            }
        };
        out.push((tok, col));
        i += 1;
    }
    Ok(out)
}

/// Greek letters the paper uses as symbols (`\pi` is the constant).
const GREEK: &[&str] = &[
    "alpha",
    "beta",
    "gamma",
    "delta",
    "epsilon",
    "varepsilon",
    "zeta",
    "eta",
    "theta",
    "kappa",
    "lambda",
    "mu",
    "nu",
    "xi",
    "rho",
    "sigma",
    "tau",
    "phi",
    "varphi",
    "chi",
    "psi",
    "omega",
    "varpi",
    "Gamma",
    "Delta",
    "Theta",
    "Lambda",
    "Sigma",
    "Phi",
    "Psi",
    "Omega",
];

/// Parses the LaTeX of one printed equation into its chains, and lists every symbol occurrence.
pub fn parse(latex: &str) -> Result<(Vec<Chain>, Vec<Occurrence>), ParseError> {
    let toks = lex(latex)?;
    let mut p = Parser {
        toks,
        pos: 0,
        end: latex.chars().count() + 1,
        seen: Vec::new(),
    };
    let mut chains = vec![p.chain()?];
    while p.eat(&Tok::Comma) {
        chains.push(p.chain()?);
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
            Some(Tok::Cmd(c)) => format!("\\{c}"),
            Some(Tok::Num(_, t)) => t.clone(),
            Some(Tok::Letter(l)) => l.to_string(),
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
        let mut sides = vec![self.expr()?];
        let mut rels = Vec::new();
        while let Some(rel) = self.relation() {
            rels.push(rel);
            sides.push(self.expr()?);
        }
        Ok(Chain { sides, rels })
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
        let mut e = if self.eat(&Tok::Minus) {
            Expr::Neg(Box::new(self.term()?))
        } else {
            self.eat(&Tok::Plus);
            self.term()?
        };
        loop {
            if self.eat(&Tok::Plus) {
                e = Expr::bin(Op::Add, e, self.term()?);
            } else if self.eat(&Tok::Minus) {
                e = Expr::bin(Op::Sub, e, self.term()?);
            } else {
                return Ok(e);
            }
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

    /// `\times` and `\cdot` between runs of juxtaposed factors, left to right.
    fn cross(&mut self) -> R<Expr> {
        let mut e = self.product()?;
        loop {
            if self.eat_cmd("times") {
                e = Expr::bin(Op::Cross, e, self.product()?);
            } else if self.eat_cmd("cdot") {
                e = Expr::bin(Op::Dot, e, self.product()?);
            } else {
                return Ok(e);
            }
        }
    }

    fn product(&mut self) -> R<Expr> {
        let mut e = self.factor()?;
        while self.starts_factor() {
            e = Expr::bin(Op::Mul, e, self.factor()?);
        }
        Ok(e)
    }

    fn starts_factor(&self) -> bool {
        match self.peek() {
            Some(Tok::Num(..) | Tok::Letter(_) | Tok::LParen | Tok::LBrace) => true,
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
            ),
            _ => false,
        }
    }

    /// An atom and the powers written after it.
    fn factor(&mut self) -> R<Expr> {
        let mut e = self.atom()?;
        while self.eat(&Tok::Caret) {
            let p = self.script()?;
            e = Expr::bin(Op::Pow, e, p);
        }
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
            Some(Tok::Letter(_)) => self.symbol_with_scripts(col),
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
        let e = self.expr()?;
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
            Some(Tok::Cmd(c)) if c == "left" => self.atom()?,
            _ => {
                let mut arg = self.plain_symbol()?;
                while self.starts_plain_symbol() {
                    arg = Expr::bin(Op::Mul, arg, self.plain_symbol()?);
                }
                arg
            }
        };
        let call = Expr::Call(f, Box::new(arg));
        Ok(match power {
            Some(p) => Expr::bin(Op::Pow, call, p),
            None => call,
        })
    }

    fn starts_plain_symbol(&self) -> bool {
        match self.peek() {
            Some(Tok::Letter(_)) => true,
            Some(Tok::Cmd(c)) => GREEK.contains(&c.as_str()),
            _ => false,
        }
    }

    fn plain_symbol(&mut self) -> R<Expr> {
        if !self.starts_plain_symbol() {
            return Err(self.error("the argument of the function (a symbol or a parenthesis)"));
        }
        let col = self.column();
        self.symbol_with_scripts(col)
    }

    /// `\frac{A}{B}`, or a time derivative `\frac{d X}{dt}` / `\frac{d^2 X}{dt^2}`.
    fn fraction(&mut self, col: usize) -> R<Expr> {
        let save = (self.pos, self.seen.len());
        if let Some(e) = self.derivative(col) {
            return Ok(e);
        }
        self.pos = save.0;
        self.seen.truncate(save.1);
        let num = self.braced("the numerator of \\frac")?;
        let den = self.braced("the denominator of \\frac")?;
        Ok(Expr::bin(Op::Div, num, den))
    }

    /// True when the tokens from here read `{d ...}{dt}` or `{d ...}{dt^2}`: the shape of a
    /// time derivative, found by counting braces without parsing, so that a fraction that is
    /// not a derivative is parsed once, not once as a failed derivative and again (which made
    /// nested fractions take exponential time: found by fuzzing, `tests/reader_fuzz.rs`).
    fn looks_like_derivative(&self) -> bool {
        let tok = |i: usize| self.toks.get(i).map(|(t, _)| t);
        if tok(self.pos) != Some(&Tok::LBrace) || tok(self.pos + 1) != Some(&Tok::Letter('d')) {
            return false;
        }
        let mut depth = 0usize;
        let mut i = self.pos;
        let close = loop {
            match tok(i) {
                None => return false,
                Some(Tok::LBrace) => depth += 1,
                Some(Tok::RBrace) => {
                    depth -= 1;
                    if depth == 0 {
                        break i;
                    }
                }
                Some(_) => {}
            }
            i += 1;
        };
        let denominator = [
            Some(&Tok::LBrace),
            Some(&Tok::Letter('d')),
            Some(&Tok::Letter('t')),
        ];
        if (0..3).any(|j| tok(close + 1 + j) != denominator[j]) {
            return false;
        }
        match tok(close + 4) {
            Some(Tok::RBrace) => true,
            Some(Tok::Caret) => tok(close + 6) == Some(&Tok::RBrace),
            _ => false,
        }
    }

    fn derivative(&mut self, col: usize) -> Option<Expr> {
        if !self.looks_like_derivative() {
            return None;
        }
        if !(self.eat(&Tok::LBrace) && self.eat(&Tok::Letter('d'))) {
            return None;
        }
        let order = self.order()?;
        let mut sym = match self.symbol_with_scripts(col).ok()? {
            Expr::Sym(s) => s,
            _ => return None,
        };
        if !(self.eat(&Tok::RBrace)
            && self.eat(&Tok::LBrace)
            && self.eat(&Tok::Letter('d'))
            && self.eat(&Tok::Letter('t')))
        {
            return None;
        }
        if self.order()? != order || !self.eat(&Tok::RBrace) {
            return None;
        }
        sym.derivative = order;
        if let Some(last) = self.seen.last_mut() {
            last.0 = sym.clone();
        }
        Some(Expr::Sym(sym))
    }

    /// `^2` after a `d` of a derivative (2), or nothing (1).
    fn order(&mut self) -> Option<u8> {
        if self.eat(&Tok::Caret) {
            match self.peek() {
                Some(Tok::Num(x, _)) if *x == 2.0 => {
                    self.pos += 1;
                    Some(2)
                }
                _ => None,
            }
        } else {
            Some(1)
        }
    }

    /// A symbol with its accent, subscript and power: `\dot{x}_A`, `\Omega_0^2`,
    /// `\omega^2_{10}`, `\hat{\mathbf{1}}`.
    fn symbol_with_scripts(&mut self, col: usize) -> R<Expr> {
        let mut sym = self.symbol_base()?;
        let mut power = None;
        loop {
            if sym.sub.is_empty() && self.peek() == Some(&Tok::Under) {
                self.pos += 1;
                sym.sub = self.subscript_text()?;
            } else if power.is_none() && self.peek() == Some(&Tok::Caret) {
                self.pos += 1;
                power = Some(self.script()?);
            } else {
                break;
            }
        }
        self.seen.push((sym.clone(), col));
        let e = Expr::Sym(sym);
        Ok(match power {
            Some(p) => Expr::bin(Op::Pow, e, p),
            None => e,
        })
    }

    fn symbol_base(&mut self) -> R<Symbol> {
        let plain = |base: String| Symbol {
            derivative: 0,
            accent: Accent::None,
            bold: false,
            base,
            sub: String::new(),
        };
        match self.peek().cloned() {
            Some(Tok::Letter(l)) => {
                self.pos += 1;
                Ok(plain(l.to_string()))
            }
            Some(Tok::Num(_, t)) => {
                self.pos += 1;
                Ok(plain(t))
            }
            Some(Tok::Cmd(c)) => {
                self.pos += 1;
                if GREEK.contains(&c.as_str()) {
                    return Ok(plain(c));
                }
                let accent = match c.as_str() {
                    "hat" => Some(Accent::Hat),
                    "vec" => Some(Accent::Vec),
                    "dot" => Some(Accent::Dot),
                    "ddot" => Some(Accent::Ddot),
                    _ => None,
                };
                if let Some(accent) = accent {
                    self.expect(&Tok::LBrace, &format!("{{ after \\{c}"))?;
                    let mut inner = self.symbol_base()?;
                    if self.peek() == Some(&Tok::Under) {
                        self.pos += 1;
                        inner.sub = self.subscript_text()?;
                    }
                    self.expect(&Tok::RBrace, &format!("}} closing \\{c}"))?;
                    inner.accent = accent;
                    return Ok(inner);
                }
                match c.as_str() {
                    "mathbf" | "boldsymbol" => {
                        self.expect(&Tok::LBrace, "{ after \\mathbf")?;
                        let mut inner = self.symbol_base()?;
                        self.expect(&Tok::RBrace, "} closing \\mathbf")?;
                        inner.bold = true;
                        Ok(inner)
                    }
                    "mathrm" | "text" => Ok(plain(self.word()?)),
                    _ => {
                        self.pos -= 1;
                        Err(self.error("a symbol of the paper"))
                    }
                }
            }
            _ => Err(self.error("a symbol")),
        }
    }

    /// `{word}` after `\mathrm`.
    fn word(&mut self) -> R<String> {
        self.expect(&Tok::LBrace, "{ after \\mathrm")?;
        let mut w = String::new();
        while let Some(Tok::Letter(l)) = self.peek() {
            w.push(*l);
            self.pos += 1;
        }
        self.expect(&Tok::RBrace, "} closing \\mathrm")?;
        Ok(w)
    }

    /// A subscript as text: `0`, `{10}`, `{\mathrm{cm}}`, `A`, `{123}`.
    fn subscript_text(&mut self) -> R<String> {
        let single = |t: &Tok| match t {
            Tok::Num(_, s) => Some(s.clone()),
            Tok::Letter(l) => Some(l.to_string()),
            _ => None,
        };
        if !self.eat(&Tok::LBrace) {
            let t = self.peek().and_then(single);
            return match t {
                Some(s) => {
                    self.pos += 1;
                    Ok(s)
                }
                None => Err(self.error("a subscript")),
            };
        }
        let mut text = String::new();
        loop {
            match self.peek().cloned() {
                Some(Tok::RBrace) => {
                    self.pos += 1;
                    break;
                }
                Some(Tok::Cmd(c)) if c == "mathrm" || c == "text" => {
                    self.pos += 1;
                    text.push_str(&self.word()?);
                }
                Some(Tok::Cmd(c)) if GREEK.contains(&c.as_str()) => {
                    self.pos += 1;
                    text.push_str(&c);
                }
                Some(t) => match single(&t) {
                    Some(s) => {
                        self.pos += 1;
                        text.push_str(&s);
                    }
                    None => return Err(self.error("a subscript or }")),
                },
                None => return Err(self.error("} closing the subscript")),
            }
        }
        if text.is_empty() {
            return Err(self.error("a non-empty subscript"));
        }
        Ok(text)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn one(latex: &str) -> String {
        let (chains, _) = parse(latex).unwrap_or_else(|e| panic!("{latex}: {e:?}"));
        chains
            .iter()
            .map(|c| {
                let mut s = c.sides[0].to_latex();
                for (r, side) in c.rels.iter().zip(&c.sides[1..]) {
                    s += &format!(" {} {}", r.latex(), side.to_latex());
                }
                s
            })
            .collect::<Vec<_>>()
            .join(" ; ")
    }

    #[test]
    fn the_physicists_slash() {
        assert_eq!(
            one(r"\frac{5 g / \epsilon (\beta + 2) a k}{t_0 - t}"),
            "((5 g)/(epsilon (beta + 2) a k))/((t_0 - t))"
        );
        assert_eq!(one(r"x^{1 / 2 (\beta + 1)}"), "(x)^{(1)/(2 (beta + 1))}");
    }

    #[test]
    fn function_arguments_and_powers() {
        assert_eq!(one(r"\cos\varpi t"), r"\cos(varpi t)");
        assert_eq!(
            one(r"\Omega \sin\alpha \hat{\mathbf{3}}"),
            r"Omega \sin(alpha) hat:bf:3"
        );
        assert_eq!(one(r"\cos^2\alpha_0"), r"(\cos(alpha_0))^{2}");
        assert_eq!(one(r"\omega^2_{10}"), "(omega_10)^{2}");
        assert_eq!(
            one(r"\sin\alpha_0 \cos\alpha_0"),
            r"\sin(alpha_0) \cos(alpha_0)"
        );
    }

    #[test]
    fn derivatives_crosses_and_chains() {
        assert_eq!(
            one(r"\frac{d\hat{\mathbf{1}}}{dt} = \vec{\omega}_{123} \times \hat{\mathbf{1}}"),
            "d/dt:hat:bf:1 = (vec:omega_123 \\times hat:bf:1)"
        );
        assert_eq!(
            one(r"\frac{d^2 \mathbf{r}_{\mathrm{cm}}}{dt^2}"),
            "d2/dt2:bf:r_cm"
        );
        assert_eq!(
            one(r"a \hat{\mathbf{3}} \times m g \hat{\mathbf{z}}"),
            "(a hat:bf:3 \\times m g hat:bf:z)"
        );
        assert_eq!(
            one(r"I_{11} = 2 k m a^2, \qquad I_{22} = k m a^2 = I_{33}"),
            "I_11 = 2 k m (a)^{2} ; I_22 = k m (a)^{2} = I_33"
        );
        assert_eq!(one(r"\dot{x}_A"), "dot:x_A");
        assert_eq!(one(r"\left| b \right| \geq 0"), r"\abs(b) \geq 0");
    }

    #[test]
    fn errors_name_the_column() {
        let e = parse(r"\alpha = \frac{g}{a").unwrap_err();
        assert_eq!(e.column, 20, "{e:?}");
        let e = parse(r"\alpha = \foo").unwrap_err();
        assert_eq!(e.column, 10, "{e:?}");
        assert!(e.message.contains("\\foo"), "{e:?}");
        let e = parse(r"a = b )").unwrap_err();
        assert_eq!(e.column, 7, "{e:?}");
    }
}
