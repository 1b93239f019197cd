//! Reading the paper: its four files from the binary or from a directory, each checked before
//! it is parsed (size, structure, the claims' readings and premises), into one [`Paper`].

use super::{
    correction, fnv, parse_entry, premise_exists, printed, resolve_table, sha256, too_large,
    yaml_message, BTreeMap, ClaimEntry, EquationEntry, Paper, PaperError, PaperSource, Path,
    SymbolInfo, MAX_FILE_BYTES,
};

pub(super) const EQUATIONS: &str = include_str!("../../../paper/equations.yaml");
pub(super) const SYMBOLS: &str = include_str!("../../../paper/symbols.yaml");
pub(super) const CLAIMS: &str = include_str!("../../../paper/claims.yaml");
pub(super) const CORRECTIONS: &str = include_str!("../../../paper/corrections.yaml");

/// The four texts of a paper: `equations.yaml`, `symbols.yaml`, `claims.yaml` and
/// `corrections.yaml`.
#[derive(Debug, Clone, Copy)]
pub struct Texts<'a> {
    /// The 85 equations.
    pub equations: &'a str,
    /// The symbol table.
    pub symbols: &'a str,
    /// The prose claims.
    pub claims: &'a str,
    /// The corrected forms.
    pub corrections: &'a str,
}

impl Texts<'static> {
    /// The texts compiled into the binary.
    pub const BUILT_IN: Texts<'static> = Texts {
        equations: EQUATIONS,
        symbols: SYMBOLS,
        claims: CLAIMS,
        corrections: CORRECTIONS,
    };
}

impl Paper {
    /// The built-in paper.
    pub fn built_in() -> Result<Paper, PaperError> {
        Self::from_texts(PaperSource::BuiltIn, Texts::BUILT_IN)
    }

    /// SHA-256 (hex) of the built-in paper's four files, as [`Paper::sha256`] of
    /// [`Paper::built_in`] gives it, without reading the paper: what `--version` names.
    pub fn built_in_sha256() -> String {
        let t = Texts::BUILT_IN;
        sha256(&[t.equations, t.symbols, t.claims, t.corrections])
    }

    /// The built-in paper, read once per process and shared: what a user's paper is compared
    /// with where a check must know what the built-in claim gives (its `rule`, its number).
    pub fn built_in_shared() -> &'static Paper {
        static PAPER: std::sync::OnceLock<Paper> = std::sync::OnceLock::new();
        PAPER.get_or_init(|| Paper::built_in().expect("the built-in paper is read by the tests"))
    }

    /// The paper of a directory holding equations.yaml, symbols.yaml (optional: the built-in
    /// table otherwise), claims.yaml (optional: the built-in claims otherwise) and
    /// corrections.yaml (optional: the built-in corrections otherwise).
    pub fn from_dir(dir: &Path) -> Result<Paper, PaperError> {
        let read = |name: &str, fallback: Option<&str>| -> Result<String, PaperError> {
            let path = dir.join(name);
            // The size is checked before the file is read.
            if let Ok(meta) = std::fs::metadata(&path) {
                if meta.len() > MAX_FILE_BYTES as u64 {
                    return Err(too_large(&path.display().to_string(), meta.len()));
                }
            }
            match (std::fs::symlink_metadata(&path), fallback) {
                (Err(e), Some(f)) if e.kind() == std::io::ErrorKind::NotFound => Ok(f.to_string()),
                (Err(source), None) => Err(PaperError::Read {
                    path: path.display().to_string(),
                    source,
                }),
                // A FIFO or a device is refused before it is opened (opening one blocks).
                _ => crate::tex_paper::read(&path, MAX_FILE_BYTES as u64),
            }
        };
        let eqs = read("equations.yaml", None)?;
        let syms = read("symbols.yaml", Some(SYMBOLS))?;
        let claims = read("claims.yaml", Some(CLAIMS))?;
        let corrections = read("corrections.yaml", Some(CORRECTIONS))?;
        let texts = Texts {
            equations: &eqs,
            symbols: &syms,
            claims: &claims,
            corrections: &corrections,
        };
        Self::from_texts(PaperSource::Dir(dir.to_path_buf()), texts)
    }

    /// Parses the four texts.
    pub fn from_texts(source: PaperSource, texts: Texts<'_>) -> Result<Paper, PaperError> {
        let Texts {
            equations,
            symbols,
            claims,
            corrections,
        } = texts;
        let file = |name: &str| match &source {
            PaperSource::BuiltIn => format!("paper/{name} (built in)"),
            PaperSource::Dir(d) => d.join(name).display().to_string(),
        };
        for (name, text) in [
            ("equations.yaml", equations),
            ("symbols.yaml", symbols),
            ("claims.yaml", claims),
        ] {
            if text.len() > MAX_FILE_BYTES {
                return Err(too_large(&file(name), text.len() as u64));
            }
        }
        let yaml = |name: &str, e: serde_yaml::Error| PaperError::Yaml {
            path: file(name),
            message: yaml_message(&e),
        };
        let entries: Vec<EquationEntry> =
            serde_yaml::from_str(equations).map_err(|e| yaml("equations.yaml", e))?;
        let table: BTreeMap<String, SymbolInfo> =
            serde_yaml::from_str(symbols).map_err(|e| yaml("symbols.yaml", e))?;
        let mut claim_entries: Vec<ClaimEntry> =
            serde_yaml::from_str(claims).map_err(|e| yaml("claims.yaml", e))?;
        crate::quantity::place_all(&mut claim_entries, claims, &file("claims.yaml")).map_err(
            |message| PaperError::Structure {
                file: file("claims.yaml"),
                message,
            },
        )?;
        if entries.len() != 85
            || entries
                .iter()
                .enumerate()
                .any(|(i, e)| e.number as usize != i + 1)
        {
            return Err(PaperError::Structure {
                file: file("equations.yaml"),
                message: "the entries must be the paper's 85 numbered equations, numbers 1 to 85 in order".into(),
            });
        }
        crate::premises::check(&entries, equations, &file("equations.yaml"))?;
        if let Some(e) = entries.iter().find(|e| {
            e.estimate
                .as_ref()
                .is_some_and(|r| !(r.factor.is_finite() && r.factor > 1.0))
        }) {
            return Err(PaperError::Structure {
                file: file("equations.yaml"),
                message: format!(
                    "eq {}, key `estimate`: `factor` must be a finite number above 1 (for \
                     example `estimate: {{ words: quoted, factor: 3 }}`)",
                    e.number
                ),
            });
        }
        check_references(&entries, &claim_entries, &file)?;
        let fit = printed::read_fit(&claim_entries, &file("claims.yaml"))?;
        let global = resolve_table(&table, &file("symbols.yaml"), 0)?;
        let eqfile = file("equations.yaml");
        let parsed = entries
            .into_iter()
            .map(|entry| parse_entry(entry, &global, &eqfile))
            .collect::<Result<Vec<_>, _>>()?;
        let corrections = correction::parse(corrections).map_err(|message| PaperError::Yaml {
            path: file("corrections.yaml"),
            message,
        })?;
        Ok(Paper {
            hash: fnv(&[equations, symbols, claims]),
            sha256: sha256(&[equations, symbols, claims, texts.corrections]),
            source,
            equations: parsed,
            claims: claim_entries,
            corrections,
            fit,
            global,
            notes: Vec::new(),
        })
    }
}

