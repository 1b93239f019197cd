//! The author's forms of the same mathematics, generated: rewrites of an equation's LaTeX text
//! into the spellings real sources use (plain TeX's `\over`, the old font switches, Unicode
//! letters and minus, accents and `\mathbf` without braces, `\mathrm{d}`, `\frac12`, rows and
//! alignment points, labels and tags, words in `\text`, `\operatorname`, `\sin{x}`, `|b|`,
//! `dX/dt`, `\frac{d}{dt}X`). Each rewrite keeps the mathematics, so the text it gives reads back
//! as the same relations, node for node; `tests/author_forms.rs` requires the checks' outcomes on
//! them to be those of the printed text.

use crate::tex::macros::group;

/// One family of rewrites: its name and the rewrite.
pub struct Form {
    /// A short name for messages.
    pub name: &'static str,
    /// The LaTeX rewritten (unchanged where the family has nothing to rewrite).
    pub rewrite: fn(&str) -> String,
}

/// Every family.
pub const FORMS: &[Form] = &[
    Form {
        name: "over",
        rewrite: over,
    },
    Form {
        name: "font switches",
        rewrite: font_switches,
    },
    Form {
        name: "unicode",
        rewrite: unicode,
    },
    Form {
        name: "unbraced accents",
        rewrite: unbraced_accents,
    },
    Form {
        name: "upright d",
        rewrite: upright_d,
    },
    Form {
        name: "rows",
        rewrite: rows,
    },
    Form {
        name: "label, tag, nonumber",
        rewrite: label,
    },
    Form {
        name: "words",
        rewrite: words,
    },
    Form {
        name: "operatorname",
        rewrite: operatorname,
    },
    Form {
        name: "braced arguments",
        rewrite: braced_arguments,
    },
    Form {
        name: "bars",
        rewrite: bars,
    },
    Form {
        name: "operator derivative",
        rewrite: operator_derivative,
    },
    Form {
        name: "slash derivative",
        rewrite: slash_derivative,
    },
    Form {
        name: "frac digits",
        rewrite: frac_digits,
    },
];

/// Every `\cmd{A}` (with `args` braced arguments) rewritten by `f`, innermost first.
fn each_command(s: &str, cmd: &str, args: usize, f: &dyn Fn(&[String]) -> String) -> String {
    let mut out = String::new();
    let mut i = 0;
    while let Some(k) = s[i..].find(cmd) {
        let at = i + k;
        let after = at + cmd.len();
        if s[after..].starts_with(|c: char| c.is_ascii_alphabetic()) {
            out.push_str(&s[i..after]);
            i = after;
            continue;
        }
        let mut j = after;
        let mut parts = Vec::new();
        for _ in 0..args {
            match group(s, j) {
                Some((g, end)) => {
                    parts.push(each_command(g, cmd, args, f));
                    j = end;
                }
                None => break,
            }
        }
        out.push_str(&s[i..at]);
        if parts.len() == args {
            out.push_str(&f(&parts));
            i = j;
        } else {
            out.push_str(cmd);
            i = after;
        }
    }
    out.push_str(&s[i..]);
    out
}

fn over(s: &str) -> String {
    each_command(s, r"\frac", 2, &|p| format!("{{{} \\over {}}}", p[0], p[1]))
}

fn font_switches(s: &str) -> String {
    let s = each_command(s, r"\mathbf", 1, &|p| format!(r"{{\bf {}}}", p[0]));
    each_command(&s, r"\mathrm", 1, &|p| format!(r"{{\rm {}}}", p[0]))
}

fn unicode(s: &str) -> String {
    let mut out = s.replace('-', "\u{2212}");
    for (name, letter) in [
        ("alpha", "α"),
        ("beta", "β"),
        ("gamma", "γ"),
        ("delta", "δ"),
        ("epsilon", "ε"),
        ("eta", "η"),
        ("mu", "μ"),
        ("varpi", "ϖ"),
        ("omega", "ω"),
        ("Omega", "Ω"),
        ("pi", "π"),
    ] {
        out = each_word(&out, name, letter);
    }
    out
}

/// `\name` (not followed by a letter) replaced by `to`.
fn each_word(s: &str, name: &str, to: &str) -> String {
    let pat = format!("\\{name}");
    let mut out = String::new();
    let mut i = 0;
    while let Some(k) = s[i..].find(&pat) {
        let at = i + k;
        let after = at + pat.len();
        out.push_str(&s[i..at]);
        if s[after..].starts_with(|c: char| c.is_ascii_alphabetic()) {
            out.push_str(&pat);
        } else {
            out.push_str(to);
        }
        i = after;
    }
    out.push_str(&s[i..]);
    out
}

