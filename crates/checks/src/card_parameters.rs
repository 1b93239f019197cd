//! Every card names the parameters of the numbers it prints: a finding whose text (what was
//! compared and where) prints a value names at least one parameter with its value (`k = 1/4`,
//! `alpha0 0.3`, `beta = 2`, `C = 1.09e9 s^-3`, `mu = 0.2`) or the disk it was found on. Numbers
//! that are not values are set aside first: equation numbers (`eq 31`, `eqs 23-25`), exponents
//! of units and powers (`s^-1`, `^(1/3)`), digits inside a symbol's name (`omega_1`, `t0`) and
//! the count of points (`worst of 6 points`).

#![cfg(test)]

use crate::check::{run_checks, Selection};
use crate::harness::Bench;

/// Symbols that name a parameter or a point of evaluation when a value follows them.
const PARAMETERS: &[&str] = &[
    "k", "alpha0", "alpha_0", "alpha", "b/a", "b", "beta", "epsilon", "mu", "C", "a", "Omega_0",
    "Omega0", "Omega", "omega_1", "omega_10", "delta", "r", "t", "T",
];

/// Words that name the disk a value was found on.
const DISKS: &[&str] = &[
    "uniform disk",
    "toy disk",
    "toy-sized",
    "ring",
    "annulus",
    "hoop",
    "benchmark start",
];

/// `text` with its formulas' LaTeX read as the words the parameters are matched on:
/// `$\alpha_{0} = 0.3$` as `alpha_0 = 0.3`.
fn without_tex(text: &str) -> String {
    text.replace("\\mathrm", "")
        .chars()
        .filter(|c| !"$\\{}".contains(*c))
        .collect()
}

/// `text` with the numbers that are not values removed (module documentation).
fn values_only(text: &str) -> String {
    let text = &without_tex(text);
    let mut out = String::with_capacity(text.len());
    let chars: Vec<char> = text.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        let rest: String = chars[i..].iter().take(12).collect();
        let skip_number = |j: usize| {
            let mut j = j;
            while j < chars.len() && (chars[j].is_ascii_digit() || "-/,. ".contains(chars[j])) {
                if chars[j] == ' ' && !chars.get(j + 1).is_some_and(char::is_ascii_digit) {
                    break;
                }
                j += 1;
            }
            j
        };
        if rest.starts_with("eqs ") || rest.starts_with("eq ") {
            let at = i + if rest.starts_with("eqs ") { 4 } else { 3 };
            i = skip_number(at);
            continue;
        }
        if chars[i] == '^' {
            let mut j = i + 1;
            if chars.get(j) == Some(&'(') {
                while j < chars.len() && chars[j] != ')' {
                    j += 1;
                }
                i = j + 1;
            } else {
                while j < chars.len() && (chars[j].is_ascii_digit() || "-+".contains(chars[j])) {
                    j += 1;
                }
                i = j;
            }
            continue;
        }
        if chars[i].is_ascii_digit()
            && i > 0
            && (chars[i - 1].is_ascii_alphabetic() || chars[i - 1] == '_')
        {
            i += 1;
            continue;
        }
        out.push(chars[i]);
        i += 1;
    }
    let mut s = out;
    while let Some(at) = s.find("(worst of ") {
        let end = s[at..].find(')').map_or(s.len(), |e| at + e + 1);
        s.replace_range(at..end, "");
    }
    s
}

/// Whether `text` names a parameter followed by its value, or a disk.
fn names_a_parameter(text: &str) -> bool {
    if DISKS.iter().any(|d| text.contains(d)) {
        return true;
    }
    PARAMETERS.iter().any(|p| {
        text.match_indices(p).any(|(at, _)| {
            let before = text[..at].chars().next_back();
            if before.is_some_and(|c| c.is_ascii_alphanumeric() || c == '_') {
                return false;
            }
            let after = text[at + p.len()..].trim_start();
            let after = after
                .strip_prefix(['=', '<', '>'])
                .map_or(after, str::trim_start);
            let spaced = text[at + p.len()..].starts_with([' ', '=', '<', '>']);
            spaced
                && after
                    .trim_start_matches(['-', '+'])
                    .starts_with(|c: char| c.is_ascii_digit())
        })
    })
}

#[test]
fn numbers_that_are_not_values_are_set_aside() {
    assert_eq!(
        values_only("eq 82 differentiated, Omega from eq 31"),
        " differentiated, Omega from "
    );
    assert!(
        !values_only("s^-1 and C^(1/3), omega_1, t0 (worst of 6 points)")
            .contains(char::is_numeric)
    );
    assert!(names_a_parameter("at k = 0.25, alpha0 0.3"));
    assert!(names_a_parameter(&values_only(
        r"at $k = 0.25$, $\alpha = 0.3$"
    )));
    assert!(names_a_parameter("the toy disk at 2 s"));
    assert!(!names_a_parameter(
        "error 7.8e-4 at the smallest, a factor 3"
    ));
    assert!(!names_a_parameter(
        "against the amplitude epsilon/alpha0 from 3e-4"
    ));
}

/// Every check's card that prints a value names a parameter of it.
#[test]
fn every_card_names_the_parameters_of_its_numbers() {
    let checked = run_checks(&Bench::default(), &Selection::default(), 2, &|_, _| {})
        .expect("every check runs");
    let bare: Vec<String> = checked
        .iter()
        .filter_map(|c| {
            let f = c.finding.as_ref().ok()?;
            let text = values_only(&format!("{}; {}", f.compared, f.at));
            (text.contains(|c: char| c.is_ascii_digit()) && !names_a_parameter(&text))
                .then(|| format!("{}: {} | {}", c.subject.name(), f.compared, f.at))
        })
        .collect();
    assert!(
        bare.is_empty(),
        "cards printing numbers with no parameter named:\n{}",
        bare.join("\n")
    );
}
