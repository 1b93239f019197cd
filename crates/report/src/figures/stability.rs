//! The stability map: where small oscillations about steady motion grow (eq 54 gives
//! $\varpi^2 < 0$), over the tilt $\alpha_0$ and the radius $b$ of the centre of mass's circle,
//! against the paper's statement of where that happens.
//!
//! Eq 54 is a quadratic in $\rho = b/a$, $(k+1)\varpi^2/\Omega_0^2 = A + B\rho + C\rho^2$, read
//! here from the printed LaTeX ([`Paper::eq54_quadratic`]; no formula of the paper is written in
//! this file). As printed, $A > 0$, $C = 2(2k+1) > 0$ and $B$ is the paper's bracket: the form is
//! negative only between its roots, which exist when $B < 0$ and $B^2 > 4AC$: not from the
//! bracket's zero (52.2 deg for k = 1/4) but from where the discriminant vanishes (71.4 deg, at
//! $b = -aB/2C = 0.57a$).

use crate::figures::chart::{Axis, Legend, Plot, Series, Style};
use crate::figures::FigureError;
use crate::figures::{Drawing, Figure};
use numerics::oscillation::try_bisect;
use paper::{Bindings, Paper};
use std::f64::consts::FRAC_PI_2;

/// `[A, B, C]` of eq 54 at tilt `alpha0`, or the reason the printed form is not a quadratic.
fn quadratic(paper: &Paper, k: f64, alpha0: f64) -> Result<[f64; 3], FigureError> {
    paper
        .eq54_quadratic(k, alpha0)
        .map_err(|e| FigureError::Data(format!("the stability map reads eq 54: {e}")))
}

/// $(k+1)\varpi^2/\Omega_0^2$ by eq 54 at tilt `alpha0` and `rho` = b/a.
pub fn eq54(paper: &Paper, k: f64, alpha0: f64, rho: f64) -> Result<f64, FigureError> {
    let [a, b, c] = quadratic(paper, k, alpha0)?;
    Ok(a + b * rho + c * rho * rho)
}

/// The interval of b/a where eq 54 is negative at this tilt, if any (its two real roots).
pub fn unstable_band(
    paper: &Paper,
    k: f64,
    alpha0: f64,
) -> Result<Option<(f64, f64)>, FigureError> {
    let [a, b, c] = quadratic(paper, k, alpha0)?;
    let disc = b * b - 4.0 * a * c;
    Ok((c > 0.0 && disc > 0.0).then(|| {
        let r = disc.sqrt();
        ((-b - r) / (2.0 * c), (-b + r) / (2.0 * c))
    }))
}

/// The zero of eq 54's coefficient of b/a (the paper's bracket) in (0, 90 deg) (rad).
pub fn bracket_zero(paper: &Paper, k: f64) -> Result<f64, FigureError> {
    paper
        .eq54_bracket_zero(k)
        .map_err(|e| FigureError::Data(format!("the stability map reads eq 54: {e}")))
}

/// The lowest tilt at which some b > 0 is unstable (rad) and the b/a there (the vertex
/// $-B/2C$), by bisection on the discriminant between the bracket's zero and pi/2.
pub fn onset(paper: &Paper, k: f64) -> Result<(f64, f64), FigureError> {
    let (lo, hi) = (bracket_zero(paper, k)?, FRAC_PI_2 - 1e-9);
    if unstable_band(paper, k, hi)?.is_none() {
        return Err("the stability map: eq 54 is nowhere negative for b > 0".into());
    }
    let band = |al: f64| unstable_band(paper, k, al).ok().map(|b| b.is_some());
    let (_, hi) = try_bisect(lo, hi, |_, _| false, band)
        .ok_or("the stability map: eq 54 cannot be evaluated near the onset")?;
    let [_, b, c] = quadratic(paper, k, hi)?;
    Ok((hi, -b / (2.0 * c)))
}

