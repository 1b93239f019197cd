//! Rendering the report through tera templates (templates/, compiled into the binary), and
//! writing it atomically: every file goes to a temporary name first, then is renamed.

use super::Report;
use crate::error::ReportError;
use crate::figures::Figure;
use crate::json::{Outcome, VerdictKind};
use crate::parts::PartView;
use crate::FailureView;
use files::output::write_set_file;
use serde::Serialize;
use std::path::{Path, PathBuf};
use tera::{Context, Tera};

/// The output formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// One self-contained HTML file.
    Html,
    /// A LaTeX document and its PNG figures.
    Latex,
    /// The report's data.
    Json,
}

fn templates() -> Result<Tera, ReportError> {
    let mut t = Tera::default();
    t.add_raw_templates(vec![
        (
            "report.html",
            include_str!("../../../templates/report.html.tera"),
        ),
        (
            "partials/finding.html",
            include_str!("../../../templates/partials/finding.html.tera"),
        ),
        (
            "partials/study_table.html",
            include_str!("../../../templates/partials/study_table.html.tera"),
        ),
        (
            "partials/failing_claims.html",
            include_str!("../../../templates/partials/failing_claims.html.tera"),
        ),
        (
            "partials/failing_claims.tex",
            include_str!("../../../templates/partials/failing_claims.tex.tera"),
        ),
        (
            "partials/study_section.html",
            include_str!("../../../templates/partials/study_section.html.tera"),
        ),
        (
            "partials/study_section.tex",
            include_str!("../../../templates/partials/study_section.tex.tera"),
        ),
        (
            "partials/study_table.tex",
            include_str!("../../../templates/partials/study_table.tex.tera"),
        ),
        (
            "report.tex",
            include_str!("../../../templates/report.tex.tera"),
        ),
        (
            "partials/finding.tex",
            include_str!("../../../templates/partials/finding.tex.tera"),
        ),
    ])
    .map_err(|e| ReportError::Template(format!("a report template is broken: {e:?}")))?;
    for p in crate::parts::PARTS {
        let own = p.templates();
        t.add_raw_templates([
            (format!("parts/{}.html", p.name()), own.html),
            (format!("parts/{}.tex", p.name()), own.tex),
        ])
        .map_err(|e| {
            ReportError::Template(format!(
                "the templates of the report part {} are broken: {e:?}",
                p.name()
            ))
        })?;
    }
    t.register_filter("tex", super::tex::filter);
    t.register_filter("num", super::number::filter);
    super::inline_math::register(&mut t);
    t.autoescape_on(vec![".html"]);
    Ok(t)
}

/// The message of a failed rendering of `template`, with its causes.
fn failed(template: &str, e: &tera::Error) -> ReportError {
    let mut msg = format!("cannot render {template}: {e}");
    let mut source = std::error::Error::source(e);
    while let Some(s) = source {
        msg.push_str(&format!(": {s}"));
        source = s.source();
    }
    ReportError::Template(msg)
}

/// `part` rendered by its own template in `format` (`html` or `tex`).
fn render_part(t: &Tera, part: &PartView, format: &str) -> Result<String, ReportError> {
    let template = format!("parts/{}.{format}", part.name);
    let mut ctx = Context::new();
    ctx.insert("part", part);
    t.render(&template, &ctx).map_err(|e| failed(&template, &e))
}

/// Each of the report's parts rendered by its own template in `format` (`html` or `tex`).
fn parts(t: &Tera, report: &Report, format: &str) -> Result<Vec<String>, ReportError> {
    report
        .parts
        .iter()
        .map(|p| render_part(t, p, format))
        .collect()
}

/// One part rendered alone in `format` (`html` or `tex`), as the report includes it.
pub fn part(part: &PartView, format: &str) -> Result<String, ReportError> {
    render_part(&templates()?, part, format)
}

/// The summary's prose claims that do not hold, one table per verdict: the claims that fail;
/// the unit misprints (numbers right in the unit the text means, wrong in the unit printed);
/// the dimensional slips (a printed quantity right up to a dropped factor with a dimension);
/// and the claims whose verdict depends on a choice the paper leaves open. Only the first are
/// failures of the number, so the others are listed apart.
#[derive(Serialize)]
struct ProseFailures<'a> {
    /// Verdict `fails`.
    fails: Vec<&'a FailureView>,
    /// Verdict `unit misprint`.
    unit_misprints: Vec<&'a FailureView>,
    /// Verdict `dimensional slip`.
    dimensional_slips: Vec<&'a FailureView>,
    /// Verdict `depends on <choice>`.
    depends: Vec<&'a FailureView>,
}

