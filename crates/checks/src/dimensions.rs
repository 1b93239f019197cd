//! The dimensional analysis of each check's subject, as `check --json` states it: an equation's
//! printed relations ([`paper::dimensions::analyse`]); a claim's printed unit against the unit
//! of the quantity its check computes, and, where the prose prints a relation rather than a
//! number, that relation's two sides ([`PRINTED`]).
//!
//! A claim's unit is written in SI (`kg m^2/s`, `g/(cm s)`) or in the disk's constants
//! (`m a^2`, `sqrt(g/a)`, `m a g alpha_dot`); the latter is read when every factor is one of
//! them and there are two or more (`m` alone is the metre).

use crate::checked::Subject;
use crate::finding::{Finding, Verdict};
use crate::harness::Bench;
use paper::dimensions::{analyse, parse_unit, Dimension};
use paper::unit_tex::{unit_prose, unit_tex_as};

/// Claims whose prose prints a relation or a unit to analyse, not only a number: (id, what is
/// printed, the unit of the quantity it is about, the unit of what is printed, whether a
/// missing factor is named in the disk's constants (a dropped factor of the physics) or in SI
/// units (a misprinted unit)).
pub const PRINTED: &[(&str, &str, &str, &str, bool)] = &[
    (
        "angular-momentum-near-vertical",
        r"$\mathbf{L} = -\Omega \hat{\mathbf{3}}$",
        "kg m^2/s",
        "rad/s",
        true,
    ),
    (
        "air-viscosity",
        "$\\eta = 1.8 \\times 10^{-4}$ g-cm$^{-1}$-s",
        "g/(cm s)",
        "g cm^-1 s",
        false,
    ),
    (
        "omega-units-hz-vs-rad-per-s",
        "$\\Omega = 560$ Hz",
        "rad/s",
        "Hz",
        false,
    ),
];

/// The disk's constants and variables a claim's unit may be written in, as SI units.
const DISK: &[(&str, &str)] = &[
    ("m", "kg"),
    ("a", "m"),
    ("g", "m/s^2"),
    ("k", "1"),
    ("alpha_dot", "1/s"),
    ("Omega", "1/s"),
];

/// A claim's unit as a dimension (at $\beta = 2$, the paper's preferred value).
pub fn claim_unit(unit: &str) -> Option<Dimension> {
    let unit = unit.trim();
    let inner = unit.strip_prefix("sqrt(").and_then(|u| u.strip_suffix(')'));
    let tokens: Vec<&str> = inner
        .unwrap_or(unit)
        .split([' ', '/', '(', ')'])
        .filter(|t| !t.is_empty())
        .map(|t| t.split('^').next().unwrap_or(t))
        .collect();
    let in_disk = tokens.iter().all(|t| DISK.iter().any(|(s, _)| s == t));
    let read = |u: &str| parse_unit(u, 2.0).ok();
    if in_disk && (tokens.len() >= 2 || inner.is_some()) {
        let d = read(&in_si(inner.unwrap_or(unit)))?;
        Some(if inner.is_some() { d.pow(0.5) } else { d })
    } else if inner.is_some() {
        None
    } else {
        read(unit)
    }
}

/// A unit written in the disk's constants with each constant replaced by its SI unit, keeping
/// the original's products and divisions (`g/(a k)` -> `(m/s^2)/((m) (1))`).
fn in_si(original: &str) -> String {
    physics::scene::message::rewrite_tokens(
        original,
        |c, _| c.is_ascii_alphanumeric() || c == '_',
        |token| {
            DISK.iter()
                .find(|(s, _)| *s == token)
                .map_or(token.to_string(), |(_, si)| format!("({si})"))
        },
    )
}

/// The dimensional analysis of `subject`, in words: `consistent`, or where and how it is not.
pub fn of(bench: &Bench, subject: &Subject, finding: Option<&Finding>) -> String {
    match subject {
        Subject::Equation { number, .. } => analyse(bench.paper.equation(*number)).to_string(),
        Subject::Claim { id } => of_claim(bench, id, finding),
    }
}

/// A failing claim whose printed relation drops a factor of the physics ([`PRINTED`], named in
/// the disk's constants) and whose direction is right (the reference has the printed sign) is
/// a [`Verdict::DimensionalSlip`], with the factor in its `at`; any other finding is returned
/// as it is.
pub fn slip(subject: &Subject, mut f: Finding, dimensions: &str) -> Finding {
    let Subject::Claim { id } = subject else {
        return f;
    };
    let dropped = PRINTED.iter().any(|p| p.0 == *id && p.4);
    let same_sign = f.claimed.signum() == f.reference.signum() && f.reference != 0.0;
    if dropped && f.verdict == Verdict::Fails && same_sign && dimensions.starts_with("inconsistent")
    {
        if let Some((_, factor)) = dimensions.rsplit_once("missing a factor ") {
            f.at = format!("{}; dimensional slip: missing {factor}", f.at);
            f.verdict = Verdict::DimensionalSlip;
        }
    }
    f
}

