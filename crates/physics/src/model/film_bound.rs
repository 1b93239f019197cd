//! The squeeze film's dissipation number $I$ of [`super::air_film`] bounded from below by
//! conforming finite elements on a mesh that opens up the contact point.
//!
//! **The variational bound.** $P$ minimizes
//! $\tfrac12\int H^3|\nabla Q|^2\,dA - \int Q\,\rho_\perp\,dA$ over functions that vanish on
//! the rim, and at the minimum both integrals equal $I$. Any finite-dimensional space of such
//! functions therefore gives $I_h = \int P_h\rho_\perp\,dA \le I$ (Galerkin's energy is never
//! above the true one). Here the space is piecewise linear on triangles whose vertices lie in
//! the closed disk, extended by zero outside their polygon: it is conforming, and because
//! $H = 1 - x$ is linear every integral is a polynomial one, evaluated exactly
//! ($\int_T H^3 dA = \tfrac{A}{10}\sum_{|\alpha| = 3} H^\alpha$ over the vertex values). So
//! each $I_h$ is a true lower bound, up to rounding.
//!
//! **The mesh.** The difficulty is the contact point $C = (1, 0)$, where the gap closes
//! ($H = 0$) and $P$ is unbounded. Seen from $C$, a point of the disk is
//! $C + r(-\cos\psi, \sin\psi)$ with $|\psi| < \pi/2$ and $r < 2\cos\psi$; writing
//! $r = 2u\cos\psi$ maps the rectangle $0 < u < 1$, $|\psi| < \pi/2$ onto the disk, its edges
//! $u = 0$ and $\psi = \pm\pi/2$ onto $C$ and $u = 1$ onto the rim. There the gap is
//! $H = 2u\cos^2\psi$, and the leading part of $P$ near $C$ (of order $y/H = \tan\psi$) is
//! smooth. A grid uniform in $u$ and graded toward $\psi = \pm\pi/2$ (where the rim runs
//! into $C$) mapped to the plane is a mesh refined toward $C$ on which $I_h$ converges at the
//! second order. $P$ is odd in $y$, so only the half $\psi > 0$ is solved.
//!
//! **The number.** [`extrapolated`] extrapolates the bounds of two grids at the observed
//! order 2 (Richardson) and states, as its uncertainty, how far that extrapolation moved
//! from the one of the next coarser pair. Hand-written because the film's Reynolds operator
//! on this degenerate wedge is the field's own problem; the sparse Cholesky factorization is
//! nalgebra-sparse's.

use nalgebra::DVector;
use nalgebra_sparse::factorization::CscCholesky;
use nalgebra_sparse::{CooMatrix, CscMatrix};
use std::f64::consts::FRAC_PI_2;

/// The grading of the angle toward $\psi = \pi/2$: $\psi_j = \tfrac\pi2(1 - (1 - j/m)^{1.5})$.
const GRADING: f64 = 1.5;

/// $I$ estimated from the lower bounds of three grids.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FilmNumber {
    /// The Richardson extrapolation at order 2 of the two finest grids.
    pub estimate: f64,
    /// |estimate - the extrapolation of the two coarser grids|: the extrapolation's own error
    /// is well below it when the order is 2.
    pub uncertainty: f64,
    /// The finest grid's $I_h$: a lower bound on $I$.
    pub lower_bound: f64,
    /// The convergence order measured from the three grids,
    /// $\log_2[(I_{h_1} - I_{h_0})/(I_{h_2} - I_{h_1})]$.
    pub observed_order: f64,
}

/// $I$ from the lower bounds on grids of `n`, `2n` and `4n` cells in $u$ (as many in $\psi$
/// over the half disk).
pub fn extrapolated(n: usize) -> FilmNumber {
    let bounds: Vec<f64> = [n, 2 * n, 4 * n].iter().map(|&c| lower_bound(c)).collect();
    let richardson = |coarse: f64, fine: f64| fine + (fine - coarse) / 3.0;
    let estimate = richardson(bounds[1], bounds[2]);
    FilmNumber {
        estimate,
        uncertainty: (estimate - richardson(bounds[0], bounds[1])).abs(),
        lower_bound: bounds[2],
        observed_order: ((bounds[1] - bounds[0]) / (bounds[2] - bounds[1])).log2(),
    }
}

/// A vertex of the half-disk grid in the plane, with its unknown's index (`None` on the
/// rim, the axis $y = 0$, the contact point and the last ray, where $P_h = 0$).
#[derive(Clone, Copy)]
struct Vertex {
    x: f64,
    y: f64,
    unknown: Option<usize>,
}

/// The grid's vertex `(i, j)`: $u = i/n$, $\psi = \psi_j$ of `m` angular cells; `order`
/// numbers the unknowns (see [`dissection`]).
fn vertex(i: usize, j: usize, n: usize, m: usize, order: &[usize]) -> Vertex {
    let u = i as f64 / n as f64;
    let psi = FRAC_PI_2 * (1.0 - (1.0 - j as f64 / m as f64).powf(GRADING));
    let r = 2.0 * u * psi.cos();
    // Unknowns: 0 < i < n and 0 < j < m - 1. The cells between the last ray (j = m - 1) and
    // psi = pi/2 collapse onto that ray, so its vertices border the polygon and are held at 0.
    let unknown =
        (i > 0 && i < n && j > 0 && j + 1 < m).then(|| order[(j - 1) * (n - 1) + (i - 1)]);
    Vertex {
        x: 1.0 - r * psi.cos(),
        y: r * psi.sin(),
        unknown,
    }
}

