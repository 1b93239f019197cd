//! The paper as the input: `paper/equations.yaml`, `paper/symbols.yaml` and `paper/claims.yaml`
//! read (from the built-in copy or from a directory a user edited), every printed equation parsed
//! into relations ([`expr::Chain`]), and every symbol resolved to the quantity a check binds.
//!
//! The checks take their CLAIMED side from here, so an author can correct an equation and re-check
//! it with `rolling-disk check --paper DIR`, without touching Rust. The references (models,
//! integration, linearization) never import this module; `tests/architecture.rs` enforces it.

pub mod catalogue;
pub mod correction;
pub mod dimensions;
pub mod eval;
pub mod expr;
mod expr_tex;
pub mod forms;
mod load;
pub mod unit_tex;
pub use load::Texts;
pub mod mutate;
pub mod notation;
pub mod orient;
pub mod parse;
mod premises;
pub mod printed;
pub mod quantity;
pub mod tex;
mod tex_paper;
pub mod unvalued;

pub use catalogue::{ClaimEntry, EquationEntry, EstimateReading, Location, Rule, SymbolInfo};
pub use correction::Correction;
pub use eval::{EvalError, Value};
pub use expr::{Chain, Expr, Rel, Symbol};
pub use printed::Fit;
pub use quantity::{ClaimQuantity, NamedQuantity, ParameterValue};

use nalgebra::{RealField, Vector3};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Where the paper was read from.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum PaperSource {
    /// The copy compiled into the binary.
    BuiltIn,
    /// A directory given with `--paper`.
    Dir(PathBuf),
}

/// Why the paper could not be read.
#[derive(Debug, thiserror::Error)]
pub enum PaperError {
    /// A file could not be read.
    #[error("{path}: {source}")]
    Read {
        /// The file.
        path: String,
        /// Why.
        source: std::io::Error,
    },
    /// A file is not the YAML the schema asks for.
    #[error("{path}: {message}")]
    Yaml {
        /// The file.
        path: String,
        /// serde's message with its line.
        message: String,
    },
    /// An equation's LaTeX could not be read.
    #[error("{file}: eq {number}: column {column} of its latex: {message}\n  {latex}\n  {caret}")]
    Latex {
        /// The file.
        file: String,
        /// The printed number.
        number: u32,
        /// 1-based column.
        column: usize,
        /// What was expected.
        message: String,
        /// The LaTeX around the column, on one line.
        latex: String,
        /// A caret under the column.
        caret: String,
    },
    /// A symbol in an equation that no symbol table lists.
    #[error("{file}: eq {number}: column {column} of its latex: the symbol {symbol} is in neither paper/symbols.yaml nor the equation's `symbols` map: add it to one of them with the quantity it stands for")]
    UnknownSymbol {
        /// The file.
        file: String,
        /// The printed number.
        number: u32,
        /// 1-based column.
        column: usize,
        /// The symbol, canonical.
        symbol: String,
    },
    /// The equations are not the 85 of the paper, in order.
    #[error("{file}: {message}")]
    Structure {
        /// The file.
        file: String,
        /// What is wrong.
        message: String,
    },
}

/// A parsed equation: its entry, its relations and its resolved symbols.
#[derive(Debug, Clone)]
pub struct Equation {
    /// The entry of equations.yaml.
    pub entry: EquationEntry,
    /// The printed relations.
    pub chains: Vec<Chain>,
    /// Every symbol it uses, with what it stands for. A hash map with rustc's fast hasher:
    /// evaluation looks a symbol up at every node, and an ordered map's string comparisons
    /// were half the time of the sec. 11 checks (perf, 2026-11-24).
    pub symbols: rustc_hash::FxHashMap<Symbol, SymbolInfo>,
    /// The column of each symbol's first occurrence in the LaTeX, for messages.
    pub columns: rustc_hash::FxHashMap<Symbol, usize>,
}

/// One printed relation: `lhs rel rhs`, adjacent sides of a chain.
#[derive(Debug, Clone, Copy)]
pub struct Relation<'a> {
    /// Which chain (0 unless the equation prints several, like eq 18).
    pub chain: usize,
    /// Which relation of the chain (0 for the first `=`).
    pub index: usize,
    /// The relation.
    pub rel: Rel,
    /// Its left side.
    pub lhs: &'a Expr,
    /// Its right side.
    pub rhs: &'a Expr,
}

