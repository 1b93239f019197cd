//! The coverage of the experiment's stated intervals (issue 15): for one Monte Carlo study, and
//! for the stored studies the report draws ([`studies::coverage_record`]).

use super::FigureError;
use crate::figures::chart::{Axis, Legend, Plot, Series, Style};
use crate::figures::{Drawing, Figure};
use studies::coverage::Coverage;
use studies::coverage_record::StoredCoverage;

/// $P(|Z| \le z)$ for a standard normal $Z$, by Simpson's rule on $e^{-x^2/2}$ (400 panels;
/// accurate to 1e-10 for $z \le 4$): the claimed coverage curve.
fn normal_inside(z: f64) -> f64 {
    let n = 400;
    let h = z / n as f64;
    let f = |x: f64| (-0.5 * x * x).exp();
    let s: f64 = (0..=n)
        .map(|k| {
            let w = if k == 0 || k == n {
                1.0
            } else if k % 2 == 1 {
                4.0
            } else {
                2.0
            };
            w * f(k as f64 * h)
        })
        .sum();
    2.0 * s * h / 3.0 / (2.0 * std::f64::consts::PI).sqrt()
}

/// The coverage study: the fraction of recordings whose truth lies inside $\pm z$ stated
/// standard uncertainties, against $z$, for beta and t0, with the claimed normal curve.
pub fn coverage(c: &Coverage) -> Figure {
    let zs: Vec<f64> = (1..=30).map(|k| 0.1 * k as f64).collect();
    let curve = |pulls: &[f64]| -> Vec<(f64, f64)> {
        zs.iter().map(|&z| (z, c.fraction(pulls, z))).collect()
    };
    let claimed: Vec<(f64, f64)> = zs.iter().map(|&z| (z, normal_inside(z))).collect();
    let plot = Plot::new(
        "Coverage of the stated intervals",
        "z (stated standard uncertainties)",
        "fraction inside ± z (dimensionless)",
    )
    .with(Series::new("β", curve(&c.beta_pulls), Style::Points))
    .with(Series::new("t₀", curve(&c.t0_pulls), Style::Squares))
    .with(Series::new("claimed (normal)", claimed, Style::Dashed))
    .mark(Axis::X, 1.96, "95 %")
    .legend_at(Legend::LowerRight);
    Figure {
        name: "coverage",
        title: "Monte Carlo coverage of the stated uncertainties".into(),
        caption: c.summary(),
        drawing: Drawing::Plot(plot),
    }
}

/// The stored studies (clean and artifact-laden light recordings, phone sounds): the fraction of
/// recordings whose truth lies inside $\pm z$ stated standard uncertainties against $z$, beta and t0 of each,
/// with the normal curve the intervals claim. Drawn from `snapshots/coverage.json`, not run.
pub fn studies(stored: &[StoredCoverage]) -> Result<Figure, FigureError> {
    let zs: Vec<f64> = (1..=30).map(|k| 0.1 * k as f64).collect();
    let claimed: Vec<(f64, f64)> = zs.iter().map(|&z| (z, normal_inside(z))).collect();
    let mut plot = Plot::new(
        "Coverage of the stated intervals",
        "z (stated standard uncertainties)",
        "fraction inside ± z (dimensionless)",
    );
    // Markers for the light's studies, lines for the sound's; a study beyond these would reuse
    // the last pair rather than be left out.
    let styles = [
        (Style::Points, Style::Squares),
        (Style::Crosses, Style::Triangles),
        (Style::Line, Style::Dotted),
    ];
    for (i, s) in stored.iter().enumerate() {
        let (sb, st) = styles[i.min(styles.len() - 1)];
        let c = &s.coverage;
        let curve = |pulls: &[f64]| -> Vec<(f64, f64)> {
            zs.iter().map(|&z| (z, c.fraction(pulls, z))).collect()
        };
        plot = plot
            .with(Series::new(
                format!("β, {}", s.recordings),
                curve(&c.beta_pulls),
                sb,
            ))
            .with(Series::new(
                format!("t₀, {}", s.recordings),
                curve(&c.t0_pulls),
                st,
            ));
    }
    let plot = plot
        .with(Series::new("claimed (normal)", claimed, Style::Dashed))
        .mark(Axis::X, 1.96, "95 %")
        .legend_at(Legend::LowerRight);
    let lines: Vec<String> = stored.iter().map(|s| s.line()).collect();
    Ok(Figure {
        name: "coverage",
        title: "Monte Carlo coverage of the experiment's stated uncertainties".into(),
        caption: super::captions::caption(
            "coverage",
            &serde_json::json!({
                "studies": format!("{}", lines.join("; ")),
            }),
        )?,
        drawing: Drawing::Plot(plot),
    })
}

#[cfg(test)]
mod tests {
    use super::studies;
    use crate::figures::Drawing;

    /// Every stored study is drawn, beta and t0 each, besides the claimed curve.
    #[test]
    fn every_stored_study_is_drawn() {
        let stored = studies::coverage_record::stored().expect("snapshots/coverage.json");
        let Drawing::Plot(plot) = studies(&stored).unwrap().drawing else {
            panic!("the coverage figure is a plot");
        };
        let labels: Vec<&str> = plot.chart.series.iter().map(|s| s.label.as_str()).collect();
        for s in &stored {
            for q in ["β", "t₀"] {
                let label = format!("{q}, {}", s.recordings);
                assert!(
                    labels.contains(&label.as_str()),
                    "{label} not in {labels:?}"
                );
            }
        }
    }
}
