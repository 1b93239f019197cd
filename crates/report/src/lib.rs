//! The reproduction report as plain data ([`Report`]), built once from the checks, the
//! catalogue, the figures, the speed/accuracy study and the synthetic experiment, then rendered
//! by templates (`render`) to HTML, LaTeX or JSON. Templates and figures only read it.

pub mod build;
pub mod cache;
pub mod document;
pub mod error;
pub mod figures;
mod finding_view;
pub mod fonts;
pub mod inline_math;
pub mod json;
pub mod kept_film;
pub mod mathml;
pub mod mutation;
pub mod number;
pub mod parts;
pub mod pipeline;
pub mod plain_math;
pub mod render;
pub mod results;
pub mod study;
pub mod study_table;
pub mod tex;
pub mod text_cells;
pub mod timing;

/// The tool's version and the commit it is built from (`build.rs`), as `--version` and every
/// output's provenance name it.
pub const TOOL_VERSION: &str = concat!(
    env!("CARGO_PKG_VERSION"),
    " (commit ",
    env!("ROLLING_DISK_COMMIT"),
    ")"
);

use checks::check::Tally;
use serde::Serialize;

/// The whole report.
#[derive(Debug, Clone, Serialize)]
pub struct Report {
    /// The paper's title.
    pub paper: String,
    /// The tool's version.
    pub version: String,
    /// How the checks were run.
    pub settings: RunSettings,
    /// Counts and the list of what fails.
    pub summary: Summary,
    /// The paper's sections with their equations.
    pub sections: Vec<SectionView>,
    /// The prose claims.
    pub claims: Vec<ClaimView>,
    /// The figures.
    pub figures: Vec<FigureView>,
    /// The parts whose studies were computed, in the report's order ([`parts::PARTS`]).
    pub parts: Vec<parts::PartView>,
    /// The built-in scenes the figures and checks use.
    pub scenes: Vec<SceneView>,
    /// The same results for tools (`report.json`), with numbers as numbers.
    #[serde(skip)]
    pub document: json::Document,
}

/// How the checks were run.
#[derive(Debug, Clone, Serialize)]
pub struct RunSettings {
    /// Integration method of the checks.
    pub method: String,
    /// Its relative tolerance.
    pub rtol: f64,
    /// The command that reproduces this report.
    pub command: String,
}

/// Counts and failures at a glance.
#[derive(Debug, Clone, Serialize)]
pub struct Summary {
    /// Verdicts on the numbered equations.
    pub equations: Tally,
    /// Verdicts on the prose claims.
    pub claims: Tally,
    /// Equations with no check, and why.
    pub unchecked: Vec<(u32, String)>,
    /// Claims of paper/claims.yaml with no check, and why.
    pub unchecked_claims: Vec<(String, String)>,
    /// What fails, equations first.
    pub failures: Vec<FailureView>,
    /// The root causes among the failing equations, each with the equations that inherit its
    /// error.
    pub root_causes: Vec<RootCauseView>,
    /// Failing equations whose cause is undetermined (a premise fails, and no check says whether
    /// they follow from it).
    pub undetermined: Vec<FailureView>,
    /// The failing prose claims.
    pub failing_claims: Vec<FailureView>,
    /// Corrected forms of the root causes and their consequences, each checked.
    pub corrections: Vec<CorrectionView>,
    /// What the corrections change downstream, in one sentence (empty when not computed).
    pub downstream: String,
    /// The mutation score in one sentence.
    pub mutation: String,
}

/// A corrected equation as the summary shows it.
#[derive(Debug, Clone, Serialize)]
pub struct CorrectionView {
    /// The printed number.
    pub number: u32,
    /// Its anchor.
    pub anchor: String,
    /// The corrected LaTeX, and as MathML.
    pub latex: String,
    /// MathML of the corrected form.
    pub mathml: String,
    /// Why.
    pub why: String,
    /// The printed form's verdict.
    pub printed: String,
    /// The corrected form's verdict.
    pub corrected: String,
    /// True when the corrected form holds.
    pub holds: bool,
    /// The corrected form's comparison in the paper's terms, or its detail.
    pub detail: String,
}

/// A root cause and its consequences, as the summary lists them.
#[derive(Debug, Clone, Serialize)]
pub struct RootCauseView {
    /// The failing equation where the error starts.
    pub failure: FailureView,
    /// Its cause in one sentence (it may also carry a failing premise's error).
    pub cause: String,
    /// The equations that follow correctly from it and so carry its error.
    pub consequences: Vec<FailureView>,
}

/// One failure, in one line.
#[derive(Debug, Clone, Serialize)]
pub struct FailureView {
    /// "eq 43" or a claim id.
    pub name: String,
    /// The anchor to jump to.
    pub anchor: String,
    /// What was compared.
    pub compared: String,
    /// Claimed value, formatted.
    pub claimed: String,
    /// Reference value, formatted.
    pub reference: String,
    /// The error, formatted.
    pub error: String,
    /// |true - paper| / |paper| of the values in `row`, or a dash where the paper's value is 0
    /// or they are orders.
    pub relative_error: String,
    /// Where the worst case was, with the unrounded computed value for printed numbers.
    pub at: String,
    /// The comparison in the paper's terms, when the check gives one: "quantity: paper X
    /// (printed), true Y unit".
    pub headline: Option<String>,
    /// Where the headline comparison is made.
    pub headline_at: Option<String>,
    /// The row of a table in the paper's terms: what is compared, the paper's value (with its
    /// unit, and whether printed or implied), the true value; the headline's where there is
    /// one, else the finding's own.
    pub row: [String; 3],
}

