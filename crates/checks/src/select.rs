//! What the command line selects: `check --only LIST` (equation numbers, ranges and claim ids)
//! and `scenes --show NAME` (a built-in scene as a YAML template to edit).
//!
//! `--only` takes a comma-separated list. Each item is
//! - an equation number from 1 to 85, with or without a prefix: `50`, `eq50`, `eq 50`, `eq.50`,
//!   `equation-50`;
//! - a range of them: `23-25`, `eq23-25`, `eq23-eq25`, `23..25`;
//! - a claim id of `paper/claims.yaml`, with or without a prefix: `k-uniform-disk`,
//!   `claim:k-uniform-disk`, `claim-k-uniform-disk`.
//!
//! Anything else (a number outside 1-85, a backwards range, an equation or claim the paper has
//! but that cannot be checked, an unknown id) is rejected with one sentence that says what to
//! write instead.

use crate::check::Selection;
use crate::equations::{self, UNCHECKABLE_CLAIMS, UNCHECKABLE_EQUATIONS};
use paper::Paper;
use physics::scene::builtin::BUILTIN;
use thiserror::Error;

/// Why a selection was rejected.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum SelectError {
    /// The list is empty.
    #[error("--only: the list is empty; give equation numbers, ranges or claim ids, e.g. --only 23-25,50,k-uniform-disk")]
    Empty,
    /// A number outside the paper's 1-85.
    #[error("--only: {item}: the paper numbers its equations 1 to 85")]
    OutOfRange {
        /// The item as written.
        item: String,
    },
    /// A range whose ends are swapped.
    #[error("--only: the range {item} runs backwards; write {hi}-{lo}")]
    Backwards {
        /// The item as written.
        item: String,
        /// Its first end.
        hi: u32,
        /// Its second end.
        lo: u32,
    },
    /// An equation with no check.
    #[error("--only: eq {number} cannot be checked: {why}")]
    UncheckableEquation {
        /// The equation.
        number: u32,
        /// Why.
        why: String,
    },
    /// A claim with no check.
    #[error("--only: claim {id} cannot be checked: {why}")]
    UncheckableClaim {
        /// The claim.
        id: String,
        /// Why.
        why: String,
    },
    /// Neither a number nor a known claim id.
    #[error("--only: {item} is neither an equation number (1-85), a range like 23-25, nor a claim id{hint}; `rolling-disk check` lists the claim ids")]
    Unknown {
        /// The item as written.
        item: String,
        /// ", did you mean ...?" when a claim id is close.
        hint: String,
    },
    /// A scene name that is not built in.
    #[error("scenes --show: no built-in scene is called {name}; the built-in scenes are {known}")]
    UnknownScene {
        /// The name asked for.
        name: String,
        /// The names there are.
        known: String,
    },
}

/// Strips an equation prefix (`eq`, `eq.`, `eqs`, `equation`, followed by an optional space,
/// `-`, `:` or `_`), case-insensitively.
fn strip_equation_prefix(s: &str) -> &str {
    let lower = s.to_ascii_lowercase();
    for p in ["equations", "equation", "eqs", "eq"] {
        if lower.starts_with(p) {
            let rest = &s[p.len()..];
            let rest = rest.strip_prefix('.').unwrap_or(rest);
            return rest.trim_start_matches([' ', '-', ':', '_']);
        }
    }
    s
}

/// Strips a claim prefix (`claim:`, `claim-`, `claim `, `claim_`), case-insensitively.
fn strip_claim_prefix(s: &str) -> &str {
    if s.len() > 6 && s[..5].eq_ignore_ascii_case("claim") {
        if let Some(rest) = s[5..].strip_prefix([':', '-', ' ', '_']) {
            return rest;
        }
    }
    s
}

/// An equation number as written (after its prefix), if the text is all digits.
fn number(s: &str) -> Option<Result<u32, ()>> {
    let s = strip_equation_prefix(s.trim());
    if s.is_empty() || !s.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    Some(
        s.parse::<u32>()
            .ok()
            .filter(|n| (1..=85).contains(n))
            .ok_or(()),
    )
}

