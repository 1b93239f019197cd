//! An expression written back as LaTeX, for the prose the findings show a reader: the formula
//! in a card's text, between dollar signs, which the HTML sets as MathML, the LaTeX report as
//! TeX and a terminal as Unicode. It is written as the paper writes it (`\dot{\alpha}`,
//! `\hat{\mathbf{3}}`, `\frac{g}{a k}`, `\cos\alpha`), with parentheses only where the reading
//! needs them; [`Expr::to_latex`] keeps every parenthesis, for the parse tests and messages
//! about the reading itself.

use crate::expr::{Accent, Expr, Func, Op, Symbol};

impl Symbol {
    /// The symbol in LaTeX: `\dot{\alpha}`, `\Omega_{0}`, `\hat{\mathbf{3}}`,
    /// `\frac{d\mathbf{L}_{\mathrm{cm}}}{dt}`, `\omega_{\mathrm{rel}}`.
    pub fn tex(&self) -> String {
        let base = if crate::parse::GREEK.contains(&self.base.as_str()) {
            format!(r"\{}", self.base)
        } else if self.base.chars().count() > 1 {
            format!(r"\mathrm{{{}}}", self.base)
        } else {
            self.base.clone()
        };
        let base = if self.bold {
            format!(r"\mathbf{{{base}}}")
        } else {
            base
        };
        let mut x = match self.accent {
            Accent::None => base,
            Accent::Dot => format!(r"\dot{{{base}}}"),
            Accent::Ddot => format!(r"\ddot{{{base}}}"),
            Accent::Hat => format!(r"\hat{{{base}}}"),
            Accent::Vec => format!(r"\vec{{{base}}}"),
        };
        if !self.sub.is_empty() {
            let letters = self.sub.chars().filter(char::is_ascii_alphabetic).count();
            if letters > 1 {
                x = format!(r"{x}_{{\mathrm{{{}}}}}", self.sub);
            } else {
                x = format!("{x}_{{{}}}", self.sub);
            }
        }
        match self.derivative {
            0 => x,
            1 => format!(r"\frac{{d{x}}}{{dt}}"),
            n => format!(r"\frac{{d^{n} {x}}}{{dt^{n}}}"),
        }
    }
}

/// How tightly a form binds: a sum, a negation, a product, a power, an atom.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Binding {
    Sum,
    Negation,
    Product,
    Power,
    Atom,
}

fn binding(e: &Expr) -> Binding {
    match e {
        Expr::Num(x) if *x < 0.0 => Binding::Negation,
        Expr::Num(_) | Expr::Pi | Expr::Sym(_) => Binding::Atom,
        Expr::Call(..) | Expr::Bin(Op::Div, ..) => Binding::Atom,
        Expr::Neg(_) => Binding::Negation,
        Expr::Bin(Op::Add | Op::Sub, ..) => Binding::Sum,
        Expr::Bin(Op::Mul | Op::Dot | Op::Cross, ..) => Binding::Product,
        Expr::Bin(Op::Pow, ..) => Binding::Power,
    }
}

/// `e` in LaTeX, in parentheses when it binds more loosely than `least`.
fn operand(e: &Expr, least: Binding) -> String {
    let t = e.to_tex();
    if binding(e) < least {
        format!("({t})")
    } else {
        t
    }
}

/// Whether `e` is written as a fraction: a quotient, or a derivative `\frac{dx}{dt}`.
fn fraction_like(e: &Expr) -> bool {
    match e {
        Expr::Bin(Op::Div, ..) => true,
        Expr::Sym(s) => s.derivative > 0,
        _ => false,
    }
}

/// Whether a product's right factor starts with a digit, which juxtaposition would run into
/// the left factor's (`2 3`): such products are written with `\cdot`.
fn starts_with_digit(e: &Expr) -> bool {
    match e {
        Expr::Num(_) => true,
        Expr::Bin(Op::Mul | Op::Pow | Op::Dot | Op::Cross, a, _) => starts_with_digit(a),
        _ => false,
    }
}

impl Expr {
    /// The expression in LaTeX as the paper writes it (module documentation), for a formula
    /// between dollar signs in a finding's prose.
    pub fn to_tex(&self) -> String {
        match self {
            Expr::Num(x) => crate::expr::format_number(*x),
            Expr::Pi => r"\pi".into(),
            Expr::Sym(s) => s.tex(),
            Expr::Neg(a) => format!("-{}", operand(a, Binding::Product)),
            Expr::Call(Func::Sqrt, a) => format!(r"\sqrt{{{}}}", a.to_tex()),
            Expr::Call(Func::Abs, a) => format!(r"\left|{}\right|", a.to_tex()),
            Expr::Call(f, a) => match binding(a) {
                Binding::Atom if !fraction_like(a) && !matches!(**a, Expr::Call(..)) => {
                    format!("{}{}", f.latex(), spaced(&a.to_tex()))
                }
                _ => format!("{}({})", f.latex(), a.to_tex()),
            },
            Expr::Bin(Op::Pow, a, b) => {
                if let Expr::Call(f, x) = &**a {
                    if !matches!(f, Func::Sqrt | Func::Abs) {
                        let inner = Expr::Call(*f, x.clone()).to_tex();
                        let head = f.latex();
                        return format!("{head}^{{{}}}{}", b.to_tex(), &inner[head.len()..]);
                    }
                }
                let base = match &**a {
                    a if fraction_like(a) || matches!(a, Expr::Call(..)) => {
                        format!("({})", a.to_tex())
                    }
                    _ => operand(a, Binding::Atom),
                };
                format!("{base}^{{{}}}", b.to_tex())
            }
            Expr::Bin(op, a, b) => {
                let (left, right) = match op {
                    Op::Add | Op::Sub => (Binding::Sum, Binding::Product),
                    _ => (Binding::Product, Binding::Power),
                };
                let l = operand(a, left);
                let r = operand(b, right);
                match op {
                    Op::Add => format!("{l} + {r}"),
                    Op::Sub => format!("{l} - {r}"),
                    Op::Mul if starts_with_digit(b) => format!(r"{l} \cdot {r}"),
                    Op::Mul => format!("{l} {r}"),
                    Op::Div => format!(r"\frac{{{}}}{{{}}}", a.to_tex(), b.to_tex()),
                    Op::Dot => format!(r"{l} \cdot {r}"),
                    Op::Cross => format!(r"{l} \times {r}"),
                    Op::Pow => unreachable!("powers are written above"),
                }
            }
        }
    }
}

