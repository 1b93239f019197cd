//! The reader's symbols: plain and accented symbols with their scripts, fractions and time
//! derivatives.

use super::lex::{Tok, GREEK};
use super::{ParseError, Parser, R};
use crate::expr::{Accent, Expr, Op, Symbol};

impl Parser {
    pub(super) fn starts_plain_symbol(&self) -> bool {
        match self.peek() {
            Some(Tok::Letter(_)) => true,
            Some(Tok::Cmd(c)) => GREEK.contains(&c.as_str()),
            _ => false,
        }
    }

    pub(super) fn plain_symbol(&mut self) -> R<Expr> {
        if !self.starts_plain_symbol() {
            return Err(self.error("the argument of the function (a symbol or a parenthesis)"));
        }
        let col = self.column();
        self.symbol_with_scripts(col)
    }

    /// `\frac{A}{B}`, or a time derivative `\frac{d X}{dt}` / `\frac{d^2 X}{dt^2}`, or the
    /// operator written before its symbol, `\frac{d}{dt} X` / `\frac{d^2}{dt^2} X`.
    pub(super) fn fraction(&mut self, col: usize) -> R<Expr> {
        let save = (self.pos, self.seen.len());
        if let Some(e) = self.derivative(col) {
            return Ok(e);
        }
        self.pos = save.0;
        self.seen.truncate(save.1);
        if let Some(order) = self.derivative_operator()? {
            let at = self.column();
            let mut sym = self.symbol_base()?;
            if sym.derivative != 0 {
                return Err(ParseError {
                    column: at,
                    message: "a derivative of a derivative: write \\frac{d^2}{dt^2} X".into(),
                });
            }
            if self.peek() == Some(&Tok::Under) {
                self.pos += 1;
                sym.sub = self.subscript_text()?;
            }
            sym.derivative = order;
            self.seen.push((sym.clone(), at));
            return Ok(Expr::Sym(sym));
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
    pub(super) fn looks_like_derivative(&self) -> bool {
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

    pub(super) fn derivative(&mut self, col: usize) -> Option<Expr> {
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
        self.over_dt(order)?;
        sym.derivative = order;
        if let Some(last) = self.seen.last_mut() {
            last.0 = sym.clone();
        }
        Some(Expr::Sym(sym))
    }

    /// The end of a derivative's numerator and its denominator, `}{dt}` or `}{dt^2}`, of the
    /// numerator's `order`; `None` when what follows is not that.
    fn over_dt(&mut self, order: u8) -> Option<()> {
        let denominator = self.eat(&Tok::RBrace)
            && self.eat(&Tok::LBrace)
            && self.eat(&Tok::Letter('d'))
            && self.eat(&Tok::Letter('t'));
        (denominator && self.order()? == order && self.eat(&Tok::RBrace)).then_some(())
    }

    /// `{d}{dt}` or `{d^2}{dt^2}` after `\frac`, followed by a symbol: the order, the tokens
    /// eaten; followed by anything else (a group, `\dot X`, another fraction), an error saying
    /// how to write it, never the quotient $d/(dt)$; `None` with nothing eaten otherwise.
    fn derivative_operator(&mut self) -> R<Option<u8>> {
        let start = self.pos;
        let ok = (|| {
            if !(self.eat(&Tok::LBrace) && self.eat(&Tok::Letter('d'))) {
                return None;
            }
            let order = self.order()?;
            self.over_dt(order)?;
            Some((order, self.starts_plain_symbol_or_accent()))
        })();
        match ok {
            Some((order, true)) => Ok(Some(order)),
            Some((_, false)) => Err(ParseError {
                column: self.column(),
                message: "\\frac{d}{dt} is read before one symbol, as \\frac{d}{dt} X: write the \
                          derivative of what follows as a symbol's, \\frac{d X}{dt} or \
                          \\frac{d^2 X}{dt^2} (\\frac{d}{dt} \\dot X is \\frac{d^2 X}{dt^2})"
                    .into(),
            }),
            None => {
                self.pos = start;
                Ok(None)
            }
        }
    }

    fn starts_plain_symbol_or_accent(&self) -> bool {
        self.starts_plain_symbol()
            || matches!(self.peek(), Some(Tok::Cmd(c)) if matches!(c.as_str(), "hat" | "vec" | "mathbf" | "mathrm"))
    }

    /// True when the tokens from here read `d X / dt` or `d^2 X / dt^2` with X one symbol
    /// (its accent and subscript; a bold or accented X in braces).
    pub(super) fn looks_like_slash_derivative(&self) -> bool {
        let tok = |i: usize| self.toks.get(i).map(|(t, _)| t);
        if tok(self.pos) != Some(&Tok::Letter('d')) {
            return false;
        }
        // Find the first `/` at depth 0 within a short reach, then `d t` (or `d t ^ 2`).
        let mut depth = 0usize;
        let mut i = self.pos + 1;
        while let Some(t) = tok(i) {
            match t {
                Tok::LBrace => depth += 1,
                Tok::RBrace if depth == 0 => return false,
                Tok::RBrace => depth -= 1,
                Tok::Slash if depth == 0 => break,
                Tok::Cmd(c)
                    if depth == 0
                        && !(GREEK.contains(&c.as_str())
                            || matches!(
                                c.as_str(),
                                "hat" | "vec" | "dot" | "ddot" | "mathbf" | "mathrm"
                            )) =>
                {
                    return false
                }
                Tok::Plus | Tok::Minus | Tok::Equals | Tok::LParen | Tok::RParen | Tok::Comma
                    if depth == 0 =>
                {
                    return false
                }
                _ => {}
            }
            i += 1;
            if i > self.pos + 40 {
                return false;
            }
        }
        i > self.pos + 1
            && tok(i) == Some(&Tok::Slash)
            && tok(i + 1) == Some(&Tok::Letter('d'))
            && tok(i + 2) == Some(&Tok::Letter('t'))
    }

    /// `d X / dt` or `d^2 X / dt^2`: the time derivative of the symbol X.
    pub(super) fn slash_derivative(&mut self, col: usize) -> R<Expr> {
        self.pos += 1;
        let order = self
            .order()
            .ok_or_else(|| self.error("the order 2 of d^2"))?;
        let at = self.column();
        let e = self.symbol_with_scripts(col)?;
        let Expr::Sym(mut sym) = e else {
            return Err(ParseError {
                column: at,
                message: "a derivative d X/dt of a power: write the power after it, (dX/dt)^2"
                    .into(),
            });
        };
        self.expect(&Tok::Slash, "/ of dX/dt")?;
        self.expect(&Tok::Letter('d'), "dt")?;
        self.expect(&Tok::Letter('t'), "dt")?;
        if self.order() != Some(order) {
            return Err(self.error("the same order on dt as on d"));
        }
        sym.derivative = order;
        if let Some(last) = self.seen.last_mut() {
            last.0 = sym.clone();
        }
        Ok(Expr::Sym(sym))
    }

    /// `^2` after a `d` of a derivative (2), or nothing (1).
    pub(super) fn order(&mut self) -> Option<u8> {
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
    pub(super) fn symbol_with_scripts(&mut self, col: usize) -> R<Expr> {
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
        let e = match power {
            Some(p) => Expr::bin(Op::Pow, e, p),
            None => e,
        };
        super::powers_of_scalars(&e, col)?;
        Ok(e)
    }

    /// The symbol itself: its accent, boldness and base (accents nest, counted as groups).
    pub(super) fn symbol_base(&mut self) -> R<Symbol> {
        self.enter()?;
        let s = self.symbol_core();
        self.depth -= 1;
        s
    }

    fn symbol_core(&mut self) -> R<Symbol> {
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
                    // `\dot{\alpha}`, or `\dot\alpha` (one token, as TeX takes it).
                    let mut inner = if self.eat(&Tok::LBrace) {
                        let mut inner = self.symbol_base()?;
                        if self.peek() == Some(&Tok::Under) {
                            self.pos += 1;
                            inner.sub = self.subscript_text()?;
                        }
                        self.expect(&Tok::RBrace, &format!("}} closing \\{c}"))?;
                        inner
                    } else {
                        self.symbol_base()?
                    };
                    if accent == Accent::Vec && inner.accent == Accent::Vec && !inner.bold {
                        // `\vec{\vec I}`: a tensor, as `\mathbf{I}` writes it.
                        inner.accent = Accent::None;
                        inner.bold = true;
                        return Ok(inner);
                    }
                    inner.accent = accent;
                    return Ok(inner);
                }
                match c.as_str() {
                    "mathbf" | "boldsymbol" => {
                        let mut inner = if self.eat(&Tok::LBrace) {
                            let inner = self.symbol_base()?;
                            self.expect(&Tok::RBrace, "} closing \\mathbf")?;
                            inner
                        } else {
                            self.symbol_base()?
                        };
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
    pub(super) fn word(&mut self) -> R<String> {
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
    pub(super) fn subscript_text(&mut self) -> R<String> {
        let single = |t: &Tok| match t {
            Tok::Num(_, s) => Some(s.clone()),
            Tok::Letter(l) => Some(l.to_string()),
            _ => None,
        };
        if !self.eat(&Tok::LBrace) {
            // `_\mathrm{cm}` (from `_{\rm cm}`) and `_\alpha`: one command, as TeX takes it.
            match self.peek().cloned() {
                Some(Tok::Cmd(c)) if c == "mathrm" => {
                    self.pos += 1;
                    return self.word();
                }
                Some(Tok::Cmd(c)) if GREEK.contains(&c.as_str()) => {
                    self.pos += 1;
                    return Ok(c);
                }
                _ => {}
            }
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
                Some(Tok::Cmd(c)) if c == "mathrm" => {
                    self.pos += 1;
                    text.push_str(&self.word()?);
                }
                Some(Tok::Text(w))
                    if !w.is_empty() && w.chars().all(|c| c.is_ascii_alphanumeric()) =>
                {
                    self.pos += 1;
                    text.push_str(&w);
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
