//! A unit as the paper's files write it (`kg m^2/s`, `s^(beta-1)`, `sqrt(g/a)`, `m a g
//! alpha_dot`, read by [`crate::dimensions::parse_unit`]) set as LaTeX for the prose the
//! findings show: SI units upright (`\mathrm{kg}\,\mathrm{m}^{2}/\mathrm{s}`), and a unit made
//! of the disk's constants in its symbols (`m a^{2}`, `\sqrt{g/a}`, `m a g \dot{\alpha}`).

/// The disk's constants and variables a unit may be written in.
const DISK: &[&str] = &["m", "a", "g", "k", "alpha_dot", "Omega"];

/// A token of a unit: a name, a number, or one of `^ ( ) / - + *`.
fn tokens(unit: &str) -> Vec<String> {
    let mut out = Vec::new();
    let chars: Vec<char> = unit.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let run = |i: usize, f: &dyn Fn(char) -> bool| {
            let mut j = i;
            while j < chars.len() && f(chars[j]) {
                j += 1;
            }
            j
        };
        let j = if c.is_ascii_alphabetic() {
            run(i, &|c| c.is_ascii_alphanumeric() || c == '_')
        } else if c.is_ascii_digit() || c == '.' {
            run(i, &|c| c.is_ascii_digit() || c == '.')
        } else {
            i + 1
        };
        out.push(chars[i..j].iter().collect());
        i = j;
    }
    out
}

/// Whether the unit is written in the disk's constants: two or more of them and nothing else,
/// or a square root of them (`m` alone is the metre).
fn in_disk_constants(tokens: &[String]) -> bool {
    let names: Vec<&String> = tokens
        .iter()
        .filter(|t| t.starts_with(|c: char| c.is_ascii_alphabetic()) && t.as_str() != "sqrt")
        .filter(|t| !crate::parse::GREEK.contains(&t.as_str()))
        .collect();
    let all = names.iter().all(|n| DISK.contains(&n.as_str()));
    all && (names.len() >= 2 || tokens.iter().any(|t| t == "sqrt"))
}

/// `unit` in LaTeX (module documentation); a unit it cannot read is returned as it is.
pub fn unit_tex(unit: &str) -> String {
    let disk = in_disk_constants(&tokens(unit.trim()));
    unit_tex_as(unit, disk)
}

/// `unit` in LaTeX, its names read as the disk's constants (`disk`, as
/// [`crate::dimensions::Dimension::as_disk_factor`] writes a factor: `a`, `m a^2`) or as SI
/// units.
pub fn unit_tex_as(unit: &str, disk: bool) -> String {
    let tokens = tokens(unit.trim());
    let mut at = 0;
    let tex = expression(&tokens, &mut at, disk);
    if at < tokens.len() {
        return unit.to_string();
    }
    tex
}

/// `unit` in prose: its LaTeX between dollar signs, or `unit` itself when it needs no
/// mathematics (`rad/s`, `Hz`, `1`).
pub fn unit_prose(unit: &str) -> String {
    // A remark after the unit (`rad/s (printed as Hz)`) is prose.
    if let Some((head, remark)) = unit.split_once(" (") {
        return format!("{} ({remark}", unit_prose(head));
    }
    let plain = unit
        .chars()
        .all(|c| c.is_ascii_alphanumeric() || c == '/' || c == ' ');
    let names = tokens(unit);
    if plain && !in_disk_constants(&names) {
        unit.to_string()
    } else {
        format!("${}$", unit_tex(unit))
    }
}

/// A name: a Greek letter, the disk's symbol, or an SI unit set upright.
fn name(t: &str, disk: bool) -> String {
    match t {
        "alpha_dot" => r"\dot{\alpha}".into(),
        t if crate::parse::GREEK.contains(&t) => format!(r"\{t}"),
        t if disk || t.starts_with(|c: char| c.is_ascii_digit()) => t.into(),
        t => format!(r"\mathrm{{{t}}}"),
    }
}