fn unbraced_accents(s: &str) -> String {
    let mut s = s.to_string();
    for cmd in [r"\dot", r"\ddot", r"\hat", r"\vec", r"\mathbf"] {
        s = each_command(&s, cmd, 1, &|p| {
            let inner = p[0].trim();
            let one = inner.chars().count() == 1
                || (inner.starts_with('\\') && inner[1..].chars().all(|c| c.is_ascii_alphabetic()));
            if one {
                format!("{cmd} {inner}")
            } else {
                format!("{cmd}{{{inner}}}")
            }
        });
    }
    s
}

fn upright_d(s: &str) -> String {
    s.replace(r"\frac{d", r"\frac{\mathrm{d}")
        .replace("{dt}", r"{\mathrm{d}t}")
        .replace("{dt^2}", r"{\mathrm{d}t^2}")
}

/// `a = b = c` as eqnarray rows `a &=& b \\ &=& c` (for a single chain).
fn rows(s: &str) -> String {
    if s.contains(',') || s.contains(';') {
        return s.to_string();
    }
    let mut out = String::new();
    let mut first = true;
    for (k, part) in s.split(" = ").enumerate() {
        if k > 0 {
            out.push_str(if first { " &=& " } else { r" \\ &=& " });
            first = false;
        }
        out.push_str(part);
    }
    out
}

fn label(s: &str) -> String {
    format!(r"{s} \label{{eq:form}} \tag{{A}} \nonumber")
}

fn words(s: &str) -> String {
    format!(r"{s} \quad \text{{(as printed)}}")
}

fn operatorname(s: &str) -> String {
    let mut out = s.to_string();
    for f in ["sin", "cos", "tan", "cot"] {
        out = each_word(&out, f, &format!(r"\operatorname{{{f}}}"));
    }
    out
}

/// `\sin\alpha` as `\sin{\alpha}` where the argument is one symbol with a subscript at most.
fn braced_arguments(s: &str) -> String {
    let mut out = s.to_string();
    for f in ["sin", "cos", "tan", "cot"] {
        for g in ["alpha_0", "alpha"] {
            out = out.replace(&format!(r"\{f}\{g} "), &format!(r"\{f}{{\{g}}} "));
        }
    }
    out
}

fn bars(s: &str) -> String {
    s.replace(r"\left| b \right|", "|b|")
        .replace(r"\left| \Omega_0 \right|", r"|\Omega_0|")
        .replace(r"\left| \Omega \right|", r"|\Omega|")
}

fn operator_derivative(s: &str) -> String {
    each_command(s, r"\frac", 2, &|p| match p[1].as_str() {
        "dt" if p[0].starts_with('d') && !p[0].starts_with("d^") && p[0].trim() != "d" => {
            format!(r"\frac{{d}}{{dt}} {}", p[0][1..].trim())
        }
        _ => format!(r"\frac{{{}}}{{{}}}", p[0], p[1]),
    })
}

fn slash_derivative(s: &str) -> String {
    each_command(s, r"\frac", 2, &|p| match p[1].as_str() {
        "dt" if p[0].starts_with('d') && !p[0].starts_with("d^") && p[0].trim() != "d" => {
            format!(r"{{d {} / dt}}", p[0][1..].trim())
        }
        _ => format!(r"\frac{{{}}}{{{}}}", p[0], p[1]),
    })
}

fn frac_digits(s: &str) -> String {
    s.replace(r"\frac{1}{2}", r"\frac12")
        .replace(r"\frac{3}{2}", r"\frac32")
        .replace(r"\frac{5}{2}", r"\frac52")
        .replace(r"\frac{b}{a}", r"\frac ba")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse::parse;

    /// Every family, and every pair of families, on every equation of the built-in
    /// transcription: the same relations, node for node.
    #[test]
    fn every_form_and_every_pair_reads_as_the_printed_relations() {
        let entries: Vec<crate::EquationEntry> =
            serde_yaml::from_str(crate::load::EQUATIONS).unwrap();
        let mut changed = vec![0usize; FORMS.len()];
        for e in &entries {
            let (want, _) = parse(&e.latex).unwrap();
            for (i, a) in FORMS.iter().enumerate() {
                let one = (a.rewrite)(&e.latex);
                changed[i] += usize::from(one != e.latex);
                for b in FORMS.iter().skip(i) {
                    let text = (b.rewrite)(&one);
                    let got = parse(&text).unwrap_or_else(|err| {
                        panic!(
                            "eq {} in {} + {}: {text}: {err:?}",
                            e.number, a.name, b.name
                        )
                    });
                    assert_eq!(
                        got.0, want,
                        "eq {} in {} + {}: {text}",
                        e.number, a.name, b.name
                    );
                }
            }
        }
        // Each family rewrites some equation (a family that rewrites nothing tests nothing).
        for (f, n) in FORMS.iter().zip(&changed) {
            assert!(*n > 0, "{} rewrites no equation", f.name);
        }
    }
}
