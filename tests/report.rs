//! The reproduction report: complete, self-contained, reproducible to the byte; and, with the
//! tools installed (`.ci/run` installs them; run with `--include-ignored`), loaded by headless
//! Chromium without a console error and compiled by pdflatex without an error.

use rolling_disk::catalogue;
use rolling_disk::equations::Bench;
use rolling_disk::report::{build::build, render};
use std::path::PathBuf;
use std::process::Command;
use std::sync::OnceLock;

fn built() -> &'static (String, String, Vec<String>) {
    static REPORT: OnceLock<(String, String, Vec<String>)> = OnceLock::new();
    REPORT.get_or_init(|| {
        let (report, figures) = build(&Bench::default(), &|_| {}).unwrap();
        let names = figures.iter().map(|f| f.name.to_string()).collect();
        (
            render::html(&report).unwrap(),
            render::latex(&report).unwrap(),
            names,
        )
    })
}

#[test]
fn html_holds_every_equation_claim_and_figure_as_mathml_and_svg() {
    let (html, _, figures) = built();
    for n in 1..=85 {
        assert!(html.contains(&format!("id=\"eq-{n}\"")), "eq {n} missing");
    }
    for c in catalogue::claims() {
        assert!(
            html.contains(&format!("id=\"claim-{}\"", c.id)),
            "claim {} missing",
            c.id
        );
    }
    assert!(figures.len() >= 10, "{} figures", figures.len());
    for f in figures {
        assert!(
            html.contains(&format!("id=\"fig-{f}\"")),
            "figure {f} missing"
        );
    }
    assert_eq!(
        html.matches("<math").count(),
        85,
        "one MathML block per equation"
    );
    assert!(html.matches("<svg").count() >= figures.len());
}

#[test]
fn html_refers_to_nothing_outside_itself() {
    let (html, _, _) = built();
    for bad in [
        "<script",
        "<link",
        "src=\"http",
        "href=\"http",
        "url(",
        "@import",
    ] {
        assert!(
            !html.contains(bad),
            "the report refers outside itself: {bad}"
        );
    }
    // The only absolute URIs are XML namespace names, which nothing fetches.
    let namespaces = [
        "http://www.w3.org/1998/Math/MathML",
        "http://www.w3.org/2000/svg",
        "http://www.w3.org/1999/xlink",
    ];
    let mut rest = html.as_str();
    while let Some(i) = rest.find("http") {
        let tail = &rest[i..];
        assert!(
            namespaces.iter().any(|ns| tail.starts_with(ns)),
            "outside reference: {}",
            &tail[..tail.len().min(60)]
        );
        rest = &tail[4..];
    }
}

#[test]
fn two_builds_give_identical_bytes() {
    let (html, tex, _) = built();
    let (report, _) = build(&Bench::default(), &|_| {}).unwrap();
    assert!(
        render::html(&report).unwrap() == *html,
        "HTML differs between runs"
    );
    assert!(
        render::latex(&report).unwrap() == *tex,
        "LaTeX differs between runs"
    );
}

fn out_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("rolling-disk-report-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
#[ignore = "needs chromium (installed by .ci/run)"]
fn chromium_loads_the_html_without_console_errors() {
    let dir = out_dir("chromium");
    let (report, figures) = build(&Bench::default(), &|_| {}).unwrap();
    render::write(&report, &figures, &dir, &[render::Format::Html]).unwrap();
    let html = dir.join("report.html");
    let shot = dir.join("top.png");
    let profile = dir.join("profile");
    let out = Command::new("chromium")
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--enable-logging=stderr",
            "--v=0",
            "--window-size=1280,2000",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .arg(format!("--screenshot={}", shot.display()))
        .arg(format!("file://{}", html.display()))
        .output()
        .expect("chromium runs");
    let log = String::from_utf8_lossy(&out.stderr);
    // Chromium logs every console message (console.error and uncaught exceptions included) as an
    // INFO:CONSOLE line; the report has no script, so any console message is a defect.
    let console_errors: Vec<&str> = log.lines().filter(|l| l.contains(":CONSOLE")).collect();
    assert!(
        console_errors.is_empty(),
        "console errors:\n{}",
        console_errors.join("\n")
    );
    assert!(
        std::fs::metadata(&shot)
            .map(|m| m.len() > 10_000)
            .unwrap_or(false),
        "no screenshot; chromium said:\n{log}"
    );
}

#[test]
#[ignore = "needs pdflatex (installed by .ci/run)"]
fn pdflatex_compiles_the_latex_report() {
    let dir = out_dir("latex");
    let (report, figures) = build(&Bench::default(), &|_| {}).unwrap();
    render::write(&report, &figures, &dir, &[render::Format::Latex]).unwrap();
    for _ in 0..2 {
        // Twice, for the table of contents.
        let out = Command::new("pdflatex")
            .args(["-interaction=nonstopmode", "-halt-on-error", "report.tex"])
            .current_dir(&dir)
            .output()
            .expect("pdflatex runs");
        let log = String::from_utf8_lossy(&out.stdout);
        assert!(
            out.status.success(),
            "pdflatex failed:\n{}",
            &log[log.len().saturating_sub(3000)..]
        );
    }
    assert!(dir.join("report.pdf").exists());
}