/// The claims' ids unique and their rules sound, and every reference between the entries
/// (`rests_on`, `part_of`, `restates`) to something the files hold; `file` names a file in
/// messages.
fn check_references(
    entries: &[EquationEntry],
    claim_entries: &[ClaimEntry],
    file: &dyn Fn(&str) -> String,
) -> Result<(), PaperError> {
    let mut ids = std::collections::BTreeSet::new();
    for c in claim_entries {
        if !ids.insert(c.id.as_str()) {
            return Err(PaperError::Structure {
                file: file("claims.yaml"),
                message: format!(
                    "claim `{}` is given twice: keep one (a fact stated in several places \
                     lists the others under `also_at`)",
                    c.id
                ),
            });
        }
        if let Some(problem) = c.rule.as_ref().and_then(|r| r.problem()) {
            return Err(PaperError::Structure {
                file: file("claims.yaml"),
                message: format!("claim `{}`, key `rule`: {problem}", c.id),
            });
        }
    }
    for c in claim_entries {
        if let Some(bad) = c
            .rests_on
            .iter()
            .find(|p| !premise_exists(p, claim_entries))
        {
            return Err(PaperError::Structure {
                file: file("claims.yaml"),
                message: format!(
                    "claim `{}`, key `rests_on`: `{bad}` is neither a claim id of this file \
                     nor `eq N` with N from 1 to 85",
                    c.id
                ),
            });
        }
        if let Some(whole) = c
            .part_of
            .as_ref()
            .filter(|w| **w == c.id || !claim_entries.iter().any(|e| e.id == **w))
        {
            return Err(PaperError::Structure {
                file: file("claims.yaml"),
                message: format!(
                    "claim `{}`, key `part_of`: `{whole}` is not the id of another claim of \
                     this file; write the id of the claim whose statement it is a part of",
                    c.id
                ),
            });
        }
        if let Some(n) = c.restates.filter(|n| !(1..=85).contains(n)) {
            return Err(PaperError::Structure {
                file: file("claims.yaml"),
                message: format!(
                    "claim `{}`, key `restates`: {n} is not an equation number; write the \
                     printed number of the equation it states again, from 1 to 85",
                    c.id
                ),
            });
        }
    }
    for e in entries {
        if let Some(bad) = e
            .rests_on
            .iter()
            .find(|p| !premise_exists(p, claim_entries))
        {
            return Err(PaperError::Structure {
                file: file("equations.yaml"),
                message: format!(
                    "eq {}, key `rests_on`: `{bad}` is not a claim id of claims.yaml",
                    e.number
                ),
            });
        }
    }
    Ok(())
}
