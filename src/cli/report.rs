//! `report` and `figures`: the reproduction report and the figures alone.

use super::*;

pub(crate) fn report(
    format: ReportFormat,
    out: &Path,
    accuracy: Option<Accuracy>,
    paper: Option<&Path>,
) -> anyhow::Result<()> {
    use ::report::{build::build, render};
    // Check --out and make room beside it before computing anything.
    let set = SetWriter::begin(out)?;
    let bench = bench_for(accuracy, load_paper(paper)?);
    let status = |s: &str| eprintln!("report: {s}");
    let (report, figures) = build(&bench, &status)?;
    let formats = match format {
        ReportFormat::Html => vec![render::Format::Html],
        ReportFormat::Latex => vec![render::Format::Latex],
        ReportFormat::Json => vec![render::Format::Json],
        ReportFormat::All => vec![
            render::Format::Html,
            render::Format::Latex,
            render::Format::Json,
        ],
    };
    status("writing");
    let written = render::write(&report, &figures, set.dir(), &formats)?;
    let shown: Vec<PathBuf> = written.iter().map(|p| set.final_path(p)).collect();
    set.commit(&written)?;
    let written = shown;
    let t = &report.summary.equations;
    println!(
        "{} equations checked: {} hold, {} hold approximately, {} definitions, {} fail; {} claims fail",
        t.holds + t.approximately + t.definitions + t.fails + t.not_run,
        t.holds,
        t.approximately,
        t.definitions,
        t.fails,
        report.summary.claims.fails
    );
    for p in written
        .iter()
        .filter(|p| p.extension().is_some_and(|e| e != "png"))
    {
        println!("wrote {}", p.display());
    }
    let pngs = written
        .iter()
        .filter(|p| p.extension().is_some_and(|e| e == "png"))
        .count();
    if pngs > 0 {
        println!(
            "wrote {pngs} figures under {}",
            out.join("figures").display()
        );
    }
    Ok(())
}

pub(crate) fn figures(only: Option<&str>, out: &Path, format: FigureFormat) -> anyhow::Result<()> {
    use ::report::pipeline::{compute, RunConfig};
    let names: Vec<&str> = ::report::figures::NAMES.to_vec();
    let wanted: Vec<&str> = match only {
        Some(list) => list
            .split(',')
            .map(str::trim)
            .filter(|s| !s.is_empty())
            .collect(),
        None => names.clone(),
    };
    if wanted.is_empty() {
        return Err(anyhow::anyhow!(
            "--only was given no figure name; name some (the figures are: {}) or leave --only out \
             to draw them all",
            names.join(", ")
        ));
    }
    for w in &wanted {
        if !names.contains(w) {
            return Err(anyhow::anyhow!(
                "--only: no figure is called {w}; the figures are: {}",
                names.join(", ")
            ));
        }
    }
    std::fs::create_dir_all(out)
        .map_err(|e| anyhow::anyhow!("cannot create {}: {e}", out.display()))?;
    // Only the studies the wanted figures are drawn from, each once.
    let config = RunConfig::figures(::checks::equations::Bench::default(), &wanted)?;
    let results = compute(&config, &|s: &str| eprintln!("figures: {s}"))?;
    let all = ::report::figures::some(&wanted, &results)?;
    for f in &all {
        let path = match format {
            FigureFormat::Svg => {
                let path = out.join(format!("{}.svg", f.name));
                let svg = f.drawing.to_svg(760, 480)?;
                write_atomically(&path, svg.as_bytes())
                    .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", path.display()))?;
                path
            }
            FigureFormat::Png => {
                let path = out.join(format!("{}.png", f.name));
                let tmp = out.join(format!(".{}.{}.png", f.name, std::process::id()));
                f.drawing.to_png(&tmp)?;
                std::fs::rename(&tmp, &path)
                    .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", path.display()))?;
                path
            }
        };
        println!("wrote {}", path.display());
    }
    Ok(())
}
