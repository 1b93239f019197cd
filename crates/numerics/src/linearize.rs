//! Exact Jacobians by forward-mode dual numbers, and the eigenvalues of small matrices.

use nalgebra::DMatrix;
use nalgebra::{Complex, SMatrix, SVector};
use num_dual::Dual64;

/// The Jacobian $\partial f_i / \partial y_j$ of `f` at `y`, exact to round-off: one pass of
/// `f` per column with that column's seed set to 1.
pub fn jacobian<const N: usize>(
    f: impl Fn(&[Dual64; N]) -> [Dual64; N],
    y: &[f64; N],
) -> SMatrix<f64, N, N> {
    let mut jac = SMatrix::<f64, N, N>::zeros();
    for j in 0..N {
        let x: [Dual64; N] =
            std::array::from_fn(|i| Dual64::new(y[i], if i == j { 1.0 } else { 0.0 }));
        let fx = f(&x);
        for i in 0..N {
            jac[(i, j)] = fx[i].eps;
        }
    }
    jac
}

/// The value of `f` at `y` (the real parts), for checking that `y` is an equilibrium.
pub fn value<const N: usize>(
    f: impl Fn(&[Dual64; N]) -> [Dual64; N],
    y: &[f64; N],
) -> SVector<f64, N> {
    let x: [Dual64; N] = std::array::from_fn(|i| Dual64::from(y[i]));
    let fx = f(&x);
    SVector::<f64, N>::from_fn(|i, _| fx[i].re)
}

/// The eigenvalues of a real square matrix (complex in general), sorted by imaginary part.
pub fn eigenvalues<const N: usize>(m: &SMatrix<f64, N, N>) -> Vec<Complex<f64>> {
    let d = DMatrix::from_iterator(N, N, m.iter().copied());
    let mut ev: Vec<Complex<f64>> = d.complex_eigenvalues().iter().copied().collect();
    ev.sort_by(|a, b| a.im.total_cmp(&b.im));
    ev
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_dual::DualNum;

    #[test]
    fn harmonic_oscillator_has_eigenvalues_plus_minus_i_omega() {
        let w2 = 9.0;
        let f = |y: &[Dual64; 2]| [y[1], y[0] * (-w2)];
        let j = jacobian(f, &[0.3, -0.1]);
        assert_eq!(j, SMatrix::<f64, 2, 2>::new(0.0, 1.0, -9.0, 0.0));
        let ev = eigenvalues(&j);
        assert!((ev[1].im - 3.0).abs() < 1e-12 && ev[1].re.abs() < 1e-12);
    }

    #[test]
    fn derivatives_of_nonlinear_functions_are_exact() {
        let f = |y: &[Dual64; 2]| [y[0].sin() * y[1], y[0] * y[0]];
        let j = jacobian(f, &[0.7, 2.0]);
        assert!((j[(0, 0)] - 0.7f64.cos() * 2.0).abs() < 1e-15);
        assert!((j[(0, 1)] - 0.7f64.sin()).abs() < 1e-15);
        assert!((j[(1, 0)] - 1.4).abs() < 1e-15);
    }
}