impl Relation<'_> {
    /// A short name for findings: "form 2" of a chain, "relation 1 of 2".
    pub fn name(&self) -> String {
        format!(
            "relation {} (${} {} {}$)",
            self.index + 1,
            self.lhs.to_tex(),
            self.rel.latex(),
            self.rhs.to_tex()
        )
    }
}

/// Values of the quantities a check knows at one point.
///
/// A short list searched in order rather than a hash map: a check binds a dozen quantities or
/// fewer, names are string literals of the checks, and a check clones its bindings for every
/// point it evaluates, so a list of `&'static str` keys clones without allocating strings and
/// looks up without hashing (the report spent a fifth of its time hashing and cloning here).
#[derive(Debug, Clone, Default)]
pub struct Bindings<T: RealField + Copy> {
    list: Vec<(&'static str, Value<T>)>,
}

impl<T: RealField + Copy> Bindings<T> {
    /// No values.
    pub fn new() -> Self {
        Self { list: Vec::new() }
    }

    /// Binds a scalar quantity.
    pub fn scalar(mut self, quantity: &'static str, x: T) -> Self {
        self.set(quantity, Value::Scalar(x));
        self
    }

    /// Binds a vector quantity.
    pub fn vector(mut self, quantity: &'static str, v: Vector3<T>) -> Self {
        self.set(quantity, Value::Vector(v));
        self
    }

    /// Binds any value.
    pub fn value(mut self, quantity: &'static str, v: Value<T>) -> Self {
        self.set(quantity, v);
        self
    }

    /// Binds in place (a quantity bound again takes the new value).
    pub fn set(&mut self, quantity: &'static str, v: Value<T>) {
        match self.list.iter_mut().find(|(q, _)| *q == quantity) {
            Some(slot) => slot.1 = v,
            None => self.list.push((quantity, v)),
        }
    }

    /// The value of a quantity, if bound.
    pub fn get(&self, quantity: &str) -> Option<Value<T>> {
        self.list
            .iter()
            .find(|(q, _)| same_name(q, quantity))
            .map(|(_, v)| *v)
    }
}

/// `a == b` for quantity names, rejecting most unequal pairs by their length and their first
/// and last bytes before comparing the whole (evaluation looks every symbol up in a list of a
/// dozen names; the full comparisons were most of the sec. 11 checks' time, perf 2026-11-24).
fn same_name(a: &str, b: &str) -> bool {
    let (x, y) = (a.as_bytes(), b.as_bytes());
    x.len() == y.len() && x.first() == y.first() && x.last() == y.last() && x == y
}

impl Equation {
    /// The printed number.
    pub fn number(&self) -> u32 {
        self.entry.number
    }

    /// Every relation, chain by chain, left to right.
    pub fn relations(&self) -> Vec<Relation<'_>> {
        let mut out = Vec::new();
        for (ci, c) in self.chains.iter().enumerate() {
            for (i, rel) in c.rels.iter().enumerate() {
                out.push(Relation {
                    chain: ci,
                    index: i,
                    rel: *rel,
                    lhs: &c.sides[i],
                    rhs: &c.sides[i + 1],
                });
            }
        }
        out
    }

    /// Evaluates an expression of this equation with the quantities of `b`.
    pub fn eval<T: RealField + Copy>(
        &self,
        e: &Expr,
        b: &Bindings<T>,
    ) -> Result<Value<T>, EvalError> {
        let lookup = |s: &Symbol| -> Result<Value<T>, EvalError> {
            let info = self
                .symbols
                .get(s)
                .ok_or_else(|| EvalError::Unbound(format!("{s} (not in any symbol table)")))?;
            b.get(&info.quantity).ok_or_else(|| {
                let named = format!(
                    "{s} at column {} of eq {}'s latex (quantity {}, {})",
                    self.columns.get(s).copied().unwrap_or(0),
                    self.entry.number,
                    info.quantity,
                    info.means
                );
                unvalued::note(named.clone());
                EvalError::Unbound(named)
            })
        };
        eval::eval(e, &lookup)
    }

    /// Evaluates a scalar expression.
    pub fn scalar<T: RealField + Copy>(&self, e: &Expr, b: &Bindings<T>) -> Result<T, EvalError> {
        self.eval(e, b)?.scalar()
    }
}