/// A section of the paper.
#[derive(Debug, Clone, Serialize)]
pub struct SectionView {
    /// Its number in the paper.
    pub number: u32,
    /// Its subject, in our words.
    pub title: String,
    /// Its numbered equations.
    pub equations: Vec<EquationView>,
}

/// One equation and its finding.
#[derive(Debug, Clone, Serialize)]
pub struct EquationView {
    /// Printed number.
    pub number: u32,
    /// LaTeX label.
    pub label: String,
    /// `eq-N`.
    pub anchor: String,
    /// The transcribed LaTeX.
    pub latex: String,
    /// Its MathML.
    pub mathml: String,
    /// What it says, in our words.
    pub says: String,
    /// Its kind.
    pub kind: String,
    /// The equations it follows from.
    pub premises: Vec<u32>,
    /// The finding (absent when it cannot be checked).
    pub finding: Option<FindingView>,
    /// Why it cannot be checked, when it cannot.
    pub uncheckable: Option<String>,
    /// Its mutation score in one sentence (built-in paper only).
    pub mutants: Option<String>,
}

/// A finding, formatted for reading.
#[derive(Debug, Clone, Serialize)]
pub struct FindingView {
    /// Method of the reference.
    pub method: String,
    /// What was compared.
    pub compared: String,
    /// Claimed value at the worst point.
    pub claimed: String,
    /// Reference value there.
    pub reference: String,
    /// Error there.
    pub error: String,
    /// Tolerance.
    pub tolerance: String,
    /// The rule it came from.
    pub rule: String,
    /// The verdict in words.
    pub verdict: String,
    /// A CSS/TeX class: holds, approx, definition, fails, error.
    pub class: String,
    /// Where the worst error was.
    pub at: String,
    /// A figure that shows it.
    pub figure: Option<String>,
    /// The printed value against the true one of the same quantity, in the paper's terms
    /// ("quantity: paper X (printed), true Y unit"), where the check gives one: the summary's
    /// comparison, which the card leads with.
    pub headline: Option<String>,
    /// Where the headline comparison is made.
    pub headline_at: Option<String>,
    /// What `error` measures, named: "relative error", "|fitted - claimed order|", ...
    pub error_measure: String,
    /// The equation whose failing finding this claim restates (anchor `eq-N`), if any.
    pub restates: Option<u32>,
}

/// One prose claim and its finding.
#[derive(Debug, Clone, Serialize)]
pub struct ClaimView {
    /// Its id.
    pub id: String,
    /// `claim-ID`.
    pub anchor: String,
    /// Its section.
    pub section: u32,
    /// The equation it is about.
    pub near_equation: u32,
    /// The claim in our words.
    pub claim: String,
    /// The number as printed, with its unit.
    pub printed: String,
    /// How it is computed.
    pub how: String,
    /// How its loose wording is read (paper/claims.yaml `rule`), in words.
    pub rule: Option<String>,
    /// Other places that state the same fact: "sec. 12 (eq 54): ...".
    pub also: Vec<String>,
    /// The finding (absent when it cannot be checked).
    pub finding: Option<FindingView>,
    /// The computed value of the quantity printed, with its unit (the headline's true value
    /// where the check gives one; an approximation's fitted order otherwise).
    pub computed: String,
    /// |computed - printed| / |printed|, or a dash where the printed value is 0, qualitative,
    /// or not the quantity computed (an approximation's order).
    pub relative_error: String,
    /// Why it cannot be checked, when it cannot.
    pub uncheckable: Option<String>,
}

/// A figure, rendered.
#[derive(Debug, Clone, Serialize)]
pub struct FigureView {
    /// Its number in the report (Figure 1, ..), the same in the HTML and the LaTeX.
    pub number: usize,
    /// Its name (the paper's where it is one of the paper's).
    pub name: String,
    /// Title.
    pub title: String,
    /// Caption, in our words.
    pub caption: String,
    /// Inline SVG (HTML report).
    #[serde(skip)]
    pub svg: String,
    /// File name of its PNG (LaTeX report), relative to the report.
    pub file: String,
    /// For one of the paper's figures: its version at the paper's size, beside what the
    /// paper's figure shows.
    pub paper: Option<PaperScaleView>,
}

/// One of the paper's figures at the paper's 3.0 in width ([`crate::figures::paper_scale`]).
#[derive(Debug, Clone, Serialize)]
pub struct PaperScaleView {
    /// Its label in the paper's LaTeX.
    pub label: String,
    /// What the paper's figure shows, in our words.
    pub says: String,
    /// Inline SVG at the paper's size (HTML report).
    #[serde(skip)]
    pub svg: String,
    /// File name of its paper-size PNG (LaTeX report), relative to the report.
    pub file: String,
}

/// A built-in scene.
#[derive(Debug, Clone, Serialize)]
pub struct SceneView {
    /// Name.
    pub name: String,
    /// Model.
    pub model: String,
    /// Description.
    pub description: String,
}

/// A number with 6 significant digits, for reading ([`number::significant`]).
pub fn fmt_num(x: f64) -> String {
    number::significant(x)
}