/// A function's argument after its command: `\cos\alpha`, `\cos 2`, `\cot\alpha_{0}`.
fn spaced(arg: &str) -> String {
    if arg.starts_with('\\') {
        arg.to_string()
    } else {
        format!(" {arg}")
    }
}

#[cfg(test)]
mod tests {
    use crate::parse::parse;

    fn tex(latex: &str) -> String {
        let (chains, _) = parse(latex).unwrap();
        let c = &chains[0];
        let mut s = c.sides[0].to_tex();
        for (r, side) in c.rels.iter().zip(&c.sides[1..]) {
            s += &format!(" {} {}", r.latex(), side.to_tex());
        }
        s
    }

    #[test]
    fn symbols_are_written_as_the_paper_writes_them() {
        assert_eq!(
            tex(r"\mathbf{a} = a \hat{\mathbf{3}}"),
            r"\mathbf{a} = a \hat{\mathbf{3}}"
        );
        assert_eq!(
            tex(r"\dot{\alpha} = \Omega_0 \cos\alpha"),
            r"\dot{\alpha} = \Omega_{0} \cos\alpha"
        );
        assert_eq!(
            tex(r"\frac{d \mathbf{L}_{\mathrm{cm}}}{dt} = \mathbf{a} \times \mathbf{F}"),
            r"\frac{d\mathbf{L}_{\mathrm{cm}}}{dt} = \mathbf{a} \times \mathbf{F}"
        );
        assert_eq!(
            tex(r"\omega_{\mathrm{rel}} = \vec{\omega}_{123}"),
            r"\omega_{\mathrm{rel}} = \vec{\omega}_{123}"
        );
    }

    #[test]
    fn parentheses_only_where_the_reading_needs_them() {
        assert_eq!(
            tex(r"\Omega_0^2 = \frac{g \cot\alpha_0}{k a \cos\alpha_0 + (2k+1) b}"),
            r"\Omega_{0}^{2} = \frac{g \cot\alpha_{0}}{k a \cos\alpha_{0} + (2 k + 1) b}"
        );
        assert_eq!(
            tex(r"\dot{\alpha}^2 \sin^2\alpha = -(a - b) c"),
            r"\dot{\alpha}^{2} \sin^{2}\alpha = -(a - b) c"
        );
        assert_eq!(
            tex(r"x = \sqrt{\frac{g}{a}} (a - (b + c))"),
            r"x = \sqrt{\frac{g}{a}} (a - (b + c))"
        );
        assert_eq!(tex(r"x = a - b c + 2 \cdot 3"), r"x = a - b c + 2 \cdot 3");
    }

    #[test]
    fn what_is_written_reads_back_the_same() {
        for latex in [
            r"\Omega_0^2 = \frac{g \cot\alpha_0}{k a \cos\alpha_0 + (2k+1) b}",
            r"\epsilon \varpi^2 (k + \cos^2\alpha_0) = \epsilon k \Omega_0^2 (1 - 2\cos^2\alpha_0) - 2 \delta k \Omega_0 \sin\alpha_0 \cos\alpha_0",
            r"\Omega_{\mathrm{max}} = \left(\frac{k(\beta+2)^2}{2\beta}\right)^{1/(2(\beta+1))} C^{1/(\beta+1)}",
            r"x = -(a - b) - c (d + e)^{2}",
            r"\frac{d\hat{\mathbf{1}}}{dt} = \vec{\omega}_{123} \times \hat{\mathbf{1}} = - \Omega \sin\alpha \hat{\mathbf{2}} - \dot{\alpha} \hat{\mathbf{3}}",
        ] {
            let (printed, _) = parse(latex).unwrap();
            let (again, _) = parse(&tex(latex)).unwrap();
            assert_eq!(printed, again, "{latex} -> {}", tex(latex));
        }
    }
}

#[cfg(test)]
mod paper_tests {
    use crate::parse::parse;
    use crate::Paper;

    /// Every relation of the built-in paper, written back as LaTeX, reads as the same tree:
    /// the parentheses left out are only those the reading does not need.
    #[test]
    fn every_printed_side_reads_back_from_its_latex() {
        let p = Paper::built_in().unwrap_or_else(|e| panic!("{e}"));
        let mut sides = 0;
        for eq in &p.equations {
            for chain in &eq.chains {
                for side in &chain.sides {
                    let tex = side.to_tex();
                    let (again, _) = parse(&format!("x = {tex}"))
                        .unwrap_or_else(|e| panic!("eq {}: {tex}: {e:?}", eq.entry.number));
                    assert_eq!(&again[0].sides[1], side, "eq {}: {tex}", eq.entry.number);
                    sides += 1;
                }
            }
        }
        assert!(sides > 150, "{sides} sides");
    }
}