/// The paper, read and parsed.
#[derive(Debug, Clone)]
pub struct Paper {
    /// Where it came from.
    pub source: PaperSource,
    /// The 85 equations, in order.
    pub equations: Vec<Equation>,
    /// The prose claims.
    pub claims: Vec<ClaimEntry>,
    /// The corrected forms of `corrections.yaml` (their LaTeX is read when they are substituted,
    /// [`Paper::with_latex`], so a paper whose symbols no longer fit them still loads).
    pub corrections: Vec<Correction>,
    /// A hash of the three files' bytes (FNV-1a, 64 bits, hex), to tell two papers apart.
    pub hash: String,
    /// SHA-256 (hex) of the four files as read: equations.yaml, symbols.yaml, claims.yaml and
    /// corrections.yaml, in that order; what a report or a check's JSON names the paper by.
    pub sha256: String,
    /// The experimental fit of sec. 11, read from the claims.
    pub fit: Fit,
    /// symbols.yaml resolved, for equations parsed later ([`Paper::with_latex`]).
    global: BTreeMap<Symbol, SymbolInfo>,
    /// What a user should know about how the paper was read: where a LaTeX source's form of
    /// an equation differs from equations.yaml's (the source's is read).
    pub notes: Vec<String>,
}

impl Paper {
    /// The same paper with eq `n`'s LaTeX replaced by `latex` (an author's or a referee's
    /// correction), parsed and resolved as the files' are: a LaTeX error or an unknown symbol
    /// is an error naming the equation and the column. The hash changes with the LaTeX.
    pub fn with_latex(&self, n: u32, latex: &str) -> Result<Paper, PaperError> {
        let mut p = self.clone();
        let i = (n.clamp(1, 85) - 1) as usize;
        let mut entry = p.equations[i].entry.clone();
        entry.latex = latex.to_string();
        p.equations[i] = parse_entry(entry, &self.global, "a correction of equations.yaml")?;
        p.hash = fnv(&[&self.hash, &n.to_string(), latex]);
        Ok(p)
    }

    /// Where the paper was read from, in words: "the built-in paper" or "--paper DIR".
    pub fn origin(&self) -> String {
        match &self.source {
            PaperSource::BuiltIn => "the built-in paper".into(),
            PaperSource::Dir(d) => format!("--paper {}", d.display()),
        }
    }

    /// Equation `n` (1-85).
    pub fn equation(&self, n: u32) -> &Equation {
        &self.equations[(n.clamp(1, 85) - 1) as usize]
    }

    /// The same paper with eq `n`'s relations replaced (a mutant, or an author's correction).
    pub fn with_chains(&self, n: u32, chains: Vec<Chain>) -> Paper {
        let mut p = self.clone();
        p.equations[(n.clamp(1, 85) - 1) as usize].chains = chains;
        p
    }
}

/// The largest file of the paper the reader takes (the built-in equations.yaml is about 40 KB).
pub const MAX_FILE_BYTES: usize = 1 << 20;

fn too_large(file: &str, bytes: u64) -> PaperError {
    PaperError::Structure {
        file: file.to_string(),
        message: format!(
            "{bytes} bytes, more than the {MAX_FILE_BYTES} the reader takes for one of the \
             paper's files: is it the right file? (the built-in ones are under 40 KB)"
        ),
    }
}

/// At most `max` characters of `text`, on one line: what a message may quote of an input.
fn quote(text: &str, max: usize) -> String {
    let line = text.lines().next().unwrap_or("");
    let mut out: String = line.chars().take(max).collect();
    if out.len() < text.len() {
        out.push_str(" ...");
    }
    out
}

/// serde's message about a YAML file on one line, a value it quotes shortened, with its line
/// and column.
fn yaml_message(e: &serde_yaml::Error) -> String {
    let full = e.to_string();
    let location = e
        .location()
        .map(|l| format!(" at line {} column {}", l.line(), l.column()));
    let body = match &location {
        Some(l) if full.ends_with(l.as_str()) => &full[..full.len() - l.len()],
        _ => full.as_str(),
    };
    format!("{}{}", quote(body, 200), location.unwrap_or_default())
}

