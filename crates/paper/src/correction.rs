//! `corrections.yaml`: for an equation the checks find wrong at the root, its corrected form as
//! LaTeX and the reason, as the paper directory gives them (the built-in file otherwise). The
//! checks of the corrected forms are [`checks::corrections`]'s; this is only the data.

use serde::{Deserialize, Serialize};

/// One corrected equation, as `corrections.yaml` gives it.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Correction {
    /// The printed number.
    pub number: u32,
    /// The whole equation, corrected, in the paper's LaTeX.
    pub latex: String,
    /// Why, in one or two sentences.
    pub why: String,
}

/// Reads corrections from YAML text; each equation at most once. The error is the sentence
/// after the file's name.
pub fn parse(text: &str) -> Result<Vec<Correction>, String> {
    let cs: Vec<Correction> = serde_yaml::from_str(text).map_err(|e| e.to_string())?;
    let mut seen = std::collections::BTreeSet::new();
    for c in &cs {
        if !(1..=85).contains(&c.number) || !seen.insert(c.number) {
            return Err(format!(
                "eq {} is not an equation of the paper (1-85) or is corrected twice: give each \
                 equation once",
                c.number
            ));
        }
    }
    Ok(cs)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_equation_corrected_twice_or_out_of_range_is_refused() {
        let twice = "- { number: 76, latex: 'a', why: x }\n- { number: 76, latex: 'a', why: x }\n";
        assert!(parse(twice).unwrap_err().contains("eq 76"));
        let zero = "- { number: 0, latex: 'a', why: x }\n";
        assert!(parse(zero).unwrap_err().contains("eq 0"));
        assert_eq!(
            parse("- { number: 3, latex: 'a', why: x }\n")
                .unwrap()
                .len(),
            1
        );
    }
}