/// Parses the `--only` list against `paper`'s claims and the registered checks.
pub fn parse_only(text: &str, paper: &Paper) -> Result<Selection, SelectError> {
    let checked: Vec<u32> = equations::equations().iter().map(|e| e.number).collect();
    let claim_ids: Vec<String> = paper.claims.iter().map(|c| c.id.clone()).collect();
    let (mut numbers, mut claims) = (Vec::<u32>::new(), Vec::<String>::new());
    let items: Vec<&str> = text
        .split(',')
        .map(str::trim)
        .filter(|p| !p.is_empty())
        .collect();
    if items.is_empty() {
        return Err(SelectError::Empty);
    }
    for item in items {
        let out_of_range = || SelectError::OutOfRange { item: item.into() };
        let range = item
            .split_once("..")
            .or_else(|| item.split_once('-').filter(|(a, _)| number(a).is_some()));
        let picked: Vec<u32> = match (number(item), range) {
            (Some(n), _) => vec![n.map_err(|_| out_of_range())?],
            (None, Some((a, b))) if number(a).is_some() && number(b).is_some() => {
                let a = number(a).and_then(Result::ok).ok_or_else(out_of_range)?;
                let b = number(b).and_then(Result::ok).ok_or_else(out_of_range)?;
                if a > b {
                    return Err(SelectError::Backwards {
                        item: item.into(),
                        hi: b,
                        lo: a,
                    });
                }
                (a..=b).collect()
            }
            _ => {
                let id = strip_claim_prefix(item);
                if let Some((_, why)) = UNCHECKABLE_CLAIMS.iter().find(|(c, _)| *c == id) {
                    return Err(SelectError::UncheckableClaim {
                        id: id.into(),
                        why: (*why).into(),
                    });
                }
                if !claim_ids.iter().any(|c| c == id) {
                    return Err(SelectError::Unknown {
                        item: item.into(),
                        hint: hint(id, &claim_ids),
                    });
                }
                if !claims.iter().any(|c| c == id) {
                    claims.push(id.to_string());
                }
                continue;
            }
        };
        // Inside a range an equation without a check is skipped (`76-85` holds eq 82, whose
        // reason the report states); named alone, it is refused with that reason.
        let ranged = picked.len() > 1;
        for n in picked {
            if ranged && !checked.contains(&n) {
                continue;
            }
            if !checked.contains(&n) {
                let why = UNCHECKABLE_EQUATIONS
                    .iter()
                    .find(|(u, _)| *u == n)
                    .map_or("it has no check", |(_, w)| w);
                return Err(SelectError::UncheckableEquation {
                    number: n,
                    why: why.into(),
                });
            }
            if !numbers.contains(&n) {
                numbers.push(n);
            }
        }
    }
    numbers.sort_unstable();
    Ok(Selection {
        numbers: Some(numbers),
        claims: Some(claims),
    })
}

/// ", did you mean X?" for the claim id nearest to `id` ([`physics::nearest`]).
fn hint(id: &str, known: &[String]) -> String {
    physics::nearest::nearest(id, known.iter().map(String::as_str))
        .map_or(String::new(), |k| format!(" (did you mean {k}?)"))
}