/// Eq 30's bound on b/a, its right side at a = 1.
pub fn eq30_bound(paper: &Paper, k: f64, alpha0: f64) -> Result<f64, FigureError> {
    let bind = Bindings::new()
        .scalar("a", 1.0)
        .scalar("k", k)
        .scalar("alpha_0", alpha0);
    paper
        .right_side(30, &bind)
        .map_err(|e| FigureError::Data(format!("the stability map reads eq 30: {e}")))
}

/// The figure, for the uniform disk (k = 1/4), from the paper's eqs 30 and 54.
pub fn figure(paper: &Paper) -> Result<Figure, FigureError> {
    let k = 0.25;
    let top: f64 = 3.0;
    let bottom: f64 = -0.3;
    let d_alpha = 0.5_f64;
    let d_rho: f64 = 0.025;
    let mut cells = Vec::new();
    let n_alpha = (90.0 / d_alpha) as usize;
    let n_rho = ((top - bottom) / d_rho).round() as usize;
    for i in 0..n_alpha {
        let deg = (i as f64 + 0.5) * d_alpha;
        let alpha = deg.to_radians();
        let ([a, b, c], bound) = (quadratic(paper, k, alpha)?, eq30_bound(paper, k, alpha)?);
        for j in 0..=n_rho {
            let rho = bottom + j as f64 * d_rho;
            if rho > bound && a + b * rho + c * rho * rho < 0.0 {
                cells.push((deg, rho));
            }
        }
    }
    let (a_on, rho_on) = onset(paper, k)?;
    // The true boundary: the two roots from the onset, the lower to 90 deg, the upper until it
    // leaves the plot, joined at the onset.
    let n = 400;
    let mut lower = Vec::new();
    let mut upper = Vec::new();
    for i in 0..=n {
        let a = a_on + (FRAC_PI_2 - 1e-6 - a_on) * (i as f64 / n as f64).powi(2);
        if let Some((lo, hi)) = unstable_band(paper, k, a)? {
            lower.push((a.to_degrees(), lo));
            if hi <= top {
                upper.push((a.to_degrees(), hi));
            }
        }
    }
    let mut boundary: Vec<(f64, f64)> = upper.into_iter().rev().collect();
    boundary.push((a_on.to_degrees(), rho_on));
    boundary.extend(lower);
    let bound: Vec<(f64, f64)> = (0..=180)
        .map(|i| {
            let deg = i as f64 * 0.5;
            eq30_bound(paper, k, deg.to_radians()).map(|b| (deg, b))
        })
        .collect::<Result<_, _>>()?;
    let zero = bracket_zero(paper, k)?.to_degrees();
    let plot = Plot::new(
        "Where small oscillations about steady motion grow (k = 1/4)",
        "tilt α₀ (degrees)",
        "b/a (centre of mass's circle / disk radius)",
    )
    .x_range(0.0, 90.0)
    .y_range(bottom, top)
    .with_colored(
        Series::new("unstable: eq 54 gives ϖ² < 0", cells, Style::Cells),
        [213, 94, 0],
    )
    .with_colored(
        Series::new("true boundary (roots of eq 54 in b)", boundary, Style::Line),
        [0, 0, 0],
    )
    .with_colored(
        Series::new(
            format!("onset: {:.1} deg, b = {:.2} a", a_on.to_degrees(), rho_on),
            vec![(a_on.to_degrees(), rho_on)],
            Style::Triangles,
        ),
        [0, 0, 0],
    )
    .with_colored(
        Series::new("eq 30: no steady motion below", bound, Style::Dashed),
        [0, 114, 178],
    )
    .mark(Axis::X, zero, "")
    .mark(Axis::X, 60.0, "")
    .note(
        zero + 0.8,
        1.75,
        format!("{zero:.1}°: eq 54's bracket\nturns negative"),
    )
    .note(60.8, 2.75, "60°: the paper's\n'about 60 degrees'")
    .legend_at(Legend::UpperLeft);
    Ok(Figure {
        name: "stability-map",
        title: "Where steady rolling is unstable".into(),
        caption: super::captions::caption(
            "stability-map",
            &serde_json::json!({
                "zero": format!("{:.1}", zero),
                "a_on": format!("{:.1}", a_on.to_degrees()),
                "rho_on": format!("{:.2}", rho_on),
            }),
        )?,
        drawing: Drawing::Plot(plot),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use physics::disk::Disk;
    use physics::model::steady::steady_motion;

    /// varpi^2 (k+1)/Omega0^2 from the model's exact Jacobian: the sum of its principal 2x2
    /// minors is varpi^2 (two zero eigenvalues, two at +-i varpi).
    fn model_ratio(d: &Disk, alpha0: f64, rho: f64) -> f64 {
        let m = steady_motion(d, alpha0, rho * d.a).unwrap();
        let j = physics::model::rolling::jacobian(d, &[m.alpha, m.alpha_dot, m.precession, m.spin]);
        let mut e2 = 0.0;
        for a in 0..4 {
            for b in a + 1..4 {
                e2 += j[(a, a)] * j[(b, b)] - j[(a, b)] * j[(b, a)];
            }
        }
        e2 * (d.k + 1.0) / (m.precession * m.precession)
    }

    #[test]
    fn eq54_agrees_with_the_models_linearization_on_the_grid() {
        let p = Paper::built_in().unwrap();
        let d = Disk::uniform(0.0375);
        for deg in [10.0, 45.0, 60.0, 72.0, 80.0, 88.0] {
            for rho in [-0.1, 0.0, 0.3, 0.6, 1.0, 2.5] {
                let a = f64::to_radians(deg);
                if rho <= eq30_bound(&p, 0.25, a).unwrap() {
                    continue;
                }
                let (claim, model) = (eq54(&p, 0.25, a, rho).unwrap(), model_ratio(&d, a, rho));
                assert!(
                    (claim - model).abs() < 1e-9 * (1.0 + model.abs()),
                    "{deg} {rho}: {claim} {model}"
                );
            }
        }
    }

    #[test]
    fn onset_is_at_71_4_degrees_and_0_57_a() {
        let p = Paper::built_in().unwrap();
        let (a, rho) = onset(&p, 0.25).unwrap();
        assert!((a.to_degrees() - 71.4).abs() < 0.05, "{}", a.to_degrees());
        assert!((rho - 0.57).abs() < 0.01, "{rho}");
        let zero = bracket_zero(&p, 0.25).unwrap();
        // The paper's own statement of the zero (sec. 7's prose), for this test only.
        assert!((zero.tan() - (2.5f64 / 1.5).sqrt()).abs() < 1e-9);
        // Just above the onset the band's middle is unstable, just below nothing is.
        assert!(eq54(&p, 0.25, a + 1e-4, rho).unwrap() < 0.0);
        assert!(unstable_band(&p, 0.25, a - 1e-4).unwrap().is_none());
    }

    #[test]
    fn an_edited_eq_54_redraws_the_map_and_a_shapeless_one_is_refused() {
        let p = Paper::built_in().unwrap();
        // An author's edit: the bracket's (6k+1) written (4k+1) moves its zero.
        let latex = p.equation(54).entry.latex.replace("(6k + 1)", "(4k + 1)");
        let edited = p.with_latex(54, &latex).unwrap();
        let (z0, z1) = (
            bracket_zero(&p, 0.25).unwrap(),
            bracket_zero(&edited, 0.25).unwrap(),
        );
        assert!((z1.tan() - (2.0f64 / 1.5).sqrt()).abs() < 1e-9, "{z0} {z1}");
        let flat = p
            .with_latex(54, r"\frac{\varpi^2}{\Omega_0^2} (k + 1) = 3 k")
            .unwrap();
        let e = figure(&flat).unwrap_err().to_string();
        assert!(e.contains("eq 54"), "{e}");
    }
}