/// The LaTeX around `column` (1-based) and a caret under it, each on one line of at most about
/// 120 characters: what an error quotes of an equation.
fn latex_window(latex: &str, column: usize) -> (String, String) {
    let chars: Vec<char> = latex
        .chars()
        .map(|c| if c == '\n' { ' ' } else { c })
        .collect();
    let at = column.saturating_sub(1).min(chars.len());
    let start = at.saturating_sub(60);
    let end = (at + 60).min(chars.len());
    let mut shown: String = chars[start..end].iter().collect();
    let mut caret = " ".repeat(at - start);
    if start > 0 {
        shown = format!("... {shown}");
        caret = format!("    {caret}");
    }
    if end < chars.len() {
        shown.push_str(" ...");
    }
    caret.push('^');
    (shown, caret)
}

/// One entry of equations.yaml parsed, its symbols resolved against its own `symbols` map and
/// then the paper's table `global`.
fn parse_entry(
    entry: EquationEntry,
    global: &BTreeMap<Symbol, SymbolInfo>,
    eqfile: &str,
) -> Result<Equation, PaperError> {
    let latex_error = |column: usize, message: String| {
        let (latex, caret) = latex_window(&entry.latex, column);
        PaperError::Latex {
            file: eqfile.to_string(),
            number: entry.number,
            column,
            message,
            latex,
            caret,
        }
    };
    let (chains, seen) =
        parse::parse(&entry.latex).map_err(|e| latex_error(e.column, e.message))?;
    let chains = chains.into_iter().map(orient::oriented).collect();
    let local = resolve_table(&entry.symbols, eqfile, entry.number)?;
    let mut symbols = rustc_hash::FxHashMap::default();
    let mut columns = rustc_hash::FxHashMap::default();
    for (s, col) in seen {
        columns.entry(s.clone()).or_insert(col);
        let info =
            local
                .get(&s)
                .or_else(|| global.get(&s))
                .ok_or_else(|| PaperError::UnknownSymbol {
                    file: eqfile.to_string(),
                    number: entry.number,
                    column: col,
                    symbol: quote(&s.to_string(), 80),
                })?;
        symbols.insert(s, info.clone());
    }
    Ok(Equation {
        entry,
        chains,
        symbols,
        columns,
    })
}

/// A symbol table's LaTeX keys, read by the equation reader into canonical symbols.
fn resolve_table(
    table: &BTreeMap<String, SymbolInfo>,
    file: &str,
    number: u32,
) -> Result<BTreeMap<Symbol, SymbolInfo>, PaperError> {
    let mut out = BTreeMap::new();
    for (key, info) in table {
        let bad = |message: String| PaperError::Structure {
            file: file.to_string(),
            message: if number == 0 {
                format!("the key '{}' is not one symbol: {message}", quote(key, 80))
            } else {
                format!(
                    "eq {number}: the symbols key '{}' is not one symbol: {message}",
                    quote(key, 80)
                )
            },
        };
        let (chains, _) = parse::parse(key).map_err(|e| bad(e.message))?;
        match chains.as_slice() {
            [c] if c.rels.is_empty() => match &c.sides[0] {
                Expr::Sym(s) => {
                    out.insert(s.clone(), info.clone());
                }
                other => return Err(bad(format!("it reads as {}", other.to_latex()))),
            },
            _ => return Err(bad("it holds a relation".into())),
        }
    }
    Ok(out)
}

/// True when `premise` names a claim of `claims` or is `eq N` with N from 1 to 85.
fn premise_exists(premise: &str, claims: &[ClaimEntry]) -> bool {
    match premise.strip_prefix("eq ") {
        Some(n) => n.parse::<u32>().is_ok_and(|n| (1..=85).contains(&n)),
        None => claims.iter().any(|c| c.id == premise),
    }
}

/// SHA-256 over the texts, one after another, as lowercase hex.
fn sha256(texts: &[&str]) -> String {
    use sha2::{Digest, Sha256};
    let mut h = Sha256::new();
    for t in texts {
        h.update(t.as_bytes());
    }
    h.finalize().iter().map(|b| format!("{b:02x}")).collect()
}

/// FNV-1a over the texts, each followed by a zero byte.
fn fnv(texts: &[&str]) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for t in texts {
        for &b in t.as_bytes().iter().chain(std::iter::once(&0u8)) {
            h ^= u64::from(b);
            h = h.wrapping_mul(0x0000_0100_0000_01b3);
        }
    }
    format!("{h:016x}")
}

#[cfg(test)]
mod tests;