/// $I_h$ on the grid of `n` cells in $u$ and `n` in $\psi$ over the half disk: a lower bound
/// on $I$.
pub fn lower_bound(n: usize) -> f64 {
    let m = n;
    let unknowns = (n - 1) * (m - 2);
    let order = dissection(n - 1, m - 2);
    let mut stiffness = CooMatrix::new(unknowns, unknowns);
    let mut load = DVector::zeros(unknowns);
    // The quads j = m - 1 collapse onto the last ray; the others split along (i, j)-(i+1, j+1).
    for j in 0..m - 1 {
        for i in 0..n {
            let corner = |di: usize, dj: usize| vertex(i + di, j + dj, n, m, &order);
            let (a, b, c, d) = (corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1));
            for triangle in [[a, b, c], [a, c, d]] {
                add_element(&triangle, &mut stiffness, &mut load);
            }
        }
    }
    match CscCholesky::factor(&CscMatrix::from(&stiffness)) {
        // Both halves of the disk contribute alike.
        Ok(chol) => 2.0 * load.dot(&chol.solve(&load).column(0)),
        // Symmetric positive definite (a conforming Galerkin matrix with a Dirichlet edge),
        // so this is unreachable; NaN makes any check that uses it fail.
        Err(_) => f64::NAN,
    }
}

/// The position in the factorization's order of each unknown of a `width` x `height` grid
/// (index `row * width + column`): nested dissection, which halves the grid by a line of
/// unknowns numbered after both halves, recursively. The Cholesky factor of a grid numbered
/// row by row fills its whole band (of `width`); this order keeps the fill near
/// $N\log N$, which makes the fine grids affordable.
fn dissection(width: usize, height: usize) -> Vec<usize> {
    let mut order = vec![0; width * height];
    let mut next = 0;
    number_block(&mut order, &mut next, width, (0, width), (0, height));
    order
}

/// Numbers the unknowns of the block `columns` x `rows` by nested dissection from `next` on.
fn number_block(
    order: &mut [usize],
    next: &mut usize,
    width: usize,
    columns: (usize, usize),
    rows: (usize, usize),
) {
    let (w, h) = (columns.1 - columns.0, rows.1 - rows.0);
    if w == 0 || h == 0 {
        return;
    }
    if w * h <= 16 {
        for r in rows.0..rows.1 {
            for c in columns.0..columns.1 {
                order[r * width + c] = *next;
                *next += 1;
            }
        }
        return;
    }
    if w >= h {
        let mid = columns.0 + w / 2;
        number_block(order, next, width, (columns.0, mid), rows);
        number_block(order, next, width, (mid + 1, columns.1), rows);
        number_block(order, next, width, (mid, mid + 1), rows);
    } else {
        let mid = rows.0 + h / 2;
        number_block(order, next, width, columns, (rows.0, mid));
        number_block(order, next, width, columns, (mid + 1, rows.1));
        number_block(order, next, width, columns, (mid, mid + 1));
    }
}

/// Adds one linear triangle's $\int H^3\nabla\phi_k\cdot\nabla\phi_l\,dA$ and
/// $\int y\,\phi_k\,dA$, exactly, to the rows of its unknowns. A triangle with two vertices at
/// the contact point has no area and adds nothing.
fn add_element(t: &[Vertex; 3], stiffness: &mut CooMatrix<f64>, load: &mut DVector<f64>) {
    let twice_area = (t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[2].x - t[0].x) * (t[1].y - t[0].y);
    let area = 0.5 * twice_area.abs();
    if area == 0.0 {
        return;
    }
    // Gradients of the barycentric coordinates.
    let grad = |k: usize| {
        let (p, q) = (&t[(k + 1) % 3], &t[(k + 2) % 3]);
        ((p.y - q.y) / twice_area, (q.x - p.x) / twice_area)
    };
    let h: Vec<f64> = t.iter().map(|v| 1.0 - v.x).collect();
    // The ten cubic monomials of the vertex values: sum_{|alpha| = 3} h^alpha.
    let cubic = h.iter().map(|v| v.powi(3)).sum::<f64>()
        + h[0] * h[0] * (h[1] + h[2])
        + h[1] * h[1] * (h[0] + h[2])
        + h[2] * h[2] * (h[0] + h[1])
        + h[0] * h[1] * h[2];
    let conductance = area / 10.0 * cubic;
    let y_sum: f64 = t.iter().map(|v| v.y).sum();
    for k in 0..3 {
        let Some(row) = t[k].unknown else { continue };
        load[row] += area / 12.0 * (t[k].y + y_sum);
        let gk = grad(k);
        for (l, vl) in t.iter().enumerate() {
            if let Some(col) = vl.unknown {
                let gl = grad(l);
                stiffness.push(row, col, conductance * (gk.0 * gl.0 + gk.1 * gl.1));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bounds_rise_at_the_second_order() {
        let number = extrapolated(16);
        let b: Vec<f64> = [16, 32, 64].iter().map(|&n| lower_bound(n)).collect();
        assert!(b[0] < b[1] && b[1] < b[2], "{b:?}");
        assert!((1.6..2.2).contains(&number.observed_order), "{number:?}");
    }
}
