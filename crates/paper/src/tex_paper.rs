//! The paper read from its LaTeX source (`--paper paper.tex`, or a folder holding one): each
//! entry of `equations.yaml` takes its LaTeX from the source's equation with the same `\label`;
//! the entries' other keys (section, kind, premises, symbols) and the symbols, claims and
//! corrections come from the folder's YAML files where present, else the built-in ones.

use super::{
    fnv, latex_window, parse, sha256, EquationEntry, Paper, PaperError, PaperSource, Texts,
};
use std::path::{Path, PathBuf};

/// The largest LaTeX source the reader takes (the paper's is about 70 KB).
pub const MAX_SOURCE_BYTES: u64 = 8 << 20;

/// A file read for the paper: refused at once if it is not a regular file (a FIFO, a device).
pub(super) fn read(path: &Path, limit: u64) -> Result<String, PaperError> {
    files::input::read_text(path, limit).map_err(|e| PaperError::Structure {
        file: path.display().to_string(),
        message: e.reason(),
    })
}

/// A file of `dir`, or `None` where it does not exist.
fn optional(dir: Option<&Path>, name: &str) -> Result<Option<String>, PaperError> {
    let Some(dir) = dir else { return Ok(None) };
    let path = dir.join(name);
    match std::fs::symlink_metadata(&path) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(None),
        _ => read(&path, super::MAX_FILE_BYTES as u64).map(Some),
    }
}

