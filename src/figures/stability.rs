//! The stability map: where small oscillations about steady motion grow (eq 54 gives
//! $\varpi^2 < 0$), over the tilt $\alpha_0$ and the radius $b$ of the centre of mass's circle,
//! against the paper's statement of where that happens.
//!
//! Eq 54 is a quadratic in $\rho = b/a$:
//! $(k+1)\varpi^2/\Omega_0^2 = A + B\rho + 2(2k+1)\rho^2$ with $A = 3k\cos^2\alpha_0 + \sin^2\alpha_0 > 0$
//! and $B = (6k+1)\cos\alpha_0 - (2k+1)\sin^2\alpha_0/\cos\alpha_0$ (the paper's bracket). It is
//! negative only between its roots, which exist when $B < 0$ and $B^2 > 8(2k+1)A$: not from the
//! bracket's zero at $\tan\alpha_0 = \sqrt{(6k+1)/(2k+1)}$ (52.2 deg for k = 1/4) but from where the
//! discriminant vanishes (71.4 deg, at $b = -aB/4(2k+1) = 0.57a$).

use crate::figures::chart::{Axis, Legend, Plot, Series, Style};
use crate::figures::FigureError;
use crate::figures::{Drawing, Figure};
use std::f64::consts::FRAC_PI_2;

/// $(k+1)\varpi^2/\Omega_0^2$ by eq 54 at tilt `alpha0` and `rho` = b/a.
pub fn eq54(k: f64, alpha0: f64, rho: f64) -> f64 {
    let (s, c) = alpha0.sin_cos();
    3.0 * k * c * c
        + s * s
        + rho * ((6.0 * k + 1.0) * c - (2.0 * k + 1.0) * s * s / c)
        + 2.0 * rho * rho * (2.0 * k + 1.0)
}

/// The roots in b/a of eq 54's quadratic at `alpha0`, if real: the unstable band's edges.
pub fn unstable_band(k: f64, alpha0: f64) -> Option<(f64, f64)> {
    let (s, c) = alpha0.sin_cos();
    let a = 3.0 * k * c * c + s * s;
    let b = (6.0 * k + 1.0) * c - (2.0 * k + 1.0) * s * s / c;
    let q = 2.0 * (2.0 * k + 1.0);
    let disc = b * b - 4.0 * q * a;
    (b < 0.0 && disc > 0.0).then(|| {
        let r = disc.sqrt();
        // The smaller root without cancellation: (2A) / (-B + r).
        (2.0 * a / (-b + r), (-b + r) / (2.0 * q))
    })
}