/// The factors from `at` until a closing parenthesis or the end.
fn expression(tokens: &[String], at: &mut usize, disk: bool) -> String {
    let mut out = String::new();
    while *at < tokens.len() {
        let t = tokens[*at].as_str();
        match t {
            ")" => break,
            " " => {
                *at += 1;
                let next = tokens.get(*at).map(String::as_str);
                if !out.is_empty() && !matches!(next, Some("/" | ")" | " ") | None) {
                    out.push_str(if disk { " " } else { r"\," });
                }
            }
            "(" => {
                *at += 1;
                let inner = expression(tokens, at, disk);
                *at += 1;
                out.push_str(&format!("({inner})"));
            }
            "sqrt" if tokens.get(*at + 1).map(String::as_str) == Some("(") => {
                *at += 2;
                let inner = expression(tokens, at, disk);
                *at += 1;
                out.push_str(&format!(r"\sqrt{{{inner}}}"));
            }
            "^" => {
                *at += 1;
                out.push_str(&format!("^{{{}}}", exponent(tokens, at, disk)));
            }
            "-" | "+" | "/" | "*" => {
                out.push_str(t);
                *at += 1;
            }
            t => {
                out.push_str(&name(t, disk));
                *at += 1;
            }
        }
    }
    out
}

/// An exponent: a group `(beta-1)`, or a sign and a number or a group (`-1`, `-(beta+2)`).
fn exponent(tokens: &[String], at: &mut usize, disk: bool) -> String {
    let mut sign = "";
    if tokens.get(*at).is_some_and(|t| t == "-" || t == "+") {
        sign = if tokens[*at] == "-" { "-" } else { "" };
        *at += 1;
    }
    match tokens.get(*at).map(String::as_str) {
        Some("(") => {
            *at += 1;
            let inner = expression(tokens, at, disk);
            *at += 1;
            if sign.is_empty() {
                inner
            } else {
                format!("-({inner})")
            }
        }
        Some(t) => {
            *at += 1;
            format!("{sign}{}", name(t, disk))
        }
        None => sign.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn si_units_are_upright_and_the_disks_constants_are_symbols() {
        assert_eq!(
            unit_tex("kg m^2/s"),
            r"\mathrm{kg}\,\mathrm{m}^{2}/\mathrm{s}"
        );
        assert_eq!(unit_tex("rad^2/s^2"), r"\mathrm{rad}^{2}/\mathrm{s}^{2}");
        assert_eq!(
            unit_tex("rad^-(beta+2) s^(beta+1)"),
            r"\mathrm{rad}^{-(\beta+2)}\,\mathrm{s}^{\beta+1}"
        );
        assert_eq!(unit_tex("s^-1"), r"\mathrm{s}^{-1}");
        assert_eq!(unit_tex("m a^2"), "m a^{2}");
        assert_eq!(unit_tex("m a g alpha_dot"), r"m a g \dot{\alpha}");
        assert_eq!(unit_tex("sqrt(g/(a k))"), r"\sqrt{g/(a k)}");
        assert_eq!(unit_tex("sqrt(a/g)^(beta-1)"), r"\sqrt{a/g}^{\beta-1}");
    }

    #[test]
    fn a_unit_that_needs_no_mathematics_stays_text() {
        assert_eq!(unit_prose("rad/s"), "rad/s");
        assert_eq!(unit_prose("Hz"), "Hz");
        assert_eq!(unit_prose("1/s^2"), r"$1/\mathrm{s}^{2}$");
        assert_eq!(unit_prose("m a^2"), "$m a^{2}$");
        assert_eq!(unit_prose("m g"), "$m g$");
        assert_eq!(
            unit_prose("rad/s^2 (printed as Hz)"),
            r"$\mathrm{rad}/\mathrm{s}^{2}$ (printed as Hz)"
        );
    }
}