/// A built-in scene as a YAML template: a header that says how to use it and what else each
/// key takes, then the scene itself, which loads unchanged.
pub fn scene_template(name: &str) -> Result<String, SelectError> {
    let Some((_, src)) = BUILTIN.iter().find(|(n, _)| *n == name) else {
        return Err(SelectError::UnknownScene {
            name: name.into(),
            known: BUILTIN
                .iter()
                .map(|(n, _)| *n)
                .collect::<Vec<_>>()
                .join(", "),
        });
    };
    let mut out = format!(
        "# The built-in scene {name}, to edit: save it (rolling-disk scenes --show {name} > my.yaml),\n\
         # change it, and run it with `rolling-disk simulate my.yaml`. Units are SI.\n\
         # model:  rolling | frictionless | dissipative | adiabatic | lab-frame | lab-frame-frictionless\n\
         #         | sliding (with friction: {{ mu, restitution }})\n\
         # dissipation: {{ epsilon, beta }} (eq 75; dissipative, adiabatic)\n\
         # mechanisms: [ {{ viscous_rolling: {{ time }} }}, ... ] (dissipative): rolling_friction: {{ coefficient }},\n\
         #         rolling_resistance: {{ lever }}, pivoting: {{ mu_radius }}, air_film: {{ viscosity }},\n\
         #         air_layer: {{ viscosity, kinematic }}\n\
         # start:  steady: {{ alpha0, b }} (+ perturb) | vertical_spin: {{ precession }}\n\
         #         | rolling_straight: {{ spin }} | explicit: {{ alpha, alpha_dot, precession, spin }}\n\
         #         (+ slip: {{ forward, sideways }} for sliding)\n\
         # stop:   time (required), alpha_below, lift_off\n\
         # record: alpha, alpha_dot, precession, spin, energy, heading, path, face, lz, normal_force, friction\n\
         #         (sliding: slip_speed, cm_speed, contact_gap, dissipated)\n\
         # solver: method rk4 (with step) | dopri5 | dop853; rtol; atol\n\n"
    );
    out.push_str(src);
    if !out.ends_with('\n') {
        out.push('\n');
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn paper() -> &'static Paper {
        Paper::built_in_shared()
    }

    fn nums(s: &str) -> Vec<u32> {
        parse_only(s, paper()).unwrap().numbers.unwrap()
    }

    #[test]
    fn numbers_ranges_and_prefixes() {
        assert_eq!(nums("50"), [50]);
        assert_eq!(nums("eq50, Eq 51,eq.52,equation-53"), [50, 51, 52, 53]);
        assert_eq!(nums("23-25"), [23, 24, 25]);
        assert_eq!(nums("eq23-eq25"), [23, 24, 25]);
        assert_eq!(nums("eq23-25,24"), [23, 24, 25]);
        assert_eq!(nums("23..25"), [23, 24, 25]);
    }

    #[test]
    fn claims_with_or_without_a_prefix() {
        let s = parse_only(
            "k-uniform-disk,claim:k-rim-disk,claim-k-uniform-disk,3",
            paper(),
        )
        .unwrap();
        assert_eq!(
            s.claims.unwrap(),
            ["k-uniform-disk".to_string(), "k-rim-disk".to_string()]
        );
        assert_eq!(s.numbers.unwrap(), [3]);
    }

    #[test]
    fn rejects_with_a_sentence() {
        let e = |s: &str| parse_only(s, paper()).unwrap_err().to_string();
        assert!(e("86").contains("1 to 85"), "{}", e("86"));
        assert!(e("eq0").contains("1 to 85"));
        assert!(e("25-23").contains("write 23-25"), "{}", e("25-23"));
        // Every equation has a check now (eq 82's since the squeeze-film reference).
        assert_eq!(parse_only("82", paper()).unwrap().numbers, Some(vec![82]));
        let range = parse_only("80-85", paper()).unwrap();
        assert_eq!(range.numbers, Some(vec![80, 81, 82, 83, 84, 85]));
        assert!(
            e("k-uniform-dsk").contains("did you mean k-uniform-disk"),
            "{}",
            e("k-uniform-dsk")
        );
        assert!(e("nonsense").contains("neither an equation number"));
        assert!(e(" , ").contains("empty"));
        let (id, _) = UNCHECKABLE_CLAIMS[0];
        assert!(e(id).contains("cannot be checked"), "{}", e(id));
    }

    #[test]
    fn every_scene_template_loads_as_the_scene_it_shows() {
        for (name, src) in BUILTIN {
            let t = scene_template(name).unwrap();
            let shown = physics::scene::Scene::parse(&t, name).expect("the template parses");
            let built = physics::scene::Scene::parse(src, name).expect("built in");
            assert_eq!(format!("{shown:?}"), format!("{built:?}"), "{name}");
        }
        assert!(scene_template("nope")
            .unwrap_err()
            .to_string()
            .contains("nutating-coin"));
    }
}