impl Paper {
    /// The paper at `path` as `--paper` takes it: a LaTeX source, a folder holding one (with
    /// optional YAML files beside it), or a folder of YAML files ([`Paper::from_dir`]).
    pub fn from_path(path: &Path) -> Result<Paper, PaperError> {
        let meta = std::fs::metadata(path).map_err(|source| PaperError::Read {
            path: path.display().to_string(),
            source,
        })?;
        if !meta.is_dir() {
            return Self::from_tex(path, path, None);
        }
        let mut sources: Vec<PathBuf> = std::fs::read_dir(path)
            .map_err(|source| PaperError::Read {
                path: path.display().to_string(),
                source,
            })?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "tex"))
            .collect();
        sources.sort();
        match sources.as_slice() {
            [] => Self::from_dir(path),
            [one] => Self::from_tex(path, one, Some(path)),
            many => Err(PaperError::Structure {
                file: path.display().to_string(),
                message: format!(
                    "holds {} .tex files ({}): give --paper the one that is the paper",
                    many.len(),
                    many.iter()
                        .filter_map(|p| p.file_name().map(|n| n.to_string_lossy().into_owned()))
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
            }),
        }
    }

    /// The paper of the LaTeX source `tex`, named `shown` in its source, with the YAML files of
    /// `dir` where present.
    fn from_tex(shown: &Path, tex: &Path, dir: Option<&Path>) -> Result<Paper, PaperError> {
        let source = read(tex, MAX_SOURCE_BYTES)?;
        let file = tex.display().to_string();
        let found = super::tex::equations(&source).map_err(|message| PaperError::Structure {
            file: file.clone(),
            message,
        })?;
        let equations = optional(dir, "equations.yaml")?;
        let symbols = optional(dir, "symbols.yaml")?;
        let claims = optional(dir, "claims.yaml")?;
        let corrections = optional(dir, "corrections.yaml")?;
        let built_in = Texts::BUILT_IN;
        let eqfile = match (&equations, dir) {
            (Some(_), Some(d)) => format!("{}/equations.yaml", d.display()),
            _ => "paper/equations.yaml (built in)".to_string(),
        };
        let yaml = equations.as_deref().unwrap_or(built_in.equations);
        let mut entries: Vec<EquationEntry> =
            serde_yaml::from_str(yaml).map_err(|e| PaperError::Yaml {
                path: eqfile.clone(),
                message: super::yaml_message(&e),
            })?;
        crate::premises::check(&entries, yaml, &eqfile)?;
        let mut numbered = found.iter().filter(|t| t.number.is_some());
        if let Some(extra) =
            numbered.find(|t| !entries.iter().any(|e| Some(&e.label) == t.label.as_ref()))
        {
            let lost = entries.iter().find(|e| {
                Some(e.number) == extra.number
                    && !found.iter().any(|t| t.label.as_ref() == Some(&e.label))
            });
            if let (None, Some(entry)) = (&extra.label, lost) {
                return Err(PaperError::Structure {
                    file: format!("{file}:{}", extra.line),
                    message: format!(
                        "equation ({}) has no \\label, and eq {} of {eqfile} has the label `{}` \
                         that no equation carries: add \\label{{{}}} to it",
                        entry.number, entry.number, entry.label, entry.label
                    ),
                });
            }
            return Err(PaperError::Structure {
                file: format!("{file}:{}", extra.line),
                message: format!(
                    "equation ({}){} has no entry in {eqfile}: add one with its label, or \
                     write \\nonumber if it is not one of the paper's equations",
                    extra.number.unwrap_or(0),
                    extra
                        .label
                        .as_ref()
                        .map_or(" (without a \\label)".to_string(), |l| format!(
                            " labelled `{l}`"
                        ))
                ),
            });
        }
        let mut notes = Vec::new();
        for entry in &mut entries {
            let Some(eq) = found
                .iter()
                .find(|t| t.label.as_deref() == Some(&entry.label))
            else {
                return Err(PaperError::Structure {
                    file: eqfile,
                    message: format!(
                        "eq {}: its label `{}` is on no equation of {file}: add \\label{{{}}} to \
                         the equation it transcribes, or correct the entry's `label`",
                        entry.number, entry.label, entry.label
                    ),
                });
            };
            if eq.number != Some(entry.number) {
                return Err(PaperError::Structure {
                    file: format!("{file}:{}", eq.line),
                    message: format!(
                        "the equation labelled `{}` is numbered {} by LaTeX, but is eq {} in \
                         {eqfile}: number the entries as the source numbers its equations",
                        entry.label,
                        eq.number
                            .map_or("with a \\tag".to_string(), |n| n.to_string()),
                        entry.number
                    ),
                });
            }
            let (tex_chains, _) = parse::parse(&eq.latex).map_err(|e| {
                let (latex, caret) = latex_window(&eq.latex, e.column);
                PaperError::Latex {
                    file: format!("{file}:{} (\\label{{{}}})", eq.line, entry.label),
                    number: entry.number,
                    column: e.column,
                    message: e.message,
                    latex,
                    caret,
                }
            })?;
            let read = |c: Vec<super::Chain>| -> Vec<super::Chain> {
                c.into_iter().map(super::orient::oriented).collect()
            };
            let tex_chains = read(tex_chains);
            let same = parse::parse(&entry.latex).is_ok_and(|(c, _)| read(c) == tex_chains);
            if !same {
                notes.push(format!(
                    "eq {} ({file}:{}): the source's form is read, and differs from {eqfile}'s: \
                     source `{}`, equations.yaml `{}`",
                    entry.number,
                    eq.line,
                    tex_chains
                        .iter()
                        .map(|c| {
                            let mut s = c.sides[0].to_plain();
                            for (r, side) in c.rels.iter().zip(&c.sides[1..]) {
                                s += &format!(" {} {}", r.latex(), side.to_plain());
                            }
                            s
                        })
                        .collect::<Vec<_>>()
                        .join("; "),
                    entry.latex
                ));
            }
            entry.latex = eq.latex.clone();
        }
        let merged = serde_yaml::to_string(&entries).map_err(|e| PaperError::Yaml {
            path: eqfile.clone(),
            message: e.to_string(),
        })?;
        let texts = Texts {
            equations: &merged,
            symbols: symbols.as_deref().unwrap_or(built_in.symbols),
            claims: claims.as_deref().unwrap_or(built_in.claims),
            corrections: corrections.as_deref().unwrap_or(built_in.corrections),
        };
        let mut paper = Self::from_texts(PaperSource::Dir(shown.to_path_buf()), texts)?;
        paper.hash = fnv(&[&source, yaml, texts.symbols, texts.claims]);
        paper.sha256 = sha256(&[
            &source,
            yaml,
            texts.symbols,
            texts.claims,
            texts.corrections,
        ]);
        paper.notes = notes;
        Ok(paper)
    }
}