/// The lowest tilt at which some b > 0 is unstable (rad) and the b/a there, by bisection on the
/// discriminant between the bracket's zero and pi/2.
pub fn onset(k: f64) -> (f64, f64) {
    let (mut lo, mut hi) = (bracket_zero(k), FRAC_PI_2 - 1e-9);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if unstable_band(k, mid).is_some() {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let (s, c) = hi.sin_cos();
    let b = (6.0 * k + 1.0) * c - (2.0 * k + 1.0) * s * s / c;
    (hi, -b / (4.0 * (2.0 * k + 1.0)))
}

/// The zero of the paper's bracket, $\tan\alpha_0 = \sqrt{(6k+1)/(2k+1)}$ (rad).
pub fn bracket_zero(k: f64) -> f64 {
    ((6.0 * k + 1.0) / (2.0 * k + 1.0)).sqrt().atan()
}

/// Eq 30's bound on b/a: $-k\cos\alpha_0/(2k+1)$.
pub fn eq30_bound(k: f64, alpha0: f64) -> f64 {
    -k * alpha0.cos() / (2.0 * k + 1.0)
}

/// The figure, for the uniform disk (k = 1/4).
pub fn figure() -> Result<Figure, FigureError> {
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
        for j in 0..=n_rho {
            let rho = bottom + j as f64 * d_rho;
            if rho > eq30_bound(k, alpha) && eq54(k, alpha, rho) < 0.0 {
                cells.push((deg, rho));
            }
        }
    }
    let (a_on, rho_on) = onset(k);
    // The true boundary: the two roots from the onset, the lower to 90 deg, the upper until it
    // leaves the plot, joined at the onset.
    let n = 400;
    let mut lower = Vec::new();
    let mut upper = Vec::new();
    for i in 0..=n {
        let a = a_on + (FRAC_PI_2 - 1e-6 - a_on) * (i as f64 / n as f64).powi(2);
        if let Some((lo, hi)) = unstable_band(k, a) {
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
            (deg, eq30_bound(k, deg.to_radians()))
        })
        .collect();
    let paper = bracket_zero(k).to_degrees();
    let plot = Plot::new(
        "Where small oscillations about steady motion grow (k = 1/4)",
        "tilt α0 (degrees)",
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
    .mark(Axis::X, paper, "")
    .mark(Axis::X, 60.0, "")
    .note(
        paper + 0.8,
        1.75,
        format!("{paper:.1}°: eq 54's bracket\nturns negative"),
    )
    .note(60.8, 2.75, "60°: the paper's\n'about 60 degrees'")
    .legend_at(Legend::UpperLeft);
    Ok(Figure {
        name: "stability-map",
        title: "Where steady rolling is unstable".into(),
        caption: format!(
            "Cells where eq 54 gives a negative varpi^2 for a uniform disk (k = 1/4): the steady \
             motion at tilt alpha0 with the centre of mass on a circle of radius b is unstable \
             there. The paper says the bracket of eq 54 is negative above \
             alpha0 = atan(sqrt((6k+1)/(2k+1))) = {paper:.1} deg, 'about 60 degrees', so that \
             positive b is unstable at large tilt (grey dashed lines at {paper:.1} and 60 deg). \
             A negative bracket is necessary but not sufficient: eq 54 is a quadratic in b/a \
             with a positive constant and a positive b^2 term, negative only between its roots, \
             which are real only above {:.1} deg (triangle, b = {:.2} a). Between {paper:.1} and \
             {:.1} deg every b is stable; above, only a band of b is unstable, and small b (the \
             spinning coin) and large b (a wide circle) stay stable. Below the blue dashed line \
             (eq 30) there is no steady motion; negative b is always stable, as the paper says. \
             The test of this figure checks the cells against the sign of varpi^2 from the exact \
             Jacobian of eqs 23-25.",
            a_on.to_degrees(),
            rho_on,
            a_on.to_degrees()
        ),
        drawing: Drawing::Plot(plot),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::disk::Disk;
    use crate::model::rolling::rates;
    use crate::model::steady::steady_motion;
    use crate::model::Motion;
    use crate::numerics::linearize::jacobian;
    use num_dual::Dual64;

    /// varpi^2 (k+1)/Omega0^2 from the model's exact Jacobian: the sum of its principal 2x2
    /// minors is varpi^2 (two zero eigenvalues, two at +-i varpi).
    fn model_ratio(d: &Disk, alpha0: f64, rho: f64) -> f64 {
        let m = steady_motion(d, alpha0, rho * d.a).unwrap();
        let f = |y: &[Dual64; 4]| {
            let mm = Motion {
                alpha: y[0],
                alpha_dot: y[1],
                precession: y[2],
                spin: y[3],
            };
            let r = rates(d, &mm, [Dual64::from(0.0); 3]);
            [y[1], r.alpha_ddot, r.precession_dot, r.spin_dot]
        };
        let j = jacobian(f, &[m.alpha, m.alpha_dot, m.precession, m.spin]);
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
        let d = Disk::uniform(0.0375);
        for deg in [10.0, 45.0, 60.0, 72.0, 80.0, 88.0] {
            for rho in [-0.1, 0.0, 0.3, 0.6, 1.0, 2.5] {
                let a = f64::to_radians(deg);
                if rho <= eq30_bound(0.25, a) {
                    continue;
                }
                let (claim, model) = (eq54(0.25, a, rho), model_ratio(&d, a, rho));
                assert!(
                    (claim - model).abs() < 1e-9 * (1.0 + model.abs()),
                    "{deg} {rho}: {claim} {model}"
                );
            }
        }
    }

    #[test]
    fn onset_is_at_71_4_degrees_and_0_57_a() {
        let (a, rho) = onset(0.25);
        assert!((a.to_degrees() - 71.4).abs() < 0.05, "{}", a.to_degrees());
        assert!((rho - 0.57).abs() < 0.01, "{rho}");
        assert!((bracket_zero(0.25).to_degrees() - 52.2).abs() < 0.05);
        // Just above the onset the band's middle is unstable, just below nothing is.
        assert!(eq54(0.25, a + 1e-4, rho) < 0.0);
        assert!(unstable_band(0.25, a - 1e-4).is_none());
    }
}
