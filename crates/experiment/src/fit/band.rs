//! Generalised least squares with banded, correlated errors.
//!
//! Every quantity fitted here is a function of a few consecutive peak times, so its error is a
//! linear combination of the peak-time errors $e_j$ (independent, variances $w_j = \sigma_{t_j}^2$):
//! $r_i = \sum_j B_{ij} e_j$ with row $i$ using peaks $s_i, \dots, s_i + m$. The residuals then have
//! the banded covariance $\Sigma = B\,W B^{\mathsf T}$ (half-bandwidth $m$): neighbouring
//! $\Omega_i$ share a peak and are anti-correlated, which ordinary least squares ignores. We
//! factor $\Sigma = L L^{\mathsf T}$ (banded Cholesky, $O(n m^2)$) and fit the whitened residuals
//! $L^{-1} r$, which are independent with unit variance when $\Sigma$ is right.

/// A row of $B$: the first peak it uses and its coefficients on that peak and the next ones.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// Index of the first peak.
    pub start: usize,
    /// $\partial r_i / \partial t_{start + j}$.
    pub coef: Vec<f64>,
}

/// The lower Cholesky factor of a banded SPD matrix: `l[i][k]` is $L_{i, i - m + k}$.
#[derive(Debug, Clone)]
pub struct BandCholesky {
    m: usize,
    l: Vec<Vec<f64>>,
}

impl BandCholesky {
    /// Factors $\Sigma = B W B^{\mathsf T}$ for rows sorted by `start` (strictly increasing).
    /// `None` if it is not positive definite.
    pub fn from_rows(rows: &[Row], w: &[f64]) -> Option<Self> {
        let m = rows.iter().map(|r| r.coef.len()).max().unwrap_or(1).max(1) - 1;
        let n = rows.len();
        let sigma = |i: usize, k: usize| -> f64 {
            let (a, b) = (&rows[i], &rows[k]);
            let mut s = 0.0;
            for (ja, ca) in a.coef.iter().enumerate() {
                let p = a.start + ja;
                if p >= b.start && p < b.start + b.coef.len() {
                    s += ca * b.coef[p - b.start] * w.get(p).copied().unwrap_or(0.0);
                }
            }
            s
        };
        let mut l = vec![vec![0.0; m + 1]; n];
        for i in 0..n {
            let j0 = i.saturating_sub(m);
            for j in j0..=i {
                let mut s = sigma(i, j);
                let k0 = j0.max(j.saturating_sub(m));
                for k in k0..j {
                    s -= l[i][k + m - i] * l[j][k + m - j];
                }
                if j == i {
                    if !(s > 0.0 && s.is_finite()) {
                        return None;
                    }
                    l[i][m] = s.sqrt();
                } else {
                    l[i][j + m - i] = s / l[j][m];
                }
            }
        }
        Some(Self { m, l })
    }

    /// $\ln\det\Sigma = 2\sum_i \ln L_{ii}$.
    pub fn ln_det(&self) -> f64 {
        2.0 * self.l.iter().map(|row| row[self.m].ln()).sum::<f64>()
    }

    /// Solves $L z = r$ in place (whitening).
    pub fn whiten(&self, r: &mut [f64]) {
        let m = self.m;
        for i in 0..r.len() {
            let k0 = i.saturating_sub(m);
            let s: f64 = (k0..i).map(|k| self.l[i][k + m - i] * r[k]).sum();
            r[i] = (r[i] - s) / self.l[i][m];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::DMatrix;

    #[test]
    fn whitening_matches_a_dense_cholesky() {
        let rows: Vec<Row> = (0..7)
            .map(|i| Row {
                start: i,
                coef: vec![-1.0 - 0.1 * i as f64, 0.3, 1.0 + 0.05 * i as f64],
            })
            .collect();
        let w: Vec<f64> = (0..9).map(|j| 1.0 + 0.2 * j as f64).collect();
        let mut b = DMatrix::<f64>::zeros(7, 9);
        for (i, r) in rows.iter().enumerate() {
            for (j, c) in r.coef.iter().enumerate() {
                b[(i, r.start + j)] = *c;
            }
        }
        let sigma =
            &b * DMatrix::from_diagonal(&nalgebra::DVector::from_vec(w.clone())) * b.transpose();
        let dense = sigma.cholesky().unwrap().l();
        let band = BandCholesky::from_rows(&rows, &w).unwrap();
        let r: Vec<f64> = (0..7).map(|i| (i as f64 * 0.7).sin()).collect();
        let mut z = r.clone();
        band.whiten(&mut z);
        let zd = dense
            .solve_lower_triangular(&nalgebra::DVector::from_vec(r))
            .unwrap();
        for i in 0..7 {
            assert!((z[i] - zd[i]).abs() < 1e-12, "{i}: {} vs {}", z[i], zd[i]);
        }
    }
}