/// A claim's analysis (see the module's doc).
fn of_claim(bench: &Bench, id: &str, finding: Option<&Finding>) -> String {
    if let Some((_, relation, quantity, printed, disk)) = PRINTED.iter().find(|p| p.0 == id) {
        let (q, p) = (parse_unit(quantity, 2.0), parse_unit(printed, 2.0));
        return match (q, p) {
            (Ok(q), Ok(p)) if q.same(p) => "consistent".into(),
            (Ok(q), Ok(p)) => {
                format!(
                "inconsistent: the printed {relation} is in ${}$, the quantity in ${}$: missing \
                 a factor ${}$",
                unit_tex_as(&p.to_string(), false),
                unit_tex_as(&q.to_string(), false),
                match Some(q.over(p)).filter(|_| *disk).and_then(Dimension::as_disk_factor) {
                    Some(f) => unit_tex_as(&f, true),
                    None => unit_tex_as(&q.over(p).to_string(), false),
                }
            )
            }
            (Err(e), _) | (_, Err(e)) => format!("not analysed: {e}"),
        };
    }
    let Some(c) = bench.paper.claims.iter().find(|c| c.id == id) else {
        return "not analysed: the claim is not in claims.yaml".into();
    };
    let Some(printed) = claim_unit(&c.unit) else {
        return format!("not analysed: the unit `{}` is not read", c.unit);
    };
    // The check compares the claim's own number where its headline shows that number.
    let compared = finding
        .and_then(|f| f.headline.as_ref())
        .filter(|h| Some(h.paper) == c.claimed_value)
        .map(|h| h.unit.trim_end_matches(" (printed as Hz)").to_string());
    match compared.as_deref().map(|u| (u, claim_unit(u))) {
        Some((_, Some(d))) if d.same(printed) => "consistent".into(),
        Some((u, Some(d))) => format!(
            "inconsistent: the claim's unit {} is ${}$, the computed quantity's ({}) is ${}$",
            unit_prose(&c.unit),
            unit_tex_as(&printed.to_string(), false),
            unit_prose(u),
            unit_tex_as(&d.to_string(), false)
        ),
        _ => format!(
            "unit read: {} is ${}$ (the check compares another quantity)",
            unit_prose(&c.unit),
            unit_tex_as(&printed.to_string(), false)
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn claim_units_are_read_in_si_or_in_the_disks_constants() {
        let d = |u: &str| claim_unit(u).unwrap();
        assert!(d("m a^2").same(Dimension::new(1.0, 2.0, 0.0)));
        assert!(d("m g").same(Dimension::new(1.0, 1.0, -2.0)));
        assert!(d("sqrt(g/a)").same(Dimension::new(0.0, 0.0, -1.0)));
        assert!(d("sqrt(g/(a k))").same(Dimension::new(0.0, 0.0, -1.0)));
        assert!(d("m a g alpha_dot").same(Dimension::new(1.0, 2.0, -3.0)));
        assert!(d("m").same(Dimension::new(0.0, 1.0, 0.0)));
        assert!(d("g/(cm s)").same(Dimension::new(1.0, -1.0, -1.0)));
        assert!(d("s^(3/4)").same(Dimension::new(0.0, 0.0, 0.75)));
        assert!(d("Hz").same(Dimension::new(0.0, 0.0, -1.0)));
    }

    #[test]
    fn every_equation_of_the_paper_is_dimensionally_consistent() {
        let b = Bench::default();
        let bad: Vec<String> = b
            .paper
            .equations
            .iter()
            .map(|e| (e.number(), analyse(e)))
            .filter(|(_, h)| *h != paper::dimensions::Homogeneity::Consistent)
            .map(|(n, h)| format!("eq {n}: {h}"))
            .collect();
        assert!(bad.is_empty(), "{bad:#?}");
    }

    #[test]
    fn a_planted_factor_is_named() {
        let b = Bench::default();
        // Eq 72 with its potential energy multiplied by a: a sum of an energy and an energy
        // times a length.
        let latex = &b.paper.equation(72).entry.latex;
        let planted = latex.replacen("+ m g h", "+ m g h a", 1);
        assert_ne!(&planted, latex);
        let paper = b.paper.with_latex(72, &planted).unwrap();
        let h = analyse(paper.equation(72));
        let text = h.to_string();
        assert!(text.starts_with("inconsistent"), "{text}");
        assert!(text.contains("m g h a"), "{text}");
        assert!(
            text.contains("the second is the first times $a$;"),
            "{text}"
        );
    }

    #[test]
    fn the_dropped_angular_momentum_factor_is_named() {
        let b = Bench::default();
        let s = of(
            &b,
            &Subject::Claim {
                id: "angular-momentum-near-vertical".into(),
            },
            None,
        );
        assert!(s.contains("missing a factor $m a^{2}$"), "{s}");
        let s = of(
            &b,
            &Subject::Claim {
                id: "air-viscosity".into(),
            },
            None,
        );
        assert!(s.contains(r"missing a factor $\mathrm{s}^{-2}$"), "{s}");
    }
}