impl<'a> ProseFailures<'a> {
    /// The summary's failing claims of `report`, sorted by the verdict of each claim's record.
    fn of(report: &'a Report) -> Self {
        let verdict = |f: &FailureView| {
            report
                .document
                .claims
                .iter()
                .find_map(|c| match &c.outcome {
                    Outcome::Checked { verdict, .. } if f.anchor == format!("claim-{}", c.id) => {
                        Some(*verdict)
                    }
                    _ => None,
                })
        };
        let with = |kind: VerdictKind| -> Vec<&'a FailureView> {
            report
                .summary
                .failing_claims
                .iter()
                .filter(|f| verdict(f).as_ref() == Some(&kind))
                .collect()
        };
        let apart = [
            VerdictKind::UnitMisprint,
            VerdictKind::DimensionalSlip,
            VerdictKind::Depends,
        ];
        Self {
            fails: report
                .summary
                .failing_claims
                .iter()
                .filter(|f| !verdict(f).is_some_and(|v| apart.contains(&v)))
                .collect(),
            unit_misprints: with(VerdictKind::UnitMisprint),
            dimensional_slips: with(VerdictKind::DimensionalSlip),
            depends: with(VerdictKind::Depends),
        }
    }
}

fn render(report: &Report, template: &str) -> Result<String, ReportError> {
    let t = templates()?;
    let ctx = Context::from_serialize(report).map_err(|e| ReportError::Input(e.to_string()))?;
    let mut ctx = ctx;
    ctx.insert("prose_failures", &ProseFailures::of(report));
    let svgs: Vec<&str> = report.figures.iter().map(|f| f.svg.as_str()).collect();
    ctx.insert("svgs", &svgs);
    let paper_svgs: Vec<&str> = report
        .figures
        .iter()
        .map(|f| f.paper.as_ref().map_or("", |p| p.svg.as_str()))
        .collect();
    ctx.insert("paper_svgs", &paper_svgs);
    if template == "report.html" {
        ctx.insert("fonts", super::fonts::css());
        ctx.insert("parts_html", &parts(&t, report, "html")?);
    } else {
        ctx.insert("parts_tex", &parts(&t, report, "tex")?);
    }
    t.render(template, &ctx).map_err(|e| failed(template, &e))
}

/// The HTML report: one file, math as MathML, figures as inline SVG, nothing fetched.
pub fn html(report: &Report) -> Result<String, ReportError> {
    render(report, "report.html")
}

/// The LaTeX report (figures are PNG files under `figures/`).
pub fn latex(report: &Report) -> Result<String, ReportError> {
    render(report, "report.tex")
}

/// The report's data as JSON, following `schemas/report.schema.json` (see [`super::json`]).
pub fn json(report: &Report) -> Result<String, ReportError> {
    super::json::to_json(&report.document)
}

/// Writes the report in `formats` to `dir`, each file atomically; returns the paths written.
pub fn write(
    report: &Report,
    figures: &[Figure],
    dir: &Path,
    formats: &[Format],
) -> Result<Vec<PathBuf>, ReportError> {
    std::fs::create_dir_all(dir).map_err(|e| ReportError::io("create", dir, e))?;
    let mut written = Vec::new();
    let put = |name: &str, text: String, written: &mut Vec<PathBuf>| -> Result<(), ReportError> {
        let path = dir.join(name);
        write_set_file(&path, text.as_bytes()).map_err(|e| ReportError::io("write", &path, e))?;
        written.push(path);
        Ok(())
    };
    for f in formats {
        match f {
            Format::Html => put("report.html", html(report)?, &mut written)?,
            Format::Json => put("report.json", json(report)?, &mut written)?,
            Format::Latex => {
                let fig_dir = dir.join("figures");
                std::fs::create_dir_all(&fig_dir)
                    .map_err(|e| ReportError::io("create", &fig_dir, e))?;
                // Each PNG is drawn on its own rayon thread; the files do not depend on that.
                use rayon::prelude::*;
                let paper_dir = fig_dir.join("paper");
                std::fs::create_dir_all(&paper_dir)
                    .map_err(|e| ReportError::io("create", &paper_dir, e))?;
                let png = |dir: &Path, name: &str, draw: &dyn Fn(&Path) -> Result<(), crate::figures::FigureError>| {
                    // Written whole through files::output::write_set_file.
                    let path = dir.join(format!("{name}.png"));
                    draw(&path)?;
                    Ok::<_, ReportError>(path)
                };
                let pngs: Vec<Vec<PathBuf>> = figures
                    .par_iter()
                    .map(|fig| {
                        let mut out = vec![png(&fig_dir, fig.name, &|p| fig.drawing.to_png(p))?];
                        // The paper's figures again at the paper's size.
                        if crate::figures::paper_scale::paper_figure(fig.name).is_some() {
                            out.push(png(&paper_dir, fig.name, &|p| fig.paper_png(p))?);
                        }
                        Ok(out)
                    })
                    .collect::<Result<_, ReportError>>()?;
                written.extend(pngs.into_iter().flatten());
                put("report.tex", latex(report)?, &mut written)?;
            }
        }
    }
    Ok(written)
}
